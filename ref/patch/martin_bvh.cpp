// Martin et al. 2000: refinement into flat Bézier sub-patches, their BVH, and the per-ray
// traversal with Newton from each met leaf's parameter centre.
#include "patch/martin_bvh.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "common/error.h"
namespace rpu::patch {
namespace {

using H4 = std::array<double, 4>;  // homogeneous control point (w·x, w·y, w·z, w)

// A control net: rows of constant u index, nu × nv points.
struct Net {
  int nu = 0, nv = 0;
  std::vector<H4> p;
  H4& at(int i, int j) { return p[static_cast<size_t>(i * nv + j)]; }
  const H4& at(int i, int j) const { return p[static_cast<size_t>(i * nv + j)]; }
  Net transposed() const {
    Net t{nv, nu, std::vector<H4>(p.size())};
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j) t.at(j, i) = at(i, j);
    return t;
  }
};

H4 lerp(const H4& a, const H4& b, double t) {
  return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t,
          a[3] + (b[3] - a[3]) * t};
}
Vec3 cartesian(const H4& h) { return Vec3{h[0], h[1], h[2]} / h[3]; }

// Boehm's insertion of knot t into the u direction (every column at once).
void insert_knot_u(Net& net, std::vector<double>& knots, int p, double t) {
  const int n = net.nu - 1;
  int k = p;
  while (k + 1 < static_cast<int>(knots.size()) && knots[static_cast<size_t>(k) + 1] <= t) ++k;
  const int s = static_cast<int>(std::count(knots.begin(), knots.end(), t));
  Net q{net.nu + 1, net.nv, std::vector<H4>(static_cast<size_t>((net.nu + 1) * net.nv))};
  for (int j = 0; j < net.nv; ++j) {
    for (int i = 0; i <= k - p; ++i) q.at(i, j) = net.at(i, j);
    for (int i = k - p + 1; i <= k - s; ++i) {
      const double a = (t - knots[static_cast<size_t>(i)]) /
                       (knots[static_cast<size_t>(i + p)] - knots[static_cast<size_t>(i)]);
      q.at(i, j) = lerp(net.at(i - 1, j), net.at(i, j), a);
    }
    for (int i = k - s + 1; i <= n + 1; ++i) q.at(i, j) = net.at(i - 1, j);
  }
  knots.insert(knots.begin() + k + 1, t);
  net = std::move(q);
}

// Knot insertion until every interior knot has multiplicity p: the u direction becomes a chain
// of Bézier pieces; returns the piece boundaries (distinct knots).
std::vector<double> decompose_u(Net& net, std::vector<double> knots, int p) {
  std::vector<double> distinct;
  for (double k : knots)
    if (distinct.empty() || k != distinct.back()) distinct.push_back(k);
  for (size_t d = 1; d + 1 < distinct.size(); ++d) {
    const double t = distinct[d];
    while (std::count(knots.begin(), knots.end(), t) < p) insert_knot_u(net, knots, p, t);
  }
  return distinct;
}

// De Casteljau split at the middle of u (every column).
std::pair<Net, Net> split_u(const Net& net) {
  const int p = net.nu - 1;
  Net a = net, b = net;
  std::vector<H4> c(static_cast<size_t>(p + 1));
  for (int j = 0; j < net.nv; ++j) {
    for (int i = 0; i <= p; ++i) c[static_cast<size_t>(i)] = net.at(i, j);
    a.at(0, j) = c[0];
    b.at(p, j) = c[static_cast<size_t>(p)];
    for (int r = 1; r <= p; ++r) {
      for (int i = 0; i + r <= p; ++i)
        c[static_cast<size_t>(i)] = lerp(c[static_cast<size_t>(i)], c[static_cast<size_t>(i) + 1], 0.5);
      a.at(r, j) = c[0];
      b.at(p - r, j) = c[static_cast<size_t>(p - r)];
    }
  }
  return {a, b};
}

struct SubPatchRefiner {
  const MartinOptions& o;
  int patch;
  std::vector<MartinLeaf>& leaves;

  // Bilinear deviation of the control net from its corners, relative to the box diagonal.
  void subdivide(const Net& net, double u0, double u1, double v0, double v1, int depth) {
    const int p = net.nu - 1, q = net.nv - 1;
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    std::vector<Vec3> c(net.p.size());
    double c_min = std::numeric_limits<double>::infinity(), c_max = -c_min;
    for (size_t k = 0; k < c.size(); ++k) {
      c[k] = cartesian(net.p[k]);
      lo = {std::min(lo.x, c[k].x), std::min(lo.y, c[k].y), std::min(lo.z, c[k].z)};
      hi = {std::max(hi.x, c[k].x), std::max(hi.y, c[k].y), std::max(hi.z, c[k].z)};
      if (o.eye_plane) {
        const double d = dot(o.eye_plane->forward, c[k] - o.eye_plane->eye);
        c_min = std::min(c_min, d), c_max = std::max(c_max, d);
      }
    }
    // The sub-patch lies in the convex hull of its control points (NURBS: positive weights).
    if (o.eye_plane && !(c_max > 0.0)) return;  // wholly behind the eye
    const bool straddles = o.eye_plane && !(c_min > 0.0);
    const auto C = [&](int i, int j) { return c[static_cast<size_t>(i * net.nv + j)]; };
    const double diag = length(hi - lo);
    double dev = 0;
    for (int i = 0; i <= p; ++i)
      for (int j = 0; j <= q; ++j) {
        const double s = double(i) / p, t = double(j) / q;
        const Vec3 bl = C(0, 0) * ((1 - s) * (1 - t)) + C(p, 0) * (s * (1 - t)) +
                        C(0, q) * ((1 - s) * t) + C(p, q) * (s * t);
        dev = std::max(dev, length(C(i, j) - bl));
      }
    if ((dev <= o.flatness * diag || depth >= o.max_depth) &&
        (!straddles || depth >= o.max_depth + o.eye_plane_depth)) {
      if (static_cast<long long>(leaves.size()) >= o.max_leaves)
        throw Error(o.where, fmt::format(
            "Martin's BVH needs more than {} sub-patch leaves (README, \"Limits\"); use fewer or "
            "flatter patches, or --patch-method thesis or newton", o.max_leaves));
      const Vec3 pad = Vec3{1, 1, 1} * (1e-9 * (diag + 1e-300));
      leaves.push_back({patch, u0, u1, v0, v1, lo - pad, hi + pad});
      return;
    }
    // Split across the longer direction of the control net; a flat sub-patch that straddles
    // the eye plane across the direction in which its depth varies more (so one child of each
    // split lies in front or behind, and the straddling chain stays one leaf wide).
    if (straddles && dev <= o.flatness * diag) {
      double cu = 0, cv = 0;
      const auto depth_of = [&](int i, int j) {
        return dot(o.eye_plane->forward, C(i, j) - o.eye_plane->eye);
      };
      for (int j = 0; j <= q; ++j)
        for (int i = 0; i < p; ++i) cu = std::max(cu, std::fabs(depth_of(i + 1, j) - depth_of(i, j)));
      for (int i = 0; i <= p; ++i)
        for (int j = 0; j < q; ++j) cv = std::max(cv, std::fabs(depth_of(i, j + 1) - depth_of(i, j)));
      split(net, u0, u1, v0, v1, depth, cu >= cv);
      return;
    }
    double len_u = 0, len_v = 0;
    for (int j = 0; j <= q; ++j)
      for (int i = 0; i < p; ++i) len_u += length(C(i + 1, j) - C(i, j));
    for (int i = 0; i <= p; ++i)
      for (int j = 0; j < q; ++j) len_v += length(C(i, j + 1) - C(i, j));
    len_u /= (q + 1), len_v /= (p + 1);
    split(net, u0, u1, v0, v1, depth, len_u >= len_v);
  }

  void split(const Net& net, double u0, double u1, double v0, double v1, int depth, bool along_u) {
    if (along_u) {
      const auto [a, b] = split_u(net);
      const double um = 0.5 * (u0 + u1);
      subdivide(a, u0, um, v0, v1, depth + 1);
      subdivide(b, um, u1, v0, v1, depth + 1);
    } else {
      const auto [a, b] = split_u(net.transposed());
      const double vm = 0.5 * (v0 + v1);
      subdivide(a.transposed(), u0, u1, v0, vm, depth + 1);
      subdivide(b.transposed(), u0, u1, vm, v1, depth + 1);
    }
  }
};

void grow(Vec3& lo, Vec3& hi, const Vec3& a, const Vec3& b) {
  lo = {std::min(lo.x, a.x), std::min(lo.y, a.y), std::min(lo.z, a.z)};
  hi = {std::max(hi.x, b.x), std::max(hi.y, b.y), std::max(hi.z, b.z)};
}

// Slab test; the entry parameter, or +inf when the ray misses the box within (t_min, t_max).
inline double box_entry(const Vec3& lo, const Vec3& hi, const Vec3& org, const Vec3& inv,
                        double t_min, double t_max) {
  double t0 = t_min, t1 = t_max;
  const double o[3] = {org.x, org.y, org.z}, iv[3] = {inv.x, inv.y, inv.z};
  const double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
  for (int a = 0; a < 3; ++a) {
    double ta = (l[a] - o[a]) * iv[a], tb = (h[a] - o[a]) * iv[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = ta > t0 ? ta : t0;
    t1 = tb < t1 ? tb : t1;
    if (t0 > t1) return std::numeric_limits<double>::infinity();
  }
  return t0;
}

}  // namespace

MartinBvh::MartinBvh(const std::vector<PatchSurface>& patches, const MartinOptions& options)
    : options_(options) {
  for (size_t k = 0; k < patches.size(); ++k) {
    const PatchSurface& s = patches[k];
    const scene::Patch& pt = s.patch();
    Net net{pt.size_u, pt.size_v, {}};
    for (int i = 0; i < pt.size_u * pt.size_v; ++i) {
      const double w = s.rational() ? pt.weights[static_cast<size_t>(i)] : 1.0;
      const Vec3& c = pt.control_points[static_cast<size_t>(i)];
      net.p.push_back({c.x * w, c.y * w, c.z * w, w});
    }
    std::vector<double> bu{0.0, 1.0}, bv{0.0, 1.0};
    if (pt.type != scene::PatchType::kBezier) {
      // Bézier pieces: the distinct knot spans in u times those in v, counted before the knot
      // insertion (whose work grows with the pieces times the net).
      const auto spans = [](const std::vector<double>& k) {
        long long n = 0;
        for (size_t i = 0; i + 1 < k.size(); ++i) n += k[i + 1] > k[i];
        return n;
      };
      const long long pieces = spans(s.knots_u()) * spans(s.knots_v());
      if (pieces > options_.max_pieces_per_patch)
        throw Error(options_.where + "[" + std::to_string(k) + "]",
                    fmt::format("Martin's method splits this patch into {} Bézier pieces; at most "
                                "{} per patch (README, \"Limits\"); use --patch-method thesis or "
                                "newton", pieces, options_.max_pieces_per_patch));
      bu = decompose_u(net, s.knots_u(), pt.degree_u);
      Net t = net.transposed();
      bv = decompose_u(t, s.knots_v(), pt.degree_v);
      net = t.transposed();
    }
    SubPatchRefiner refiner{options_, static_cast<int>(k), leaves_};
    const int p = pt.degree_u, q = pt.degree_v;
    for (size_t a = 0; a + 1 < bu.size(); ++a)
      for (size_t b = 0; b + 1 < bv.size(); ++b) {
        Net piece{p + 1, q + 1, {}};
        for (int i = 0; i <= p; ++i)
          for (int j = 0; j <= q; ++j) piece.p.push_back(net.at(static_cast<int>(a) * p + i, static_cast<int>(b) * q + j));
        refiner.subdivide(piece, bu[a], bu[a + 1], bv[b], bv[b + 1], 0);
      }
  }
  // Median-split BVH over the leaf boxes, one sub-patch per leaf.
  std::vector<int> order(leaves_.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  nodes_.reserve(2 * leaves_.size() + 1);
  nodes_.push_back({});
  struct Task { int node, begin, end; };
  std::vector<Task> stack{{0, 0, static_cast<int>(order.size())}};
  while (!stack.empty()) {
    const Task t = stack.back();
    stack.pop_back();
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300}, clo = lo, chi = hi;
    for (int i = t.begin; i < t.end; ++i) {
      const MartinLeaf& l = leaves_[static_cast<size_t>(order[static_cast<size_t>(i)])];
      grow(lo, hi, l.lo, l.hi);
      const Vec3 c = (l.lo + l.hi) * 0.5;
      grow(clo, chi, c, c);
    }
    MartinNode& n = nodes_[static_cast<size_t>(t.node)];
    n.lo = lo, n.hi = hi;
    if (t.end - t.begin <= 1) {
      n.first = t.begin, n.count = t.end - t.begin;
      continue;
    }
    const Vec3 ext = chi - clo;
    const int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
    const int mid = (t.begin + t.end) / 2;
    std::nth_element(order.begin() + t.begin, order.begin() + mid, order.begin() + t.end,
                     [&](int a, int b) {
                       const MartinLeaf &la = leaves_[static_cast<size_t>(a)], &lb = leaves_[static_cast<size_t>(b)];
                       const double ca = axis == 0 ? la.lo.x + la.hi.x : axis == 1 ? la.lo.y + la.hi.y : la.lo.z + la.hi.z;
                       const double cb = axis == 0 ? lb.lo.x + lb.hi.x : axis == 1 ? lb.lo.y + lb.hi.y : lb.lo.z + lb.hi.z;
                       return ca < cb;
                     });
    const int left = static_cast<int>(nodes_.size());
    nodes_[static_cast<size_t>(t.node)].first = left;
    nodes_[static_cast<size_t>(t.node)].count = 0;
    nodes_.push_back({});
    nodes_.push_back({});
    stack.push_back({left, t.begin, mid});
    stack.push_back({left + 1, mid, t.end});
  }
  // Leaves in traversal order, so a leaf node's range indexes leaves_ directly.
  std::vector<MartinLeaf> sorted(leaves_.size());
  for (size_t i = 0; i < order.size(); ++i) sorted[i] = leaves_[static_cast<size_t>(order[i])];
  leaves_ = std::move(sorted);
}

MartinBvh::Hit MartinBvh::intersect(const std::vector<PatchSurface>& patches, const RayFrame& ray,
                                    MartinStats& stats, double t_min) const {
  Hit best;
  double best_t = std::numeric_limits<double>::infinity();
  const Vec3 inv{1.0 / ray.dir.x, 1.0 / ray.dir.y, 1.0 / ray.dir.z};
  if (nodes_.empty() || leaves_.empty()) return best;
  struct Entry { int node; double t; };
  Entry stack[128];
  int top = 0;
  ++stats.box_tests;
  const double t_root = box_entry(nodes_[0].lo, nodes_[0].hi, ray.eye, inv, t_min, best_t);
  if (!std::isfinite(t_root)) return best;
  stack[top++] = {0, t_root};
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.t > best_t) continue;  // a nearer hit was found since the box was met
    const MartinNode& n = nodes_[static_cast<size_t>(e.node)];
    if (n.count > 0) {
      for (int k = n.first; k < n.first + n.count; ++k) {
        const MartinLeaf& l = leaves_[static_cast<size_t>(k)];
        ++stats.newton_starts;
        const RefineResult r = newton(patches[static_cast<size_t>(l.patch)], ray, 0.5 * (l.u0 + l.u1),
                                      0.5 * (l.v0 + l.v1), options_.newton);
        stats.evaluations += r.evaluations;
        if (!r.converged()) continue;
        ++stats.newton_converged;
        // ray.dir has W component 1, so the ray parameter of the hit is its depth c.
        if (r.depth > t_min && r.depth < best_t) {
          best_t = r.depth;
          best = {true, l.patch, r.u, r.v, r.depth};
        }
      }
      continue;
    }
    const MartinNode &a = nodes_[static_cast<size_t>(n.first)], &b = nodes_[static_cast<size_t>(n.first) + 1];
    stats.box_tests += 2;
    const double ta = box_entry(a.lo, a.hi, ray.eye, inv, t_min, best_t);
    const double tb = box_entry(b.lo, b.hi, ray.eye, inv, t_min, best_t);
    // Nearer child on top of the stack.
    if (ta <= tb) {
      if (std::isfinite(tb)) stack[top++] = {n.first + 1, tb};
      if (std::isfinite(ta)) stack[top++] = {n.first, ta};
    } else {
      if (std::isfinite(ta)) stack[top++] = {n.first, ta};
      if (std::isfinite(tb)) stack[top++] = {n.first + 1, tb};
    }
  }
  return best;
}

}  // namespace rpu::patch
