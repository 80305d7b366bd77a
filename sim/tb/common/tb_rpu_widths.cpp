// tb_rpu_widths: every width formula of rtl/common/rpu_widths.vh against its C++ twin in
// ref/model/hw_params.h (HwParams, and surface_ip_lanes for the search's lanes), over the whole
// range in the table (hw_params.def) of each parameter it takes, all combinations: the Verilated
// rpu_widths_probe evaluates the macros as a module's parameter declaration would. Exhaustive; no
// random vectors. A disagreement prints the formula, the parameters, and both values.
#include <verilated.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "Vrpu_widths_probe.h"
#include "model/hw_params.h"
#include "model/surface/rpu_surface_latency.h"

namespace {

using rpu::ref::HwParams;
using Probe = Vrpu_widths_probe;
namespace hr = rpu::ref::hw_range;

// The inputs of a formula: the hardware parameters, a step k and an indicator count.
struct Point {
  HwParams p;
  int k = 0, ind = 0;
};

// One swept input: its name (as the Verilog parameter), its range, and where it goes.
struct Axis {
  const char* name;
  int lo, hi;
  int& (*at)(Point&);
};
#define RPU_AXIS(id, name, lo, hi, field) \
  const Axis id{name, lo, hi, [](Point& x) -> int& { return field; }};
#define RPU_WIDTH(...)
#include "tb_rpu_widths.def"
#undef RPU_AXIS
#undef RPU_WIDTH

struct Formula {
  const char* name;
  std::vector<Axis> over;
  long (*rtl)(const Probe&);
  long (*cpp)(const Point&);
};

// rpu_widths.vh's formulas, in its order, with their twins (tb_rpu_widths.def).
const std::vector<Formula>& formulas() {
#define RPU_AXIS(...)
#define RPU_WIDTH(macro, out, twin, ...)                              \
  {#macro, {__VA_ARGS__}, [](const Probe& v) -> long { return v.out; }, \
   [](const Point& x) -> long { return (void)x, twin; }},
  static const std::vector<Formula> f = {
#include "tb_rpu_widths.def"
  };
#undef RPU_AXIS
#undef RPU_WIDTH
  return f;
}

void drive(Probe& v, const Point& x) {
  v.coord_w_i = x.p.coord_w;
  v.dir_frac_i = x.p.dir_frac;
  v.t_frac_i = x.p.t_frac;
  v.unit_frac_i = x.p.unit_frac;
  v.edge_frac_i = x.p.edge_frac;
  v.surf_w_i = x.p.surf_w;
  v.n1_i = x.p.n1;
  v.k_i = x.k;
  v.ind_i = x.ind;
  v.eval();
}

}  // namespace

int main(int argc, char** argv) {
  auto ctx = std::make_unique<VerilatedContext>();
  ctx->commandArgs(argc, argv);
  Probe v(ctx.get());
  long compared = 0, failed = 0;
  for (const Formula& f : formulas()) {
    // Every combination of the formula's axes, the other inputs at their defaults.
    Point x;
    for (const Axis& a : f.over) a.at(x) = a.lo;
    for (bool more = true; more;) {
      drive(v, x);
      const long rtl = f.rtl(v), cpp = f.cpp(x);
      ++compared;
      if (rtl != cpp && ++failed <= 20) {
        std::string at;
        for (const Axis& a : f.over)
          at += (at.empty() ? "" : ", ") + std::string(a.name) + " " + std::to_string(a.at(x));
        std::printf("FAILURE %s at %s: rpu_widths.vh gives %ld, hw_params.h %ld\n", f.name,
                    at.empty() ? "-" : at.c_str(), rtl, cpp);
      }
      more = false;
      for (const Axis& a : f.over) {  // the next combination (the first axis fastest)
        if (++a.at(x) <= a.hi) {
          more = true;
          break;
        }
        a.at(x) = a.lo;
      }
    }
  }
  v.final();
  if (failed) {
    std::printf("FAILURE: %ld of %ld width values differ\n", failed, compared);
    return 1;
  }
  std::printf("tb_rpu_widths: %ld values of %zu formulas of rpu_widths.vh equal hw_params.h's\n",
              compared, formulas().size());
  return 0;
}
