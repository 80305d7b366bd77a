#include "model/surface/surface_descriptors.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "common/error.h"

namespace rpu::ref {
namespace {

using scene::SurfaceType;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// A scale constant below this many LSBs of Q(1.KF) would carry less than 8 bits: refused.
constexpr i64 kMinScaleLsb = 256;
// Smallest bounding radius, in LSB, of a surface the model takes (far below a pixel, which the
// precision rule keeps at 64 LSB or more); it also keeps the transform's block shift ≥ 0.
constexpr double kMinSurfaceLsb = 8.0;
// Extra bits of the per-turn constants 2π·a, 2π·k beyond LW (a range of φ down to 2π/64).
constexpr int kTurnConstExtra = 8;

// Round v · 2^frac to an integer of at most `width` signed bits, or throw naming `what`.
i64 quantize(double v, int frac, int width, const std::string& where, const char* what) {
  const double s = std::ldexp(v, frac);
  const double limit = std::ldexp(1.0, width - 1);
  if (!(std::fabs(s) < limit))
    throw Error(where, fmt::format("{} = {:.6g} does not fit the surface format (|{}| · 2^{} "
                                   "reaches 2^{}); the surface is too large or too small relative "
                                   "to its own parts for --surf-w",
                                   what, v, what, frac, width - 1));
  return static_cast<i64>(std::llround(s));
}

// A scale constant in (0, 1], Q(1.KF).
i64 unit_scale(double v, const HwParams& p, const std::string& where, const char* what) {
  const i64 q = quantize(v, p.surf_const_frac(), p.surf_const_frac() + 2, where, what);
  if (q < kMinScaleLsb)
    throw Error(where, fmt::format("{} = {:.3g}: the surface's proportions are too extreme for "
                                   "the Q(1.{}) scale constants (the ratio of its smallest to its "
                                   "largest semi-axis must be at least 2^-{}); raise --surf-w",
                                   what, v, p.surf_const_frac(), p.surf_const_frac() - 8));
  return q;
}

// (m · 2^(F+G))², the squared threshold of a scaled-coordinate test, rounded.
i128 squared_threshold(double m, int frac) {
  const double v = std::ldexp(m, frac + HwParams::kSurfGuard);
  return static_cast<i128>(std::llround(v)) * static_cast<i128>(std::llround(v));
}

// The azimuth range φ ∈ [0, phi_max] as full turns plus a binary end angle.
void azimuth_range(SurfaceDesc& d, double phi_max, const HwParams& p, const std::string& where) {
  const std::uint64_t turn = full_turn(p.angle_w);
  const auto total = static_cast<std::uint64_t>(std::llround(phi_max / kTwoPi * static_cast<double>(turn)));
  d.full_turns = static_cast<int>(total >> p.angle_w);
  d.end_angle = total & (turn - 1);
  const int lanes = d.full_turns + (d.end_angle != 0 ? 1 : 0);
  if (lanes > kSurfaceTurnLanes)
    throw Error(where + ".phi_max", fmt::format("phi_max = {:.6g} needs {} turns; the surface "
                                                "unit evaluates at most {}", phi_max, lanes,
                                                kSurfaceTurnLanes));
  const double e = kTwoPi * static_cast<double>(d.end_angle) / static_cast<double>(turn);
  d.end_cos = quantize(std::cos(e), p.surf_const_frac(), p.surf_const_frac() + 2, where, "cos(phi_max)");
  d.end_sin = quantize(std::sin(e), p.surf_const_frac(), p.surf_const_frac() + 2, where, "sin(phi_max)");
}

// A block-floating-point constant with a right shift (s ≥ 0), or throw naming `what`.
ScaledConst right_shift_const(double v, int mant_w, const std::string& where, const char* what) {
  const ScaledConst c = scaled_const(v, mant_w);
  if (c.s < 0)
    throw Error(where, fmt::format("{} = {:.6g} is too large for the surface constants (at most "
                                   "2^{})", what, v, mant_w - 3));
  return c;
}

}  // namespace

ScaledConst scaled_const(double v, int mant_w) {
  if (v == 0.0) return {};
  int e = 0;
  std::frexp(v, &e);  // |v| ∈ [2^(e-1), 2^e)
  ScaledConst c;
  c.s = mant_w - 2 - e;  // |v|·2^s ∈ [2^(MW-3), 2^(MW-2)): a signed MW-bit mantissa
  c.m = static_cast<i64>(std::llround(std::ldexp(v, c.s)));
  return c;
}

SurfaceDesc quantize_surface(const scene::CompiledSurface& cs, const Normalization& norm,
                             const HwParams& p, const std::string& where) {
  const scene::Surface& su = cs.surface;
  const scene::SurfaceParams& q = su.p;
  const int LW = p.surf_w, KF = p.surf_const_frac(), MW = p.surf_mant_w();
  SurfaceDesc d;
  d.type = su.type;
  d.primitive = cs.primitive;

  // Bounding sphere, grown so that the quantised frame (origin within ½ LSB, M within a relative
  // 2^-(MW-2)) still keeps the whole surface inside: a relative 2^-(MW-4) and 4 LSB.
  SegmentDesc& b = d.bound;
  b.primitive = cs.primitive;
  b.c0 = norm.position(cs.centre);
  if (cs.radius * norm.scale < kMinSurfaceLsb)
    throw Error(where, fmt::format("the surface quantises to a bounding radius of {:.3g} LSB "
                                   "(minimum {}): coord_w = {} is too small to hold this scene",
                                   cs.radius * norm.scale, kMinSurfaceLsb, p.coord_w));
  const double R = cs.radius * norm.scale * (1.0 + std::ldexp(1.0, -(MW - 4))) + 4.0;
  b.R2 = static_cast<i128>(std::ceil(R * R));
  b.inv_s = p.t_frac;  // d = 0: the sphere unit's α = β = 0, no shift

  // Local scale: the local box (bounding sphere around it) fills at most 2^(LW-2) llsb, leaving
  // one bit of headroom for points the world rounding puts a little outside.
  const Vec3& lc = cs.local_centre;
  const double extent =
      std::max({std::fabs(lc.x), std::fabs(lc.y), std::fabs(lc.z)}) + cs.local_radius;
  if (!(extent > 0.0) || !std::isfinite(extent))
    throw Error(where, "degenerate surface: its local bounding sphere is empty");
  int F = static_cast<int>(std::floor(std::log2(std::ldexp(1.0, LW - 2) / extent)));
  while (std::ldexp(extent, F) > std::ldexp(1.0, LW - 2)) --F;
  while (std::ldexp(extent, F + 1) <= std::ldexp(1.0, LW - 2)) ++F;
  d.local_frac = F;

  // World LSB → llsb: M = to_local · 2^F / S, one block exponent for the nine entries.
  d.origin = norm.position(su.position);
  double mmax = 0.0;
  for (double v : cs.to_local.m) mmax = std::max(mmax, std::fabs(v));
  const double mscale = std::ldexp(1.0, F) / norm.scale;
  int e = 0;
  std::frexp(mmax * mscale, &e);
  d.to_local_s = MW - 2 - e;  // max |M|·2^s ∈ [2^(MW-3), 2^(MW-2)]: signed MW-bit entries
  for (int k = 0; k < 9; ++k)
    d.to_local[k] = static_cast<i64>(std::llround(std::ldexp(cs.to_local.m[k] * mscale, d.to_local_s)));

  const auto llsb = [&](double v, const char* what) { return quantize(v, F, LW, where, what); };
  const auto unit = [&](double v, const char* what) { return unit_scale(v, p, where, what); };
  switch (su.type) {
    case SurfaceType::kEllipsoid: {
      const double m = std::min({q.a, q.b, q.c});
      d.sx = unit(m / q.a, "min(a,b,c)/a");
      d.sy = unit(m / q.b, "min(a,b,c)/b");
      d.sz = unit(m / q.c, "min(a,b,c)/c");
      d.r2 = squared_threshold(m, F);
      d.y_min = llsb(q.y_min, "y_min");
      d.y_max = llsb(q.y_max, "y_max");
      break;
    }
    case SurfaceType::kReliefEllipsoid: {
      const double kmax = q.d + std::fabs(q.e);
      const double m = std::min({q.a * kmax, q.b, q.c * kmax});
      d.sx = unit(m / (q.a * kmax), "min/(a·(d+|e|))");
      d.sy = unit(m / q.b, "min/b");
      d.sz = unit(m / (q.c * kmax), "min/(c·(d+|e|))");
      d.r2 = squared_threshold(m, F);
      d.kd = quantize(q.d / kmax, KF, KF + 2, where, "d/(d+|e|)");
      d.ke2 = quantize(q.e / (2.0 * kmax), KF, KF + 2, where, "e/(2(d+|e|))");
      d.y_angle = right_shift_const(9.0 / kTwoPi * std::ldexp(1.0, p.angle_w - F), MW, where, "9y");
      d.y_min = llsb(q.y_min, "y_min");
      d.y_max = llsb(q.y_max, "y_max");
      break;
    }
    case SurfaceType::kSpiral: {
      const double m = std::min(q.b, q.c);
      d.sx = unit(m / q.c, "min(b,c)/c");
      d.sy = unit(m / q.b, "min(b,c)/b");
      d.r2 = squared_threshold(m, F);
      d.rho0 = llsb(q.R, "R");
      d.a_turn = quantize(kTwoPi * q.a, F, LW + kTurnConstExtra, where, "2π·a");
      d.k_turn = quantize(kTwoPi * q.k, F, LW + kTurnConstExtra, where, "2π·k");
      azimuth_range(d, q.phi_max, p, where);
      break;
    }
    case SurfaceType::kSnail:
      d.a_turn = quantize(kTwoPi * q.a, F, LW + kTurnConstExtra, where, "2π·a");
      azimuth_range(d, q.phi_max, p, where);
      break;
    case SurfaceType::kRocket:
      d.rocket_a = llsb(q.a, "a");
      d.rocket_b = llsb(q.b, "b");
      d.fin = right_shift_const(q.d / q.c, MW, where, "d/c");
      d.cone = right_shift_const(q.a / q.e, MW, where, "a/e");
      d.y_min = llsb(-q.c, "-c");
      d.y_max = llsb(q.b + q.e, "b+e");
      break;
  }
  return d;
}

}  // namespace rpu::ref
