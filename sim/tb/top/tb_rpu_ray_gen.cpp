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
// Random valid gaps with garbage on every data input in the gaps (each pixel samples its own
// camera ports with valid_i); every output field, the tag and the latency compared in order.
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "Vrpu_ray_gen.h"
#include "model/descriptors.h"
#include "model/units.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "tb_common.h"

#if !defined(DIR_FRAC) || !defined(EDGE_FRAC) || !defined(RPU_SCENE_DIR)
#error "DIR_FRAC, EDGE_FRAC and RPU_SCENE_DIR must be defined (see sim/tests/top/rpu_ray_gen.cmake)"
#endif
#ifndef IDX_W
#define IDX_W 14
#endif
#ifndef TAG_W
#define TAG_W 1
#endif
#ifndef RAYGEN_FULL
#define RAYGEN_FULL 0
#endif

namespace {

using namespace rpu;
using rpu::sim::i128;
using rpu::sim::u128;

constexpr int kFv = DIR_FRAC, kFe = EDGE_FRAC, kIdxW = IDX_W, kTagW = TAG_W;
constexpr int kGuard = ref::HwParams::kRayGuard;
constexpr int kVgW = ref::HwParams::kDirInt + kFv + kGuard;   // v0, dx, dy
constexpr int kEgW = ref::HwParams::kEdgeInt + kFe + kGuard;  // el0, et0, sw
constexpr int kVW = ref::HwParams::kDirInt + kFv;             // v
constexpr int kVhW = 2 + kFv;                                 // v̂
constexpr int kEoW = kEgW + kIdxW + 1;                        // edge vectors out

// A port of three `w`-bit components {z, y, x} as 32-bit words (x in the lowest bits).
struct Bits {
  std::vector<std::uint32_t> words;
  explicit Bits(int width) : words(static_cast<size_t>((width + 31) / 32), 0u) {}
  void set(int lo, int width, i128 v) {
    const u128 u = static_cast<u128>(v);
    for (int b = 0; b < width; ++b) {
      const int pos = lo + b;
      const std::uint32_t bit = b < 128 ? static_cast<std::uint32_t>((u >> b) & 1) : 0u;
      auto& w = words[static_cast<size_t>(pos / 32)];
      w = (w & ~(1u << (pos % 32))) | (bit << (pos % 32));
    }
  }
  i128 get_signed(int lo, int width) const {
    u128 u = 0;
    for (int b = 0; b < width; ++b) {
      const int pos = lo + b;
      u |= static_cast<u128>((words[static_cast<size_t>(pos / 32)] >> (pos % 32)) & 1u) << b;
    }
    const u128 sign = u128{1} << (width - 1);
    return static_cast<i128>((u ^ sign) - sign);
  }
};

// Ports of up to 64 bits (CData .. QData) and wide ones (VlWide).
template <class T>
void store(T& port, const Bits& b) {
  std::uint64_t v = b.words[0];
  if (b.words.size() > 1) v |= static_cast<std::uint64_t>(b.words[1]) << 32;
  port = static_cast<T>(v);
}
template <std::size_t N>
void store(VlWide<N>& port, const Bits& b) {
  for (std::size_t k = 0; k < N; ++k) port[k] = k < b.words.size() ? b.words[k] : 0u;
}
template <class T>
Bits load(const T& port, int width) {
  Bits b(width);
  const std::uint64_t v = static_cast<std::uint64_t>(port);
  b.words[0] = static_cast<std::uint32_t>(v);
  if (b.words.size() > 1) b.words[1] = static_cast<std::uint32_t>(v >> 32);
  return b;
}
template <std::size_t N>
Bits load(const VlWide<N>& port, int width) {
  Bits b(width);
  for (std::size_t k = 0; k < N && k < b.words.size(); ++k) b.words[k] = port[k];
  return b;
}

using V3 = std::array<i128, 3>;
V3 of(const ref::IVec3& v) { return {v.x, v.y, v.z}; }
V3 of(const ref::WVec3& v) { return {v.x, v.y, v.z}; }

template <class T>
void put_vec(T& port, const V3& v, int w) {
  Bits b(3 * w);
  for (int c = 0; c < 3; ++c) b.set(c * w, w, v[static_cast<size_t>(c)]);
  store(port, b);
}
template <class T>
V3 get_vec(const T& port, int w) {
  const Bits b = load(port, 3 * w);
  return {b.get_signed(0, w), b.get_signed(w, w), b.get_signed(2 * w, w)};
}

std::string str(const V3& v) {
  return "(" + sim::to_string(v[0]) + ", " + sim::to_string(v[1]) + ", " + sim::to_string(v[2]) +
         ")";
}

struct Scene {
  std::string name;
  ref::ModelScene model;
};

struct Pixel {
  int cam, i, j;  // cams[cam]
};

struct Item {
  Pixel px;
  ref::RayGenOut want;
  std::uint64_t tag;
  long issued;
};

i128 random_bits(std::mt19937_64& rng, int width) {
  const u128 bits = (static_cast<u128>(rng()) << 64) | rng();
  return static_cast<i128>(bits & fixed::max_unsigned(width));
}
i128 random_signed(std::mt19937_64& rng, int width) {
  const u128 u = static_cast<u128>(random_bits(rng, width)), sign = u128{1} << (width - 1);
  return static_cast<i128>((u ^ sign) - sign);
}
bool fits_signed(i128 v, int width) {
  return v >= -(i128{1} << (width - 1)) && v < (i128{1} << (width - 1));
}

// A synthetic camera for pixel (i, j) whose direction v0 + i·dx + j·dy is `vg` (Q(4.FV+14)):
// dx, dy random (at a random scale), v0 what is left; false if v0 does not fit its port.
bool synth_camera(std::mt19937_64& rng, const V3& vg, int i, int j, ref::CameraDesc& cam) {
  V3 dx{}, dy{}, v0{};
  const int scale = static_cast<int>(rng() % static_cast<unsigned>(kVgW - kIdxW));
  for (size_t c = 0; c < 3; ++c) {
    dx[c] = random_signed(rng, scale + 1);
    dy[c] = random_signed(rng, scale + 1);
    v0[c] = vg[c] - dx[c] * i - dy[c] * j;
    if (!fits_signed(v0[c], kVgW)) return false;
  }
  const auto iv = [](const V3& v) {
    return ref::IVec3{static_cast<std::int64_t>(v[0]), static_cast<std::int64_t>(v[1]),
                      static_cast<std::int64_t>(v[2])};
  };
  cam.v0 = iv(v0);
  cam.dx = iv(dx);
  cam.dy = iv(dy);
  cam.el0 = iv({random_signed(rng, kEgW), random_signed(rng, kEgW), random_signed(rng, kEgW)});
  cam.et0 = iv({random_signed(rng, kEgW), random_signed(rng, kEgW), random_signed(rng, kEgW)});
  cam.sw = iv({random_signed(rng, kEgW), random_signed(rng, kEgW), random_signed(rng, kEgW)});
  cam.width = cam.height = 1 << kIdxW;
  return true;
}

// Garbage on every data input (a gap cycle).
void drive_garbage(Vrpu_ray_gen& top, std::mt19937_64& rng) {
  const auto rv = [&](int w) { return V3{random_bits(rng, w), random_bits(rng, w), random_bits(rng, w)}; };
  sim::put(top.i_i, random_bits(rng, kIdxW), kIdxW);
  sim::put(top.j_i, random_bits(rng, kIdxW), kIdxW);
  put_vec(top.v0_i, rv(kVgW), kVgW);
  put_vec(top.dx_i, rv(kVgW), kVgW);
  put_vec(top.dy_i, rv(kVgW), kVgW);
  put_vec(top.el0_i, rv(kEgW), kEgW);
  put_vec(top.et0_i, rv(kEgW), kEgW);
  put_vec(top.sw_i, rv(kEgW), kEgW);
  sim::put(top.tag_i, random_bits(rng, kTagW), kTagW);
}

void drive_camera(Vrpu_ray_gen& top, const ref::CameraDesc& cam) {
  put_vec(top.v0_i, of(cam.v0), kVgW);
  put_vec(top.dx_i, of(cam.dx), kVgW);
  put_vec(top.dy_i, of(cam.dy), kVgW);
  put_vec(top.el0_i, of(cam.el0), kEgW);
  put_vec(top.et0_i, of(cam.et0), kEgW);
  put_vec(top.sw_i, of(cam.sw), kEgW);
}

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_ray_gen");
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_ray_gen>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_ray_gen");
  std::mt19937_64 rng(seed);

  ref::HwParams params;
  params.dir_frac = kFv;
  params.edge_frac = kFe;
  const int kLatency = ref::ray_gen_latency(params, kIdxW);
  std::vector<Scene> scenes;
  for (const char* name : {"curve12", "airfield"}) {
    const std::string path = std::string(RPU_SCENE_DIR) + "/" + name + ".json";
    scene::Scene sc = scene::load_scene(path);
    // Narrow direction formats: the compiler refuses a view whose pixel spans fewer than
    // ref::Precision::kRefuse direction LSBs (curve12 at 256 pixels spans 13 at FV = 12), so the
    // frames shrink to 32 pixels on their longer side (104 and 186 LSBs per pixel).
    if (kFv < 16) {
      const int side = std::max(sc.camera.width, sc.camera.height);
      sc.camera.width = std::max(1, sc.camera.width * 32 / side);
      sc.camera.height = std::max(1, sc.camera.height * 32 / side);
    }
    scenes.push_back({name, ref::quantize_scene(scene::compile_scene(sc), params)});
  }
  const Scene& curve = scenes[0];
  std::vector<ref::CameraDesc> cams = {scenes[0].model.camera, scenes[1].model.camera};
  std::vector<std::string> cam_names = {scenes[0].name, scenes[1].name};
  for (const Scene& s : scenes)
    if (s.model.camera.width > (1 << kIdxW) || s.model.camera.height > (1 << kIdxW)) {
      std::printf("FAILURE: %s is %dx%d, wider than IdxW = %d bits\n", s.name.c_str(),
                  s.model.camera.width, s.model.camera.height, kIdxW);
      return 1;
    }

  // The pixel list.
  std::deque<Pixel> pixels;
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
    n_air = sim::vector_count(40000);
    for (long k = 0; k < n_air; ++k) random_pixel(1);
    n_mixed = 2000;  // the two cameras alternating pixel by pixel
    for (long k = 0; k < n_mixed; ++k) random_pixel(static_cast<int>(k & 1));
  } else {
    n_mixed = sim::vector_count(4000);
    for (long k = 0; k < n_mixed; ++k) random_pixel(static_cast<int>(rng() & 1));
  }
  // Synthetic cameras (see the header), one per pixel.
  const long n_synth = sim::vector_count(3000), n_square = 500;
  long made = 0, made_sq = 0;
  while (made + made_sq < n_synth + n_square) {
    const bool square = made_sq < n_square && (made >= n_synth || rng() % 8 == 0);
    const int i = static_cast<int>(random_bits(rng, kIdxW));
    const int j = static_cast<int>(random_bits(rng, kIdxW));
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
        vg[c] = (rng() % 2 ? v[c] : -v[c]) * (i128{1} << kGuard) + random_bits(rng, kGuard);
    } else {
      for (size_t c = 0; c < 3; ++c) vg[c] = random_signed(rng, kVgW);
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

  sim::reset(*top, *ctx);
  std::deque<Item> expected;
  long matched = 0, cycle = 0;
  std::uint64_t tag = 0;
  const std::uint64_t tag_mask = kTagW >= 64 ? ~0ull : (1ull << kTagW) - 1;
  const long total = static_cast<long>(pixels.size());
  while (matched < total) {
    // Drive: a new pixel on ~85 % of the cycles; garbage on every data input otherwise.
    const bool issue = !pixels.empty() && (rng() % 100) < 85;
    top->valid_i = issue;
    if (issue) {
      const Pixel px = pixels.front();
      pixels.pop_front();
      const ref::CameraDesc& cam = cams[static_cast<size_t>(px.cam)];
      drive_camera(*top, cam);
      sim::put(top->i_i, px.i, kIdxW);
      sim::put(top->j_i, px.j, kIdxW);
      sim::put(top->tag_i, static_cast<i128>(tag & tag_mask), kTagW);
      expected.push_back({px, ref::ray_generator(scenes[0].model.params, cam, px.i, px.j),
                          tag & tag_mask, cycle});
      ++tag;
    } else {
      drive_garbage(*top, rng);
    }
    sim::tick(*top, *ctx);
    ++cycle;
    if (top->valid_o) {
      if (expected.empty()) {
        std::printf("FAILURE cycle %ld: valid_o with no pixel outstanding\n", cycle);
        return 1;
      }
      const Item want = expected.front();
      expected.pop_front();
      struct Field {
        const char* name;
        V3 want, got;
      };
      const Field fields[] = {
          {"v", of(want.want.v), get_vec(top->v_o, kVW)},
          {"vhat", of(want.want.vhat), get_vec(top->vhat_o, kVhW)},
          {"e_left", of(want.want.e_left), get_vec(top->e_left_o, kEoW)},
          {"e_right", of(want.want.e_right), get_vec(top->e_right_o, kEoW)},
          {"e_top", of(want.want.e_top), get_vec(top->e_top_o, kEoW)},
          {"e_bottom", of(want.want.e_bottom), get_vec(top->e_bottom_o, kEoW)},
      };
      const std::uint64_t got_tag = static_cast<std::uint64_t>(sim::get_unsigned(top->tag_o, kTagW));
      bool ok = got_tag == want.tag && cycle - want.issued == kLatency;
      for (const Field& f : fields) ok = ok && f.want == f.got;
      if (!ok) {
        std::printf("FAILURE cycle %ld item %ld: %s pixel (i = %d, j = %d), latency %ld (expected "
                    "%d), tag %llu (expected %llu)\n",
                    cycle, matched, cam_names[static_cast<size_t>(want.px.cam)].c_str(),
                    want.px.i, want.px.j, cycle - want.issued, kLatency,
                    static_cast<unsigned long long>(got_tag),
                    static_cast<unsigned long long>(want.tag));
        const ref::CameraDesc& c = cams[static_cast<size_t>(want.px.cam)];
        std::printf("  camera v0 %s dx %s dy %s\n  el0 %s et0 %s sw %s\n", str(of(c.v0)).c_str(),
                    str(of(c.dx)).c_str(), str(of(c.dy)).c_str(), str(of(c.el0)).c_str(),
                    str(of(c.et0)).c_str(), str(of(c.sw)).c_str());
        for (const Field& f : fields)
          std::printf("  %-8s expected %s, got %s%s\n", f.name, str(f.want).c_str(),
                      str(f.got).c_str(), f.want == f.got ? "" : "  <-- differs");
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
      std::printf("FAILURE cycle %ld: spurious valid_o after the last pixel\n", cycle);
      return 1;
    }
  }
  top->final();
  std::printf("rpu_ray_gen DirFrac=%d EdgeFrac=%d IdxW=%d latency %d: matched %ld items (8 corners, "
              "%ld curve12 all pixels, %ld airfield random, %ld mixed random, %ld synthetic "
              "cameras, %ld with v.v = k^2-1) in %ld cycles\n",
              kFv, kFe, kIdxW, kLatency, matched, n_curve, n_air, n_mixed, made, made_sq, cycle);
  return 0;
}
