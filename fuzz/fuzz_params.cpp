// fuzz_params (issue 14, item 3): the hardware parameters as `rpu render`/`rpu config` take them
// (--n, --n1, --coord-w, ..., --surf-w, --angle-w): every field drawn from the bytes, validated
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

// A width near [lo, hi] (a little beyond, so both ends of validate() are exercised).
int width(FuzzedDataProvider& in, int lo, int hi) { return in.ConsumeIntegralInRange<int>(lo - 2, hi + 2); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const auto& scenes = rpu::app::builtin_scenes();
  const auto& builtin = scenes[in.ConsumeIntegralInRange<std::size_t>(0, scenes.size() - 1)];
  rpu::ref::HwParams p;
  p.n1 = width(in, 1, 8);
  p.n = p.n1 * in.ConsumeIntegralInRange<int>(0, 41);
  p.coord_w = width(in, 12, rpu::ref::HwParams::kMaxCoordW);
  p.dir_frac = width(in, 8, rpu::ref::HwParams::kMaxDirFrac);
  p.t_frac = width(in, 8, 48);
  p.unit_frac = width(in, 8, 40);
  p.edge_frac = width(in, 8, 40);
  p.inv_w = width(in, 8, 40);
  p.sqrt_w = in.ConsumeBool() ? 0 : width(in, 16, 126);
  p.metric = in.ConsumeBool() ? rpu::ref::Metric::kAbs : rpu::ref::Metric::kSquared;
  p.unrolled = in.ConsumeBool();
  p.surf_w = width(in, 16, rpu::ref::HwParams::kMaxSurfW);
  p.angle_w = width(in, 12, 32);
  try {
    p.validate();
    rpu::tracer::check_ip_parameters(p.n, p.n1);
    (void)p.describe();
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
