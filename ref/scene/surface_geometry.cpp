#include "scene/surface_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rpu::scene {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

constexpr double sq(double v) { return v * v; }

// Distance to a whole number of half turns below which the end plane is taken to be the plane
// x = 0 (phi_max = 10π is not a whole number of turns in double arithmetic).
constexpr double kPlaneSnap = 1e-9;

}  // namespace

double azimuth(const Vec3& p) {
  const double psi = std::atan2(p.x, p.z);
  return psi < 0.0 ? psi + kTwoPi : psi;
}

SurfaceGeometry::SurfaceGeometry(SurfaceType type, const SurfaceParams& p) : type_(type), p_(p) {
  if (has_azimuth_range()) {
    double alpha = std::fmod(p.phi_max, kTwoPi);
    if (alpha < 0.0) alpha += kTwoPi;
    if (alpha < kPlaneSnap || kTwoPi - alpha < kPlaneSnap) alpha = 0.0;
    if (std::fabs(alpha - kPi) < kPlaneSnap) alpha = kPi;
    end_azimuth_ = alpha;
  }
}

double SurfaceGeometry::azimuth_on_branch(const Vec3& p, bool x_negative) {
  // A point a rounding error across x = 0 is put on the plane: ψ = 0 or π (x ≥ 0 side), 2π or π
  // (x ≤ 0 side), the limits from within the piece. The |x| passed to atan2 is +0.0 on the plane
  // (atan2(−0, z < 0) would be −π).
  return x_negative ? kTwoPi - std::atan2(p.x < 0.0 ? -p.x : 0.0, p.z)
                    : std::atan2(p.x > 0.0 ? p.x : 0.0, p.z);
}

AzimuthBranch SurfaceGeometry::branch_at(const Vec3& p) const {
  AzimuthBranch b;
  b.x_negative = p.x < 0.0;
  if (has_azimuth_range()) {
    const double psi = azimuth_on_branch(p, b.x_negative);
    // Largest m with ψ + 2πm ≤ phi_max (−1: no turn reaches this azimuth).
    const double m = std::floor((p_.phi_max - psi) / kTwoPi);
    b.top_turn = static_cast<int>(std::clamp(m, -1.0, 1e6));
  }
  return b;
}

double SurfaceGeometry::rocket_radius(double psi, double y) const {
  if (y <= 0.0) return p_.a + (std::sin(5.0 * psi) - 1.0) * y * p_.d / p_.c;  // fins
  if (y <= p_.b) return p_.a;                                                   // cylinder
  return p_.a * (1.0 - (y - p_.b) / p_.e);                                      // cone
}

double SurfaceGeometry::snail_axis(int m, double psi) const {
  const double mm = m;
  return p_.a * (psi + kTwoPi * mm) + 2.0 * p_.a * (kPi * mm * (mm - 1.0) + mm * psi);
}

bool SurfaceGeometry::inside(const Vec3& p, const AzimuthBranch& br) const {
  const SurfaceParams& q = p_;
  switch (type_) {
    case SurfaceType::kEllipsoid:  // eq 2
      return sq(p.x / q.a) + sq(p.y / q.b) + sq(p.z / q.c) < 1.0;
    case SurfaceType::kReliefEllipsoid: {  // eq 3
      const double s2 = 1.0 - sq(p.y / q.b);
      if (!(s2 > 0.0)) return false;
      const double q2 = sq(p.x / q.a) + sq(p.z / q.c);
      // k lies in [d − |e|, d + |e|] (d > |e|): outside the larger bound or inside the smaller
      // one the answer needs no trigonometry (the same comparison, decided early).
      const double k_hi = q.d + std::fabs(q.e), k_lo = q.d - std::fabs(q.e);
      if (!(q2 < k_hi * k_hi * s2)) return false;
      if (k_lo > 0.0 && q2 < k_lo * k_lo * s2) return true;
      const double phi = std::atan2(p.x / q.a, p.z / q.c);
      const double k = q.d + q.e * std::sin(10.0 * phi) * std::cos(9.0 * p.y);
      return q2 < k * k * s2;
    }
    case SurfaceType::kSpiral: {  // eq 5
      const double rho = std::sqrt(p.x * p.x + p.z * p.z);
      const double psi = azimuth_on_branch(p, br.x_negative);
      // The rotation keeps u² + w² = Δρ² + Δy², and inside needs it below max(b, c)²: turns
      // farther away are skipped before the rotation is computed (the same answer but for
      // rounding at the ends of the ellipse's major axis).
      const double reach2 = sq(std::max(std::fabs(q.b), std::fabs(q.c)));
      double c4 = 0.0, s4 = 0.0;
      bool rotation = false;
      for (int m = 0; m <= br.top_turn; ++m) {
        const double phi = psi + kTwoPi * m;
        const double dr = rho - (q.R + q.a * phi), dy = p.y - q.k * phi;
        if (!(dr * dr + dy * dy < reach2)) continue;
        if (!rotation) {
          c4 = std::cos(4.0 * psi), s4 = std::sin(4.0 * psi);  // 4φ_m ≡ 4ψ
          rotation = true;
        }
        const double u = dr * c4 - dy * s4, w = dr * s4 + dy * c4;
        if (sq(u / q.c) + sq(w / q.b) < 1.0) return true;
      }
      return false;
    }
    case SurfaceType::kSnail: {  // eq 6
      // Every section radius a·φ_m is below a·2π(top + 1) (ψ ≤ 2π): above or below that, no
      // turn can hold the point (decided before the azimuth is computed).
      if (!(sq(p.y) < sq(q.a * kTwoPi * (br.top_turn + 1.0)))) return false;
      const double rho = std::sqrt(p.x * p.x + p.z * p.z);
      const double psi = azimuth_on_branch(p, br.x_negative);
      for (int m = 0; m <= br.top_turn; ++m) {
        const double r = q.a * (psi + kTwoPi * m);
        if (sq(rho - snail_axis(m, psi)) + sq(p.y) < r * r) return true;
      }
      return false;
    }
    case SurfaceType::kRocket: {  // eq 7 (sin 5ψ is 2π-periodic: no branch needed)
      const double rho = std::sqrt(p.x * p.x + p.z * p.z);
      if (p.y > 0.0) return rho < rocket_radius(0.0, p.y);  // cylinder, cone: no ψ
      // Fins: sin 5ψ − 1 ∈ [−2, 0] puts r between a and a − 2y·d/c (the formula's own values
      // there); only a radius between the two needs the azimuth.
      const double fin_tip = q.a + (-2.0 * p.y) * q.d / q.c;
      if (rho < std::min(q.a, fin_tip)) return true;
      if (!(rho < std::max(q.a, fin_tip))) return false;
      return rho < rocket_radius(std::atan2(p.x, p.z), p.y);
    }
  }
  return false;
}

double SurfaceGeometry::indicator(const Vec3& p, const AzimuthBranch& br) const {
  const SurfaceParams& q = p_;
  switch (type_) {
    case SurfaceType::kEllipsoid:
      return sq(p.x / q.a) + sq(p.y / q.b) + sq(p.z / q.c) - 1.0;
    case SurfaceType::kReliefEllipsoid: {
      const double s2 = 1.0 - sq(p.y / q.b);
      const double q2 = sq(p.x / q.a) + sq(p.z / q.c);
      const double phi = std::atan2(p.x / q.a, p.z / q.c);
      const double k = q.d + q.e * std::sin(10.0 * phi) * std::cos(9.0 * p.y);
      return q2 - k * k * s2;
    }
    case SurfaceType::kSpiral: {
      const double rho = std::sqrt(p.x * p.x + p.z * p.z);
      const double psi = azimuth_on_branch(p, br.x_negative);
      const double c4 = std::cos(4.0 * psi), s4 = std::sin(4.0 * psi);
      double f = HUGE_VAL;
      for (int m = 0; m <= br.top_turn; ++m) {
        const double phi = psi + kTwoPi * m;
        const double dr = rho - (q.R + q.a * phi), dy = p.y - q.k * phi;
        const double u = dr * c4 - dy * s4, w = dr * s4 + dy * c4;
        f = std::min(f, sq(u / q.c) + sq(w / q.b) - 1.0);
      }
      return f;
    }
    case SurfaceType::kSnail: {
      const double rho = std::sqrt(p.x * p.x + p.z * p.z);
      const double psi = azimuth_on_branch(p, br.x_negative);
      double f = HUGE_VAL;
      for (int m = 0; m <= br.top_turn; ++m)
        f = std::min(f, std::hypot(rho - snail_axis(m, psi), p.y) - q.a * (psi + kTwoPi * m));
      return f;
    }
    case SurfaceType::kRocket:
      return std::sqrt(p.x * p.x + p.z * p.z) - rocket_radius(std::atan2(p.x, p.z), p.y);
  }
  return HUGE_VAL;
}

Vec3 SurfaceGeometry::gradient(const Vec3& p, double h) const {
  const AzimuthBranch b = branch_at(p);
  const auto f = [&](double dx, double dy, double dz) {
    return indicator({p.x + dx, p.y + dy, p.z + dz}, b);
  };
  return Vec3{f(h, 0, 0) - f(-h, 0, 0), f(0, h, 0) - f(0, -h, 0), f(0, 0, h) - f(0, 0, -h)} /
         (2.0 * h);
}

int SurfaceGeometry::pieces(const Vec3& o, const Vec3& d, double t_lo, double t_hi,
                            std::array<SurfacePiece, kMaxSurfacePieces>& out) const {
  if (!(t_hi > t_lo)) return 0;
  if (!has_azimuth_range()) {
    double y_min = p_.y_min, y_max = p_.y_max;
    if (type_ == SurfaceType::kRocket) y_min = -p_.c, y_max = p_.b + p_.e;
    if (d.y == 0.0) {
      if (o.y < y_min || o.y > y_max) return 0;
    } else {
      const double ta = (y_min - o.y) / d.y, tb = (y_max - o.y) / d.y;
      t_lo = std::max(t_lo, std::min(ta, tb));
      t_hi = std::min(t_hi, std::max(ta, tb));
      if (!(t_hi > t_lo)) return 0;
    }
    out[0] = {t_lo, t_hi, {}};
    return 1;
  }
  // Cuts where the ray crosses the plane x = 0 and the end plane n·P = 0 with
  // n = (cos α, 0, −sin α) (it contains the y axis and the direction (sin α, 0, cos α)).
  std::array<double, 2> cuts{};
  int n_cuts = 0;
  const auto cut = [&](const Vec3& n) {
    const double dn = dot(n, d);
    if (dn == 0.0) return;
    const double tc = -dot(n, o) / dn;
    if (tc > t_lo && tc < t_hi) cuts[n_cuts++] = tc;
  };
  cut({1.0, 0.0, 0.0});
  const double alpha = end_azimuth_;
  if (alpha != 0.0 && alpha != kPi) cut({std::cos(alpha), 0.0, -std::sin(alpha)});
  if (n_cuts == 2 && cuts[1] < cuts[0]) std::swap(cuts[0], cuts[1]);
  int count = 0;
  double start = t_lo;
  for (int k = 0; k <= n_cuts; ++k) {
    const double end = k < n_cuts ? cuts[k] : t_hi;
    if (end > start) {
      const Vec3 mid = o + d * (0.5 * (start + end));
      out[count++] = {start, end, branch_at(mid)};
    }
    start = end;
  }
  return count;
}

Vec3 SurfaceGeometry::point(double phi, double v) const {
  const SurfaceParams& q = p_;
  const double sp = std::sin(phi), cp = std::cos(phi);
  switch (type_) {
    case SurfaceType::kEllipsoid: {  // eq 2: (a·s·sin φ, y, c·s·cos φ), s = √(1 − y²/b²)
      const double s = std::sqrt(std::max(0.0, 1.0 - sq(v / q.b)));
      return {q.a * s * sp, v, q.c * s * cp};
    }
    case SurfaceType::kReliefEllipsoid: {  // eq 3: the same scaled by k
      const double s = std::sqrt(std::max(0.0, 1.0 - sq(v / q.b)));
      const double k = q.d + q.e * std::sin(10.0 * phi) * std::cos(9.0 * v);
      return {k * q.a * s * sp, v, k * q.c * s * cp};
    }
    case SurfaceType::kSpiral: {  // eq 5, v = γ
      const double c4 = std::cos(4.0 * phi), s4 = std::sin(4.0 * phi);
      const double radial = q.c * std::cos(v) * c4 + q.b * std::sin(v) * s4;
      const double axial = q.b * std::sin(v) * c4 - q.c * std::cos(v) * s4;
      const double rho = q.R + q.a * phi + radial;
      return {rho * sp, q.k * phi + axial, rho * cp};
    }
    case SurfaceType::kSnail: {  // eq 6, v = γ
      const double turn = std::floor(phi / kTwoPi);
      const double m = phi - kTwoPi * turn;
      const double axis = q.a * phi + 2.0 * q.a * (kPi * turn * (turn - 1.0) + turn * m);
      const double r = q.a * phi;
      const double rho = axis + r * std::cos(v);
      return {rho * sp, r * std::sin(v), rho * cp};
    }
    case SurfaceType::kRocket: {  // eq 7, v = y
      const double r = rocket_radius(phi, v);
      return {r * sp, v, r * cp};
    }
  }
  return {};
}

Vec3 SurfaceGeometry::section_centre(double phi, double v) const {
  const SurfaceParams& q = p_;
  switch (type_) {
    case SurfaceType::kSpiral: {
      const double rho = q.R + q.a * phi;
      return {rho * std::sin(phi), q.k * phi, rho * std::cos(phi)};
    }
    case SurfaceType::kSnail: {
      const double turn = std::floor(phi / kTwoPi);
      const double m = phi - kTwoPi * turn;
      const double axis = q.a * phi + 2.0 * q.a * (kPi * turn * (turn - 1.0) + turn * m);
      return {axis * std::sin(phi), 0.0, axis * std::cos(phi)};
    }
    default:
      return {0.0, v, 0.0};
  }
}

}  // namespace rpu::scene
