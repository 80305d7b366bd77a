// Twin of rtl/surface/rpu_surface_setup.v
#include "model/surface/rpu_surface_setup.h"

#include <algorithm>
#include <array>

#include "model/surface/surface_descriptors.h"

namespace rpu::ref {

using fixed::truncate;
using fixed::u128;
using scene::SurfaceType;

namespace {

i128 abs128(i128 v) { return v < 0 ? -v : v; }

// num/den clamped to [0, 1] in Q(1.SF) for den > 0: 0 when num ≤ 0, 1 when num ≥ den, else the
// floor quotient (restoring division, SF quotient bits).
i128 clamped_ratio(i128 num, i128 den, int sf) {
  if (num <= 0) return 0;
  if (num >= den) return i128{1} << sf;
  return static_cast<i128>(fixed::udiv(static_cast<u128>(num) << sf, static_cast<u128>(den), sf));
}

// The zero of the linear f from fA (s = 0) to fB (s = 1) when its sign bit changes:
// s = |fA| / (|fA| + |fB|) ∈ [0, 1], Q(1.SF), floor (SF + 1 quotient bits).
bool plane_cut(i128 fA, i128 fB, int sf, i128& s) {
  if ((fA < 0) == (fB < 0)) return false;
  const i128 a = abs128(fA), den = a + abs128(fB);
  s = static_cast<i128>(fixed::udiv(static_cast<u128>(a) << sf, static_cast<u128>(den), sf + 1));
  return true;
}

// P + floor(D·s·2^-SF) per component.
WVec3 along(const WVec3& P, const WVec3& D, i128 s, int sf) { return P + scale_truncate(D, s, sf); }

}  // namespace

int surface_piece_items(SurfaceType t) {
  return t == SurfaceType::kSpiral || t == SurfaceType::kSnail ? 3 : 1;
}

WVec3 surface_to_local(const HwParams& p, const SurfaceDesc& s, const WVec3& X, Overflow& ovf) {
  const WVec3 q = X - widen(s.origin);  // LSB, CW+1 bits
  const auto row = [&](int r) {
    const i128 v = s.to_local[3 * r] * q.x + s.to_local[3 * r + 1] * q.y + s.to_local[3 * r + 2] * q.z;
    return fixed::saturate(truncate(v, s.to_local_s), p.surf_w, ovf);
  };
  return {row(0), row(1), row(2)};
}

SurfaceSetupOut surface_setup(const HwParams& p, const IVec3& eye, const IVec3& vhat,
                              const SurfaceDesc& s, int piece, Overflow& ovf) {
  SurfaceSetupOut o;
  o.sphere = sphere_unit(p, eye, vhat, s.bound, ovf);
  if (!o.sphere.pred1) return o;
  o.la = surface_to_local(p, s, o.sphere.A, ovf);
  o.lb = surface_to_local(p, s, o.sphere.B, ovf);
  const int sf = p.surf_cut_frac();
  const i128 one = i128{1} << sf;

  // Piece bounds along A → B (at most two cuts: three pieces).
  std::array<i128, 4> bound{};
  int nb = 0;
  i128 cut_x = 0, cut_e = 0;
  bool has_x = false, has_e = false;
  i128 fxA = 0, fxB = 0, feA = 0, feB = 0;
  if (s.type == SurfaceType::kSpiral || s.type == SurfaceType::kSnail) {
    // The plane x = 0 and the end plane x·cos − z·sin = 0 (Q(.KF) llsb), exact.
    fxA = o.la.x, fxB = o.lb.x;
    has_x = plane_cut(fxA, fxB, sf, cut_x);
    if (s.end_angle != 0) {
      feA = o.la.x * s.end_cos - o.la.z * s.end_sin;
      feB = o.lb.x * s.end_cos - o.lb.z * s.end_sin;
      has_e = plane_cut(feA, feB, sf, cut_e);
    }
    bound[nb++] = 0;
    if (has_x && has_e) {
      bound[nb++] = std::min(cut_x, cut_e);
      bound[nb++] = std::max(cut_x, cut_e);
    } else if (has_x || has_e) {
      bound[nb++] = has_x ? cut_x : cut_e;
    }
    bound[nb++] = one;
  } else {
    // The slab y_min ≤ y ≤ y_max: entry and exit parameters, clamped to [0, 1].
    const i128 yA = o.la.y, dy = o.lb.y - o.la.y;
    i128 lo = 0, hi = 0;
    if (dy == 0) {
      if (yA >= s.y_min && yA <= s.y_max) hi = one;
    } else if (dy > 0) {
      lo = clamped_ratio(s.y_min - yA, dy, sf);
      hi = clamped_ratio(s.y_max - yA, dy, sf);
    } else {
      lo = clamped_ratio(yA - s.y_max, -dy, sf);
      hi = clamped_ratio(yA - s.y_min, -dy, sf);
    }
    bound[nb++] = lo;
    bound[nb++] = hi;
  }
  // The non-empty pieces, in order; `piece` selects one of them.
  int found = -1;
  for (int k = 0; k + 1 < nb; ++k) {
    if (bound[k] >= bound[k + 1]) continue;
    if (o.pieces++ == piece) found = k;
  }
  if (found < 0) return o;
  o.valid = true;
  o.s_lo = bound[found];
  o.s_hi = bound[found + 1];
  const WVec3 AB = o.sphere.B - o.sphere.A, lAB = o.lb - o.la;
  o.A = along(o.sphere.A, AB, o.s_lo, sf);
  o.AB = along(o.sphere.A, AB, o.s_hi, sf) - o.A;
  o.lA = along(o.la, lAB, o.s_lo, sf);
  o.lAB = along(o.la, lAB, o.s_hi, sf) - o.lA;
  if (s.type == SurfaceType::kSpiral || s.type == SurfaceType::kSnail) {
    // A piece ending at or before a cut lies on A's side of that plane, any other on B's.
    o.x_negative = has_x && o.s_hi > cut_x ? fxB < 0 : fxA < 0;
    const bool e_negative = has_e && o.s_hi > cut_e ? feB < 0 : feA < 0;
    // Turn full_turns is in range where ψ < end angle: on x ≥ 0 with f_e < 0 when the end angle
    // is below π, else on x ≥ 0 or f_e < 0 (f_e = ρ·sin(ψ − end angle)).
    const bool end_low = s.end_angle < (full_turn(p.angle_w) >> 1);
    o.last_turn = s.end_angle != 0 &&
                  (end_low ? !o.x_negative && e_negative : !o.x_negative || e_negative);
  }
  return o;
}

}  // namespace rpu::ref
