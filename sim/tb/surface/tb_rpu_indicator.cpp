// rpu_indicator against its twin rpu::ref::indicator_unit, bit for bit: the inside bit, the
// per-lane turn bits, the angle and ρ of the trace, the overflow bit, the tag and the latency
// (ref::indicator_latency) of every point.
// Descriptors: every surface of scenes/surf_*.json (ellipsoid, relief, spiral, snail, rocket and
// the mix's rotated, scaled relief and rocket) quantised with HwParams (SURF_W, ANGLE_W). Points,
// in llsb of each surface:
//   sphere   uniform in the cube around the local bounding sphere (radius × 1.25);
//   surface  the seed's parametric point R(φ, v) (scene::SurfaceGeometry::point) at random
//            parameters over the whole range, moved by 0..8 llsb or by up to 2^12 llsb in a
//            random direction: both sides of the surface, often within a rounding of it;
//   edge     every combination of 0, ±1 and the LW range's ends per coordinate, the y axis,
//            the plane x = 0, y at 0, ±1, b, b ± 1 (rocket), y·sy at ±b (ellipsoid, relief);
//   range    uniform over the whole LW range;
//   edited   the descriptor's fields drawn at random within the unit's port contract (a_turn,
//            k_turn over the whole LW + 8 bits, mantissas and shifts of the ScaledConsts, kd and
//            ke2 over KF + 2 bits, sx, sy, sz over KF + 1 bits, r2 ≤ 2^(2LW), full_turns and
//            last_turn with full_turns + last_turn ≤ LANES): the widths, saturations and caps;
//   boundary the spiral's lanes with ρ − ρ_a or y − y_a swept over ±2^e (every lane's saturation
//            and clamp edges), and spiral, snail (turns 4 .. LANES − 1 mostly, ρ up to its largest,
//            a_turn of either sign) and relief points with one field (r2, or the snail's |y|)
//            bisected on the twin to the last value on either side of a lane's boundary.
// x_negative and last_turn follow the point's side of x = 0 and of the end plane (the piece's
// branch), 5 % of them flipped. RPU_VECTORS sets the point count (default 40,000).
#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <string>
#include <vector>

#include "Vrpu_indicator.h"
#include "model/surface/rpu_indicator.h"
#include "model/surface/rpu_indicator_latency.h"
#include "tb_surface_common.h"

#ifndef LANES
#define LANES 8
#endif

namespace {

using scene::SurfaceType;

constexpr int kLw = SURF_W, kAw = ANGLE_W, kLanes = LANES;
constexpr int kKf = kLw, kMw = kLw + 2, kTurnW = kLw + 8, kCw = kLw + 6;

enum Source { kSphere, kSurface, kEdge, kRange, kEdited, kBoundary, kSources };
const char* const kSourceName[] = {"sphere", "surface", "edge", "range", "edited", "boundary"};
const char* const* const kTypeName = sim::kSurfaceTypeName;

struct Item {
  int surf;  // index into surfaces
  Source source;
  ref::SurfaceDesc desc;
  ref::WVec3 l;
  bool x_negative, last_turn;
  bool inside, ovf;
  ref::IndicatorTrace trace;
};

using sim::uniform;
i128 clamp_lw(i128 v) {
  return std::clamp<i128>(v, fixed::min_signed(kLw), fixed::max_signed(kLw));
}

// Whether the descriptor fits the unit's ports and contract (the scenes' do; tb checks).
std::string port_problem(const ref::SurfaceDesc& s) {
  const auto fits_s = fixed::fits_signed;
  const auto fits_u = sim::fits_unsigned;
  if (!fits_u(s.sx, kKf + 1) || !fits_u(s.sy, kKf + 1) || !fits_u(s.sz, kKf + 1)) return "sx/sy/sz";
  if (s.r2 < 0 || s.r2 > (i128{1} << (2 * kLw))) return "r2 > 2^(2LW)";
  if (!fits_s(s.kd, kKf + 2) || !fits_s(s.ke2, kKf + 2)) return "kd/ke2";
  if (!fits_s(s.rho0, kLw) || !fits_s(s.rocket_a, kLw) || !fits_s(s.rocket_b, kLw)) return "llsb field";
  if (!fits_s(s.a_turn, kTurnW) || !fits_s(s.k_turn, kTurnW)) return "a_turn/k_turn";
  for (const ref::ScaledConst* c : {&s.y_angle, &s.fin, &s.cone})
    if (!fits_s(c->m, kMw) || c->s < 0 || c->s > 127) return "ScaledConst";
  if (s.full_turns < 0 || s.full_turns > kLanes) return "full_turns";
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_indicator> tb("tb_rpu_indicator", argc, argv);
  auto& rng = tb.rng;
  const ref::HwParams p = sim::tb_params();
  const int kLatency = ref::indicator_latency(p);
  std::printf("tb_rpu_indicator: LW %d, AW %d, %d lanes, latency %d\n", kLw, kAw, kLanes, kLatency);

  std::deque<scene::CompiledScene> scenes;
  const std::vector<sim::SurfCase> surfs = sim::load_surface_cases(p, scenes);
  bool have_type[5] = {};
  for (const sim::SurfCase& s : surfs) {
    if (const std::string problem = port_problem(s.d); !problem.empty())
      return tb.fail("%s: the descriptor does not fit the unit's ports (%s)", s.name.c_str(),
                     problem.c_str());
    have_type[static_cast<int>(s.d.type)] = true;
  }
  for (int t = 0; t < 5; ++t)
    if (!have_type[t]) return tb.fail("no %s among the demo scenes' surfaces", kTypeName[t]);

  const long count = tb.vectors(40000);
  std::vector<Item> items;
  const i128 lw_max = fixed::max_signed(kLw), lw_min = fixed::min_signed(kLw);
  const std::uint64_t turn = std::uint64_t{1} << kAw;

  // A point with the given branch bits (full_turns + last_turn ≤ LANES).
  const auto add_branch = [&](int k, Source src, const ref::SurfaceDesc& d, const ref::WVec3& l,
                              bool xneg, bool last) {
    Item it{k, src, d, l, xneg, last, false, false, {}};
    fixed::Overflow ovf;
    it.inside = ref::indicator_unit(p, d, l, xneg, last, ovf, &it.trace);
    it.ovf = ovf.flag;
    items.push_back(it);
  };
  // The piece's branch of a point: its side of x = 0 and of the end plane, 5 % flipped.
  const auto add = [&](int k, Source src, const ref::SurfaceDesc& d, const ref::WVec3& l) {
    bool xneg = l.x < 0 || (l.x == 0 && rng() % 2);
    const double psi = std::atan2(static_cast<double>(l.x), static_cast<double>(l.z));
    const double psi_turns = (psi < 0 ? psi + 2 * std::numbers::pi : psi) / (2 * std::numbers::pi);
    bool last = d.end_angle != 0 &&
                psi_turns * static_cast<double>(turn) < static_cast<double>(d.end_angle);
    if (rng() % 20 == 0) xneg = !xneg;
    if (rng() % 20 == 0) last = !last;
    if (d.full_turns + (last ? 1 : 0) > kLanes) last = false;
    add_branch(k, src, d, l, xneg, last);
  };

  // Edge points first, for every surface.
  const i128 edge[] = {0, 1, -1, lw_max, lw_min, lw_max - 1, lw_min + 1};
  for (int k = 0; k < static_cast<int>(surfs.size()); ++k) {
    const ref::SurfaceDesc& d = surfs[static_cast<size_t>(k)].d;
    for (i128 x : edge)
      for (i128 y : edge)
        for (i128 z : edge) add(k, kEdge, d, {x, y, z});
    for (int r = 0; r < 64; ++r) {
      const i128 a = sim::random_magnitude(rng, kLw - 1), b = sim::random_magnitude(rng, kLw - 1);
      add(k, kEdge, d, {0, a, b});                        // the plane x = 0
      add(k, kEdge, d, {0, a, 0});                        // the y axis
      add(k, kEdge, d, {static_cast<i128>(rng() % 3) - 1, a, b});
    }
    if (d.type == SurfaceType::kRocket) {
      for (i128 y : {i128{0}, i128{1}, i128{-1}, i128{d.rocket_b}, i128{d.rocket_b} + 1,
                     i128{d.rocket_b} - 1})
        for (int r = 0; r < 32; ++r) {
          const double ang = uniform(rng, 0, 2 * std::numbers::pi);
          const double rad = static_cast<double>(d.rocket_a) * uniform(rng, 0.5, 1.6);
          add(k, kEdge, d, {static_cast<i128>(std::llround(rad * std::sin(ang))), y,
                            static_cast<i128>(std::llround(rad * std::cos(ang)))});
        }
    }
    if (d.type == SurfaceType::kEllipsoid || d.type == SurfaceType::kReliefEllipsoid) {
      // y·sy at ±m (s²m² = r2 − (y·sy)² near 0): y = ±√r2 / sy · 2^(KF−G).
      const double yb = std::sqrt(static_cast<double>(d.r2)) / static_cast<double>(d.sy) *
                        std::ldexp(1.0, kKf - 2);
      for (int sgn : {1, -1})
        for (int off = -3; off <= 3; ++off)
          for (int r = 0; r < 8; ++r)
            add(k, kEdge, d, {sim::random_magnitude(rng, kLw - 4),
                              clamp_lw(sgn * static_cast<i128>(std::llround(yb)) + off),
                              sim::random_magnitude(rng, kLw - 4)});
    }
  }

  while (static_cast<long>(items.size()) < count) {
    const int k = static_cast<int>(rng() % surfs.size());
    const sim::SurfCase& S = surfs[static_cast<size_t>(k)];
    const ref::SurfaceDesc& d = S.d;
    const double f = std::ldexp(1.0, d.local_frac);
    const unsigned kind = static_cast<unsigned>(rng() % 100);
    if (kind < 30) {  // the cube around the bounding sphere
      const double rad = S.cs->local_radius * 1.25;
      const Vec3 c = S.cs->local_centre;
      const auto coord = [&](double cc) {
        return clamp_lw(static_cast<i128>(std::llround((cc + uniform(rng, -rad, rad)) * f)));
      };
      add(k, kSphere, d, {coord(c.x), coord(c.y), coord(c.z)});
    } else if (kind < 85) {  // near the surface
      const Vec3 pt = sim::random_seed_point(S.cs->surface, rng) * f;
      const double spread = rng() % 2 ? 8.0 : std::ldexp(1.0, static_cast<int>(rng() % 13));
      const auto coord = [&](double cc) {
        return clamp_lw(static_cast<i128>(std::llround(cc + uniform(rng, -spread, spread))));
      };
      add(k, kSurface, d, {coord(pt.x), coord(pt.y), coord(pt.z)});
    } else if (kind < 88) {  // anywhere
      add(k, kRange, d, {sim::random_signed(rng, kLw), sim::random_signed(rng, kLw), sim::random_signed(rng, kLw)});
    } else {  // edited descriptor, points of every magnitude
      const ref::SurfaceDesc e = sim::edit_indicator_fields(d, p, kLanes + 1, rng, true);
      add(k, kEdited, e, {sim::random_magnitude(rng, kLw), sim::random_magnitude(rng, kLw),
                          sim::random_magnitude(rng, kLw)});
    }
  }

  // Boundary points (count / 10 more, after the sweeps below): the spiral's and snail's upper turns
  // (lanes 4 .. LANES − 1 three times in four) and the relief, one field bisected on the twin to
  // the last value on either side of a lane's boundary (both are added), so that any change of the
  // lane's sums flips its bit. Spiral, one in three: the point on an axis with turn m's offsets
  // near ±2^e (as in the sweep); else a_turn (either sign), rho0, k_turn, sx, sy redrawn so that
  // every turn fits the LW range, the point on the section's ellipse of turn m, r2 bisected.
  // Snail: a_turn redrawn so that turn m fits (half of them with ρ near its largest, the factors
  // |P_m|, |P_{m+1}| at their largest; one in five negative, with ψ unwrapped below 0: the turns'
  // signs reversed), ρ in turn m's band, |y| bisected. Relief: a point near the surface, half of
  // them with kd and ke2 redrawn over KF + 2 bits, r2 bisected.
  std::vector<int> bsurfs;
  for (int k = 0; k < static_cast<int>(surfs.size()); ++k) {
    const SurfaceType t = surfs[static_cast<size_t>(k)].d.type;
    if (t == SurfaceType::kSpiral || t == SurfaceType::kSnail || t == SurfaceType::kReliefEllipsoid)
      bsurfs.push_back(k);
  }
  const auto bisect = [](i128 lo, i128 hi, const auto& pred) {  // pred(lo) false, pred(hi) true
    while (hi - lo > 1) {
      const i128 mid = lo + (hi - lo) / 2;
      (pred(mid) ? hi : lo) = mid;
    }
    return hi;  // the first value with pred true
  };
  const auto twin_trace = [&](const ref::SurfaceDesc& d, const ref::WVec3& l, bool xneg,
                              bool last) {
    fixed::Overflow o;
    ref::IndicatorTrace t;
    ref::indicator_unit(p, d, l, xneg, last, o, &t);
    return t;
  };
  const i128 r2_max = i128{1} << (2 * kLw);
  const double half = std::ldexp(1.0, kLw - 1);
  // A spiral point on an axis (ψ = ¼ or ¾ turn, the latter with x < 0: 4ψ ≡ 0, so (u, w) =
  // (ρ − ρ_a, y − y_a)), sx = sy = 2^KF (the scaled offsets are 4u, 4w), r2 = 2^(2LW − 8), with
  // the given a_turn and k_turn (no point where they do not fit).
  const auto on_axis = [&](int k, ref::SurfaceDesc d, double rho, double yv, double a, double kt,
                           bool left, bool last) {
    const double tmax = std::ldexp(1.0, kTurnW - 1) - 2;
    if (std::fabs(a) > tmax || std::fabs(kt) > tmax) return;
    d.rho0 = static_cast<std::int64_t>(std::llround(rho));
    d.a_turn = static_cast<std::int64_t>(std::llround(a));
    d.k_turn = static_cast<std::int64_t>(std::llround(kt));
    d.sx = d.sy = std::int64_t{1} << kKf;
    d.r2 = i128{1} << (2 * kLw - 8);
    const i128 rr = static_cast<i128>(std::llround(rho));
    add_branch(k, kBoundary, d, {left ? -rr : rr, static_cast<i128>(std::llround(yv)), 0}, left,
               last);
  };
  // The spiral's lanes at the limits of their offsets (before the random boundary points): the
  // point on an axis at ψ = ¾ turn; a_turn or k_turn set so that turn m's ρ − ρ_a or y − y_a is
  // ±2^e (just above, just below, 1.2×), e = LW − 4 .. LW + 10, the other offset small, with all
  // lanes enabled and with lanes 0 .. m: every lane's saturation of the rotation inputs (and its
  // overflow bit) and clamps of the squares at their edges.
  for (int k = 0; k < static_cast<int>(surfs.size()); ++k) {
    if (surfs[static_cast<size_t>(k)].d.type != SurfaceType::kSpiral) continue;
    for (int m = 0; m < kLanes; ++m)
      for (int e = kLw - 4; e <= kLw + 10; ++e)
        for (int sgn : {1, -1})
          for (int which = 0; which < 2; ++which)
            for (int f = 0; f < 6; ++f) {
              ref::SurfaceDesc d = surfs[static_cast<size_t>(k)].d;
              d.full_turns = f < 3 ? kLanes : m + 1;  // m + 1: the overflow bit is lane m's
              const double frac = f % 3 == 0   ? 1 + uniform(rng, 0, 1.0 / 256)
                                  : f % 3 == 1 ? 1 - uniform(rng, 0, 1.0 / 256)
                                               : 1.2;
              const double big = sgn * std::ldexp(frac, e);
              const double small = uniform(rng, -1, 1) * std::ldexp(1.0, kLw - 9);
              const double du = which == 0 ? big : small, dw = which == 0 ? small : big;
              const double rho = uniform(rng, half / 8, half / 2);
              const double yv = uniform(rng, -half / 4, half / 4);
              const double phi = 0.75 + m;
              on_axis(k, d, rho, yv, -du / phi, (yv - dw) / phi, true, false);
            }
  }
  // The snail's lane-1 product at a perfect square: the point (0, ±y, z0) with a small z0 (ψ ≈ 0),
  // y² in [2^21, 2^22), a_turn bisected so that P_1·P_2 (G_1 = 2r0, G_2 = 2(2r0 + a_turn)) is
  // within 2 of y² (1 or 2 above it when its bit 1 is set, else 0 or 1 below): the bit decided by
  // the product's last bits.
  for (int k = 0; k < static_cast<int>(surfs.size()); ++k) {
    if (surfs[static_cast<size_t>(k)].d.type != SurfaceType::kSnail) continue;
    int added = 0;
    for (i128 z0 = 1; z0 <= 6 && added < 48; ++z0) {
      ref::SurfaceDesc d = surfs[static_cast<size_t>(k)].d;
      d.full_turns = 2;
      const ref::IndicatorTrace t0 = twin_trace(d, {0, 0, z0}, false, false);
      const i128 rho = t0.rho;
      const i128 psi_u = static_cast<i128>(t0.angle) >= (i128{3} << (kAw - 2))
                             ? static_cast<i128>(t0.angle) - (i128{1} << kAw)
                             : static_cast<i128>(t0.angle);
      const auto prod_at = [&](i128 a) {  // −P_1·P_2, or −1 unless of opposite signs
        const i128 num = a * psi_u;
        const i128 r0 = num >= 0 ? num >> kAw : -((-num + (i128{1} << kAw) - 1) >> kAw);
        const i128 p1 = rho - 2 * r0, p2 = rho - 2 * (2 * r0 + a);
        return p1 > 0 && p2 < 0 ? -p1 * p2 : i128{-1};
      };
      for (i128 y = 1449; y < 2048 && added < 48; y += 1 + static_cast<i128>(rng() % 3)) {
        const i128 a_hi = fixed::max_signed(kTurnW - 2);
        if (prod_at(a_hi) < y * y) continue;
        const i128 a0 = bisect(0, a_hi, [&](i128 a) { return prod_at(a) >= y * y; });
        for (i128 a = a0 - 1; a <= a0 + 1; ++a) {
          const i128 pr = prod_at(a), dl = pr - y * y;
          if (pr < 0 || ((pr >> 21) & 1) == 0) continue;
          if (((pr >> 1) & 1) ? (dl != 1 && dl != 2) : (dl != 0 && dl != -1)) continue;
          d.a_turn = static_cast<std::int64_t>(a);
          add_branch(k, kBoundary, d, {0, (rng() % 2 ? y : -y), z0}, false, false);
          ++added;
        }
      }
    }
  }
  const long n_boundary = count / 10;
  const long boundary_end = static_cast<long>(items.size()) + n_boundary;
  while (static_cast<long>(items.size()) < boundary_end) {
    const int k = bsurfs[rng() % bsurfs.size()];
    const sim::SurfCase& S = surfs[static_cast<size_t>(k)];
    ref::SurfaceDesc d = S.d;
    const int m = kLanes > 4 && rng() % 4 != 0 ? 4 + static_cast<int>(rng() % (kLanes - 4))
                                                : static_cast<int>(rng() % kLanes);
    const bool last = rng() % 2;
    const int turns = m + 1 + static_cast<int>(rng() % static_cast<unsigned>(kLanes - m));
    d.full_turns = turns - (last ? 1 : 0);
    const double tt = uniform(rng, 0, 1);
    const double cs = std::cos(2 * std::numbers::pi * tt), sn = std::sin(2 * std::numbers::pi * tt);
    const auto fits = [&](double v) { return std::fabs(v) < half - 2; };
    if (d.type == SurfaceType::kSpiral && rng() % 3 == 0) {
      // The point on an axis (on_axis), a_turn and k_turn chosen so that turn m's scaled offsets
      // are near ±2^e, e = LW − 2 .. LW + 8, or small: the clamps of the squares and the
      // saturation of the rotation inputs on either side of their limits.
      const bool left = rng() % 2;
      const double rho = uniform(rng, half / 8, half / 2), psi_t = left ? 0.75 : 0.25;
      const auto target = [&] {
        if (rng() % 3 == 0) return uniform(rng, -1, 1) * std::ldexp(1.0, kLw - 5);
        const double big = std::ldexp(1.0, kLw - 2 + static_cast<int>(rng() % 11)) +
                           uniform(rng, -1, 1) * std::ldexp(1.0, kLw - 3);
        return rng() % 2 ? big : -big;
      };
      const double phi = psi_t + m, tu = target(), tw = target();
      const double yv = uniform(rng, -half / 4, half / 4);
      on_axis(k, d, rho, yv, -tu / 4 / phi, (yv - tw / 4) / phi, left, last);
    } else if (d.type == SurfaceType::kSpiral) {
      const bool neg = rng() % 4 == 0;
      const double amag = uniform(rng, 0.3, 1.0) * 0.7 * half / (kLanes + 1.5);
      const double rho0 = (neg ? amag * (kLanes + 1.5) : 0) + uniform(rng, 0, half / 8);
      const double a = neg ? -amag : amag, kt = uniform(rng, -1, 1) * half / (4 * (kLanes + 2));
      const double rt = amag * uniform(rng, 0.15, 0.45);
      const i128 sx = (i128{1} << (kKf - 1)) + sim::random_bits(rng, kKf - 1);
      const i128 sy = std::clamp<i128>(static_cast<i128>(static_cast<double>(sx) *
                                                         uniform(rng, 0.6, 1.4)),
                                       1, fixed::max_unsigned(kKf + 1));
      d.rho0 = static_cast<std::int64_t>(rho0);
      d.a_turn = static_cast<std::int64_t>(a);
      d.k_turn = static_cast<std::int64_t>(kt);
      d.sx = static_cast<std::int64_t>(sx);
      d.sy = static_cast<std::int64_t>(sy);
      const double phi = tt + m, alpha = 2 * std::numbers::pi * 4 * tt;
      const double th = uniform(rng, 0, 2 * std::numbers::pi);
      const double u = rt * std::cos(th), w = rt * static_cast<double>(sx) /
                                              static_cast<double>(sy) * std::sin(th);
      const double rho = rho0 + a * phi + u * std::cos(alpha) + w * std::sin(alpha);
      const double y = kt * phi - u * std::sin(alpha) + w * std::cos(alpha);
      const ref::WVec3 l{static_cast<i128>(std::llround(rho * sn)),
                         static_cast<i128>(std::llround(y)),
                         static_cast<i128>(std::llround(rho * cs))};
      if (!fits(rho) || !fits(y)) continue;
      const bool xneg = l.x < 0;
      const auto in_lane = [&](i128 r2) {
        ref::SurfaceDesc e = d;
        e.r2 = r2;
        return ((twin_trace(e, l, xneg, last).turn_inside >> m) & 1) != 0;
      };
      if (!in_lane(r2_max)) continue;
      const i128 r2 = bisect(0, r2_max, in_lane);
      for (const i128 v : {r2, r2 - 1}) {
        d.r2 = v;
        add_branch(k, kBoundary, d, l, xneg, last);
      }
    } else if (d.type == SurfaceType::kSnail) {
      const bool neg = rng() % 5 == 0;
      // Turn m's outer edge G_{m+1} ≤ (m + 1)(m + 2.5)·a_turn up to 1.35 half: |x|, |z| checked.
      const double amag = uniform(rng, 0.3, 1.0) * 1.35 * half / ((m + 1) * (m + 2.5));
      double rho = 0, t_u = tt;
      bool xneg = sn < 0;
      if (!neg && m > 0 && rng() % 2) {
        // ρ near its largest (|x| ≈ |z| ≈ 2^(LW−1)), inside turn m's band: G_m < ρ < G_{m+1},
        // G_j = j(2ψ_u + j − 1)·a_turn: the factors |P_j| at their largest.
        t_u = (1 + 2 * static_cast<int>(rng() % 4)) / 8.0 + uniform(rng, -0.01, 0.01);
        xneg = t_u > 0.5;
        rho = uniform(rng, 0.9, 1.0) * std::sqrt(2.0) * (half - 4) *
              std::min(1 / std::fabs(std::cos(2 * std::numbers::pi * t_u)),
                       1 / std::fabs(std::sin(2 * std::numbers::pi * t_u))) / std::sqrt(2.0);
        const double gm = m * (2 * t_u + m - 1), gm1 = (m + 1) * (2 * t_u + m);
        d.a_turn = static_cast<std::int64_t>(rho / gm * uniform(rng, gm / gm1, 1.0));
      } else if (!neg) {
        const double r0 = amag * tt, rm = r0 + m * amag, big_r = (2 * m + 1) * r0 + m * m * amag;
        rho = big_r + rm * uniform(rng, -1.15, 1.15);
        d.a_turn = static_cast<std::int64_t>(amag);
      } else {  // ψ in the fourth quadrant on the x ≥ 0 branch: ψ_u = ψ − 1 turn < 0
        t_u = uniform(rng, 0.76, 1.0);
        xneg = false;
        rho = uniform(rng, 0, 3.5 * amag * (1 - t_u));
        d.a_turn = -static_cast<std::int64_t>(amag);
      }
      const i128 x = static_cast<i128>(std::llround(rho * std::sin(2 * std::numbers::pi * t_u)));
      const i128 z = static_cast<i128>(std::llround(rho * std::cos(2 * std::numbers::pi * t_u)));
      if (!fits(static_cast<double>(x)) || !fits(static_cast<double>(z))) continue;
      const int bit = neg ? -1 : m;
      const auto out_at = [&](i128 y) {
        const ref::IndicatorTrace t = twin_trace(d, {x, y, z}, xneg, last);
        return bit < 0 ? t.turn_inside == 0 : ((t.turn_inside >> bit) & 1) == 0;
      };
      const i128 ymax = fixed::max_signed(kLw);
      const i128 ysign = rng() % 2 ? 1 : -1;
      if (out_at(0) || !out_at(ymax)) {
        add_branch(k, kBoundary, d, {x, ysign * sim::random_magnitude(rng, kLw - 1), z}, xneg, last);
        continue;
      }
      const i128 y = bisect(0, ymax, out_at);
      for (const i128 v : {y - 1, y}) add_branch(k, kBoundary, d, {x, ysign * v, z}, xneg, last);
    } else {  // relief
      const Vec3 pt = sim::random_seed_point(S.cs->surface, rng) * std::ldexp(1.0, d.local_frac);
      const auto coord = [&](double cc) {
        return clamp_lw(static_cast<i128>(std::llround(cc + uniform(rng, -8, 8))));
      };
      const ref::WVec3 l{coord(pt.x), coord(pt.y), coord(pt.z)};
      if (rng() % 2) {  // k' = kd + y1 + y2 of every bit pattern
        d.kd = static_cast<std::int64_t>(sim::random_magnitude(rng, kKf + 2));
        d.ke2 = static_cast<std::int64_t>(sim::random_magnitude(rng, kKf + 2));
      }
      const auto in_at = [&](i128 r2) {
        ref::SurfaceDesc e = d;
        e.r2 = r2;
        fixed::Overflow o;
        return ref::indicator_unit(p, e, l, false, false, o, nullptr);
      };
      if (!in_at(r2_max)) continue;
      const i128 r2 = bisect(0, r2_max, in_at);
      for (const i128 v : {r2, r2 - 1}) {
        d.r2 = v;
        add_branch(k, kBoundary, d, l, false, false);
      }
    }
  }

  // What the vectors exercise.
  sim::Tally by_src(kSourceName, {"points"});
  sim::Tally by_type(sim::kSurfaceTypeName, {"points", "inside", "outside"});
  sim::Tally rocket({"rocket fins", "rocket cylinder", "rocket cone"}, {"points", "inside"});
  long n_ovf = 0, n_lane_hi = 0, n_d2_neg = 0;
  for (const Item& it : items) {
    by_src.add(it.source, 1);
    by_type.add(static_cast<int>(it.desc.type), 1, it.inside, !it.inside);
    n_ovf += it.ovf;
    n_lane_hi += (it.trace.turn_inside >> 1) != 0;
    if (it.desc.type == SurfaceType::kRocket)
      rocket.add(it.l.y <= 0 ? 0 : it.l.y > it.desc.rocket_b ? 2 : 1, 1, it.inside);
    if (it.desc.type == SurfaceType::kReliefEllipsoid) {
      const i128 ys = fixed::truncate(it.l.y * it.desc.sy, kKf - 2);
      n_d2_neg += ys * ys >= it.desc.r2;
    }
  }
  std::printf("tb_rpu_indicator: %zu points; overflow %ld, a turn above the first holding the "
              "point %ld, relief s²m² ≤ 0 %ld\n", items.size(), n_ovf, n_lane_hi, n_d2_neg);
  by_src.print("per source");
  by_type.print("per surface type");
  rocket.print("per rocket region");
  if (tb.weak(by_type.too_weak({1, 2}, count / 200)) || tb.weak(rocket.too_weak({1}, 1))) return 1;
  if (n_ovf == 0 || n_lane_hi < count / 200 || n_d2_neg == 0)
    return tb.fail("the vectors are too weak (overflow, upper turns or relief s²m² ≤ 0 missing)");

  sim::Stream<Vrpu_indicator, Item> s{.latency = kLatency};
  s.inputs = [&](sim::Inputs& in, Vrpu_indicator& t, const Item& it) {
    in.vec("l", t.l_i, it.l, kLw)("x_negative", t.x_negative_i, it.x_negative, 1);
    in("last_turn", t.last_turn_i, it.last_turn, 1);
    sim::indicator_inputs(in, t, p, it.desc);
  };
  s.outputs = [](sim::Outputs& o, const Vrpu_indicator& t, const Item& it) {
    const ref::IndicatorTrace& w = it.trace;
    o("inside", t.inside_o, it.inside, 1)("turns", t.turn_inside_o, w.turn_inside, kLanes);
    o("angle", t.angle_o, static_cast<i128>(w.angle), kAw)("rho", t.rho_o, w.rho, kCw)("ovf", t.ovf_o, it.ovf, 1);
    o.note("lhs", sim::str(w.lhs)).note("rhs", sim::str(w.rhs)).note("enabled", std::to_string(w.turn_enable));
  };
  s.what = [&](const Item& it) {
    return surfs[static_cast<size_t>(it.surf)].name + " (" + kTypeName[static_cast<int>(it.desc.type)] +
           "), " + kSourceName[it.source] + " point";
  };
  return tb.check(items, s);
}
