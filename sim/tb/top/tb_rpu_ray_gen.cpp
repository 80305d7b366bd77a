// rpu_ray_gen against its twin (rpu::ref::ray_generator) on camera descriptors from the real
// scene compiler: scenes/curve12.json and scenes/airfield.json, loaded, compiled and quantised
// with HwParams {dir_frac = DIR_FRAC, edge_frac = EDGE_FRAC}. RAYGEN_FULL: every pixel of curve12,
// the four corners of both images, random airfield pixels and a stretch where the two cameras
// alternate pixel by pixel; otherwise corners and a few thousand random pixels of both scenes.
// Then synthetic cameras, one per pixel: random edge vectors over the whole port range (they are
// exact for every input) and random v0, dx, dy, i, j over the whole index range, within the
// header's preconditions (every component of v0 + i·dx + j·dy fits Q(4.FV+14), |v| > 1/2); and
// directions with v·v = k² − 1 (v = ±(b², b, b) permuted, b even), where one unit of the
// radicand changes |v|.
// Each pixel samples its own camera ports with valid_i (junk on them in the gaps); every output
// field, the tag and the latency compared.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "Vrpu_ray_gen.h"
#include "tb_base.h"

#ifndef IDX_W
#define IDX_W 14
#endif
#ifndef RAYGEN_FULL
#define RAYGEN_FULL 0
#endif

namespace {

constexpr int kFv = DIR_FRAC, kFe = EDGE_FRAC, kIdxW = IDX_W;
constexpr int kGuard = ref::HwParams::kRayGuard;
constexpr int kVgW = ref::HwParams::kDirInt + kFv + kGuard;   // v0, dx, dy
constexpr int kEgW = ref::HwParams::kEdgeInt + kFe + kGuard;  // el0, et0, sw
constexpr int kVW = ref::HwParams::kDirInt + kFv;             // v
constexpr int kVhW = 2 + kFv;                                 // v̂
constexpr int kEoW = kEgW + kIdxW + 1;                        // edge vectors out

using V3 = std::array<i128, 3>;

struct Scene {
  std::string name;
  ref::ModelScene model;
};

struct Pixel {
  int cam, i, j;  // cams[cam]
  ref::RayGenOut want{};
};

// A synthetic camera for pixel (i, j) whose direction v0 + i·dx + j·dy is `vg` (Q(4.FV+14)):
// dx, dy random (at a random scale), v0 what is left; false if v0 does not fit its port.
bool synth_camera(std::mt19937_64& rng, const V3& vg, int i, int j, ref::CameraDesc& cam) {
  V3 dx{}, dy{}, v0{};
  const int scale = static_cast<int>(rng() % static_cast<unsigned>(kVgW - kIdxW));
  for (size_t c = 0; c < 3; ++c) {
    dx[c] = sim::random_signed(rng, scale + 1);
    dy[c] = sim::random_signed(rng, scale + 1);
    v0[c] = vg[c] - dx[c] * i - dy[c] * j;
    if (!fixed::fits_signed(v0[c], kVgW)) return false;
  }
  const auto iv = [](const V3& v) {
    return ref::IVec3{static_cast<std::int64_t>(v[0]), static_cast<std::int64_t>(v[1]),
                      static_cast<std::int64_t>(v[2])};
  };
  cam.v0 = iv(v0);
  cam.dx = iv(dx);
  cam.dy = iv(dy);
  cam.el0 = iv({sim::random_signed(rng, kEgW), sim::random_signed(rng, kEgW), sim::random_signed(rng, kEgW)});
  cam.et0 = iv({sim::random_signed(rng, kEgW), sim::random_signed(rng, kEgW), sim::random_signed(rng, kEgW)});
  cam.sw = iv({sim::random_signed(rng, kEgW), sim::random_signed(rng, kEgW), sim::random_signed(rng, kEgW)});
  cam.width = cam.height = 1 << kIdxW;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_ray_gen> tb("tb_rpu_ray_gen", argc, argv);
  auto& rng = tb.rng;

  const ref::HwParams params = sim::tb_params();
  std::vector<Scene> scenes;
  for (const char* name : {"curve12", "airfield"}) {
    scene::Scene sc = sim::demo_scene(name);
    sim::shrink_for_dir_frac(sc.camera, kFv, false);  // 104 and 186 LSBs per pixel at FV = 12
    scenes.push_back({name, ref::quantize_scene(scene::compile_scene(sc), params)});
  }
  const Scene& curve = scenes[0];
  std::vector<ref::CameraDesc> cams = {scenes[0].model.camera, scenes[1].model.camera};
  std::vector<std::string> cam_names = {scenes[0].name, scenes[1].name};
  for (const Scene& s : scenes)
    if (s.model.camera.width > (1 << kIdxW) || s.model.camera.height > (1 << kIdxW))
      return tb.fail("%s is %dx%d, wider than IdxW = %d bits", s.name.c_str(),
                     s.model.camera.width, s.model.camera.height, kIdxW);

  // The pixel list.
  std::vector<Pixel> pixels;
  const auto corners = [&](int k) {
    const ref::CameraDesc& c = cams[static_cast<size_t>(k)];
    for (int j : {0, c.height - 1})
      for (int i : {0, c.width - 1}) pixels.push_back({k, i, j});
  };
  const auto random_pixel = [&](int k) {
    const ref::CameraDesc& c = cams[static_cast<size_t>(k)];
    pixels.push_back({k, static_cast<int>(rng() % static_cast<unsigned>(c.width)),
                      static_cast<int>(rng() % static_cast<unsigned>(c.height))});
  };
  long n_curve = 0, n_air = 0, n_mixed = 0;
  corners(0);
  corners(1);
  if (RAYGEN_FULL) {
    for (int j = 0; j < curve.model.camera.height; ++j)
      for (int i = 0; i < curve.model.camera.width; ++i) pixels.push_back({0, i, j});
    n_curve = static_cast<long>(curve.model.camera.width) * curve.model.camera.height;
    n_air = tb.vectors(40000);
    for (long k = 0; k < n_air; ++k) random_pixel(1);
    n_mixed = 2000;  // the two cameras alternating pixel by pixel
    for (long k = 0; k < n_mixed; ++k) random_pixel(static_cast<int>(k & 1));
  } else {
    n_mixed = tb.vectors(4000);
    for (long k = 0; k < n_mixed; ++k) random_pixel(static_cast<int>(rng() & 1));
  }
  // Synthetic cameras (see the header), one per pixel.
  const long n_synth = tb.vectors(3000), n_square = 500;
  long made = 0, made_sq = 0;
  while (made + made_sq < n_synth + n_square) {
    const bool square = made_sq < n_square && (made >= n_synth || rng() % 8 == 0);
    const int i = static_cast<int>(sim::random_bits(rng, kIdxW));
    const int j = static_cast<int>(sim::random_bits(rng, kIdxW));
    V3 vg;
    if (square) {
      // v = (b², b, b) in Q(4.FV): v·v = (b² + 1)² − 1; b even so that v·v is even and bit 0 of
      // the radicand is 0; b² in [1/2, 8) so that |v| > 1/2 and the component fits.
      const i128 lo = static_cast<i128>(std::ceil(std::sqrt(std::ldexp(1.0, kFv - 1))));
      const i128 hi = static_cast<i128>(std::floor(std::sqrt(std::ldexp(8.0, kFv) - 1)));
      i128 b = lo + static_cast<i128>(rng() % static_cast<std::uint64_t>(hi - lo + 1));
      b += b & 1;
      if (b * b >= 8 * (i128{1} << kFv)) b -= 2;
      V3 v = {b * b, b, b};
      std::swap(v[0], v[rng() % 3]);
      for (size_t c = 0; c < 3; ++c)
        vg[c] = (rng() % 2 ? v[c] : -v[c]) * (i128{1} << kGuard) + sim::random_bits(rng, kGuard);
    } else {
      for (size_t c = 0; c < 3; ++c) vg[c] = sim::random_signed(rng, kVgW);
      // |v| > 1/2 (with the guard bits dropped: a little margin).
      double n2 = 0;
      for (size_t c = 0; c < 3; ++c)
        n2 += std::pow(std::ldexp(static_cast<double>(vg[c]), -(kFv + kGuard)), 2);
      if (n2 < 0.3) continue;
    }
    ref::CameraDesc cam;
    if (!synth_camera(rng, vg, i, j, cam)) continue;
    cams.push_back(cam);
    cam_names.push_back(square ? "synthetic v.v = k^2-1" : "synthetic");
    pixels.push_back({static_cast<int>(cams.size() - 1), i, j});
    (square ? made_sq : made) += 1;
  }

  for (Pixel& px : pixels)
    px.want = ref::ray_generator(scenes[0].model.params, cams[static_cast<size_t>(px.cam)], px.i, px.j);

  sim::Stream<Vrpu_ray_gen, Pixel> s{.latency = ref::ray_gen_latency(params, kIdxW)};
  s.inputs = [&](sim::Inputs& in, Vrpu_ray_gen& t, const Pixel& px) {
    const ref::CameraDesc& c = cams[static_cast<size_t>(px.cam)];
    in("i", t.i_i, px.i, kIdxW)("j", t.j_i, px.j, kIdxW);
    in.vec("v0", t.v0_i, c.v0, kVgW).vec("dx", t.dx_i, c.dx, kVgW).vec("dy", t.dy_i, c.dy, kVgW);
    in.vec("el0", t.el0_i, c.el0, kEgW).vec("et0", t.et0_i, c.et0, kEgW).vec("sw", t.sw_i, c.sw, kEgW);
  };
  s.outputs = [](sim::Outputs& o, const Vrpu_ray_gen& t, const Pixel& px) {
    const ref::RayGenOut& w = px.want;
    o.vec("v", t.v_o, w.v, kVW).vec("vhat", t.vhat_o, w.vhat, kVhW);
    o.vec("e_left", t.e_left_o, w.e_left, kEoW).vec("e_right", t.e_right_o, w.e_right, kEoW);
    o.vec("e_top", t.e_top_o, w.e_top, kEoW).vec("e_bottom", t.e_bottom_o, w.e_bottom, kEoW);
  };
  s.what = [&](const Pixel& px) {
    return cam_names[static_cast<size_t>(px.cam)] + " pixel (" + std::to_string(px.i) + ", " +
           std::to_string(px.j) + ")";
  };
  return tb.check(pixels, s,
                  "DirFrac=%d EdgeFrac=%d IdxW=%d latency %ld; 8 corners, %ld curve12 all pixels, "
                  "%ld airfield random, %ld mixed random, %ld synthetic cameras, %ld with v.v = "
                  "k^2-1", kFv, kFe, kIdxW, s.latency, n_curve, n_air, n_mixed, made, made_sq);
}
