// Building the preliminary value map: tessellate every patch on a grid of its normalised domain
// (knot lines included, cells per knot span from the projected curvature), project, and z-buffer
// the triangles at the texel centres with perspective-correct (u, v).
#include "patch/preliminary_map.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.h"
#include "common/parallel.h"

namespace rpu::patch {
namespace {

// A point of a patch in camera coordinates (a, b, c along U, V, W of P − eye) with its parameters:
// the tessellation's vertices before projection, so that triangles are clipped in 3-D.
struct CameraPoint {
  double a, b, c;
  double u, v;
};

struct ScreenVertex {
  double x, y;    // map texel coordinates (texel (a, b) has its centre at (a + 0.5, b + 0.5))
  double inv_c;   // 1 / depth
  float u, v;
};

struct Triangle {
  ScreenVertex p[3];
  std::int32_t patch;
};

// A chunk's cells give at most four triangles each (two, each clipped into at most two).
static_assert(kChunkCells * 4 * static_cast<long long>(sizeof(Triangle)) <= kMapChunkBytes);

struct Projector {
  const scene::CameraFrame& cam;
  double sx, sy;  // image → map scale
  double near;    // near plane: points at depth c <= near are behind it
  CameraPoint camera_point(const Vec3& p, double u, double v) const {
    const Vec3 q = p - cam.eye;
    return {dot(cam.U, q), dot(cam.V, q), dot(cam.W, q), u, v};
  }
  bool front(const CameraPoint& q) const { return q.c > near; }
  ScreenVertex screen(const CameraPoint& q) const {
    ScreenVertex s{};
    s.x = (q.a / (q.c * cam.sigma) + 0.5 * cam.width) * sx;
    s.y = (0.5 * cam.height - q.b / (q.c * cam.sigma)) * sy;
    s.inv_c = 1.0 / q.c;
    s.u = static_cast<float>(q.u), s.v = static_cast<float>(q.v);
    return s;
  }
};

// The near plane: 1e-6 of the largest distance of a control point from the eye, so the map is
// the same at every scale of scene and camera.
double near_depth(const std::vector<PatchSurface>& patches, const scene::CameraFrame& cam) {
  double far = 0;
  for (const PatchSurface& s : patches)
    for (const Vec3& p : s.patch().control_points) far = std::max(far, length(p - cam.eye));
  return 1e-6 * far;
}

// Parameter values of the tessellation in one direction: every knot (B-spline, NURBS) is a grid
// line, and each knot span gets its own count n from the second differences of a 9×9 probe
// grid over the span (in texels): the chord error of n cells is about 8·d2/n². Only probe points
// in front of the near plane whose middle point projects within one map size of the map count:
// parts behind the eye or far off the map are not drawn, and near the eye plane the projection's
// curvature grows without bound. A direction with more knot spans than max_cells_per_side is
// tessellated as one span, and the cells of a direction are capped at max_cells_per_side.
std::vector<double> tessellation_samples(const PatchSurface& s, const Projector& proj,
                                         const MapOptions& o, bool along_u, int map_w, int map_h) {
  std::vector<double> knots = along_u ? s.knots_u() : s.knots_v();
  if (knots.empty()) knots = {0.0, 1.0};
  knots.erase(std::unique(knots.begin(), knots.end()), knots.end());
  if (static_cast<long long>(knots.size()) - 1 > o.max_cells_per_side) knots = {0.0, 1.0};
  constexpr int kProbe = 8;
  std::vector<int> cells;
  for (size_t k = 0; k + 1 < knots.size(); ++k) {
    const double a = knots[k], b = knots[k + 1];
    int n = 0;
    if (o.grid > 0) {
      n = std::max(1, static_cast<int>(std::lround(o.grid * (b - a))));
    } else {
      double d2 = 0;
      for (int c = 0; c <= kProbe; ++c) {
        const double across = double(c) / kProbe;
        CameraPoint line[kProbe + 1];
        for (int i = 0; i <= kProbe; ++i) {
          const double t = a + (b - a) * i / kProbe;
          const double u = along_u ? t : across, v = along_u ? across : t;
          line[i] = proj.camera_point(s.point(u, v), u, v);
        }
        for (int i = 1; i < kProbe; ++i) {
          if (!proj.front(line[i - 1]) || !proj.front(line[i]) || !proj.front(line[i + 1])) continue;
          const ScreenVertex p0 = proj.screen(line[i - 1]), p1 = proj.screen(line[i]),
                             p2 = proj.screen(line[i + 1]);
          if (!(p1.x >= -map_w && p1.x <= 2.0 * map_w && p1.y >= -map_h && p1.y <= 2.0 * map_h))
            continue;
          d2 = std::max(d2, std::hypot(p0.x - 2 * p1.x + p2.x, p0.y - 2 * p1.y + p2.y));
        }
      }
      const double want = std::ceil(std::sqrt(8.0 * d2 / o.max_chord_pixels));
      n = static_cast<int>(std::clamp(want, 2.0, static_cast<double>(o.max_grid)));
    }
    cells.push_back(n);
  }
  // Cap the direction: the largest per-span count m with Σ min(n, m) <= max_cells_per_side (the
  // spans are at most that many, so m = 1 always fits).
  long long total = 0;
  for (int n : cells) total += n;
  if (total > o.max_cells_per_side) {
    int lo = 1, hi = *std::max_element(cells.begin(), cells.end());
    while (lo < hi) {
      const int m = (lo + hi + 1) / 2;
      long long t = 0;
      for (int n : cells) t += std::min(n, m);
      if (t <= o.max_cells_per_side) lo = m; else hi = m - 1;
    }
    for (int& n : cells) n = std::min(n, lo);
  }
  std::vector<double> out{0.0};
  for (size_t k = 0; k < cells.size(); ++k) {
    const double a = knots[k], b = knots[k + 1];
    const int n = cells[k];
    for (int i = 1; i <= n; ++i) out.push_back(i == n ? b : a + (b - a) * i / n);
  }
  return out;
}

// The part of triangle (p, q, r) in front of the near plane, projected, appended to `out` (none,
// the triangle, or a fan of two).
void clip_and_project(const CameraPoint& p, const CameraPoint& q, const CameraPoint& r,
                      const Projector& proj, std::int32_t patch, int map_w, int map_h,
                      std::vector<Triangle>& out) {
  const CameraPoint in[3] = {p, q, r};
  CameraPoint poly[4];
  int n = 0;
  for (int k = 0; k < 3; ++k) {
    const CameraPoint& a = in[k];
    const CameraPoint& b = in[(k + 1) % 3];
    const bool fa = proj.front(a), fb = proj.front(b);
    if (fa) poly[n++] = a;
    if (fa != fb) {
      const double t = (proj.near - a.c) / (b.c - a.c);
      const auto lerp = [t](double x, double y) { return x + (y - x) * t; };
      poly[n++] = {lerp(a.a, b.a), lerp(a.b, b.b), proj.near, lerp(a.u, b.u), lerp(a.v, b.v)};
      // Exactly on the plane counts as behind it: nudge the new vertex into the front.
      poly[n - 1].c = std::nextafter(proj.near, std::numeric_limits<double>::infinity());
    }
  }
  for (int k = 1; k + 1 < n; ++k) {
    Triangle t{{proj.screen(poly[0]), proj.screen(poly[k]), proj.screen(poly[k + 1])}, patch};
    const double x0 = std::min({t.p[0].x, t.p[1].x, t.p[2].x}), x1 = std::max({t.p[0].x, t.p[1].x, t.p[2].x});
    const double y0 = std::min({t.p[0].y, t.p[1].y, t.p[2].y}), y1 = std::max({t.p[0].y, t.p[1].y, t.p[2].y});
    if (!(x1 >= -0.5 && x0 <= map_w + 0.5 && y1 >= -0.5 && y0 <= map_h + 0.5)) continue;  // off the map
    out.push_back(t);
  }
}

double edge(const ScreenVertex& a, const ScreenVertex& b, double x, double y) {
  return (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
}

void rasterise(const Triangle& t, int row_lo, int row_hi, PreliminaryMap& map) {
  const ScreenVertex &a = t.p[0], &b = t.p[1], &c = t.p[2];
  const double area = edge(a, b, c.x, c.y);
  if (area == 0.0 || !std::isfinite(area)) return;
  const double inv_area = 1.0 / area;
  // Texel ranges clamped in floating point first: a clipped triangle near the eye plane can
  // reach far beyond the map (an int cast of such a coordinate would overflow).
  const auto index = [](double v, int lo, int hi) {
    return static_cast<int>(std::clamp(v, static_cast<double>(lo), static_cast<double>(hi)));
  };
  const int x0 = index(std::floor(std::min({a.x, b.x, c.x}) - 0.5), 0, map.width);
  const int x1 = index(std::ceil(std::max({a.x, b.x, c.x}) - 0.5), -1, map.width - 1);
  const int y0 = index(std::floor(std::min({a.y, b.y, c.y}) - 0.5), row_lo, row_hi);
  const int y1 = index(std::ceil(std::max({a.y, b.y, c.y}) - 0.5), row_lo - 1, row_hi - 1);
  for (int y = y0; y <= y1; ++y) {
    const double py = y + 0.5;
    for (int x = x0; x <= x1; ++x) {
      const double px = x + 0.5;
      // Barycentric weights (either winding); texels on an edge belong to both triangles.
      const double w0 = edge(b, c, px, py) * inv_area, w1 = edge(c, a, px, py) * inv_area;
      const double w2 = 1.0 - w0 - w1;
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      const double inv_c = w0 * a.inv_c + w1 * b.inv_c + w2 * c.inv_c;
      const double depth = 1.0 / inv_c;
      MapTexel& m = map.texels[static_cast<size_t>(y) * map.width + x];
      if (m.patch >= 0 && (depth > m.depth || (depth == m.depth && t.patch > m.patch))) continue;
      // Perspective-correct parameters: u/c and v/c are affine in screen space.
      const double u = (w0 * a.u * a.inv_c + w1 * b.u * b.inv_c + w2 * c.u * c.inv_c) * depth;
      const double v = (w0 * a.v * a.inv_c + w1 * b.v * b.inv_c + w2 * c.v * c.inv_c) * depth;
      m.patch = t.patch;
      m.depth = static_cast<float>(depth);
      m.u = static_cast<float>(std::clamp(u, 0.0, 1.0));
      m.v = static_cast<float>(std::clamp(v, 0.0, 1.0));
    }
  }
}

}  // namespace

MapGrid preliminary_map_grid(const std::vector<PatchSurface>& patches,
                             const scene::CameraFrame& camera, const MapOptions& o) {
  const int map_w = o.width > 0 ? o.width : camera.width;
  const int map_h = o.height > 0 ? o.height : camera.height;
  const Projector proj{camera, double(map_w) / camera.width, double(map_h) / camera.height,
                       near_depth(patches, camera)};
  MapGrid g;
  g.us.resize(patches.size());
  g.vs.resize(patches.size());
  parallel_rows(static_cast<int>(patches.size()), o.threads,
                [&](int k) {
                  const PatchSurface& s = patches[static_cast<size_t>(k)];
                  g.us[static_cast<size_t>(k)] = tessellation_samples(s, proj, o, true, map_w, map_h);
                  g.vs[static_cast<size_t>(k)] = tessellation_samples(s, proj, o, false, map_w, map_h);
                },
                [&](auto&) {});
  for (size_t k = 0; k < patches.size(); ++k)
    g.cells += static_cast<long long>(g.us[k].size() - 1) * static_cast<long long>(g.vs[k].size() - 1);
  return g;
}

PreliminaryMap build_preliminary_map(const std::vector<PatchSurface>& patches,
                                     const scene::CameraFrame& camera, const MapOptions& o) {
  PreliminaryMap map;
  map.image_width = camera.width, map.image_height = camera.height;
  map.width = o.width > 0 ? o.width : camera.width;
  map.height = o.height > 0 ? o.height : camera.height;
  const MapGrid grid = preliminary_map_grid(patches, camera, o);
  if (grid.cells > o.max_cells)
    throw Error(o.where, fmt::format(
        "the preliminary map of {} patches needs {} tessellation cells at a {}x{} map; at most {} "
        "(README, \"Limits\"); use fewer or smaller patches, a smaller --size or "
        "--patch-map-size", patches.size(), grid.cells, map.width, map.height, o.max_cells));
  map.texels.assign(static_cast<size_t>(map.width) * map.height, MapTexel{});
  const Projector proj{camera, double(map.width) / camera.width, double(map.height) / camera.height,
                       near_depth(patches, camera)};
  map.grid_per_patch.assign(patches.size(), 0);
  for (size_t k = 0; k < patches.size(); ++k)
    map.grid_per_patch[k] = static_cast<int>(std::max(grid.us[k].size(), grid.vs[k].size())) - 1;

  // Work items: a patch's rows of cells [row0, row1), at most kChunkCells cells each; a chunk is
  // a run of items of at most kChunkCells cells (one item at least), tessellated in parallel,
  // then rasterised in bands of rows, each band owned by one worker. Items and triangles keep
  // the patch order, so the map does not depend on the chunking.
  struct Item {
    int patch, row0, row1;
    long long cells;
  };
  std::vector<Item> items;
  for (size_t k = 0; k < patches.size(); ++k) {
    const int rows = static_cast<int>(grid.us[k].size()) - 1;
    const long long per_row = static_cast<long long>(grid.vs[k].size()) - 1;
    const int step = static_cast<int>(std::max<long long>(1, kChunkCells / std::max<long long>(per_row, 1)));
    for (int r = 0; r < rows; r += step) {
      const int r1 = std::min(rows, r + step);
      items.push_back({static_cast<int>(k), r, r1, per_row * (r1 - r)});
    }
  }
  constexpr int kBand = 16;
  const int bands = (map.height + kBand - 1) / kBand;
  for (size_t first = 0; first < items.size();) {
    size_t last = first + 1;
    long long cells = items[first].cells;
    while (last < items.size() && cells + items[last].cells <= kChunkCells) cells += items[last++].cells;
    std::vector<std::vector<Triangle>> per_item(last - first);
    parallel_rows(static_cast<int>(last - first), o.threads,
                  [&](int t) {
                    const Item& it = items[first + static_cast<size_t>(t)];
                    const PatchSurface& s = patches[static_cast<size_t>(it.patch)];
                    const std::vector<double>& us = grid.us[static_cast<size_t>(it.patch)];
                    const std::vector<double>& vs = grid.vs[static_cast<size_t>(it.patch)];
                    const int nv = static_cast<int>(vs.size());
                    std::vector<CameraPoint> vtx(static_cast<size_t>(it.row1 - it.row0 + 1) * nv);
                    for (int i = it.row0; i <= it.row1; ++i)
                      for (int j = 0; j < nv; ++j) {
                        const double u = us[static_cast<size_t>(i)], v = vs[static_cast<size_t>(j)];
                        vtx[static_cast<size_t>((i - it.row0) * nv + j)] = proj.camera_point(s.point(u, v), u, v);
                      }
                    const auto at = [&](int i, int j) -> const CameraPoint& {
                      return vtx[static_cast<size_t>((i - it.row0) * nv + j)];
                    };
                    auto& tris = per_item[static_cast<size_t>(t)];
                    for (int i = it.row0; i < it.row1; ++i)
                      for (int j = 0; j + 1 < nv; ++j) {
                        const CameraPoint& q0 = at(i, j);
                        const CameraPoint& q1 = at(i + 1, j);
                        const CameraPoint& q2 = at(i + 1, j + 1);
                        const CameraPoint& q3 = at(i, j + 1);
                        clip_and_project(q0, q1, q2, proj, it.patch, map.width, map.height, tris);
                        clip_and_project(q0, q2, q3, proj, it.patch, map.width, map.height, tris);
                      }
                  },
                  [&](auto&) {});
    std::vector<Triangle> all;
    size_t count = 0;
    for (const auto& t : per_item) count += t.size();
    all.reserve(count);
    for (auto& t : per_item) {
      all.insert(all.end(), t.begin(), t.end());
      std::vector<Triangle>().swap(t);
    }
    map.triangles += static_cast<std::int64_t>(all.size());
    std::vector<std::vector<int>> in_band(static_cast<size_t>(bands));
    for (size_t t = 0; t < all.size(); ++t) {
      const auto& p = all[t].p;
      const double lo = std::min({p[0].y, p[1].y, p[2].y}) - 0.5, hi = std::max({p[0].y, p[1].y, p[2].y}) + 0.5;
      if (!(hi >= 0 && lo < map.height)) continue;
      const int b0 = std::max(0, static_cast<int>(std::max(lo, 0.0)) / kBand);
      const int b1 = std::min(bands - 1, static_cast<int>(std::min(hi, double(map.height))) / kBand);
      for (int b = b0; b <= b1; ++b) in_band[static_cast<size_t>(b)].push_back(static_cast<int>(t));
    }
    parallel_rows(bands, o.threads,
                  [&](int b) {
                    const int lo = b * kBand, hi = std::min(map.height, lo + kBand);
                    for (int t : in_band[static_cast<size_t>(b)]) rasterise(all[static_cast<size_t>(t)], lo, hi, map);
                  },
                  [&](auto&) {});
    first = last;
  }
  if (o.quantised)
    for (MapTexel& m : map.texels)
      if (m.patch >= 0) {
        m.u = static_cast<float>(quantise_parameter(m.u));
        m.v = static_cast<float>(quantise_parameter(m.v));
      }
  return map;
}

}  // namespace rpu::patch
