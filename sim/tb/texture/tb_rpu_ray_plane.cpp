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
// Random valid gaps with junk on every data input between rays; p0_valid, p0 (x, y, z), depth,
// the tag and the latency compared for every ray, in order.
#include <algorithm>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "Vrpu_ray_plane.h"
#include "model/descriptors.h"
#include "model/units.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "tb_common.h"

#ifndef RPU_SOURCE_DIR
#error "RPU_SOURCE_DIR must be defined (see sim/tests/texture/rpu_texture.cmake)"
#endif
#ifndef COORD_W
#define COORD_W 24
#endif
#ifndef DIR_FRAC
#define DIR_FRAC 24
#endif
#ifndef EDGE_FRAC
#define EDGE_FRAC 16
#endif
#ifndef TAG_W
#define TAG_W 1
#endif

namespace {

using namespace rpu;
using sim::i128;
using sim::u128;

constexpr int kCw = COORD_W, kFv = DIR_FRAC, kFe = EDGE_FRAC, kTagW = TAG_W;
constexpr int kDirW = kFv + 2;
constexpr int kEdgeW = ref::HwParams::kEdgeInt + kFe + ref::HwParams::kRayGuard;
constexpr int kDepthW = kCw + 4 + kEdgeW + 2;

ref::HwParams make_params() {
  ref::HwParams p;
  p.coord_w = kCw;
  p.dir_frac = kFv;
  p.edge_frac = kFe;
  p.validate();
  return p;
}

struct Camera {
  std::string name;
  ref::CameraDesc cam;
};

struct Item {
  int camera;  // index into the camera list, or -1 for a random port vector
  int i, j;
  ref::IVec3 eye, vhat, w;
  ref::PlanePoint want;
  std::uint64_t tag;
  long issued;
};

i128 random_bits(std::mt19937_64& rng, int width) {
  const u128 bits = (static_cast<u128>(rng()) << 64) | rng();
  return static_cast<i128>(bits & fixed::max_unsigned(width));
}
i128 random_signed(std::mt19937_64& rng, int width) {
  const i128 u = random_bits(rng, width);
  return u >= (i128{1} << (width - 1)) ? u - (i128{1} << width) : u;
}

std::string str(i128 x, i128 y, i128 z) {
  return "(" + sim::to_string(x) + ", " + sim::to_string(y) + ", " + sim::to_string(z) + ")";
}
std::string str(const ref::IVec3& v) { return str(v.x, v.y, v.z); }

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_ray_plane");
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_ray_plane>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_ray_plane");
  std::mt19937_64 rng(seed);
  const ref::HwParams p = make_params();
  const int kLatency = ref::ray_plane_latency(p);

  const auto load = [&](const char* name) {
    return scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/" + name + ".json");
  };
  std::vector<Camera> cams;
  const auto add_camera = [&](const std::string& name, const scene::Scene& s) {
    cams.push_back({name, ref::quantize_scene(scene::compile_scene(s), p).camera});
    return static_cast<int>(cams.size()) - 1;
  };
  const scene::Scene ellipse = load("ellipse6");
  const int c_ellipse = add_camera("ellipse6", ellipse);
  const int c_air = add_camera("airfield", load("airfield"));
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

  std::deque<Item> items;
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
    Item it{c, i, j, cam.eye, ref::ray_generator(p, cam, i, j).vhat, cam.w, {}, 0, 0};
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
  random_pixels(c_air, sim::vector_count(40000));
  const long n_air = static_cast<long>(items.size()) - n_ellipse;
  const long parallel_before = n_parallel;
  for (int c : built) all_pixels(c);
  for (int c : horizontal) all_pixels(c);
  const long n_built = static_cast<long>(items.size()) - n_ellipse - n_air;
  if (n_parallel == parallel_before) {
    std::printf("FAILURE: no constructed camera gave a ray with v̂_z = 0\n");
    return 1;
  }
  // Random port values: every format at its extremes, v̂_z biased toward small magnitudes.
  const long n_random = 20000;
  for (long k = 0; k < n_random; ++k) {
    Item it{-1, 0, 0, {}, {}, {}, {}, 0, 0};
    const auto coord = [&] { return static_cast<fixed::i64>(random_signed(rng, kCw)); };
    const auto dir = [&] { return static_cast<fixed::i64>(random_signed(rng, kDirW)); };
    const auto edge = [&] { return static_cast<fixed::i64>(random_signed(rng, kEdgeW)); };
    it.eye = {coord(), coord(), coord()};
    it.vhat = {dir(), dir(), dir()};
    it.w = {edge(), edge(), edge()};
    switch (k % 8) {
      case 0:  // small |v̂_z|: far points, the quotient and the range tests
        it.vhat.z = static_cast<fixed::i64>(random_signed(rng, 1 + static_cast<int>(rng() % 12)));
        break;
      case 1:  // small |h_z|
        it.eye.z = static_cast<fixed::i64>(random_signed(rng, 1 + static_cast<int>(rng() % kCw)));
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

  sim::reset(*top, *ctx);
  std::deque<Item> expected;
  long matched = 0, cycle = 0;
  std::uint64_t tag = 0;
  const std::uint64_t tag_mask = kTagW >= 64 ? ~0ull : (1ull << kTagW) - 1;
  const long total = static_cast<long>(items.size());
  while (matched < total) {
    const bool issue = !items.empty() && (rng() % 100) < 85;
    top->valid_i = issue;
    if (issue) {
      Item it = items.front();
      items.pop_front();
      sim::put_vec3(top->eye_i, it.eye.x, it.eye.y, it.eye.z, kCw);
      sim::put_vec3(top->vhat_i, it.vhat.x, it.vhat.y, it.vhat.z, kDirW);
      sim::put_vec3(top->w_i, it.w.x, it.w.y, it.w.z, kEdgeW);
      it.tag = tag++ & tag_mask;
      it.issued = cycle;
      sim::put(top->tag_i, static_cast<i128>(it.tag), kTagW);
      expected.push_back(it);
    } else {  // junk between rays
      sim::put_vec3(top->eye_i, random_bits(rng, kCw), random_bits(rng, kCw),
                    random_bits(rng, kCw), kCw);
      sim::put_vec3(top->vhat_i, random_bits(rng, kDirW), random_bits(rng, kDirW),
                    random_bits(rng, kDirW), kDirW);
      sim::put_vec3(top->w_i, random_bits(rng, kEdgeW), random_bits(rng, kEdgeW),
                    random_bits(rng, kEdgeW), kEdgeW);
      sim::put(top->tag_i, random_bits(rng, kTagW), kTagW);
    }
    sim::tick(*top, *ctx);
    ++cycle;
    if (top->valid_o) {
      if (expected.empty()) {
        std::printf("FAILURE cycle %ld: valid_o with no ray outstanding\n", cycle);
        return 1;
      }
      const Item it = expected.front();
      expected.pop_front();
      const ref::PlanePoint& w = it.want;
      const bool valid = top->p0_valid_o != 0;
      const i128 p0[3] = {sim::get_comp(top->p0_o, 0, kCw), sim::get_comp(top->p0_o, 1, kCw),
                          sim::get_comp(top->p0_o, 2, kCw)};
      const i128 depth = sim::get_signed(top->depth_o, kDepthW);
      const std::uint64_t got_tag =
          static_cast<std::uint64_t>(sim::get_unsigned(top->tag_o, kTagW));
      const bool ok = valid == w.valid && p0[0] == w.p0.x && p0[1] == w.p0.y &&
                      p0[2] == w.p0.z && depth == w.depth && got_tag == it.tag &&
                      cycle - it.issued == kLatency;
      if (!ok) {
        std::printf("FAILURE cycle %ld item %ld: %s pixel (%d, %d)\n"
                    "  inputs   eye %s vhat %s W %s tag %llu\n"
                    "  expected valid %d p0 %s depth %s latency %d\n"
                    "  actual   valid %d p0 %s depth %s latency %ld tag %llu\n",
                    cycle, matched,
                    it.camera < 0 ? "random port vector"
                                  : cams[static_cast<size_t>(it.camera)].name.c_str(),
                    it.i, it.j, str(it.eye).c_str(), str(it.vhat).c_str(), str(it.w).c_str(),
                    static_cast<unsigned long long>(it.tag), w.valid,
                    str(w.p0.x, w.p0.y, w.p0.z).c_str(), sim::to_string(w.depth).c_str(),
                    kLatency, valid, str(p0[0], p0[1], p0[2]).c_str(),
                    sim::to_string(depth).c_str(), cycle - it.issued,
                    static_cast<unsigned long long>(got_tag));
        return 1;
      }
      ++matched;
    }
    if (cycle > 4 * total + 1000) {
      std::printf("FAILURE: timeout after %ld cycles, %ld of %ld matched\n", cycle, matched, total);
      return 1;
    }
  }
  top->valid_i = 0;
  for (int k = 0; k < kLatency + 4; ++k) {
    sim::tick(*top, *ctx);
    ++cycle;
    if (top->valid_o) {
      std::printf("FAILURE cycle %ld: spurious valid_o after the last ray\n", cycle);
      return 1;
    }
  }
  top->final();
  std::printf("rpu_ray_plane CoordW=%d DirFrac=%d EdgeFrac=%d latency %d: matched %ld items "
              "(%ld ellipse6 all pixels, %ld airfield random, %ld constructed cameras, %ld random "
              "port vectors; %ld valid, %ld rejected by sign, %ld by the quotient, %ld by the "
              "range; %ld with v̂_z = 0) in %ld cycles\n",
              kCw, kFv, kFe, kLatency, matched, n_ellipse, n_air, n_built, n_random, n_valid,
              n_sign, n_quot, n_range, n_parallel, cycle);
  return 0;
}
