// Twin of rtl/surface/rpu_indicator.v
#include "model/surface/rpu_indicator.h"

#include "model/surface/surface_descriptors.h"

namespace rpu::ref {

using fixed::truncate;
using scene::SurfaceType;

namespace {

constexpr int G = HwParams::kSurfGuard;

// x · k for a Q(1.KF) scale k, floored to G guard bits below the llsb (exact product, one floor).
i128 scaled(const HwParams& p, i128 x, i64 k) { return truncate(x * k, p.surf_const_frac() - G); }

// A CORDIC input: saturated to |v| ≤ 2^(w-2) (the unit's range; w − 1 signed bits).
i64 cordic_in(const CordicConfig& c, i128 v, Overflow& ovf) {
  return static_cast<i64>(fixed::saturate(v, c.w - 1, ovf));
}

i128 sq(i128 v) { return v * v; }

}  // namespace

CordicConfig surface_cordic(const HwParams& p) {
  CordicConfig c;
  c.w = p.surf_cordic_w();
  c.aw = p.angle_w;
  c.iters = p.angle_w;
  return c;
}

i64 unwrap_azimuth(std::uint64_t psi, bool x_negative, int aw) {
  const i64 turn = i64{1} << aw, quarter = turn >> 2;
  const i64 a = static_cast<i64>(psi);
  if (!x_negative && a >= 3 * quarter) return a - turn;
  if (x_negative && a < quarter) return a + turn;
  return a;
}

bool indicator_unit(const HwParams& p, const SurfaceDesc& s, const WVec3& l, bool x_negative,
                    bool last_turn, Overflow& ovf, IndicatorTrace* trace) {
  const CordicConfig cc = surface_cordic(p);
  const int aw = p.angle_w, KF = p.surf_const_frac();
  const std::uint64_t mask = full_turn(aw) - 1;
  IndicatorTrace t;
  bool inside = false;
  switch (s.type) {
    case SurfaceType::kEllipsoid: {
      // (x·sx)² + (y·sy)² + (z·sz)² < r2, all in (llsb·2^G)², exact after the three floors.
      t.lhs = sq(scaled(p, l.x, s.sx)) + sq(scaled(p, l.y, s.sy)) + sq(scaled(p, l.z, s.sz));
      t.rhs = s.r2;
      inside = t.lhs < t.rhs;
      break;
    }
    case SurfaceType::kReliefEllipsoid: {
      const i128 xs = scaled(p, l.x, s.sx), ys = scaled(p, l.y, s.sy), zs = scaled(p, l.z, s.sz);
      const i128 d2 = s.r2 - sq(ys);  // s²·m², (llsb·2^G)²
      // φ = atan2(x/a, z/c): the scaled coordinates have the same ratio.
      const CordicPolar pol = cordic_vectoring(cc, cordic_in(cc, zs, ovf), cordic_in(cc, xs, ovf));
      t.angle = pol.angle;
      // 10φ wraps (an integer multiple of a binary angle); 9y from the per-surface constant.
      const std::uint64_t a10 = (10 * pol.angle) & mask;
      const auto a9 = static_cast<std::uint64_t>(const_product(l.y, s.y_angle, 0)) & mask;
      // e'·sin 10φ·cos 9y = (e'/2)·(sin(10φ + 9y) + sin(10φ − 9y)): two rotations of (e'/2, 0).
      const i64 y1 = cordic_rotation(cc, s.ke2, 0, (a10 + a9) & mask).y;
      const i64 y2 = cordic_rotation(cc, s.ke2, 0, (a10 - a9) & mask).y;
      const i128 k = s.kd + i128{y1} + y2;   // k' = k/kmax, Q(1.KF)
      const i128 k2 = truncate(k * k, KF);   // k'², Q(1.KF), floor
      t.lhs = sq(xs) + sq(zs);
      t.rhs = truncate(k2 * d2, KF);         // k'²·s²·m², floor
      inside = d2 > 0 && t.lhs < t.rhs;
      break;
    }
    case SurfaceType::kSpiral:
    case SurfaceType::kSnail: {
      const CordicPolar pol = cordic_vectoring(cc, cordic_in(cc, l.z, ovf), cordic_in(cc, l.x, ovf));
      t.angle = pol.angle;
      t.rho = pol.mag;
      const i64 psi = unwrap_azimuth(pol.angle, x_negative, aw);
      const int turns = s.full_turns + (last_turn ? 1 : 0);
      const std::uint64_t a4 = (4 * pol.angle) & mask;  // 4φ_m ≡ 4ψ (mod one turn)
      const i128 r0 = truncate(i128{s.a_turn} * psi, aw);  // a·ψ, llsb (snail)
      // Spiral: the section rotation is linear and its angle 4φ_m ≡ 4ψ is the same in every
      // lane, so two rotations serve all lanes: of the first turn's offset (D0, E0) and of the
      // per-turn step (a_turn, k_turn); lane m is their difference, m steps on, scaled exactly
      // and floored once. The step's saturation matters only with a second turn enabled.
      i128 pu0 = 0, pw0 = 0, pua = 0, pwa = 0;
      if (s.type == SurfaceType::kSpiral && turns > 0) {
        Overflow o0, o1;
        const i128 d0 = t.rho - s.rho0 - r0;                         // ρ − ρ_a of turn 0
        const i128 e0 = l.y - truncate(i128{s.k_turn} * psi, aw);   // y − y_a of turn 0
        const CordicXY q0 = cordic_rotation(cc, cordic_in(cc, d0, o0), cordic_in(cc, e0, o0), a4);
        const CordicXY qa = cordic_rotation(cc, cordic_in(cc, s.a_turn, o1),
                                            cordic_in(cc, s.k_turn, o1), a4);
        if (o0.flag || (turns > 1 && o1.flag)) ovf.flag = true;
        pu0 = i128{q0.x} * s.sx;
        pw0 = i128{q0.y} * s.sy;
        pua = i128{qa.x} * s.sx;
        pwa = i128{qa.y} * s.sy;
      }
      for (int m = 0; m < turns; ++m) {
        t.turn_enable |= 1u << m;
        bool in = false;
        if (s.type == SurfaceType::kSpiral) {
          // The offset of turn m, (ρ − ρ_a, y − y_a) = (D0, E0) − m·(a_turn, k_turn), rotated by
          // 4φ_m into the section's axes (u, w) and scaled: the ellipse (u/c)² + (w/b)² < 1 as
          // (u·m/c)² + (w·m/b)² < m².
          const i128 su = truncate(pu0 - m * pua, KF - G), sw = truncate(pw0 - m * pwa, KF - G);
          in = sq(su) + sq(sw) < s.r2;
        } else {
          // Section radius r_m = aφ_m = r0 + m·2πa, axis distance R_m = (2m + 1)·r0 + m²·2πa
          // (eq 6 summed), the circle (ρ − R_m)² + y² < r_m², exact.
          const i128 rm = r0 + i128{m} * s.a_turn;
          const i128 Rm = (2 * m + 1) * r0 + i128{m} * m * s.a_turn;
          in = sq(t.rho - Rm) + sq(l.y) < sq(rm);
        }
        if (in) t.turn_inside |= 1u << m;
      }
      inside = t.turn_inside != 0;
      break;
    }
    case SurfaceType::kRocket: {
      const CordicPolar pol = cordic_vectoring(cc, cordic_in(cc, l.z, ovf), cordic_in(cc, l.x, ovf));
      t.angle = pol.angle;
      t.rho = pol.mag;
      i128 r = s.rocket_a;  // cylinder, 0 ≤ y ≤ b
      if (l.y <= 0) {
        // Fins: a + (sin 5ψ − 1)·Y with Y = y·d/c: Y·sin 5ψ from a rotation of (Y, 0).
        const i128 Y = const_product(l.y, s.fin, 0);
        const i64 ys = cordic_rotation(cc, cordic_in(cc, Y, ovf), 0, (5 * pol.angle) & mask).y;
        r = s.rocket_a - Y + ys;
      } else if (l.y > s.rocket_b) {
        r = s.rocket_a - const_product(l.y - s.rocket_b, s.cone, 0);  // cone
      }
      t.lhs = t.rho;
      t.rhs = r;
      inside = t.rho < r;
      break;
    }
  }
  if (trace) *trace = t;
  return inside;
}

}  // namespace rpu::ref
