// rpu_ray_plane against its twin rpu::ref::ray_plane_unit, on rays of the model's ray generator
// over camera descriptors from the real scene compiler (HwParams with COORD_W / DIR_FRAC /
// EDGE_FRAC, defaults otherwise):
//   - every pixel of scenes/ellipse6.json;
//   - RPU_VECTORS (default 40,000) random pixels of scenes/airfield.json;
//   - cameras built here on the ellipse6 texture: the eye below the plane looking up at it and
//     looking away from it, the eye on the plane (h_z = 0), horizontal views with an odd image
//     height (centre-row rays with v̂_z = 0 exactly; the test fails if none occurs) and grazing
//     views from just above the plane (rays near the horizon whose quotient or p0 leaves the
//     range);
//   - random port values (eye, v̂, W over their whole formats, v̂_z biased small: every rejection
//     path and the extreme widths; h_z at and around the quotient limit for the given v̂_z).
// p0_valid, p0 (x, y, z), depth, the tag and the latency compared for every ray.
#include <string>
#include <vector>

#include "Vrpu_ray_plane.h"
#include "tb_base.h"

constexpr int kCw = COORD_W, kFv = DIR_FRAC;
constexpr int kDirW = kFv + 2;
constexpr int kEdgeW = ref::HwParams::kEdgeInt + EDGE_FRAC + ref::HwParams::kRayGuard;
constexpr int kDepthW = kCw + 4 + kEdgeW + 2;

struct Camera {
  std::string name;
  ref::CameraDesc cam;
};

struct Item {
  int camera;  // index into the camera list, or -1 for a random port vector
  int i, j;
  ref::IVec3 eye, vhat, w;
  ref::PlanePoint want;
};

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_ray_plane> tb("tb_rpu_ray_plane", argc, argv);
  auto& rng = tb.rng;
  const ref::HwParams p = sim::tb_params();

  std::vector<Camera> cams;
  const auto add_camera = [&](const std::string& name, scene::Scene s) {
    sim::shrink_for_dir_frac(s.camera, kFv, true);  // odd heights: the centre row's v̂_z = 0
    cams.push_back({name, ref::quantize_scene(scene::compile_scene(s), p).camera});
    return static_cast<int>(cams.size()) - 1;
  };
  const scene::Scene ellipse = sim::demo_scene("ellipse6");
  const int c_ellipse = add_camera("ellipse6", ellipse);
  const int c_air = add_camera("airfield", sim::demo_scene("airfield"));
  // Cameras built on the ellipse6 texture.
  const auto variant = [&](const std::string& name, Vec3 eye, Vec3 target, double fov, int w,
                           int h) {
    scene::Scene s = ellipse;
    s.camera.eye = eye;
    s.camera.target = target;
    s.camera.up = {0, 0, 1};
    s.camera.fov_deg = fov;
    s.camera.width = w;
    s.camera.height = h;
    return add_camera(name, s);
  };
  std::vector<int> built = {
      variant("below, facing the plane", {0, -7, -6}, {0, 0, 0}, 50, 160, 120),
      variant("below, facing away", {0, -7, -6}, {0, 0, -12}, 60, 160, 120),
      variant("eye on the plane", {0, -7, 0}, {0, 0, 0}, 60, 96, 64),
      variant("grazing, eye 0.3 above", {0, -30, 0.3}, {0, 0, 0}, 40, 200, 151),
      variant("grazing, eye 0.02 above", {1, -12, 0.02}, {1, 0, 0}, 70, 200, 151)};
  // Horizontal views with odd heights: the centre row's v̂_z is 0 or −1 (rounding of the
  // descriptors); several heights and fields of view so that some give exactly 0.
  const int heights[] = {255, 129, 201, 253, 99, 151};
  const double fovs[] = {60, 50, 70, 45, 80, 55};
  std::vector<int> horizontal;
  for (int k = 0; k < 6; ++k)
    horizontal.push_back(variant("horizontal h=" + std::to_string(heights[k]) + " fov " +
                                     std::to_string(static_cast<int>(fovs[k])),
                                 {0, -7, 1}, {0, 0, 1}, fovs[k], 96, heights[k]));

  std::vector<Item> items;
  long n_parallel = 0, n_valid = 0, n_sign = 0, n_quot = 0, n_range = 0;
  const auto classify = [&](const Item& it) {
    if (it.vhat.z == 0) ++n_parallel;
    const i128 hz = it.eye.z, vz = it.vhat.z;
    if (it.want.valid) ++n_valid;
    else if (vz == 0 || hz == 0 || (hz > 0) == (vz > 0)) ++n_sign;
    else if (((static_cast<u128>(hz < 0 ? -hz : hz) << kFv) >> (kCw + 1)) >=
             static_cast<u128>(vz < 0 ? -vz : vz)) ++n_quot;
    else ++n_range;
  };
  const auto add_pixel = [&](int c, int i, int j) {
    const ref::CameraDesc& cam = cams[static_cast<size_t>(c)].cam;
    Item it{c, i, j, cam.eye, ref::ray_generator(p, cam, i, j).vhat, cam.w, {}};
    it.want = ref::ray_plane_unit(p, cam, it.vhat);
    classify(it);
    items.push_back(it);
  };
  const auto all_pixels = [&](int c) {
    const ref::CameraDesc& cam = cams[static_cast<size_t>(c)].cam;
    for (int j = 0; j < cam.height; ++j)
      for (int i = 0; i < cam.width; ++i) add_pixel(c, i, j);
  };
  const auto random_pixels = [&](int c, long n) {
    const ref::CameraDesc& cam = cams[static_cast<size_t>(c)].cam;
    for (long k = 0; k < n; ++k)
      add_pixel(c, static_cast<int>(rng() % static_cast<unsigned>(cam.width)),
                static_cast<int>(rng() % static_cast<unsigned>(cam.height)));
  };

  all_pixels(c_ellipse);
  const long n_ellipse = static_cast<long>(items.size());
  random_pixels(c_air, tb.vectors(40000));
  const long n_air = static_cast<long>(items.size()) - n_ellipse;
  const long parallel_before = n_parallel;
  for (int c : built) all_pixels(c);
  for (int c : horizontal) all_pixels(c);
  const long n_built = static_cast<long>(items.size()) - n_ellipse - n_air;
  if (n_parallel == parallel_before) return tb.fail("no constructed camera gave a ray with v̂_z = 0");
  // Random port values: every format at its extremes, v̂_z biased toward small magnitudes.
  const long n_random = 20000;
  for (long k = 0; k < n_random; ++k) {
    Item it{-1, 0, 0, {}, {}, {}, {}};
    const auto coord = [&] { return static_cast<fixed::i64>(sim::random_signed(rng, kCw)); };
    const auto dir = [&] { return static_cast<fixed::i64>(sim::random_signed(rng, kDirW)); };
    const auto edge = [&] { return static_cast<fixed::i64>(sim::random_signed(rng, kEdgeW)); };
    it.eye = {coord(), coord(), coord()};
    it.vhat = {dir(), dir(), dir()};
    it.w = {edge(), edge(), edge()};
    switch (k % 8) {
      case 0:  // small |v̂_z|: far points, the quotient and the range tests
        it.vhat.z = static_cast<fixed::i64>(sim::random_signed(rng, 1 + static_cast<int>(rng() % 12)));
        break;
      case 1:  // small |h_z|
        it.eye.z = static_cast<fixed::i64>(sim::random_signed(rng, 1 + static_cast<int>(rng() % kCw)));
        break;
      case 2: {  // format corners
        const fixed::i64 cmin = -(fixed::i64{1} << (kCw - 1)), cmax = -cmin - 1;
        const fixed::i64 dmin = -(fixed::i64{1} << (kDirW - 1)), dmax = -dmin - 1;
        const fixed::i64 cs[] = {cmin, cmax, -1, 1, 0};
        const fixed::i64 ds[] = {dmin, dmax, -1, 1, 0};
        it.eye = {cs[rng() % 5], cs[rng() % 5], cs[rng() % 5]};
        it.vhat = {ds[rng() % 5], ds[rng() % 5], ds[rng() % 5]};
        break;
      }
      case 3: {  // |h_z|·2^FV >> (CW+1) at |v̂_z| − 1, |v̂_z| or |v̂_z| + 1: the quotient limit
        const i128 vz = 1 + static_cast<i128>(rng() % 4096);
        const i128 q = vz + static_cast<i128>(rng() % 3) - 1;
        // The smallest |h_z| with (|h_z|·2^FV) >> (CW+1) >= q, or one less.
        const i128 lo = ((q << (kCw + 1)) + (i128{1} << kFv) - 1) >> kFv;
        const i128 hz = lo - static_cast<i128>(rng() % 2);
        if (hz < 1 || hz > (i128{1} << (kCw - 1)) - 1) break;
        const bool up = rng() % 2;
        it.eye.z = static_cast<fixed::i64>(up ? -hz : hz);
        it.vhat.z = static_cast<fixed::i64>(up ? vz : -vz);
        break;
      }
      default: break;
    }
    ref::CameraDesc cam;
    cam.eye = it.eye;
    cam.w = it.w;
    it.want = ref::ray_plane_unit(p, cam, it.vhat);
    classify(it);
    items.push_back(it);
  }

  sim::Stream<Vrpu_ray_plane, Item> s{.latency = ref::ray_plane_latency(p)};
  s.inputs = [](sim::Inputs& in, Vrpu_ray_plane& t, const Item& it) {
    in.vec("eye", t.eye_i, it.eye, kCw).vec("vhat", t.vhat_i, it.vhat, kDirW).vec("W", t.w_i, it.w, kEdgeW);
  };
  s.outputs = [](sim::Outputs& o, const Vrpu_ray_plane& t, const Item& it) {
    o("p0_valid", t.p0_valid_o, it.want.valid, 1).vec("p0", t.p0_o, it.want.p0, kCw);
    o.s("depth", t.depth_o, it.want.depth, kDepthW);
  };
  s.what = [&](const Item& it) {
    return (it.camera < 0 ? std::string("random port vector") : cams[static_cast<size_t>(it.camera)].name) +
           ", pixel (" + std::to_string(it.i) + ", " + std::to_string(it.j) + ")";
  };
  return tb.check(items, s,
                  "CoordW=%d DirFrac=%d EdgeFrac=%d latency %ld; %ld ellipse6 all pixels, %ld "
                  "airfield random, %ld constructed cameras, %ld random port vectors; %ld valid, "
                  "%ld rejected by sign, %ld by the quotient, %ld by the range; %ld with v̂_z = 0",
                  kCw, kFv, EDGE_FRAC, s.latency, n_ellipse, n_air, n_built, n_random, n_valid,
                  n_sign, n_quot, n_range, n_parallel);
}
