// fuzz_render (issue 14, item 3): tiny fuzzed scenes through the bit-accurate model (`ref`) and
// the float tracer's iterative process (`float-ip`), as `rpu compare` runs them.
//
// The input is either
//   - a scene file (its first byte '{'): parsed as the user's file would be, then made tiny
//     (each image side at most kMaxSide, patches dropped: they have no fixed-point path); or
//   - bytes from which a small scene file is derived (FuzzedDataProvider): 1 to 4 curves,
//     textures and surfaces of every type, with a camera and hardware parameters (n, n1) drawn
//     from the bytes, written as JSON text and parsed, so the scene reader's checks apply.
// A scene is refused with rpu::Error (one line) by the reader, the compiler or the model's
// quantisation; otherwise both backends render it with no sanitizer report, and, unless the model
// warned that the scene is below its precision threshold (ref::Precision, docs/fixed-point.md),
// the two images must agree as `rpu compare` measures it (app/compare_report.h, ref_vs_float_ip).
// A tiny frame has few hit pixels, so the 0.1 % bound of kRefVsFloatIpBound is applied with one
// pixel of slack per kSlackHits hits, swaps (both hit, different primitives) are left out, and so
// are the pixels where the two double-precision tracers themselves disagree (float-ip vs the
// ideal `float`): there the pair's closest approach lies on a pixel edge to within the IP's
// resolution 2^-n of the chord, and the model may land on either side (see below and
// docs/verification.md "Fuzzing").
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <fmt/format.h>
#include <fuzzer/FuzzedDataProvider.h>

#include "common/error.h"
#include "compare_report.h"
#include "model/descriptors.h"
#include "model/hw_params.h"
#include "model/ref_renderer.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "tracer/float_tracer.h"

namespace {

constexpr const char* kSource = "fuzz.json";
constexpr int kMaxSide = 16;
constexpr std::size_t kMaxSegments = 600;  // one render stays in milliseconds

// A number of the scene: k / 8 for k in [lo, hi] (exact in JSON and in double).
double eighths(FuzzedDataProvider& in, int lo, int hi) {
  return in.ConsumeIntegralInRange<int>(lo, hi) / 8.0;
}

std::string vec3(FuzzedDataProvider& in, int lo, int hi) {
  return fmt::format("[{}, {}, {}]", eighths(in, lo, hi), eighths(in, lo, hi), eighths(in, lo, hi));
}

std::string color(FuzzedDataProvider& in) {
  return fmt::format("[{}, {}, {}]", in.ConsumeIntegralInRange<int>(0, 4) / 4.0,
                     in.ConsumeIntegralInRange<int>(0, 4) / 4.0, in.ConsumeIntegralInRange<int>(0, 4) / 4.0);
}

std::string polyline(FuzzedDataProvider& in, bool texture) {
  const int points = in.ConsumeIntegralInRange<int>(2, 7);
  const bool closed = in.ConsumeBool();
  const bool normals = in.ConsumeIntegralInRange<int>(0, 3) == 0;
  std::string pts, nrm;
  for (int k = 0; k < points; ++k) {
    pts += k ? ", " : "";
    nrm += k ? ", " : "";
    if (texture) {
      pts += fmt::format("[{}, {}]", eighths(in, -16, 16), eighths(in, -16, 16));
      nrm += fmt::format("[{}, {}]", eighths(in, -8, 8), eighths(in, -8, 8));
    } else {
      pts += vec3(in, -16, 16);
      nrm += vec3(in, -8, 8);
    }
  }
  std::string s = fmt::format("{{\"points\": [{}], \"closed\": {}", pts, closed);
  if (normals) s += fmt::format(", \"normals\": [{}]", nrm);
  if (texture) s += fmt::format(", \"half_width\": {}", in.ConsumeIntegralInRange<int>(1, 32) / 64.0);
  return s + ", \"color\": " + color(in) + "}";
}

// A surface of any type, each of its own parameters present or not (the reader's defaults).
std::string surface(FuzzedDataProvider& in) {
  static const char* const kTypes[] = {"ellipsoid", "relief_ellipsoid", "spiral", "snail", "rocket"};
  static const char* const kKeys[][8] = {
      {"a", "b", "c", "y_range", nullptr},
      {"a", "b", "c", "d", "e", "y_range", nullptr},
      {"R", "k", "a", "b", "c", "phi_max", nullptr},
      {"a", "phi_max", nullptr},
      {"a", "b", "c", "d", "e", nullptr}};
  const int t = in.ConsumeIntegralInRange<int>(0, 4);
  std::string s = fmt::format("{{\"type\": \"{}\"", kTypes[t]);
  for (const char* const* k = kKeys[t]; *k; ++k) {
    if (!in.ConsumeBool()) continue;
    const std::string key = *k;
    if (key == "y_range")
      s += fmt::format(", \"y_range\": [{}, {}]", eighths(in, -16, 8), eighths(in, -8, 16));
    else if (key == "phi_max")
      s += fmt::format(", \"phi_max\": {}", in.ConsumeIntegralInRange<int>(1, 60) / 2.0);
    else
      s += fmt::format(", \"{}\": {}", key, eighths(in, -4, 24));
  }
  s += ", \"position\": " + vec3(in, -8, 8);
  if (in.ConsumeBool())
    s += fmt::format(", \"rotation_deg\": [{}, {}, {}]", in.ConsumeIntegralInRange<int>(-180, 180),
                     in.ConsumeIntegralInRange<int>(-180, 180), in.ConsumeIntegralInRange<int>(-180, 180));
  if (in.ConsumeBool()) s += fmt::format(", \"scale\": {}", in.ConsumeIntegralInRange<int>(1, 16) / 8.0);
  return s + ", \"color\": " + color(in) + "}";
}

struct Derived {
  std::string json;
  int n = 16, n1 = 2;
};

Derived derive_scene(FuzzedDataProvider& in) {
  static const int kParams[][2] = {{16, 2}, {16, 2}, {16, 2}, {12, 3}, {16, 4}, {8, 1}, {24, 4}};
  Derived d;
  const auto& p = kParams[in.ConsumeIntegralInRange<int>(0, 6)];
  d.n = p[0];
  d.n1 = p[1];
  const int w = in.ConsumeIntegralInRange<int>(1, kMaxSide), h = in.ConsumeIntegralInRange<int>(1, kMaxSide);
  const std::string eye = vec3(in, -48, 48), target = vec3(in, -8, 8);
  static const char* const kUp[] = {"[0, 0, 1]", "[0, 1, 0]", "[1, 0, 0]", "[0, 0, -1]"};
  const char* up = kUp[in.ConsumeIntegralInRange<int>(0, 3)];
  const int fov = in.ConsumeIntegralInRange<int>(1, 179);
  std::string curves, textures, surfaces;
  const int count = in.ConsumeIntegralInRange<int>(1, 4);
  for (int k = 0; k < count; ++k) {
    switch (in.ConsumeIntegralInRange<int>(0, 2)) {
      case 0: curves += (curves.empty() ? "" : ", ") + polyline(in, false); break;
      case 1: textures += (textures.empty() ? "" : ", ") + polyline(in, true); break;
      default: surfaces += (surfaces.empty() ? "" : ", ") + surface(in); break;
    }
  }
  d.json = fmt::format(
      "{{\"camera\": {{\"eye\": {}, \"target\": {}, \"up\": {}, \"fov_deg\": {}, \"width\": {}, "
      "\"height\": {}}}, \"background\": [0, 0, 0], \"curves\": [{}], \"textures\": [{}], "
      "\"surfaces\": [{}]}}",
      eye, target, up, fov, w, h, curves, textures, surfaces);
  return d;
}

[[noreturn]] void finding(const std::string& what, const std::string& scene) {
  std::fprintf(stderr, "fuzz_render: %s\nscene: %s\n", what.c_str(), scene.c_str());
  std::abort();
}

// A tiny frame has few hits: one differing pixel is already several per cent. One pixel of slack
// per kSlackHits hit pixels (at least one), on top of kRefVsFloatIpBound.
constexpr std::size_t kSlackHits = 64;

// With RPU_FUZZ_STATS set, a tally of the outcomes on exit (for docs/verification.md); with
// RPU_FUZZ_STATS=verbose also every refusal.
struct Tally {
  std::uint64_t refused = 0, rendered = 0, hit_pixels = 0, differing = 0, beyond_bound = 0,
                warned = 0, swaps = 0, ambiguous = 0;
  ~Tally() {
    if (std::getenv("RPU_FUZZ_STATS"))
      std::fprintf(stderr,
                   "fuzz_render: %llu refused, %llu rendered (%llu with a precision warning), "
                   "%llu hit pixels, %llu differing (%llu swaps, %llu where float-ip and float "
                   "disagree), %llu frames beyond the bare bound\n",
                   static_cast<unsigned long long>(refused), static_cast<unsigned long long>(rendered),
                   static_cast<unsigned long long>(warned), static_cast<unsigned long long>(hit_pixels),
                   static_cast<unsigned long long>(differing), static_cast<unsigned long long>(swaps),
                   static_cast<unsigned long long>(ambiguous),
                   static_cast<unsigned long long>(beyond_bound));
  }
} tally;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Derived d;
  const bool file = size > 0 && data[0] == '{';
  if (file) {
    d.json.assign(reinterpret_cast<const char*>(data), size);
  } else {
    FuzzedDataProvider in(data, size);
    d = derive_scene(in);
  }
  try {
    rpu::scene::Scene scene = rpu::scene::parse_scene(d.json, kSource);
    scene.camera.width = std::min(scene.camera.width, kMaxSide);
    scene.camera.height = std::min(scene.camera.height, kMaxSide);
    scene.patches.clear();
    const rpu::scene::CompiledScene sc = rpu::scene::compile_scene(scene);
    if (sc.curve_segments.size() + sc.texture_segments.size() > kMaxSegments) return 0;
    rpu::ref::HwParams hw;
    hw.n = d.n;
    hw.n1 = d.n1;
    hw.validate();
    const rpu::ref::ModelScene model = rpu::ref::quantize_scene(sc, hw);
    rpu::ref::RefOptions ro;
    ro.threads = 1;
    const rpu::image::Frame ref = rpu::ref::render_ref(sc, model, ro);
    rpu::tracer::FloatOptions fo;
    fo.method = rpu::tracer::Method::kIterative;
    fo.n = d.n;
    fo.n1 = d.n1;
    fo.surf_n1_first = hw.surf_n1_first;
    fo.threads = 1;
    const rpu::image::Frame ip = rpu::tracer::render_float(sc, fo);
    fo.method = rpu::tracer::Method::kIdeal;
    const rpu::image::Frame ideal = rpu::tracer::render_float(sc, fo);
    for (const rpu::image::Frame* f : {&ip, &ideal})
      if (ref.width != f->width || ref.height != f->height || ref.width != scene.camera.width ||
          ref.height != scene.camera.height)
        finding("frame sizes differ", d.json);
    const auto primitives = static_cast<std::int32_t>(sc.primitives.size());
    for (const rpu::image::Frame* f : {&ref, &ip, &ideal})
      for (const std::int32_t id : f->primitive)
        if (id < rpu::image::kBackground || id >= primitives) finding("unknown primitive id", d.json);
    const rpu::app::RefVsFloatIp r = rpu::app::ref_vs_float_ip(ref, ip);
    // Swaps: both hit, different primitives. Where primitives coincide or touch (two surfaces at
    // one place, a curve on a texture) the depth rounding decides the order, and ref's depth
    // format is not float-ip's, so a swap cannot be told from a tie here: compare counts swaps,
    // this check leaves them out and judges coverage (a hit in one backend only).
    // Ambiguous pixels: float-ip and the ideal tracer disagree there (one hits, the other does
    // not, or they hit different primitives). The IP's answer is then decided by where its final
    // point 2^-n along the chord falls against a pixel edge, and the model's fixed-point point may
    // fall on the other side: e.g. fuzz/regressions/fuzz_render/endpoint_on_pixel_edge.json, a
    // curve whose end projects onto a pixel corner and runs 2e-6 pixel beside the edge, which the
    // ideal tracer and the model give to the right pixel and float-ip to the left one.
    std::size_t swaps = 0, ambiguous = 0;
    for (std::size_t k = 0; k < ref.primitive.size(); ++k) {
      if (ref.primitive[k] == ip.primitive[k]) continue;
      if (ip.primitive[k] != ideal.primitive[k]) ++ambiguous;
      else if (ref.primitive[k] >= 0 && ip.primitive[k] >= 0) ++swaps;
    }
    tally.swaps += swaps;
    tally.ambiguous += ambiguous;
    const std::size_t slack = 1 + r.hit_pixels / kSlackHits;
    ++tally.rendered;
    tally.warned += !model.precision.warning.empty();
    tally.hit_pixels += r.hit_pixels;
    tally.differing += r.differing;
    tally.beyond_bound += r.beyond_bound;
    const std::size_t counted = r.differing - swaps - ambiguous;
    if (model.precision.warning.empty() && r.beyond_bound && counted > slack) {
      std::string rows;  // the two frames, primitive ids ('.' background): ref | float-ip
      for (int j = 0; j < ref.height; ++j) {
        for (const rpu::image::Frame* f : {&ref, &ip}) {
          for (int i = 0; i < f->width; ++i) {
            const std::int32_t id = f->primitive[f->index(i, j)];
            rows += id < 0 ? std::string(".") : std::to_string(id);
          }
          rows += f == &ref ? " | " : "\n";
        }
      }
      std::fputs(rows.c_str(), stderr);
      finding(fmt::format("ref vs float-ip: {} of {} hit pixels differ, {} in coverage where float "
                          "agrees with float-ip (n = {}, n1 = {})",
                          r.differing, r.hit_pixels, counted, d.n, d.n1),
              d.json);
    }
  } catch (const rpu::Error& e) {
    ++tally.refused;
    const std::string what = e.what();
    if (const char* v = std::getenv("RPU_FUZZ_STATS"); v && std::string(v) == "verbose")
      std::fprintf(stderr, "refused: %s\n", what.c_str());
    if (what.empty() || what.find('\n') != std::string::npos) finding("malformed error: " + what, d.json);
  }
  return 0;
}
