#include "patch/tessellated_reference.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>

#include "common/error.h"
#include "common/parallel.h"
#include "patch/patch_surface.h"

namespace rpu::patch {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMaxTriangles = 4e6;  // about 0.5 GB of triangles

Vec3 vmin(const Vec3& a, const Vec3& b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
Vec3 vmax(const Vec3& a, const Vec3& b) {
  return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
double axis(const Vec3& a, int k) { return k == 0 ? a.x : (k == 1 ? a.y : a.z); }

// Grid cells per side so that the chord error of a uniform n × n grid, (1/8)·|S''|·(1/n)²
// (S'' estimated from second differences on a probe grid, the mixed direction included), stays
// below `tolerance_pixels` of a pixel at the nearest depth the patch reaches.
int automatic_grid(const PatchSurface& surface, const scene::CameraFrame& cam,
                   const TessellationOptions& options) {
  // 16 probe cells per polynomial piece (B-spline/NURBS knot spans), so that the curvature of
  // every span is seen.
  const auto& pt = surface.patch();
  const int spans = pt.type == scene::PatchType::kBezier
                        ? 1
                        : std::max(pt.size_u - pt.degree_u, pt.size_v - pt.degree_v);
  const int kProbe = 16 * std::clamp(spans, 1, 16);
  const double h = 1.0 / kProbe;
  std::vector<Vec3> p((kProbe + 1) * (kProbe + 1));
  auto at = [&](int a, int b) -> Vec3& { return p[a * (kProbe + 1) + b]; };
  double nearest = kInf;
  for (int a = 0; a <= kProbe; ++a)
    for (int b = 0; b <= kProbe; ++b) {
      at(a, b) = surface.point(a * h, b * h);
      nearest = std::min(nearest, dot(at(a, b) - cam.eye, cam.W));
    }
  double second = 0;  // largest |S''| over the probe grid (per unit parameter²)
  for (int a = 0; a <= kProbe; ++a)
    for (int b = 0; b <= kProbe; ++b) {
      if (a > 0 && a < kProbe)
        second = std::max(second, length(at(a - 1, b) - at(a, b) * 2.0 + at(a + 1, b)) / (h * h));
      if (b > 0 && b < kProbe)
        second = std::max(second, length(at(a, b - 1) - at(a, b) * 2.0 + at(a, b + 1)) / (h * h));
      if (a > 0 && b > 0 && a < kProbe && b < kProbe)  // along the diagonal of a cell
        second = std::max(second, length(at(a - 1, b - 1) - at(a, b) * 2.0 + at(a + 1, b + 1)) /
                                      (2 * h * h));
    }
  if (!(nearest > 0)) return options.max_grid;  // the patch reaches the eye plane: finest grid
  const double tolerance = options.max_chord_error_pixels * cam.sigma * nearest;
  const double n = std::ceil(std::sqrt(second / (8.0 * tolerance)));
  return static_cast<int>(std::clamp(n, 8.0, static_cast<double>(options.max_grid)));
}

// Ray/box slab test: entry distance, or +inf when the ray misses the box within (t_min, t_max).
double box_entry(const TessellatedPatches::Node& node, const Vec3& eye, const Vec3& inv,
                 double t_min, double t_max) {
  double t0 = t_min, t1 = t_max;
  for (int k = 0; k < 3; ++k) {
    const double o = axis(eye, k), d = axis(inv, k);
    double ta = (axis(node.lo, k) - o) * d, tb = (axis(node.hi, k) - o) * d;
    if (ta > tb) std::swap(ta, tb);
    if (std::isnan(ta)) ta = -kInf;  // 0·inf: the ray lies in a slab plane
    if (std::isnan(tb)) tb = kInf;
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb * (1 + 4 * std::numeric_limits<double>::epsilon()));
    if (t0 > t1) return kInf;
  }
  return t0;
}

}  // namespace

TessellatedPatches::TessellatedPatches(const std::vector<scene::Patch>& patches,
                                       const scene::CameraFrame& camera,
                                       const TessellationOptions& options) {
  const auto t0 = Clock::now();
  std::vector<PatchSurface> surfaces;
  surfaces.reserve(patches.size());
  for (const auto& p : patches) surfaces.emplace_back(p);
  const int count = static_cast<int>(surfaces.size());

  // 1. Grid resolution (one n for every patch, see the header).
  int n = options.grid;
  if (n <= 0) {
    std::vector<int> per(count, 8);
    parallel_rows(
        count, options.threads,
        [&](int k) { per[k] = automatic_grid(surfaces[k], camera, options); }, [](auto&) {});
    n = 8;
    for (int g : per) n = std::max(n, g);
    // Memory: at most kMaxTriangles triangles in all.
    const double budget = std::sqrt(kMaxTriangles / (2.0 * std::max(count, 1)));
    n = std::max(1, std::min(n, static_cast<int>(budget)));
  }
  stats_.grid_per_patch.assign(count, n);

  // 2. Samples and triangles, patch by patch on all cores.
  const int cells = n * n;
  triangles_.resize(static_cast<size_t>(count) * cells * 2);
  std::vector<int> bad(count, 0);
  parallel_rows(
      count, options.threads,
      [&](int k) {
        std::vector<Vec3> s((n + 1) * (n + 1));
        for (int a = 0; a <= n; ++a)
          for (int b = 0; b <= n; ++b) {
            s[a * (n + 1) + b] = surfaces[k].point(static_cast<double>(a) / n,
                                                   static_cast<double>(b) / n);
            if (!is_finite(s[a * (n + 1) + b])) bad[k] = 1;
          }
        Triangle* out = &triangles_[static_cast<size_t>(k) * cells * 2];
        const double h = 1.0 / n;
        for (int a = 0; a < n; ++a)
          for (int b = 0; b < n; ++b) {
            const Vec3 p00 = s[a * (n + 1) + b], p10 = s[(a + 1) * (n + 1) + b];
            const Vec3 p01 = s[a * (n + 1) + b + 1], p11 = s[(a + 1) * (n + 1) + b + 1];
            const double u = a * h, v = b * h;
            // (u, v), (u + h, v), (u + h, v + h)  and  (u, v), (u + h, v + h), (u, v + h)
            *out++ = Triangle{p00, p10 - p00, p11 - p00, u, v, h, 0, h, h, k};
            *out++ = Triangle{p00, p11 - p00, p01 - p00, u, v, h, h, 0, h, k};
          }
      },
      [](auto&) {});
  for (int k = 0; k < count; ++k)
    if (bad[k])
      throw Error("patches[" + std::to_string(k) + "]", "the surface has non-finite points");

  // 3. Drop degenerate triangles (collapsed rows at poles), then the BVH: median split of the
  // centroids on the longest axis, leaves of at most 4 triangles.
  std::erase_if(triangles_, [](const Triangle& t) {
    return length_squared(cross(t.e1, t.e2)) == 0.0;
  });
  stats_.triangles = static_cast<std::int64_t>(triangles_.size());
  std::vector<Vec3> centroid(triangles_.size());
  for (size_t i = 0; i < triangles_.size(); ++i)
    centroid[i] = triangles_[i].p0 + (triangles_[i].e1 + triangles_[i].e2) / 3.0;
  std::vector<int> order(triangles_.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);

  struct Task {
    int node, begin, end;
  };
  nodes_.reserve(triangles_.size() / 2 + 1);
  nodes_.push_back({});
  std::vector<Task> stack;
  if (!triangles_.empty()) stack.push_back({0, 0, static_cast<int>(order.size())});
  else nodes_[0] = Node{{0, 0, 0}, {0, 0, 0}, 0, 0};
  while (!stack.empty()) {
    const Task task = stack.back();
    stack.pop_back();
    Vec3 lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf}, clo = lo, chi = hi;
    for (int i = task.begin; i < task.end; ++i) {
      const Triangle& t = triangles_[order[i]];
      const Vec3 p1 = t.p0 + t.e1, p2 = t.p0 + t.e2;
      lo = vmin(lo, vmin(t.p0, vmin(p1, p2)));
      hi = vmax(hi, vmax(t.p0, vmax(p1, p2)));
      clo = vmin(clo, centroid[order[i]]);
      chi = vmax(chi, centroid[order[i]]);
    }
    Node& node = nodes_[task.node];
    node.lo = lo;
    node.hi = hi;
    const int size = task.end - task.begin;
    const Vec3 extent = chi - clo;
    const int k = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    if (size <= 4 || axis(extent, k) == 0.0) {
      node.first = task.begin;
      node.count = size;
      continue;
    }
    const int mid = task.begin + size / 2;
    std::nth_element(order.begin() + task.begin, order.begin() + mid, order.begin() + task.end,
                     [&](int a, int b) { return axis(centroid[a], k) < axis(centroid[b], k); });
    const int left = static_cast<int>(nodes_.size());
    node.first = left;
    node.count = 0;
    nodes_.push_back({});
    nodes_.push_back({});
    stack.push_back({left, task.begin, mid});
    stack.push_back({left + 1, mid, task.end});
  }
  // Triangles in leaf order, so a leaf's range is contiguous.
  std::vector<Triangle> sorted(triangles_.size());
  for (size_t i = 0; i < order.size(); ++i) sorted[i] = triangles_[order[i]];
  triangles_ = std::move(sorted);
  stats_.bvh_nodes = static_cast<std::int64_t>(nodes_.size());
  stats_.build_seconds = seconds_since(t0);
}

PatchPixel TessellatedPatches::intersect(const Vec3& eye, const Vec3& dir, double t_min) const {
  PatchPixel best;
  if (triangles_.empty()) return best;
  double t_best = kInf;
  const Vec3 inv{1.0 / dir.x, 1.0 / dir.y, 1.0 / dir.z};
  int stack[128];
  int top = 0;
  if (box_entry(nodes_[0], eye, inv, t_min, t_best) == kInf) return best;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        // Möller–Trumbore, edges inclusive (a ray through a shared edge hits one of the two).
        const Triangle& tri = triangles_[i];
        const Vec3 pv = cross(dir, tri.e2);
        const double det = dot(tri.e1, pv);
        if (det == 0.0) continue;
        const double inv_det = 1.0 / det;
        const Vec3 tv = eye - tri.p0;
        const double b1 = dot(tv, pv) * inv_det;
        if (b1 < 0.0 || b1 > 1.0) continue;
        const Vec3 qv = cross(tv, tri.e1);
        const double b2 = dot(dir, qv) * inv_det;
        if (b2 < 0.0 || b1 + b2 > 1.0) continue;
        const double t = dot(tri.e2, qv) * inv_det;
        if (t <= t_min || t >= t_best) continue;
        t_best = t;
        best.hit = true;
        best.patch = tri.patch;
        best.u = std::clamp(tri.u0 + b1 * tri.du1 + b2 * tri.du2, 0.0, 1.0);
        best.v = std::clamp(tri.v0 + b1 * tri.dv1 + b2 * tri.dv2, 0.0, 1.0);
        best.depth = t;
      }
      continue;
    }
    const double ta = box_entry(nodes_[node.first], eye, inv, t_min, t_best);
    const double tb = box_entry(nodes_[node.first + 1], eye, inv, t_min, t_best);
    // Push the farther child first so the nearer is visited first.
    if (ta <= tb) {
      if (tb != kInf) stack[top++] = node.first + 1;
      if (ta != kInf) stack[top++] = node.first;
    } else {
      if (ta != kInf) stack[top++] = node.first;
      if (tb != kInf) stack[top++] = node.first + 1;
    }
  }
  return best;
}

PatchHitMap TessellatedPatches::trace(const scene::CameraFrame& camera, int threads,
                                      double* seconds) const {
  const auto t0 = Clock::now();
  PatchHitMap map;
  map.width = camera.width;
  map.height = camera.height;
  map.pixels.resize(static_cast<size_t>(camera.width) * camera.height);
  parallel_rows(
      camera.height, threads,
      [&](int j) {
        for (int i = 0; i < camera.width; ++i)
          // ray_direction has W-component 1, so t is the depth c of capture_test.
          map.at(i, j) = intersect(camera.eye, camera.ray_direction(i, j));
      },
      [](auto&) {});
  if (seconds) *seconds = seconds_since(t0);
  return map;
}

PatchHitMap render_tessellated_reference(const std::vector<scene::Patch>& patches,
                                         const scene::Camera& camera, const std::string& source,
                                         const TessellationOptions& options,
                                         TessellationStats* stats) {
  const scene::CameraFrame frame = scene::make_camera_frame(camera, source);
  const TessellatedPatches tess(patches, frame, options);
  double seconds = 0;
  PatchHitMap map = tess.trace(frame, options.threads, &seconds);
  if (stats) {
    *stats = tess.stats();
    stats->trace_seconds = seconds;
  }
  return map;
}

HitMapComparison compare_hit_maps(const PatchHitMap& reference, const PatchHitMap& method) {
  if (reference.width != method.width || reference.height != method.height ||
      reference.pixels.size() != method.pixels.size())
    throw Error("compare_hit_maps", "the two renderings differ in size (" +
                                        std::to_string(reference.width) + "x" +
                                        std::to_string(reference.height) + " and " +
                                        std::to_string(method.width) + "x" +
                                        std::to_string(method.height) + ")");
  HitMapComparison c;
  double sum_du = 0, sum_dv = 0, sum_depth = 0;
  for (size_t k = 0; k < reference.pixels.size(); ++k) {
    const PatchPixel& r = reference.pixels[k];
    const PatchPixel& m = method.pixels[k];
    if (!r.hit && !m.hit) continue;
    ++c.union_hits;
    if (r.hit && !m.hit) {
      ++c.only_reference;
      continue;
    }
    if (!r.hit) {
      ++c.only_method;
      continue;
    }
    ++c.both_hit;
    const double rel = std::abs(m.depth - r.depth) / std::abs(r.depth);
    sum_depth += rel;
    c.max_rel_depth_error = std::max(c.max_rel_depth_error, rel);
    if (r.patch != m.patch) continue;
    ++c.same_patch;
    const double du = std::abs(m.u - r.u), dv = std::abs(m.v - r.v);
    sum_du += du;
    sum_dv += dv;
    c.max_abs_du = std::max(c.max_abs_du, du);
    c.max_abs_dv = std::max(c.max_abs_dv, dv);
  }
  if (c.union_hits > 0) c.agreement_percent = 100.0 * c.both_hit / c.union_hits;
  if (c.both_hit > 0) c.mean_rel_depth_error = sum_depth / c.both_hit;
  if (c.same_patch > 0) {
    c.mean_abs_du = sum_du / c.same_patch;
    c.mean_abs_dv = sum_dv / c.same_patch;
  }
  return c;
}

}  // namespace rpu::patch
