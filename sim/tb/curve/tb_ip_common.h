// Shared by the candidate, IP-step and IP testbenches: editing guides, sampling real (segment,
// search interval) pairs of a demo scene, the segment and interval ports those modules share,
// and the IP state vector {τ, lo.t, lo.X, lo.md, hi.md}.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>

#include "tb_base.h"
#include "frame_word.h"
#include "tb_guide.h"
#include "model/curve/rpu_test_point.h"

namespace rpu::sim {

// How edit_guide draws (each testbench keeps the stream its mutants were measured with).
struct GuideEdit {
  int octave_shift = 0;        // a flat guide's h: kFlatRatio·L·(1 + 2^(octave + shift)·U[0,1))
  bool unused_mode = false;    // kind 7: the unused mode code 3 (acts as straight), else straight
  bool flat_near_threshold = false;  // always flat, h just above the threshold (2^-6 octave)
};

// A guide as the descriptor compiler would quantise one of height h (in LSB) on a segment of
// length² L2: flat beyond kFlatRatio·L (set_flat_guide), else an arc or straight. A straight end
// (no direction) gets a random unit direction first.
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
    const double h =
        L * ref::HwParams::kFlatRatio * (1.0 + 1e-6 + std::ldexp(uniform(rng, 0, 1), octave));
    set_flat_guide(g, L2, h, p.t_frac);
  } else if (kind == 5) {  // arc, h in [L/2, 16·L]
    g.h = static_cast<std::int64_t>(std::llround(L * uniform(rng, 0.5, 16)));
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
  const Vec3 world = scene::curve_point(sc.curve_segments[k].geom, uniform(rng, 0, 1));
  if (!scene::project_to_pixel(sc.camera, world, ci, cj)) return false;
  ci = std::clamp(ci + static_cast<int>(rng() % 5) - 2, 0, m.camera.width - 1);
  cj = std::clamp(cj + static_cast<int>(rng() % 5) - 2, 0, m.camera.height - 1);
  const ref::RayGenOut ray = ref::ray_generator(p, m.camera, ci, cj);
  fixed::Overflow o;
  out.si = ref::sphere_unit(p, m.camera.eye, ray.vhat, m.curve_segments[k], o);
  out.seg = k;
  return out.si.pred1;
}

// The interval and segment input fields shared by rpu_test_point and rpu_ip (A and B − A where
// the unit has them).
template <class Top>
void pair_inputs(Inputs& in, Top& top, const ref::HwParams& p, const ref::SegmentDesc& s,
                 const ref::SearchInterval& si) {
  const int CW = p.coord_w, DW = p.diff_w(), TW = p.t_w();
  if constexpr (requires { top.a_i; }) in.vec("A", top.a_i, si.A, CW).vec("AB", top.ab_i, si.AB, DW);
  in("alpha", top.alpha_i, si.alpha, TW)("beta", top.beta_i, si.beta, TW);
  in.vec("p1", top.p1_i, s.p1, CW).vec("d", top.d_i, s.d, DW)("L2", top.l2_i, s.L2, p.l2_w());
  const ref::GuideDesc& g1 = s.guide[0];
  const ref::GuideDesc& g2 = s.guide[1];
  guide_input(in, "g1", top.g1_i, p, g1);
  guide_input(in, "g2", top.g2_i, p, g2);
  // rpu_test_point takes h² from its caller (rpu_ip squares h once per pair).
  if constexpr (requires { top.hh1_i; }) {
    in("hh1", top.hh1_i, i128{g1.h} * g1.h, p.guide_radicand_w());
    in("hh2", top.hh2_i, i128{g2.h} * g2.h, p.guide_radicand_w());
  }
}

// Width of one md value (rpu_candidate's md_o), and the state vector {τ, lo.md, hi.md}.
inline int md_width(const ref::HwParams& p) {
  constexpr int F = ref::HwParams::kFrameMdFracMax;
  return p.metric == ref::Metric::kAbs ? F + 3 : 2 * F + 3;
}
inline Bits pack_state(const ref::HwParams& p, const ref::IpState& st) {
  Concat c;
  c.add(static_cast<i128>(st.tau), p.n);
  c.add(st.lo.md, md_width(p));
  c.add(st.hi.md, md_width(p));
  return c.bits();
}

// The state out of a port, compared field by field with the expected one.
template <class P>
void state_outputs(Outputs& o, const P& port, const ref::HwParams& p, const ref::IpState& w) {
  const int MdW = md_width(p);
  Unpack f(get_bits(port, p.n + 2 * MdW));
  o.value("tau", static_cast<i128>(w.tau), f.u(p.n));
  o.value("lo.md", w.lo.md, f.u(MdW));
  o.value("hi.md", w.hi.md, f.u(MdW));
}


// rpu_ip's result {τ, t, X (z, y, x), lo.md, hi.md}, compared field by field.
template <class P>
void ip_outputs(Outputs& o, const P& port, const ref::HwParams& p, const ref::IpState& w,
                const ref::TestPoint& tp) {
  const int TW = p.t_w(), XW = p.point_w(), MdW = md_width(p);
  Unpack f(get_bits(port, p.n + TW + 3 * XW + 2 * MdW));
  o.value("tau", static_cast<i128>(w.tau), f.u(p.n));
  o.value("t", tp.t, f.s(TW));
  const i128 z = f.s(XW), y = f.s(XW), x = f.s(XW);
  o.value("X.x", tp.X.x, x).value("X.y", tp.X.y, y).value("X.z", tp.X.z, z);
  o.value("lo.md", w.lo.md, f.u(MdW));
  o.value("hi.md", w.hi.md, f.u(MdW));
}

}  // namespace rpu::sim
