// rpu_top against the model, work item by work item (rpu::ref::process_curve_pair): every field
// of every result. Modes (first argument):
//   frame        the binned work items of a demo frame, random valid and ready (default)
//   throughput   10,000 work items, input always valid, output always ready: counts cycles,
//                checks cycles ≤ items + latency + 8 (unrolled) and reports latency and rate
//   backpressure random valid and ready with long stalls: a scoreboard proves nothing is lost,
//                duplicated or reordered
// Options: --scene NAME (default curve12), --size N (square image side, default 64), --x-seed S
// (Verilator's random initial values; with --x-initial unique every seed must give the same
// results).
#include <algorithm>
#include <cstring>
#include <deque>
#include <memory>
#include <string>

#include "Vrpu_top.h"
#include "model/units.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "scene/screen_bins.h"
#include "tb_common.h"

#ifndef TOP_UNROLLED
#define TOP_UNROLLED 1
#endif

namespace {

using namespace rpu;
using sim::i128;
using sim::u128;

// Packs fields MSB first, like a Verilog concatenation {a, b, c}.
class Concat {
 public:
  void add(i128 v, int width) { fields_.push_back({v, width}); }
  void add3(i128 x, i128 y, i128 z, int width) {  // {z, y, x}
    add(z, width);
    add(y, width);
    add(x, width);
  }
  template <std::size_t N>
  void store(VlWide<N>& port) const {
    for (std::size_t k = 0; k < N; ++k) port[k] = 0;
    int at = 0;
    for (auto it = fields_.rbegin(); it != fields_.rend(); ++it) {
      const u128 u = static_cast<u128>(it->value);
      for (int b = 0; b < it->width; ++b, ++at) {
        const bool bit = b < 128 ? ((u >> b) & 1) != 0 : it->value < 0;
        if (bit && static_cast<std::size_t>(at / 32) < N) port[static_cast<std::size_t>(at / 32)] |= 1u << (at % 32);
      }
    }
  }
  int width() const {
    int w = 0;
    for (const auto& f : fields_) w += f.width;
    return w;
  }

 private:
  struct Field {
    i128 value;
    int width;
  };
  std::vector<Field> fields_;
};

struct Work {
  std::uint32_t id;
  int i, j;
  int seg;
  ref::PairResult want;
  int primitive;
};

}  // namespace

int main(int argc, char** argv) {
  std::string mode = "frame", scene_name = "curve12";
  int size = 64;
  std::uint64_t x_seed = 0;
  for (int a = 1; a < argc; ++a) {
    const std::string s = argv[a];
    if (s == "--scene" && a + 1 < argc) scene_name = argv[++a];
    else if (s == "--size" && a + 1 < argc) size = std::atoi(argv[++a]);
    else if (s == "--x-seed" && a + 1 < argc) x_seed = std::strtoull(argv[++a], nullptr, 0);
    else if (s[0] != '+') mode = s;
  }
  auto ctx = std::make_unique<VerilatedContext>();
  ctx->commandArgs(argc, argv);
  if (x_seed != 0) {
    ctx->randReset(2);  // randomise every initial value (with --x-initial unique)
    ctx->randSeed(static_cast<int>(x_seed));
  }
  auto top = std::make_unique<Vrpu_top>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_top");
  std::mt19937_64 rng(seed);

  scene::Scene scn = scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/" + scene_name + ".json");
  scn.camera.width = size;
  scn.camera.height = size;
  const scene::CompiledScene sc = scene::compile_scene(scn);
  ref::HwParams p;
  p.unrolled = TOP_UNROLLED != 0;
  const ref::ModelScene m = ref::quantize_scene(sc, p);
  const int CW = p.coord_w, DW = CW + 1, TW = p.t_w(), UW = p.unit_w(), XW = CW + 3;
  const int VgW = 4 + p.dir_frac + 14, EgW = 4 + p.edge_frac + 14, HW = CW + 5;
  const int PrimW = 16, R2W = 2 * CW + 1, L2W = 2 * CW + 3, DepthW = CW + 4 + EgW + 2;

  // ---- descriptors ----
  {
    const ref::CameraDesc& c = m.camera;
    Concat cam;
    cam.add3(c.v0.x, c.v0.y, c.v0.z, VgW);
    cam.add3(c.dx.x, c.dx.y, c.dx.z, VgW);
    cam.add3(c.dy.x, c.dy.y, c.dy.z, VgW);
    cam.add3(c.el0.x, c.el0.y, c.el0.z, EgW);
    cam.add3(c.et0.x, c.et0.y, c.et0.z, EgW);
    cam.add3(c.sw.x, c.sw.y, c.sw.z, EgW);
    cam.add3(c.w.x, c.w.y, c.w.z, EgW);
    cam.add3(c.eye.x, c.eye.y, c.eye.z, CW);
    cam.store(top->cam_data_i);
  }
  top->rst_ni = 0;
  top->item_valid_i = 0;
  top->res_ready_i = 0;
  top->cam_we_i = 1;
  sim::tick(*top, *ctx);
  top->cam_we_i = 0;
  for (size_t k = 0; k < m.curve_segments.size(); ++k) {
    const ref::SegmentDesc& s = m.curve_segments[k];
    Concat d;
    d.add(s.primitive, PrimW);
    d.add3(s.p1.x, s.p1.y, s.p1.z, CW);
    d.add3(s.d.x, s.d.y, s.d.z, DW);
    d.add3(s.c0.x, s.c0.y, s.c0.z, CW);
    d.add(s.R2, R2W);
    d.add(s.L2, L2W);
    d.add(s.inv_m, p.inv_w);
    d.add(s.inv_s, 7);
    for (const ref::GuideDesc& g : s.guide) {
      d.add(static_cast<int>(g.mode), 2);
      d.add(g.h, HW);
      d.add(g.a, CW);
      d.add(g.b, p.t_frac);
      d.add3(g.u.x, g.u.y, g.u.z, UW);
    }
    d.store(top->seg_data_i);
    top->seg_addr_i = static_cast<unsigned>(k);
    top->seg_we_i = 1;
    sim::tick(*top, *ctx);
  }
  top->seg_we_i = 0;
  sim::reset(*top, *ctx);

  // ---- work items: the frame's binned (pixel, segment) pairs ----
  std::vector<Work> work;
  const scene::ScreenBins bins(sc.camera, sc.curve_segments);
  std::uint32_t id = 0;
  for (int j = 0; j < m.camera.height; ++j)
    for (int i = 0; i < m.camera.width; ++i)
      for (auto k : bins.segments_for_pixel(i, j))
        work.push_back({id++, i, j, static_cast<int>(k),
                        ref::process_curve_pair(p, m.camera, m.curve_segments[k], i, j),
                        m.curve_segments[k].primitive});
  if (mode == "throughput") {
    std::vector<Work> w;
    for (std::uint32_t k = 0; k < 10000; ++k) {
      Work x = work[k % work.size()];
      x.id = k;
      w.push_back(x);
    }
    work = w;
  }

  // ---- run ----
  const int valid_pct = mode == "frame" ? 80 : mode == "backpressure" ? 50 : 100;
  const int ready_pct = mode == "frame" ? 80 : mode == "backpressure" ? 30 : 100;
  std::deque<Work> pending;
  size_t next = 0;
  long matched = 0, cycle = 0, hits = 0, first_out = -1, stall_cycles = 0;
  const long total = static_cast<long>(work.size());
  bool stall_phase = false;
  while (matched < total) {
    if (mode == "backpressure" && cycle % 500 == 0) stall_phase = !stall_phase && (rng() % 3 == 0);
    const bool issue = next < work.size() && static_cast<int>(rng() % 100) < valid_pct;
    const bool ready_in = !stall_phase && static_cast<int>(rng() % 100) < ready_pct;
    top->item_valid_i = issue;
    if (issue) {
      const Work& w = work[next];
      top->item_id_i = w.id;
      top->item_i_i = static_cast<unsigned>(w.i);
      top->item_j_i = static_cast<unsigned>(w.j);
      top->item_seg_i = static_cast<unsigned>(w.seg);
    }
    top->res_ready_i = ready_in;
    top->eval();
    const bool accepted = issue && top->item_ready_o;
    const bool popped = top->res_valid_o && ready_in;
    if (popped) {
      const std::uint32_t rid = top->res_id_o;
      if (pending.empty() || pending.front().id != rid) {
        std::printf("FAILURE cycle %ld: result id %u but %s expected (lost, duplicated or reordered)\n",
                    cycle, rid, pending.empty() ? "nothing" : std::to_string(pending.front().id).c_str());
        return 1;
      }
      const Work w = pending.front();
      pending.pop_front();
      const ref::PairResult& r = w.want;
      const i128 depth = sim::get_signed(top->res_depth_o, DepthW);
      const i128 t = sim::get_signed(top->res_t_o, TW);
      const i128 x[3] = {sim::get_comp(top->res_x_o, 0, XW), sim::get_comp(top->res_x_o, 1, XW),
                         sim::get_comp(top->res_x_o, 2, XW)};
      const bool ok = top->res_i_o == static_cast<unsigned>(w.i) &&
                      top->res_j_o == static_cast<unsigned>(w.j) &&
                      top->res_seg_o == static_cast<unsigned>(w.seg) &&
                      top->res_prim_o == static_cast<unsigned>(w.primitive) &&
                      static_cast<bool>(top->res_pred1_o) == r.interval.pred1 &&
                      static_cast<bool>(top->res_hit_o) == r.hit && depth == r.depth &&
                      top->res_tau_o == r.tau && t == r.t && x[0] == r.X.x && x[1] == r.X.y &&
                      x[2] == r.X.z && static_cast<bool>(top->res_ovf_o) == r.overflow;
      if (!ok) {
        std::printf("FAILURE cycle %ld item %u: pixel (%d,%d) segment %d\n"
                    "  expected pred1 %d hit %d depth %s tau %llu t %s X (%s, %s, %s) ovf %d prim %d\n"
                    "  actual   pred1 %d hit %d depth %s tau %llu t %s X (%s, %s, %s) ovf %d prim %u\n",
                    cycle, w.id, w.i, w.j, w.seg, r.interval.pred1, r.hit,
                    sim::to_string(r.depth).c_str(), static_cast<unsigned long long>(r.tau),
                    sim::to_string(r.t).c_str(), sim::to_string(r.X.x).c_str(),
                    sim::to_string(r.X.y).c_str(), sim::to_string(r.X.z).c_str(), r.overflow,
                    w.primitive, top->res_pred1_o, top->res_hit_o, sim::to_string(depth).c_str(),
                    static_cast<unsigned long long>(top->res_tau_o), sim::to_string(t).c_str(),
                    sim::to_string(x[0]).c_str(), sim::to_string(x[1]).c_str(),
                    sim::to_string(x[2]).c_str(), top->res_ovf_o, top->res_prim_o);
        return 1;
      }
      if (first_out < 0) first_out = cycle;
      hits += r.hit;
      ++matched;
    }
    if (issue && !accepted) ++stall_cycles;
    sim::tick(*top, *ctx);
    ++cycle;
    if (accepted) {
      pending.push_back(work[next]);
      ++next;
    }
    if (cycle > 100 * total + 100000) {
      std::printf("FAILURE: timeout after %ld cycles, %ld of %ld matched\n", cycle, matched, total);
      return 1;
    }
  }
  top->final();
  std::printf("rpu_top %s (%s), %s %dx%d: matched %ld items (%ld hits) in %ld cycles, latency %ld "
              "cycles, %.3f items/cycle, %ld input stall cycles\n",
              mode.c_str(), TOP_UNROLLED ? "unrolled" : "iterative", scene_name.c_str(), size, size,
              matched, hits, cycle, first_out, static_cast<double>(matched) / cycle, stall_cycles);
  if (mode == "throughput" && TOP_UNROLLED && cycle > total + first_out + 8) {
    std::printf("FAILURE: %ld cycles for %ld items exceeds items + latency (%ld) + 8\n", cycle, total,
                first_out);
    return 1;
  }
  return 0;
}
