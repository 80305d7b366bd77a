// The refiners of docs/algorithms.md §4 (seed 003), eqs 4, 9 and 10–13, and plain Newton.
#include "patch/refiners.h"

#include <algorithm>
#include <cmath>

namespace rpu::patch {
namespace {

constexpr double kInverseGoldenRatio = 0.6180339887498949;  // 1/φ, eq 9 step control

double clamp01(double t) { return t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t); }

// The parameter domain of one patch: [0, 1]², clamped, or wrapped around in a closed direction.
struct Domain {
  bool wrap_u, wrap_v;
  explicit Domain(const PatchSurface& s) : wrap_u(s.closed_u()), wrap_v(s.closed_v()) {}
  static double wrap(double t) { return t - std::floor(t); }
  double u(double t) const { return wrap_u ? wrap(t) : clamp01(t); }
  double v(double t) const { return wrap_v ? wrap(t) : clamp01(t); }
  bool on_boundary(double a, double b) const {
    return (!wrap_u && (a == 0.0 || a == 1.0)) || (!wrap_v && (b == 0.0 || b == 1.0));
  }
};

// Convergence: the point p is within `tolerance_pixels` of a pixel of the ray, the pixel taken at
// p's own depth c (a start behind the eye, c <= 0, has not converged: Martin's leaf centres, a
// map start across the eye plane; the iteration goes on from there).
bool converged(const RayFrame& ray, const RefineOptions& o, const Vec3& p, double g) {
  const double depth = ray.depth(p);
  if (!(depth > 0.0)) return false;
  const double tol = o.tolerance_pixels * ray.pixel_angle * depth;
  return g < tol * tol;
}

// Residual (S_x, S_y) and its Jacobian in the ray frame.
struct Linearised {
  double x, y;            // S_x, S_y
  double xu, xv, yu, yv;  // ∂S_x/∂u, ∂S_x/∂v, ∂S_y/∂u, ∂S_y/∂v
  double g() const { return x * x + y * y; }
};

Linearised linearise(const RayFrame& ray, const SurfacePoint& sp) {
  return {ray.sx(sp.p),      ray.sy(sp.p),      dot(ray.e1, sp.du),
          dot(ray.e1, sp.dv), dot(ray.e2, sp.du), dot(ray.e2, sp.dv)};
}

RefineResult finish(RefineResult r, RefineStatus status, const RayFrame& ray, const Vec3& p,
                    double g) {
  r.status = status;
  r.depth = ray.depth(p);
  r.distance = std::sqrt(g);
  return r;
}

RefineStatus no_progress(const Domain& d, double u, double v) {
  return d.on_boundary(u, v) ? RefineStatus::kLeftDomain : RefineStatus::kStalled;
}

double det3(double a, double b, double c, double d, double e, double f, double g, double h,
            double i) {
  return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
}

}  // namespace

// Eq 4: (u, v)_{i+1} = (u, v)_i − h·∇g(u_i, v_i). With the residual r = (S_x, S_y) and its
// Jacobian J, ∇g = 2·Jᵀr and ∇²g ≈ 2·JᵀJ; h = 1 / (2·λ_max(JᵀJ)) at the start is the largest
// fixed step for which the descent is stable on the linearised problem. A step that would
// increase g is refused and h halved (g never increases).
RefineResult gradient_descent(const PatchSurface& s, const RayFrame& ray, double u0, double v0,
                              const RefineOptions& o) {
  RefineResult r;
  const Domain dom(s);
  r.u = dom.u(u0), r.v = dom.v(v0);
  SurfacePoint sp = s.evaluate(r.u, r.v);
  r.evaluations = 1;
  Linearised l = linearise(ray, sp);
  double g = l.g();
  if (converged(ray, o, sp.p, g)) return finish(r, RefineStatus::kConverged, ray, sp.p, g);
  const double a = l.xu * l.xu + l.yu * l.yu, b = l.xu * l.xv + l.yu * l.yv,
               c = l.xv * l.xv + l.yv * l.yv;
  const double lambda_max = 0.5 * (a + c) + std::sqrt(0.25 * (a - c) * (a - c) + b * b);
  if (!(lambda_max > 0.0) || !std::isfinite(lambda_max))
    return finish(r, RefineStatus::kSingular, ray, sp.p, g);
  double h = 0.5 / lambda_max;
  while (r.iterations < o.max_iterations && r.evaluations < o.max_evaluations) {
    ++r.iterations;
    const double gu = 2.0 * (l.x * l.xu + l.y * l.yu), gv = 2.0 * (l.x * l.xv + l.y * l.yv);
    const double nu = dom.u(r.u - h * gu), nv = dom.v(r.v - h * gv);
    if (nu == r.u && nv == r.v) return finish(r, no_progress(dom, r.u, r.v), ray, sp.p, g);
    const SurfacePoint next = s.evaluate(nu, nv);
    ++r.evaluations;
    const Linearised ln = linearise(ray, next);
    if (!(ln.g() < g)) {
      h *= 0.5;
      continue;
    }
    r.u = nu, r.v = nv, sp = next, l = ln, g = ln.g();
    if (converged(ray, o, sp.p, g)) return finish(r, RefineStatus::kConverged, ray, sp.p, g);
  }
  return finish(r, RefineStatus::kIterationLimit, ray, sp.p, g);
}

// Eq 9, steps 1–4: the direction (Δu, Δv) = ∇g/|∇g| is kept while g decreases, each step a
// point evaluation only; when a step would increase g, h ← h/φ and the direction is recomputed
// at the current point (an evaluation with derivatives; skipped when no step was taken since
// the last one, the direction being the same). The first h is the linearised line minimum
// along the first direction.
RefineResult steepest_descent(const PatchSurface& s, const RayFrame& ray, double u0, double v0,
                              const RefineOptions& o) {
  RefineResult r;
  const Domain dom(s);
  r.u = dom.u(u0), r.v = dom.v(v0);
  const SurfacePoint sp = s.evaluate(r.u, r.v);
  r.evaluations = 1;
  Linearised l = linearise(ray, sp);
  Vec3 p = sp.p;
  double g = l.g();
  if (converged(ray, o, p, g)) return finish(r, RefineStatus::kConverged, ray, p, g);
  // d = Jᵀr = ∇g/2; the linearised line minimum of g along −d is at −(rᵀJd / |Jd|²)·d.
  double du = l.x * l.xu + l.y * l.yu, dv = l.x * l.xv + l.y * l.yv;
  double dn = std::hypot(du, dv);
  if (!(dn > 0.0) || !std::isfinite(dn)) return finish(r, RefineStatus::kSingular, ray, p, g);
  const double jdx = l.xu * du + l.xv * dv, jdy = l.yu * du + l.yv * dv;
  double h = dn * (l.x * jdx + l.y * jdy) / (jdx * jdx + jdy * jdy);
  du /= dn, dv /= dn;
  r.iterations = 1;  // directions computed
  bool moved = false;
  while (r.evaluations < o.max_evaluations) {
    const double nu = dom.u(r.u - h * du), nv = dom.v(r.v - h * dv);
    double gn = g;
    Vec3 pn = p;
    if (nu != r.u || nv != r.v) {
      pn = s.point(nu, nv);
      ++r.evaluations;
      gn = ray.g(pn);
    }
    if (gn < g) {  // step 3: keep the direction
      r.u = nu, r.v = nv, p = pn, g = gn, moved = true;
      if (converged(ray, o, p, g)) return finish(r, RefineStatus::kConverged, ray, p, g);
      continue;
    }
    // Step 4: shrink the step by the inverse golden ratio, recompute the direction (step 1).
    h *= kInverseGoldenRatio;
    if (h < 1e-15) return finish(r, no_progress(dom, r.u, r.v), ray, p, g);
    if (!moved) continue;
    if (r.iterations >= o.max_iterations) break;
    const SurfacePoint e = s.evaluate(r.u, r.v);
    ++r.evaluations;
    ++r.iterations;
    l = linearise(ray, e);
    du = l.x * l.xu + l.y * l.yu, dv = l.x * l.xv + l.y * l.yv;
    dn = std::hypot(du, dv);
    if (!(dn > 0.0)) return finish(r, no_progress(dom, r.u, r.v), ray, p, g);
    if (o.steepest_restart_step) {
      const double jx = l.xu * du + l.xv * dv, jy = l.yu * du + l.yv * dv;
      h = dn * (l.x * jx + l.y * jy) / (jx * jx + jy * jy);
    }
    du /= dn, dv /= dn;
    moved = false;
  }
  return finish(r, RefineStatus::kIterationLimit, ray, p, g);
}

// Eqs 10–13: the homogeneous surface (w·x, w·y, w·z, w) projected into the ray frame gives
// x*(u, v) = e1·(H − w·eye), y*(u, v) = e2·(H − w·eye) and w(u, v); the ray is the point
// (x_R, y_R) = (0, 0) of the projection plane (eq 10). One step (eq 11):
//   (u, v) += (w / M)·(M_u, M_v),  M = det[X, X_u, X_v]  (eq 12),
//   M_u = det[X, R, X_v],  M_v = det[X, X_u, R]  (eq 13),  X = (x*, y*, w), R = (x_R, y_R, 1):
// Cramer's rule for α·X + X_u·Δu + X_v·Δv = R, with α = 1/w at the root.
RefineResult newton_cramer(const PatchSurface& s, const RayFrame& ray, double u0, double v0,
                           const RefineOptions& o) {
  RefineResult r;
  const Domain dom(s);
  r.u = dom.u(u0), r.v = dom.v(v0);
  const double ex = dot(ray.e1, ray.eye), ey = dot(ray.e2, ray.eye);
  const Vec3& a = ray.e1;
  const Vec3& b = ray.e2;
  constexpr double xr = 0.0, yr = 0.0;  // the ray's point in the projection plane
  while (true) {
    const HomogeneousPoint h = s.homogeneous(r.u, r.v);
    ++r.evaluations;
    const double xs = a.x * h.hx + a.y * h.hy + a.z * h.hz - ex * h.w;
    const double ys = b.x * h.hx + b.y * h.hy + b.z * h.hz - ey * h.w;
    const double g = (xs * xs + ys * ys) / (h.w * h.w);
    const Vec3 p = Vec3{h.hx, h.hy, h.hz} / h.w;
    if (converged(ray, o, p, g)) return finish(r, RefineStatus::kConverged, ray, p, g);
    if (r.iterations >= o.max_newton_iterations)
      return finish(r, RefineStatus::kIterationLimit, ray, p, g);
    ++r.iterations;
    const double xs_u = a.x * h.hx_u + a.y * h.hy_u + a.z * h.hz_u - ex * h.w_u;
    const double xs_v = a.x * h.hx_v + a.y * h.hy_v + a.z * h.hz_v - ex * h.w_v;
    const double ys_u = b.x * h.hx_u + b.y * h.hy_u + b.z * h.hz_u - ey * h.w_u;
    const double ys_v = b.x * h.hx_v + b.y * h.hy_v + b.z * h.hz_v - ey * h.w_v;
    const double m = det3(xs, xs_u, xs_v, ys, ys_u, ys_v, h.w, h.w_u, h.w_v);     // eq 12
    const double m_u = det3(xs, xr, xs_v, ys, yr, ys_v, h.w, 1.0, h.w_v);         // eq 13
    const double m_v = det3(xs, xs_u, xr, ys, ys_u, yr, h.w, h.w_u, 1.0);
    if (m == 0.0 || !std::isfinite(m)) return finish(r, RefineStatus::kSingular, ray, p, g);
    const double nu = dom.u(r.u + h.w * m_u / m), nv = dom.v(r.v + h.w * m_v / m);  // eq 11
    if (nu == r.u && nv == r.v) return finish(r, no_progress(dom, r.u, r.v), ray, p, g);
    r.u = nu, r.v = nv;
  }
}

// Newton on F(u, v) = (S_x, S_y): J·Δ = −F by Cramer's rule on the 2×2 Jacobian of the
// Cartesian (for NURBS: rational, quotient-rule) derivatives. Martin et al. 2000 iterate this
// with the ray as two planes, which is the same pair of equations.
RefineResult newton(const PatchSurface& s, const RayFrame& ray, double u0, double v0,
                    const RefineOptions& o) {
  RefineResult r;
  const Domain dom(s);
  r.u = dom.u(u0), r.v = dom.v(v0);
  while (true) {
    const SurfacePoint sp = s.evaluate(r.u, r.v);
    ++r.evaluations;
    const Linearised l = linearise(ray, sp);
    const double g = l.g();
    if (converged(ray, o, sp.p, g)) return finish(r, RefineStatus::kConverged, ray, sp.p, g);
    if (r.iterations >= o.max_newton_iterations)
      return finish(r, RefineStatus::kIterationLimit, ray, sp.p, g);
    ++r.iterations;
    const double det = l.xu * l.yv - l.xv * l.yu;
    if (det == 0.0 || !std::isfinite(det)) return finish(r, RefineStatus::kSingular, ray, sp.p, g);
    const double du = -(l.x * l.yv - l.xv * l.y) / det, dv = -(l.xu * l.y - l.x * l.yu) / det;
    const double nu = dom.u(r.u + du), nv = dom.v(r.v + dv);
    if (nu == r.u && nv == r.v) return finish(r, no_progress(dom, r.u, r.v), ray, sp.p, g);
    r.u = nu, r.v = nv;
  }
}

RefineResult refine(Refiner which, const PatchSurface& s, const RayFrame& ray, double u0,
                    double v0, const RefineOptions& o) {
  switch (which) {
    case Refiner::kGradientDescent: return gradient_descent(s, ray, u0, v0, o);
    case Refiner::kSteepestDescent: return steepest_descent(s, ray, u0, v0, o);
    case Refiner::kNewtonCramer: return newton_cramer(s, ray, u0, v0, o);
    case Refiner::kNewton: return newton(s, ray, u0, v0, o);
  }
  return newton(s, ray, u0, v0, o);
}

const char* refiner_name(Refiner r) {
  switch (r) {
    case Refiner::kGradientDescent: return "gradient descent (eq 4)";
    case Refiner::kSteepestDescent: return "steepest descent, golden-ratio step (eq 9)";
    case Refiner::kNewtonCramer: return "Newton + Cramer, projected homogeneous form (eqs 10-13)";
    case Refiner::kNewton: return "Newton";
  }
  return "?";
}

}  // namespace rpu::patch
