// Building the preliminary value map: tessellate every patch on a grid of its normalised domain
// (knot lines included, cells per knot span from the projected curvature), project, and z-buffer
// the triangles at the texel centres with perspective-correct (u, v).
#include "patch/preliminary_map.h"

#include <algorithm>
#include <cmath>

#include "common/parallel.h"

namespace rpu::patch {
namespace {

struct ScreenVertex {
  double x, y;    // map texel coordinates (texel (a, b) has its centre at (a + 0.5, b + 0.5))
  double inv_c;   // 1 / depth
  double u, v;
  bool front;     // in front of the eye
};

struct Triangle {
  ScreenVertex p[3];
  std::int32_t patch;
};

struct Projector {
  const scene::CameraFrame& cam;
  double sx, sy;  // image → map scale
  ScreenVertex operator()(const Vec3& p, double u, double v) const {
    const Vec3 q = p - cam.eye;
    const double a = dot(cam.U, q), b = dot(cam.V, q), c = dot(cam.W, q);
    ScreenVertex s{};
    s.front = c > 1e-12;
    if (!s.front) return s;
    s.x = (a / (c * cam.sigma) + 0.5 * cam.width) * sx;
    s.y = (0.5 * cam.height - b / (c * cam.sigma)) * sy;
    s.inv_c = 1.0 / c;
    s.u = u, s.v = v;
    return s;
  }
};

// Parameter values of the tessellation in one direction: every knot (B-spline, NURBS) is a grid
// line, and each knot span gets its own count n from the second differences of a 9×9 probe
// grid over the span (in texels): the chord error of n cells is about 8·d2/n².
std::vector<double> tessellation_samples(const PatchSurface& s, const Projector& proj,
                                         const MapOptions& o, bool along_u) {
  std::vector<double> knots = along_u ? s.knots_u() : s.knots_v();
  if (knots.empty()) knots = {0.0, 1.0};
  knots.erase(std::unique(knots.begin(), knots.end()), knots.end());
  std::vector<double> out{0.0};
  constexpr int kProbe = 8;
  for (size_t k = 0; k + 1 < knots.size(); ++k) {
    const double a = knots[k], b = knots[k + 1];
    int n = 0;
    if (o.grid > 0) {
      n = std::max(1, static_cast<int>(std::lround(o.grid * (b - a))));
    } else {
      double d2 = 0;
      bool behind = false;
      for (int c = 0; c <= kProbe && !behind; ++c) {
        const double across = double(c) / kProbe;
        ScreenVertex line[kProbe + 1];
        for (int i = 0; i <= kProbe; ++i) {
          const double t = a + (b - a) * i / kProbe;
          const double u = along_u ? t : across, v = along_u ? across : t;
          line[i] = proj(s.point(u, v), u, v);
          behind = behind || !line[i].front;
        }
        for (int i = 1; i < kProbe && !behind; ++i)
          d2 = std::max(d2, std::hypot(line[i - 1].x - 2 * line[i].x + line[i + 1].x,
                                       line[i - 1].y - 2 * line[i].y + line[i + 1].y));
      }
      n = behind ? o.max_grid
                 : std::clamp(static_cast<int>(std::ceil(std::sqrt(8.0 * d2 / o.max_chord_pixels))), 2,
                              o.max_grid);
    }
    for (int i = 1; i <= n; ++i) out.push_back(i == n ? b : a + (b - a) * i / n);
  }
  return out;
}

double edge(const ScreenVertex& a, const ScreenVertex& b, double x, double y) {
  return (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
}

void rasterise(const Triangle& t, int row_lo, int row_hi, PreliminaryMap& map) {
  const ScreenVertex &a = t.p[0], &b = t.p[1], &c = t.p[2];
  const double area = edge(a, b, c.x, c.y);
  if (area == 0.0 || !std::isfinite(area)) return;
  const double inv_area = 1.0 / area;
  const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x, b.x, c.x}) - 0.5)));
  const int x1 = std::min(map.width - 1, static_cast<int>(std::ceil(std::max({a.x, b.x, c.x}) - 0.5)));
  const int y0 = std::max(row_lo, static_cast<int>(std::floor(std::min({a.y, b.y, c.y}) - 0.5)));
  const int y1 = std::min(row_hi - 1, static_cast<int>(std::ceil(std::max({a.y, b.y, c.y}) - 0.5)));
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

PreliminaryMap build_preliminary_map(const std::vector<PatchSurface>& patches,
                                     const scene::CameraFrame& camera, const MapOptions& o) {
  PreliminaryMap map;
  map.image_width = camera.width, map.image_height = camera.height;
  map.width = o.width > 0 ? o.width : camera.width;
  map.height = o.height > 0 ? o.height : camera.height;
  map.texels.assign(static_cast<size_t>(map.width) * map.height, MapTexel{});
  const Projector proj{camera, double(map.width) / camera.width, double(map.height) / camera.height};

  // Tessellation, one patch per task.
  std::vector<std::vector<Triangle>> per_patch(patches.size());
  map.grid_per_patch.assign(patches.size(), 0);
  parallel_rows(static_cast<int>(patches.size()), o.threads,
                [&](int k) {
                  const PatchSurface& s = patches[static_cast<size_t>(k)];
                  const std::vector<double> us = tessellation_samples(s, proj, o, true);
                  const std::vector<double> vs = tessellation_samples(s, proj, o, false);
                  const int nu = static_cast<int>(us.size()), nv = static_cast<int>(vs.size());
                  map.grid_per_patch[static_cast<size_t>(k)] = std::max(nu, nv) - 1;
                  std::vector<ScreenVertex> vtx(us.size() * vs.size());
                  for (int i = 0; i < nu; ++i)
                    for (int j = 0; j < nv; ++j)
                      vtx[static_cast<size_t>(i * nv + j)] =
                          proj(s.point(us[static_cast<size_t>(i)], vs[static_cast<size_t>(j)]),
                               us[static_cast<size_t>(i)], vs[static_cast<size_t>(j)]);
                  auto& tris = per_patch[static_cast<size_t>(k)];
                  const auto at = [&](int i, int j) { return vtx[static_cast<size_t>(i * nv + j)]; };
                  for (int i = 0; i + 1 < nu; ++i)
                    for (int j = 0; j + 1 < nv; ++j) {
                      const ScreenVertex q[4] = {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
                      if (!(q[0].front && q[1].front && q[2].front && q[3].front)) continue;
                      tris.push_back({{q[0], q[1], q[2]}, k});
                      tris.push_back({{q[0], q[2], q[3]}, k});
                    }
                },
                [&](auto&) {});
  std::vector<Triangle> all;
  for (auto& t : per_patch) all.insert(all.end(), t.begin(), t.end());
  map.triangles = static_cast<std::int64_t>(all.size());

  // Rasterisation in bands of rows, each band owned by one worker.
  constexpr int kBand = 16;
  const int bands = (map.height + kBand - 1) / kBand;
  std::vector<std::vector<int>> in_band(static_cast<size_t>(bands));
  for (size_t t = 0; t < all.size(); ++t) {
    const auto& p = all[t].p;
    const double lo = std::min({p[0].y, p[1].y, p[2].y}) - 0.5, hi = std::max({p[0].y, p[1].y, p[2].y}) + 0.5;
    if (!(hi >= 0 && lo < map.height)) continue;
    const int b0 = std::max(0, static_cast<int>(lo) / kBand);
    const int b1 = std::min(bands - 1, static_cast<int>(hi) / kBand);
    for (int b = b0; b <= b1; ++b) in_band[static_cast<size_t>(b)].push_back(static_cast<int>(t));
  }
  parallel_rows(bands, o.threads,
                [&](int b) {
                  const int lo = b * kBand, hi = std::min(map.height, lo + kBand);
                  for (int t : in_band[static_cast<size_t>(b)]) rasterise(all[static_cast<size_t>(t)], lo, hi, map);
                },
                [&](auto&) {});
  if (o.quantised)
    for (MapTexel& m : map.texels)
      if (m.patch >= 0) {
        m.u = static_cast<float>(quantise_parameter(m.u));
        m.v = static_cast<float>(quantise_parameter(m.v));
      }
  return map;
}

}  // namespace rpu::patch
