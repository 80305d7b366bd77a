// fuzz_params (issue 14, item 3): the hardware parameters as `rpu render`/`rpu config` take them
// (--n, --n1, --coord-w, ..., --surf-w, --angle-w): every entry of the parameter table
// (ref/model/hw_params.def) drawn from the bytes, a little beyond its range, validated
// (HwParams::validate, tracer::check_ip_parameters), and every accepted set renders a built-in
// scene (its camera cut to at most 8×8 pixels) with the bit-accurate model.
//
// A refused set or scene must be one rpu::Error, one line. A crash, undefined behaviour (shifts,
// signed overflow, float-to-integer conversion out of range in the model's widths), a hang or a
// leak at any accepted set is a finding. No comparison with float-ip: the accuracy bound is
// documented at the defaults only.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <fuzzer/FuzzedDataProvider.h>

#include "builtin_scenes.h"
#include "common/error.h"
#include "model/descriptors.h"
#include "model/hw_params.h"
#include "model/ref_renderer.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "tracer/float_tracer.h"

namespace {

constexpr int kMaxSide = 8;

// A value of the entry near its range (a little beyond, so both ends of validate() are
// exercised): an integer in [min - 2, max + 2], sometimes the entry's off value (sqrt_w 0); a
// choice's value or one just outside them (an invalid metric must be refused, not rendered).
int draw(FuzzedDataProvider& in, const rpu::ref::HwParamInfo& d) {
  using rpu::ref::HwParamKind;
  if (d.kind == HwParamKind::kChoice) return in.ConsumeIntegralInRange<int>(d.min - 1, d.max + 1);
  if (d.kind == HwParamKind::kRangeOrOff && in.ConsumeBool()) return d.choices.front().value;
  return in.ConsumeIntegralInRange<int>(d.min - 2, d.max + 2);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const auto& scenes = rpu::app::builtin_scenes();
  const auto& builtin = scenes[in.ConsumeIntegralInRange<std::size_t>(0, scenes.size() - 1)];
  rpu::ref::HwParams p;
  for (const rpu::ref::HwParamInfo& d : rpu::ref::hw_param_table()) d.set(p, draw(in, d));
  // n % n1 == 0 (a combination validate() checks) would refuse most draws: half the time n is
  // rounded down to a multiple of n1.
  if (p.n1 > 0 && in.ConsumeBool()) p.n -= p.n % p.n1;
  try {
    p.validate();
    rpu::tracer::check_ip_parameters(p.n, p.n1);
    (void)p.describe();
    (void)p.summary();
    rpu::scene::Scene scene = rpu::scene::parse_scene(builtin.json, builtin.name);
    if (!scene.patches.empty()) return 0;  // no fixed-point path
    scene.camera.width = std::min(scene.camera.width, kMaxSide);
    scene.camera.height = std::min(scene.camera.height, kMaxSide);
    const rpu::scene::CompiledScene sc = rpu::scene::compile_scene(scene);
    const rpu::ref::ModelScene model = rpu::ref::quantize_scene(sc, p);
    rpu::ref::RefOptions ro;
    ro.threads = 1;
    (void)rpu::ref::render_ref(sc, model, ro);
  } catch (const rpu::Error& e) {
    const std::string what = e.what();
    if (what.empty() || what.find('\n') != std::string::npos) {
      std::fprintf(stderr, "fuzz_params: malformed error message: [%s]\n", what.c_str());
      std::abort();
    }
  }
  return 0;
}
