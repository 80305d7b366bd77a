#include "patch/coons.h"

#include <string>

#include "common/error.h"

namespace rpu::patch {
namespace {

// Cubic Hermite basis (value at 0, value at 1, tangent at 0, tangent at 1).
std::array<double, 4> hermite(double t) {
  const double t2 = t * t, t3 = t2 * t;
  return {2 * t3 - 3 * t2 + 1, -2 * t3 + 3 * t2, t3 - 2 * t2 + t, t3 - t2};
}

// The 4×4 geometry matrix of eq 14.
std::array<std::array<Vec3, 4>, 4> geometry(const CoonsPatch& c) {
  std::array<std::array<Vec3, 4>, 4> g;
  for (int a = 0; a < 2; ++a) {
    g[a] = {c.p[a][0], c.p[a][1], c.pv[a][0], c.pv[a][1]};
    g[2 + a] = {c.pu[a][0], c.pu[a][1], c.puv[a][0], c.puv[a][1]};
  }
  return g;
}

}  // namespace

Vec3 evaluate_coons(const CoonsPatch& patch, double u, double v) {
  const auto g = geometry(patch);
  const auto hu = hermite(u), hv = hermite(v);
  Vec3 s;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) s += g[r][c] * (hu[r] * hv[c]);
  return s;
}

std::array<Vec3, 16> coons_to_bezier(const CoonsPatch& patch) {
  // Eq 17: B = M · G · Mᵀ.
  static constexpr double M[4][4] = {
      {1, 0, 0, 0}, {1, 0, 1.0 / 3, 0}, {0, 1, 0, -1.0 / 3}, {0, 1, 0, 0}};
  const auto g = geometry(patch);
  std::array<std::array<Vec3, 4>, 4> mg{};  // M · G
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 4; ++k) mg[r][c] += g[k][c] * M[r][k];
  std::array<Vec3, 16> b{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 4; ++k) b[r * 4 + c] += mg[r][k] * M[c][k];
  return b;
}

scene::Patch coons_to_bezier_patch(const CoonsPatch& patch, const scene::Color& color) {
  scene::Patch p;
  p.type = scene::PatchType::kBezier;
  p.degree_u = p.degree_v = 3;
  p.size_u = p.size_v = 4;
  const auto b = coons_to_bezier(patch);
  p.control_points.assign(b.begin(), b.end());
  p.color = color;
  return p;
}

std::vector<CoonsPatch> coons_grid(const std::vector<Vec3>& points, int rows, int cols,
                                   const CoonsGridOptions& options) {
  const std::string where = "coons grid";
  if (rows < 2 || cols < 2)
    throw Error(where, "needs at least 2 x 2 points, got " + std::to_string(rows) + " x " +
                           std::to_string(cols));
  if (points.size() != static_cast<size_t>(rows) * cols)
    throw Error(where, std::to_string(points.size()) + " points for a " + std::to_string(rows) +
                           " x " + std::to_string(cols) + " grid");
  for (size_t k = 0; k < points.size(); ++k)
    if (!is_finite(points[k]))
      throw Error(where + ": point " + std::to_string(k), "not a finite point");

  auto wrap = [](int k, int n, bool closed) { return closed ? (k % n + n) % n : k; };
  auto at = [&](int i, int j) {
    return points[wrap(i, rows, options.closed_u) * cols + wrap(j, cols, options.closed_v)];
  };
  // Eq 15: central differences; one-sided on an open border.
  auto tangent = [&](int i, int j, bool along_u) {
    const int n = along_u ? rows : cols;
    const bool closed = along_u ? options.closed_u : options.closed_v;
    const int k = along_u ? i : j;
    auto shifted = [&](int d) { return along_u ? at(i + d, j) : at(i, j + d); };
    if (closed || (k > 0 && k < n - 1)) return (shifted(1) - shifted(-1)) * 0.5;
    return k == 0 ? shifted(1) - shifted(0) : shifted(0) - shifted(-1);
  };
  auto twist = [&](int i, int j) {
    switch (options.twist) {
      case TwistRule::kZero:
        return Vec3{};
      case TwistRule::kCentralDifference: {
        // Difference of the v tangents along u (one-sided on open borders, as the tangents).
        const bool inner = options.closed_u || (i > 0 && i < rows - 1);
        if (inner) return (tangent(i + 1, j, false) - tangent(i - 1, j, false)) * 0.5;
        return i == 0 ? tangent(1, j, false) - tangent(0, j, false)
                      : tangent(i, j, false) - tangent(i - 1, j, false);
      }
      case TwistRule::kThesisCross:
      default:
        return cross(tangent(i, j, true), tangent(i, j, false));  // eq 16
    }
  };

  const int cells_u = options.closed_u ? rows : rows - 1;
  const int cells_v = options.closed_v ? cols : cols - 1;
  std::vector<CoonsPatch> out;
  out.reserve(static_cast<size_t>(cells_u) * cells_v);
  for (int i = 0; i < cells_u; ++i)
    for (int j = 0; j < cells_v; ++j) {
      CoonsPatch c;
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) {
          // Tangents and twists are taken at the grid point; on a closed grid the point index
          // wraps, so neighbouring cells share them and join with C1 continuity.
          const int gi = wrap(i + a, rows, options.closed_u), gj = wrap(j + b, cols, options.closed_v);
          c.p[a][b] = at(gi, gj);
          c.pu[a][b] = tangent(gi, gj, true);
          c.pv[a][b] = tangent(gi, gj, false);
          c.puv[a][b] = twist(gi, gj);
        }
      out.push_back(c);
    }
  return out;
}

std::vector<scene::Patch> coons_grid_bezier(const std::vector<Vec3>& points, int rows, int cols,
                                            const CoonsGridOptions& options,
                                            const scene::Color& color) {
  std::vector<scene::Patch> out;
  for (const auto& c : coons_grid(points, rows, cols, options))
    out.push_back(coons_to_bezier_patch(c, color));
  return out;
}

}  // namespace rpu::patch
