// The helpers every unit testbench's vector generator shares: the build's hardware parameters,
// the demo scenes, random values of a given width, a flat guide as the descriptor compiler
// forms it, values as text and the tally of what the vectors exercise. (The testbench itself:
// tb_base.h.)
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "bits.h"
#include "model/hw_params.h"
#include "model/units.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"

// The hardware parameters a testbench is built with: the macros of its registration line
// (sim/tests/<subsystem>/*.cmake: PARAMS -GName=v gives NAME=v, sim/CMakeLists.txt), else the
// table's defaults (ref/model/hw_params.def; CTest rtl_params fails on a default here that
// differs from the table's).
#ifndef IP_N
#define IP_N 16
#endif
#ifndef IP_N1
#define IP_N1 2
#endif
#ifndef COORD_W
#define COORD_W 24
#endif
#ifndef DIR_FRAC
#define DIR_FRAC 24
#endif
#ifndef T_FRAC
#define T_FRAC 24
#endif
#ifndef UNIT_FRAC
#define UNIT_FRAC 16
#endif
#ifndef EDGE_FRAC
#define EDGE_FRAC 16
#endif
#ifndef INV_W
#define INV_W 18
#endif
#ifndef SQRT_W
#define SQRT_W 0
#endif
#ifndef METRIC
#define METRIC 0
#endif
#ifndef UNROLLED
#define UNROLLED 1
#endif
#ifndef SURF_W
#define SURF_W 24
#endif
#ifndef ANGLE_W
#define ANGLE_W 20
#endif
#ifndef SURFACES
#define SURFACES 1
#endif
#ifndef SURF_IND
#define SURF_IND 0  // rpu_surface_ip's Indicators (0: 2^n1 − 1)
#endif
#ifndef SURF_N1_FIRST
#define SURF_N1_FIRST 7  // rpu_surface_ip's N1First (0: the seed's schedule)
#endif
#ifndef TAG_W
#define TAG_W 1
#endif
#ifndef RPU_SOURCE_DIR
#error "RPU_SOURCE_DIR must name the source tree (rpu_verilated_test defines it)"
#endif

namespace rpu::sim {

inline ref::HwParams tb_params() {
  ref::HwParams p;
  p.n = IP_N;
  p.n1 = IP_N1;
  p.coord_w = COORD_W;
  p.dir_frac = DIR_FRAC;
  p.t_frac = T_FRAC;
  p.unit_frac = UNIT_FRAC;
  p.edge_frac = EDGE_FRAC;
  p.inv_w = INV_W;
  p.sqrt_w = SQRT_W;
  p.metric = METRIC == 0 ? ref::Metric::kAbs : ref::Metric::kSquared;
  p.unrolled = UNROLLED != 0;
  p.surf_w = SURF_W;
  p.angle_w = ANGLE_W;
  p.surf_n1_first = SURF_N1_FIRST;
  p.surfaces = SURFACES != 0;
  p.validate();
  return p;
}

// A demo scene (scenes/NAME.json), as written or compiled.
inline scene::Scene demo_scene(const std::string& name) {
  return scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/" + name + ".json");
}
inline scene::CompiledScene compiled_demo_scene(const std::string& name) {
  return scene::compile_scene(demo_scene(name));
}

// A demo scene as the vector generators take it: compiled, and quantised at the build's
// parameters (tb_params()). const auto [sc, p, m] = sim::quantized_demo_scene("curve12");
struct QuantizedScene {
  scene::CompiledScene sc;
  ref::HwParams p;
  ref::ModelScene m;
};
inline QuantizedScene quantized_demo_scene(const std::string& name) {
  QuantizedScene q{compiled_demo_scene(name), tb_params(), {}};
  q.m = ref::quantize_scene(q.sc, q.p);
  return q;
}

// Narrow direction formats (DirFrac < 16): the compiler refuses a view whose pixel spans fewer
// than ref::Precision::kRefuse direction LSBs (curve12 at 256 pixels spans 13 at FV = 12), so the
// frame shrinks to 32 pixels on its longer side; `keep_odd`: an odd height stays odd.
inline void shrink_for_dir_frac(scene::Camera& c, int dir_frac, bool keep_odd) {
  if (dir_frac >= 16) return;
  const int side = std::max(c.width, c.height), odd = keep_odd && c.height % 2;
  c.width = std::max(1, c.width * 32 / side);
  c.height = std::max(1, c.height * 32 / side);
  if (odd && c.height % 2 == 0) ++c.height;
}

// Random values (each draws two 64-bit numbers, then what its name says).
// `width` random bits (width ≤ 128).
inline i128 random_bits(std::mt19937_64& rng, int width) {
  const u128 bits = (static_cast<u128>(rng()) << 64) | rng();
  return static_cast<i128>(low_bits(bits, width));
}
// A random two's-complement `width`-bit value.
inline i128 random_signed(std::mt19937_64& rng, int width) {
  return sign_extend(static_cast<u128>(random_bits(rng, width)), width);
}
// Spread over magnitudes: a random width 1..width first (one more draw), then unsigned bits ...
inline i128 random_spread(std::mt19937_64& rng, int width) {
  return random_bits(rng, 1 + static_cast<int>(rng() % static_cast<unsigned>(width)));
}
// ... or a signed value of that random width.
inline i128 random_magnitude(std::mt19937_64& rng, int width) {
  const int w = 1 + static_cast<int>(rng() % static_cast<unsigned>(width));
  return random_signed(rng, w);
}

// t over Q(3.FT): mostly inside [0, 1], some within 8 LSB of its ends, a quarter anywhere.
inline i128 random_t(std::mt19937_64& rng, int t_frac) {
  const i128 one = i128{1} << t_frac;
  switch (rng() % 8) {
    case 0: return static_cast<i128>(rng() % 17) - 8;
    case 1: return one + static_cast<i128>(rng() % 17) - 8;
    case 2:
    case 3: return random_signed(rng, t_frac + 3);
    default: return random_bits(rng, t_frac + 1) % (one + 1);
  }
}
// A uniform double in [lo, hi) (one std::uniform_real_distribution draw).
inline double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
// Whether every component of v fits a w-bit two's-complement port; whether v (of either sign)
// fits a w-bit unsigned one.
template <class V>
bool fits_signed3(const V& v, int w) {
  return fixed::fits_signed(v.x, w) && fixed::fits_signed(v.y, w) && fixed::fits_signed(v.z, w);
}
inline bool fits_unsigned(i128 v, int w) {
  return v >= 0 && fixed::fits_unsigned(static_cast<u128>(v), w);
}
// Vectors: integer to double and back (rounded), a random unit direction, and a direction
// quantised as the ray generator's v̂ (Q(2.FV); zero for a zero vector).
inline Vec3 to_vec(const ref::IVec3& v) {
  return {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)};
}
inline ref::IVec3 round3(const Vec3& v) {
  return {std::llround(v.x), std::llround(v.y), std::llround(v.z)};
}
inline Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Vec3 u;
  do u = {g(rng), g(rng), g(rng)};
  while (length(u) < 1e-6);
  return normalize(u);
}
inline ref::IVec3 quantise_dir(const ref::HwParams& p, const Vec3& d) {
  if (length(d) < 1e-12) return {};
  const Vec3 u = normalize(d);
  return {std::llround(std::ldexp(u.x, p.dir_frac)), std::llround(std::ldexp(u.y, p.dir_frac)),
          std::llround(std::ldexp(u.z, p.dir_frac))};
}

// A flat guide as the descriptor compiler quantises one of height h (in LSB, beyond
// kFlatRatio·L) on a segment of length² L2: a = L²/2h, b = L²/4h² in Q(0.FT); straight when
// a rounds to 0.
inline void set_flat_guide(ref::GuideDesc& g, i128 L2, double h, int t_frac) {
  g.a = static_cast<std::int64_t>(std::llround(static_cast<double>(L2) / (2.0 * h)));
  g.b = static_cast<std::int64_t>(
      std::llround(std::ldexp(static_cast<double>(L2) / (4.0 * h * h), t_frac)));
  g.h = 0;
  g.mode = g.a > 0 ? ref::GuideMode::kFlat : ref::GuideMode::kStraight;
}

// Values as text: integers in decimal, vectors (anything with x, y, z) as "(x, y, z)".
inline std::string str(i128 v) { return fixed::to_decimal(v); }
template <class V>
  requires requires(const V& v) { v.x; v.y; v.z; }
std::string str(const V& v) {
  std::string s("(");  // appended piecewise (GCC 12 warns falsely on "(" + std::string)
  s += str(static_cast<i128>(v.x));
  s += ", ";
  s += str(static_cast<i128>(v.y));
  s += ", ";
  s += str(static_cast<i128>(v.z));
  s += ")";
  return s;
}
inline std::string to_string(i128 v) { return str(v); }

// What the vectors exercise: counts of named properties (columns) of the items of each named
// category (rows: the sources, the surface types...), printed as a table; too_weak names the
// first count of the given columns below its minimum ("" when there is none).
class Tally {
 public:
  Tally(std::vector<std::string> rows, std::vector<std::string> cols)
      : rows_(std::move(rows)), cols_(std::move(cols)), n_(rows_.size() * cols_.size()) {}
  template <size_t N>
  Tally(const char* const (&rows)[N], std::vector<std::string> cols)
      : Tally(std::vector<std::string>(rows, rows + N), std::move(cols)) {}
  // One item of category `row`: a value for each column, in order (true counts 1).
  template <class... V>
  void add(int row, V... v) {
    size_t k = static_cast<size_t>(row) * cols_.size();
    ((n_[k++] += static_cast<long>(v)), ...);
  }
  long operator()(int row, int col) const {
    return n_[static_cast<size_t>(row) * cols_.size() + static_cast<size_t>(col)];
  }
  long total(int col) const {
    long t = 0;
    for (size_t r = 0; r < rows_.size(); ++r) t += (*this)(static_cast<int>(r), col);
    return t;
  }
  void print(const char* title) const {
    std::printf("  %s:\n", title);
    for (size_t r = 0; r < rows_.size(); ++r) {
      std::printf("    %-24s", rows_[r].c_str());
      for (size_t c = 0; c < cols_.size(); ++c)
        std::printf("%s %7ld %s", c ? "," : "", n_[r * cols_.size() + c], cols_[c].c_str());
      std::printf("\n");
    }
  }
  std::string too_weak(std::initializer_list<int> cols, long min) const {
    for (size_t r = 0; r < rows_.size(); ++r)
      for (int c : cols)
        if ((*this)(static_cast<int>(r), c) < min)
          return "the vectors are too weak: " + rows_[r] + " has " +
                 std::to_string((*this)(static_cast<int>(r), c)) + " " + cols_[c] + " (under " +
                 std::to_string(min) + ")";
    return "";
  }

 private:
  std::vector<std::string> rows_, cols_;
  std::vector<long> n_;
};

}  // namespace rpu::sim
