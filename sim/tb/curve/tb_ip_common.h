// Shared by the candidate, IP-step and IP testbenches: sampling real (segment, search interval)
// pairs of a demo scene, driving the segment and interval ports those modules share, and
// decoding the IP state vector {τ, lo.t, lo.X, lo.md, hi.md}.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>

#include "model/units.h"
#include "scene/compiled_scene.h"
#include "tb_common.h"

namespace rpu::sim {

// A random value of `width` bits, sign-extended.
inline i128 random_signed(std::mt19937_64& rng, int width) {
  const u128 bits = (static_cast<u128>(rng()) << 64) | rng();
  const u128 u = bits & ((u128{1} << width) - 1), sign = u128{1} << (width - 1);
  return static_cast<i128>((u ^ sign) - sign);
}

// How edit_guide draws (each testbench keeps the stream its mutants were measured with).
struct GuideEdit {
  int octave_shift = 0;        // a flat guide's h: kFlatRatio·L·(1 + 2^(octave + shift)·U[0,1))
  bool unused_mode = false;    // kind 7: the unused mode code 3 (acts as straight), else straight
  bool flat_near_threshold = false;  // always flat, h just above the threshold (2^-6 octave)
};

// A guide as the descriptor compiler would quantise one of height h (in LSB) on a segment of
// length² L2: flat beyond kFlatRatio·L (a = L²/2h, b = L²/4h² in Q(0.FT)), else an arc or
// straight. A straight end (no direction) gets a random unit direction first.
inline void edit_guide(const ref::HwParams& p, i128 L2, std::mt19937_64& rng, ref::GuideDesc& g,
                       const GuideEdit& how = {}) {
  if (g.u == ref::IVec3{}) {
    std::normal_distribution<double> nd;
    const double v[3] = {nd(rng), nd(rng), nd(rng)};
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) + 1e-30;
    const auto q = [&](double c) {
      return static_cast<std::int64_t>(std::llround(std::ldexp(c / n, p.unit_frac)));
    };
    g.u = {q(v[0]), q(v[1]), q(v[2])};
  }
  const double L = std::sqrt(static_cast<double>(L2));
  const unsigned kind = how.flat_near_threshold ? 0 : static_cast<unsigned>(rng() % 8);
  if (kind < 5) {  // flat: h from just above the threshold to 2^12 times it
    const int octave =
        how.flat_near_threshold ? -6 : static_cast<int>(rng() % 13) + how.octave_shift;
    const double h = L * ref::HwParams::kFlatRatio *
                     (1.0 + 1e-6 + std::ldexp(std::uniform_real_distribution<double>(0, 1)(rng),
                                              octave));
    g.a = static_cast<std::int64_t>(std::llround(static_cast<double>(L2) / (2.0 * h)));
    g.b = static_cast<std::int64_t>(
        std::llround(std::ldexp(static_cast<double>(L2) / (4.0 * h * h), p.t_frac)));
    g.h = 0;
    g.mode = g.a > 0 ? ref::GuideMode::kFlat : ref::GuideMode::kStraight;
  } else if (kind == 5) {  // arc, h in [L/2, 16·L]
    g.h = static_cast<std::int64_t>(
        std::llround(L * std::uniform_real_distribution<double>(0.5, 16)(rng)));
    g.mode = ref::GuideMode::kArc;
  } else if (kind == 6 || !how.unused_mode) {
    g.mode = ref::GuideMode::kStraight;
  } else {
    g.mode = static_cast<ref::GuideMode>(3);
  }
}

// A pair whose ray meets the segment's interpolation sphere: a pixel at or beside the projection
// of a random point of a random segment's curve (so both hits and near misses).
struct SampledPair {
  size_t seg = 0;
  ref::SearchInterval si;
};
inline bool sample_pred1_pair(const scene::CompiledScene& sc, const ref::ModelScene& m,
                              const ref::HwParams& p, std::mt19937_64& rng, SampledPair& out) {
  const size_t k = rng() % m.curve_segments.size();
  int ci, cj;
  const Vec3 world = scene::curve_point(sc.curve_segments[k].geom,
                                        std::uniform_real_distribution<double>(0, 1)(rng));
  if (!scene::project_to_pixel(sc.camera, world, ci, cj)) return false;
  ci = std::clamp(ci + static_cast<int>(rng() % 5) - 2, 0, m.camera.width - 1);
  cj = std::clamp(cj + static_cast<int>(rng() % 5) - 2, 0, m.camera.height - 1);
  const ref::RayGenOut ray = ref::ray_generator(p, m.camera, ci, cj);
  fixed::Overflow o;
  out.si = ref::sphere_unit(p, m.camera.eye, ray.vhat, m.curve_segments[k], o);
  out.seg = k;
  return out.si.pred1;
}

// The interval and segment ports shared by rpu_candidate, rpu_ip_step and rpu_ip.
template <class Top>
void drive_pair(Top& top, const ref::HwParams& p, const ref::SegmentDesc& s,
                const ref::SearchInterval& si) {
  const int CW = p.coord_w, DW = CW + 1, TW = p.t_w(), UW = p.unit_w();
  put_vec3(top.a_i, si.A.x, si.A.y, si.A.z, CW);
  put_vec3(top.ab_i, si.AB.x, si.AB.y, si.AB.z, DW);
  put(top.alpha_i, si.alpha, TW);
  put(top.beta_i, si.beta, TW);
  put_vec3(top.p1_i, s.p1.x, s.p1.y, s.p1.z, CW);
  put_vec3(top.d_i, s.d.x, s.d.y, s.d.z, DW);
  put(top.l2_i, s.L2, 2 * CW + 3);
  const ref::GuideDesc& g1 = s.guide[0];
  const ref::GuideDesc& g2 = s.guide[1];
  top.mode1_i = static_cast<unsigned>(g1.mode);
  put(top.h1_i, g1.h, CW + 5);
  put(top.a1_i, g1.a, CW);
  put(top.b1_i, g1.b, p.t_frac);
  put_vec3(top.u1_i, g1.u.x, g1.u.y, g1.u.z, UW);
  top.mode2_i = static_cast<unsigned>(g2.mode);
  put(top.h2_i, g2.h, CW + 5);
  put(top.a2_i, g2.a, CW);
  put(top.b2_i, g2.b, p.t_frac);
  put_vec3(top.u2_i, g2.u.x, g2.u.y, g2.u.z, UW);
  // rpu_candidate and rpu_ip_step take h² from their caller (rpu_ip squares h once per pair).
  if constexpr (requires { top.hh1_i; }) {
    put(top.hh1_i, i128{g1.h} * g1.h, 2 * CW + 10);
    put(top.hh2_i, i128{g2.h} * g2.h, 2 * CW + 10);
  }
}

// Width of one md value and of the state vector.
inline int md_width(const ref::HwParams& p) {
  return p.metric == ref::Metric::kAbs ? p.coord_w + 4 : 2 * p.coord_w + 8;
}
inline int state_width(const ref::HwParams& p) {
  return p.n + p.t_w() + 3 * (p.coord_w + 3) + 2 * md_width(p);
}

// Decoded state {τ, lo.t, lo.X, lo.md, hi.md}.
struct IpStateFields {
  i128 tau = 0, lo_t = 0, x[3]{}, lo_md = 0, hi_md = 0;
};
template <std::size_t N>
IpStateFields read_state(const VlWide<N>& port, const ref::HwParams& p) {
  const int TW = p.t_w(), XW = p.coord_w + 3, MdW = md_width(p);
  const auto field = [&](int hi_bit, int width) {
    u128 u = 0;
    for (int b = 0; b < width; ++b) {
      const int bit = hi_bit - width + 1 + b;
      if ((port[static_cast<std::size_t>(bit / 32)] >> (bit % 32)) & 1) u |= u128{1} << b;
    }
    return u;
  };
  const auto sext = [](u128 u, int w) {
    const u128 sign = u128{1} << (w - 1);
    return static_cast<i128>((u ^ sign) - sign);
  };
  IpStateFields f;
  int at = state_width(p) - 1;
  f.tau = static_cast<i128>(field(at, p.n));
  at -= p.n;
  f.lo_t = sext(field(at, TW), TW);
  at -= TW;
  for (int c = 2; c >= 0; --c) {  // {z, y, x}
    f.x[c] = sext(field(at, XW), XW);
    at -= XW;
  }
  f.lo_md = static_cast<i128>(field(at, MdW));
  at -= MdW;
  f.hi_md = static_cast<i128>(field(at, MdW));
  return f;
}

// Encodes a model state into a state port.
template <std::size_t N>
void write_state(VlWide<N>& port, const ref::HwParams& p, const ref::IpState& st) {
  for (std::size_t w = 0; w < N; ++w) port[w] = 0;
  const int TW = p.t_w(), XW = p.coord_w + 3, MdW = md_width(p);
  int at = state_width(p);
  const auto put_field = [&](i128 v, int w) {
    at -= w;
    for (int b = 0; b < w; ++b)
      if ((static_cast<u128>(v) >> b) & 1)
        port[static_cast<std::size_t>((at + b) / 32)] |= 1u << ((at + b) % 32);
  };
  put_field(static_cast<i128>(st.tau), p.n);
  put_field(st.lo.t, TW);
  put_field(st.lo.X.z, XW);
  put_field(st.lo.X.y, XW);
  put_field(st.lo.X.x, XW);
  put_field(st.lo.md, MdW);
  put_field(st.hi.md, MdW);
}

}  // namespace rpu::sim
