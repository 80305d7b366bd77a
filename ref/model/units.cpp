#include "model/units.h"

#include <algorithm>
#include <vector>

namespace rpu::ref {

using fixed::round_half_up;
using fixed::truncate;
using fixed::u128;

namespace {

i128 dot(const WVec3& a, const WVec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
WVec3 widen(const IVec3& v) { return {v.x, v.y, v.z}; }
WVec3 operator+(const WVec3& a, const WVec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
WVec3 operator-(const WVec3& a, const WVec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
// Each component times k, then `bits` fraction bits dropped (floor).
WVec3 scale_truncate(const WVec3& v, i128 k, int bits) {
  return {truncate(v.x * k, bits), truncate(v.y * k, bits), truncate(v.z * k, bits)};
}
WVec3 saturate_vec(const WVec3& v, int width, Overflow& ovf) {
  return {fixed::saturate(v.x, width, ovf), fixed::saturate(v.y, width, ovf),
          fixed::saturate(v.z, width, ovf)};
}

}  // namespace

i128 sqrt_unit(i128 x, int format_w, int sqrt_w, Overflow& ovf) {
  x = fixed::saturate_unsigned(x, format_w, ovf);
  if (sqrt_w == 0 || format_w <= sqrt_w)
    return static_cast<i128>(fixed::isqrt(static_cast<u128>(x), format_w));
  const int s = (format_w - sqrt_w + 1) / 2;  // pre-shift by 2s ≥ format_w - sqrt_w
  const u128 r = fixed::isqrt(static_cast<u128>(x) >> (2 * s), format_w - 2 * s);
  return static_cast<i128>(r << s);
}

RayGenOut ray_generator(const HwParams& p, const CameraDesc& cam, int i, int j) {
  RayGenOut r;
  // v = v0 + i·dx + j·dy exactly in Q(4.FV+14) (the compiler checked the image corners fit),
  // then the guard bits dropped: Q(4.FV).
  const WVec3 vg = widen(cam.v0) + scale_truncate(widen(cam.dx), i, 0) +
                   scale_truncate(widen(cam.dy), j, 0);
  const WVec3 v = {truncate(vg.x, HwParams::kRayGuard), truncate(vg.y, HwParams::kRayGuard),
                   truncate(vg.z, HwParams::kRayGuard)};
  r.v = {static_cast<i64>(v.x), static_cast<i64>(v.y), static_cast<i64>(v.z)};
  // |v| = floor(sqrt(v·v)), Q(.FV); 1/|v| = floor(2^(2FV+2) / |v|), Q(.FV+2); v̂ = v·(1/|v|).
  Overflow unused;
  const int vv_w = 2 * p.dir_w() + 4;
  const i128 len = sqrt_unit(dot(v, v), vv_w, 0, unused);
  const i128 recip = static_cast<i128>(
      fixed::udiv(u128{1} << (2 * p.dir_frac + 2), static_cast<u128>(len), p.dir_frac + 3));
  const WVec3 vh = scale_truncate(v, recip, p.dir_frac + 2);
  r.vhat = {static_cast<i64>(vh.x), static_cast<i64>(vh.y), static_cast<i64>(vh.z)};
  // Edge vectors, linear in i and j: E_left(i) = el0 - i·σW, E_top(j) = et0 - j·σW.
  const WVec3 el0 = widen(cam.el0), et0 = widen(cam.et0), sw = widen(cam.sw);
  r.e_left = el0 - scale_truncate(sw, i, 0);
  r.e_right = el0 - scale_truncate(sw, i + 1, 0);
  r.e_top = et0 - scale_truncate(sw, j, 0);
  r.e_bottom = et0 - scale_truncate(sw, j + 1, 0);
  return r;
}

i128 chord_parameter(const HwParams& p, const SegmentDesc& s, i128 dot_value, Overflow& ovf) {
  const i128 t = truncate(dot_value * s.inv_m, s.inv_s - p.t_frac);
  return fixed::saturate(t, p.t_w(), ovf);
}

SearchInterval sphere_unit(const HwParams& p, const IVec3& eye, const IVec3& vhat,
                           const SegmentDesc& s, Overflow& ovf) {
  SearchInterval si;
  const WVec3 h = widen(eye), v = widen(vhat);
  const WVec3 q = widen(s.c0) - h;                        // LSB, CW+1 bits
  si.tc = truncate(dot(v, q), p.dir_frac);                // LSB
  // The squared distance of c0 from the ray, from the cross product q × v̂ (exact), each
  // component floored to kSphereGuard fraction bits, squared and summed exactly, floored to LSB².
  // Not R² + tc² − q·q: that cancels two numbers of (distance to the eye)² when the camera is
  // far from the segment, and a one-LSB error of tc or of |v̂| then swamps R² (issue 11, item 9).
  const int g = HwParams::kSphereGuard, sh = p.dir_frac - g;
  const WVec3 w = {truncate(q.y * v.z - q.z * v.y, sh), truncate(q.z * v.x - q.x * v.z, sh),
                   truncate(q.x * v.y - q.y * v.x, sh)};  // Q(.G) LSB
  const i128 perp2 = truncate(dot(w, w), 2 * g);           // LSB², < 2^(2CW+4)
  const i128 disc = s.R2 - perp2;                          // LSB², in (−2^(2CW+4), 2^(2CW))
  if (disc < 0) return si;                                // pred_1: the ray misses the sphere
  si.half_chord = sqrt_unit(disc, p.sphere_radicand_w(), p.sqrt_w, ovf);
  const i128 t2 = si.tc + si.half_chord;
  if (t2 <= 0) return si;                                 // the sphere is behind the eye
  const i128 t1 = std::max<i128>(0, si.tc - si.half_chord);  // eye inside: start at the eye
  si.pred1 = true;
  si.A = saturate_vec(h + scale_truncate(v, t1, p.dir_frac), p.coord_w, ovf);
  si.B = saturate_vec(h + scale_truncate(v, t2, p.dir_frac), p.coord_w, ovf);
  si.AB = si.B - si.A;
  const WVec3 d = widen(s.d);
  si.alpha = chord_parameter(p, s, dot(si.A - widen(s.p1), d), ovf);
  si.beta = chord_parameter(p, s, dot(si.AB, d), ovf);
  return si;
}

i128 guide_weight(const HwParams& p, i128 t) {
  const i128 one = i128{1} << p.t_frac;
  const i128 tc = std::clamp<i128>(t, 0, one);
  return truncate(tc * (one - tc), p.t_frac);  // Q(0.FT), ≤ 1/4
}

i128 guide_unit(const HwParams& p, const GuideDesc& g, i128 L2, i128 w, Overflow& ovf) {
  switch (g.mode) {
    case GuideMode::kStraight:
      return 0;
    case GuideMode::kArc: {
      // g = sqrt(h² + L²·w) - h: one square root, no division.
      const i128 rad = i128{g.h} * g.h + truncate(L2 * w, p.t_frac);
      return sqrt_unit(rad, p.guide_radicand_w(), p.sqrt_w, ovf) - g.h;
    }
    case GuideMode::kFlat: {
      // h > 16·L: g = h(√(1+x) - 1) = a·w·(1 - b·w) + O(h x³/16) with x = L²w/h² ≤ 1/1024.
      const i128 aw = truncate(i128{g.a} * w, p.t_frac);
      const i128 bw = truncate(i128{g.b} * w, p.t_frac);
      return aw - truncate(aw * bw, p.t_frac);
    }
  }
  return 0;
}

WVec3 curve_point_unit(const HwParams& p, const SegmentDesc& s, i128 t, i128 g1, i128 g2) {
  const i128 one = i128{1} << p.t_frac;
  // s(t) = p(t) + u_1·g_1·(1-t) + u_2·g_2·t  (seed 000 eq. 23 with the closed-form guides).
  const WVec3 pt = widen(s.p1) + scale_truncate(widen(s.d), t, p.t_frac);
  const i128 G1 = truncate(g1 * (one - t), p.t_frac);
  const i128 G2 = truncate(g2 * t, p.t_frac);
  return pt + scale_truncate(widen(s.guide[0].u), G1, p.unit_frac) +
         scale_truncate(widen(s.guide[1].u), G2, p.unit_frac);
}

Candidate candidate_evaluator(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                              std::uint64_t m, Overflow& ovf) {
  Candidate c;
  const i128 mm = static_cast<i128>(m);
  c.pr = si.A + scale_truncate(si.AB, mm, p.n);                            // pr(τ), LSB
  c.t = fixed::saturate(si.alpha + truncate(si.beta * mm, p.n), p.t_w(), ovf);  // t(τ), Q(3.FT)
  const i128 w = guide_weight(p, c.t);
  const i128 g1 = guide_unit(p, s.guide[0], s.L2, w, ovf);
  const i128 g2 = guide_unit(p, s.guide[1], s.L2, w, ovf);
  c.X = curve_point_unit(p, s, c.t, g1, g2);
  const WVec3 diff = c.pr - c.X;
  const i128 md2 = dot(diff, diff);
  c.md = p.metric == Metric::kAbs ? sqrt_unit(md2, p.dist_radicand_w(), p.sqrt_w, ovf)
                                  : fixed::saturate_unsigned(md2, p.dist_radicand_w(), ovf);
  return c;
}

int argmin_lowest(const i128* sd, int count) {
  int best = 0;
  for (int j = 1; j < count; ++j)
    if (sd[j] < sd[best]) best = j;
  return best;
}

IpState ip_start(const HwParams& p, const SegmentDesc& s, const SearchInterval& si, Overflow& ovf) {
  IpState st;
  st.lo = candidate_evaluator(p, s, si, 0, ovf);
  st.hi = candidate_evaluator(p, s, si, std::uint64_t{1} << p.n, ovf);
  return st;
}

void ip_step_in_place(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                      IpState& st, Overflow& ovf, IpStepTrace* trace) {
  const int J = p.J();
  const int k = st.k + 1;
  const int shift = p.n - p.n1 * k;  // δ_k = 2^-(n1·k) = 2^shift τ-index units
  // The J - 1 new candidates (j = 1..J-1); the ends are the previous interval's lo and hi.
  thread_local std::vector<Candidate> cand;
  if (cand.size() < static_cast<size_t>(J) + 1) cand.resize(static_cast<size_t>(J) + 1);
  for (int j = 1; j < J; ++j)
    cand[j] = candidate_evaluator(p, s, si, st.tau + (static_cast<std::uint64_t>(j) << shift), ovf);
  const auto md = [&](int j) { return j == 0 ? st.lo.md : j == J ? st.hi.md : cand[j].md; };
  std::array<i128, 256> sd;  // uninitialised: only [0, J) is written and read
  for (int j = 0; j < J; ++j) sd[j] = md(j) + md(j + 1);
  const int eta = argmin_lowest(sd.data(), J);
  if (trace) {
    for (int j = 0; j <= J; ++j) trace->md[j] = md(j);
    for (int j = 0; j < J; ++j) trace->sd[j] = sd[j];
    trace->eta = eta;
  }
  st.k = k;
  st.tau += static_cast<std::uint64_t>(eta) << shift;
  if (eta + 1 < J) st.hi = cand[eta + 1];  // else hi stays the previous hi
  if (eta > 0) st.lo = cand[eta];          // else lo stays the previous lo
}

IpState ip_step(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                const IpState& state, Overflow& ovf, IpStepTrace* trace) {
  IpState next = state;
  ip_step_in_place(p, s, si, next, ovf, trace);
  return next;
}

IpState ip_process_unrolled(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                            Overflow& ovf) {
  // Stage 0 evaluates the two ends; stages 1..K each own one step (state.k enters as k - 1).
  IpState st = ip_start(p, s, si, ovf);
  for (int stage = 1; stage <= p.K(); ++stage) {
    st.k = stage - 1;
    ip_step_in_place(p, s, si, st, ovf, nullptr);
  }
  return st;
}

IpState ip_process_iterative(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                             Overflow& ovf) {
  // One step unit; its counter (state.k) advances each pass until K passes are done.
  IpState st = ip_start(p, s, si, ovf);
  while (st.k < p.K()) ip_step_in_place(p, s, si, st, ovf, nullptr);
  return st;
}

CaptureOut capture_unit(const HwParams& p, const CameraDesc& cam, const RayGenOut& ray,
                        const WVec3& X, i128 t) {
  CaptureOut c;
  c.t_in_range = t >= 0 && t <= (i128{1} << p.t_frac);
  const WVec3 q = X - widen(cam.eye);
  // Four multiply-subtract sign tests (seed 000 eqs 24–26): left/top edges inclusive.
  c.signs = {dot(q, ray.e_left) >= 0, dot(q, ray.e_right) < 0, dot(q, ray.e_top) >= 0,
             dot(q, ray.e_bottom) < 0};
  c.depth = dot(q, widen(cam.w));
  c.hit = c.t_in_range && c.depth > 0 && c.signs[0] && c.signs[1] && c.signs[2] && c.signs[3];
  return c;
}

PlanePoint ray_plane_unit(const HwParams& p, const CameraDesc& cam, const IVec3& vhat) {
  PlanePoint pp;
  const i128 hz = cam.eye.z, vz = vhat.z;
  // t0 = -h_z / v̂_z > 0 needs h_z and v̂_z of opposite signs (neither zero).
  if (vz == 0 || hz == 0 || (hz > 0) == (vz > 0)) return pp;
  const u128 num = static_cast<u128>(hz < 0 ? -hz : hz) << p.dir_frac;
  const u128 den = static_cast<u128>(vz < 0 ? -vz : vz);
  const int qw = p.coord_w + 1;  // t0 < 2^(CW+1) LSB, or the hit is beyond every texture
  if ((num >> qw) >= den) return pp;
  const i128 t0 = static_cast<i128>(fixed::udiv(num, den, qw));
  const WVec3 h = widen(cam.eye);
  WVec3 p0 = h + scale_truncate(widen(vhat), t0, p.dir_frac);
  p0.z = 0;
  if (!fixed::fits_signed(p0.x, p.coord_w) || !fixed::fits_signed(p0.y, p.coord_w)) return pp;
  pp.valid = true;
  pp.p0 = p0;
  pp.depth = dot(p0 - h, widen(cam.w));
  return pp;
}

TextureOut texture_unit(const HwParams& p, const SegmentDesc& s, const WVec3& p0, Overflow& ovf) {
  TextureOut o;
  const WVec3 d = widen(s.d);
  const WVec3 r1 = p0 - widen(s.p1), r2 = r1 - d;  // p0 - p1, p0 - p2
  // pr1: between the planes through p1 and p2 perpendicular to d (seed 001 eqs 7–9).
  const i128 f1 = dot(r1, d);
  o.pr1 = f1 >= 0 && dot(r2, d) <= 0;
  // pr2: round caps at the end points (eq 10).
  o.pr2 = dot(r1, r1) <= s.w0_2 || dot(r2, r2) <= s.w0_2;
  // pr3: the curve point on the guide line through p0 within w_0 (eqs 15–24).
  // t̂ = (p0 - p1)·d / L²; where pr1 fails the value is never used, so f1 is clamped to
  // [0, L²] first (a mux in hardware) and t̂ stays in [0, 1] without saturating.
  o.t = chord_parameter(p, s, std::clamp<i128>(f1, 0, s.L2), ovf);
  const i128 w = guide_weight(p, o.t);
  o.X = curve_point_unit(p, s, o.t, guide_unit(p, s.guide[0], s.L2, w, ovf),
                         guide_unit(p, s.guide[1], s.L2, w, ovf));
  const WVec3 e = o.X - p0;
  o.pr3 = dot(e, e) <= s.w0_2;
  o.covers = o.pr1 && (o.pr2 || o.pr3);
  return o;
}

PairResult process_curve_pair(const HwParams& p, const CameraDesc& cam, const RayGenOut& ray,
                              const SegmentDesc& s) {
  PairResult r;
  Overflow ovf;
  r.interval = sphere_unit(p, cam.eye, ray.vhat, s, ovf);
  if (r.interval.pred1) {
    const IpState st = ip_process(p, s, r.interval, ovf);
    r.tau = st.tau;
    r.t = st.lo.t;
    r.X = st.lo.X;
    const CaptureOut c = capture_unit(p, cam, ray, r.X, r.t);
    r.hit = c.hit;
    r.depth = c.depth;
  }
  r.overflow = ovf.flag;
  return r;
}

}  // namespace rpu::ref
