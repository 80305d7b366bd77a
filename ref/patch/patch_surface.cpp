// Patch evaluation (docs/algorithms.md §4, seed 003): tensor-product Bernstein (Bézier) and
// B-spline bases with their first derivatives, combined in homogeneous coordinates so NURBS share
// the code.
#include "patch/patch_surface.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace rpu::patch {
namespace {

constexpr int kMaxOrder = kMaxPatchDegree + 1;

double clamp01(double t) { return t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t); }

// Bernstein polynomials B_{i,p}(t) and their derivatives (de Casteljau's triangle of the basis);
// db may be null.
void bernstein_basis(int p, double t, double* b, double* db) {
  // b_{p-1} first, to form the derivative p·(B_{i-1,p-1} − B_{i,p-1}).
  std::array<double, kMaxOrder> lower{};
  const double s = 1.0 - t;
  b[0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    if (j == p) std::copy(b, b + p, lower.begin());
    double saved = 0.0;
    for (int i = 0; i < j; ++i) {
      const double tmp = b[i];
      b[i] = saved + s * tmp;
      saved = t * tmp;
    }
    b[j] = saved;
  }
  if (db == nullptr) return;
  if (p == 0) {
    db[0] = 0.0;
    return;
  }
  for (int i = 0; i <= p; ++i) {
    const double left = i >= 1 ? lower[i - 1] : 0.0;
    const double right = i <= p - 1 ? lower[i] : 0.0;
    db[i] = p * (left - right);
  }
}

}  // namespace

// Knot span index k with knots[k] <= t < knots[k+1] (the last non-empty span for t = 1),
// binary search (Piegl & Tiller A2.1).
int find_knot_span(const std::vector<double>& knots, int degree, int size, double t) {
  if (t >= knots[size]) {
    int k = size - 1;
    while (k > degree && knots[k] >= knots[k + 1]) --k;
    return k;
  }
  if (t <= knots[degree]) {
    int k = degree;
    while (k < size - 1 && knots[k + 1] <= t) ++k;
    return k;
  }
  int lo = degree, hi = size;
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    if (t < knots[mid]) hi = mid; else lo = mid;
  }
  return lo;
}

// The degree+1 non-zero B-spline basis functions N_{span-p..span,p}(t) and their first
// derivatives (dn may be null), by the Cox–de Boor triangle (Piegl & Tiller A2.3 for one
// derivative).
void bspline_basis(const std::vector<double>& knots, int p, int span, double t, double* n,
                   double* dn) {
  double ndu[kMaxOrder][kMaxOrder];
  double left[kMaxOrder], right[kMaxOrder];
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = t - knots[span + 1 - j];
    right[j] = knots[span + j] - t;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];  // knot difference (lower triangle)
      const double tmp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * tmp;
      saved = left[j - r] * tmp;
    }
    ndu[j][j] = saved;
  }
  for (int r = 0; r <= p; ++r) n[r] = ndu[r][p];
  if (dn == nullptr) return;
  if (p == 0) {
    dn[0] = 0.0;
    return;
  }
  for (int r = 0; r <= p; ++r) {
    double d = 0.0;
    if (r >= 1) d += ndu[r - 1][p - 1] / ndu[p][r - 1];
    if (r <= p - 1) d -= ndu[r][p - 1] / ndu[p][r];
    dn[r] = p * d;
  }
}

PatchSurface::PatchSurface(const scene::Patch& patch) : patch_(patch) {
  // A NURBS surface does not change when every weight is multiplied by one factor: the weights
  // are scaled by a power of two (exact) so that the largest is in [1, 2). Weights 1e-200 would
  // otherwise underflow w² in the refiners (docs/patches.md, "Precision").
  if (patch_.type == scene::PatchType::kNurbs && !patch_.weights.empty()) {
    const double largest = *std::max_element(patch_.weights.begin(), patch_.weights.end());
    if (largest > 0.0 && std::isfinite(largest)) {
      const int e = -std::ilogb(largest);
      for (double& w : patch_.weights) w = std::ldexp(w, e);
    }
  }
  const scene::Patch& p_ = patch_;
  assert(patch.degree_u >= 1 && patch.degree_u <= kMaxPatchDegree);
  assert(patch.degree_v >= 1 && patch.degree_v <= kMaxPatchDegree);
  const int count = patch.size_u * patch.size_v;
  assert(static_cast<int>(patch.control_points.size()) == count);
  rational_ = patch.type == scene::PatchType::kNurbs;
  bezier_ = patch.type == scene::PatchType::kBezier;
  const auto normalise = [](const std::vector<double>& k, int p, int n) {
    std::vector<double> out(k.size());
    const double a = k[p], b = k[n];
    for (size_t i = 0; i < k.size(); ++i) out[i] = (k[i] - a) / (b - a);
    // Clamped ends map exactly onto 0 and 1.
    for (int i = 0; i <= p; ++i) out[i] = 0.0, out[out.size() - 1 - i] = 1.0;
    return out;
  };
  if (!bezier_) {
    assert(static_cast<int>(patch.knots_u.size()) == patch.size_u + patch.degree_u + 1);
    assert(static_cast<int>(patch.knots_v.size()) == patch.size_v + patch.degree_v + 1);
    ku_ = normalise(patch.knots_u, patch.degree_u, patch.size_u);
    kv_ = normalise(patch.knots_v, patch.degree_v, patch.size_v);
  }
  hw_.resize(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double w = rational_ ? p_.weights[static_cast<size_t>(i)] : 1.0;
    const Vec3& c = patch.control_points[static_cast<size_t>(i)];
    hw_[static_cast<size_t>(i)] = {c.x * w, c.y * w, c.z * w, w};
  }
  const auto same = [&](int a, int b) { return hw_[static_cast<size_t>(a)] == hw_[static_cast<size_t>(b)]; };
  closed_u_ = closed_v_ = true;
  for (int j = 0; j < patch.size_v; ++j)
    closed_u_ = closed_u_ && same(j, (patch.size_u - 1) * patch.size_v + j);
  for (int i = 0; i < patch.size_u; ++i)
    closed_v_ = closed_v_ && same(i * patch.size_v, i * patch.size_v + patch.size_v - 1);
  // A row collapsed to one point (a pole) is not a seam: closed means a whole edge meets.
  const auto collapsed_row = [&](int i) {
    for (int j = 1; j < patch.size_v; ++j)
      if (!same(i * patch.size_v, i * patch.size_v + j)) return false;
    return true;
  };
  const auto collapsed_column = [&](int j) {
    for (int i = 1; i < patch.size_u; ++i)
      if (!same(j, i * patch.size_v + j)) return false;
    return true;
  };
  closed_u_ = closed_u_ && !collapsed_row(0);
  closed_v_ = closed_v_ && !collapsed_column(0);
}

HomogeneousPoint PatchSurface::homogeneous(double u, double v) const {
  u = clamp01(u);
  v = clamp01(v);
  const int p = patch_.degree_u, q = patch_.degree_v;
  double nu[kMaxOrder], dnu[kMaxOrder], nv[kMaxOrder], dnv[kMaxOrder];
  int su = p, sv = q;  // span: the first control index is span − degree
  if (bezier_) {
    bernstein_basis(p, u, nu, dnu);
    bernstein_basis(q, v, nv, dnv);
  } else {
    su = find_knot_span(ku_, p, patch_.size_u, u);
    sv = find_knot_span(kv_, q, patch_.size_v, v);
    bspline_basis(ku_, p, su, u, nu, dnu);
    bspline_basis(kv_, q, sv, v, nv, dnv);
  }
  HomogeneousPoint h;
  h.w = 0.0;
  const int row0 = su - p, col0 = sv - q;
  for (int i = 0; i <= p; ++i) {
    // Row i: the v-curve of that control row and its v-derivative.
    double cx = 0, cy = 0, cz = 0, cw = 0, cxv = 0, cyv = 0, czv = 0, cwv = 0;
    const std::array<double, 4>* row = &hw_[static_cast<size_t>((row0 + i) * patch_.size_v + col0)];
    for (int j = 0; j <= q; ++j) {
      const auto& c = row[j];
      cx += nv[j] * c[0]; cy += nv[j] * c[1]; cz += nv[j] * c[2]; cw += nv[j] * c[3];
      cxv += dnv[j] * c[0]; cyv += dnv[j] * c[1]; czv += dnv[j] * c[2]; cwv += dnv[j] * c[3];
    }
    h.hx += nu[i] * cx; h.hy += nu[i] * cy; h.hz += nu[i] * cz; h.w += nu[i] * cw;
    h.hx_u += dnu[i] * cx; h.hy_u += dnu[i] * cy; h.hz_u += dnu[i] * cz; h.w_u += dnu[i] * cw;
    h.hx_v += nu[i] * cxv; h.hy_v += nu[i] * cyv; h.hz_v += nu[i] * czv; h.w_v += nu[i] * cwv;
  }
  return h;
}

SurfacePoint PatchSurface::evaluate(double u, double v) const {
  const HomogeneousPoint h = homogeneous(u, v);
  SurfacePoint s;
  if (!rational_) {
    s.p = {h.hx, h.hy, h.hz};
    s.du = {h.hx_u, h.hy_u, h.hz_u};
    s.dv = {h.hx_v, h.hy_v, h.hz_v};
    return s;
  }
  // S = H / w, S_u = (H_u − w_u·S) / w (quotient rule).
  const double inv = 1.0 / h.w;
  s.p = Vec3{h.hx, h.hy, h.hz} * inv;
  s.du = (Vec3{h.hx_u, h.hy_u, h.hz_u} - s.p * h.w_u) * inv;
  s.dv = (Vec3{h.hx_v, h.hy_v, h.hz_v} - s.p * h.w_v) * inv;
  return s;
}

// The point alone: the basis functions without their derivatives (the steepest-descent refiner
// evaluates g = S_x² + S_y² many times per direction, eq 9).
Vec3 PatchSurface::point(double u, double v) const {
  u = clamp01(u);
  v = clamp01(v);
  const int p = patch_.degree_u, q = patch_.degree_v;
  double nu[kMaxOrder], nv[kMaxOrder];
  int su = p, sv = q;
  if (bezier_) {
    bernstein_basis(p, u, nu, nullptr);
    bernstein_basis(q, v, nv, nullptr);
  } else {
    su = find_knot_span(ku_, p, patch_.size_u, u);
    sv = find_knot_span(kv_, q, patch_.size_v, v);
    bspline_basis(ku_, p, su, u, nu, nullptr);
    bspline_basis(kv_, q, sv, v, nv, nullptr);
  }
  double x = 0, y = 0, z = 0, w = 0;
  const int row0 = su - p, col0 = sv - q;
  for (int i = 0; i <= p; ++i) {
    double cx = 0, cy = 0, cz = 0, cw = 0;
    const std::array<double, 4>* row = &hw_[static_cast<size_t>((row0 + i) * patch_.size_v + col0)];
    for (int j = 0; j <= q; ++j) {
      const auto& c = row[j];
      cx += nv[j] * c[0]; cy += nv[j] * c[1]; cz += nv[j] * c[2]; cw += nv[j] * c[3];
    }
    x += nu[i] * cx; y += nu[i] * cy; z += nu[i] * cz; w += nu[i] * cw;
  }
  if (!rational_) return {x, y, z};
  return Vec3{x, y, z} / w;
}

}  // namespace rpu::patch
