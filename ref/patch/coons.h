// Bicubic Coons patches in Hermite form and their conversion to Bézier (seed 003, eqs 14-17):
// the thesis's local interpolation of a topologically rectangular grid of surface points.
#pragma once

#include <array>
#include <vector>

#include "common/vec3.h"
#include "scene/scene.h"

namespace rpu::patch {

// The Hermite geometry of one bicubic Coons patch (eq 14): corner points, tangent vectors along
// u and v, twist vectors. Index [a][b] is the corner (u, v) = (a, b), a, b ∈ {0, 1}.
struct CoonsPatch {
  std::array<std::array<Vec3, 2>, 2> p, pu, pv, puv;
};

// S(u, v) = H(u) · G · H(v)ᵀ with the cubic Hermite basis H = (h00, h01, h10, h11) and G the
// 4×4 matrix of eq 14 (rows: P(0,·), P(1,·), Pu(0,·), Pu(1,·); columns: (·,0), (·,1), v-tangent
// at (·,0), v-tangent at (·,1)).
Vec3 evaluate_coons(const CoonsPatch& patch, double u, double v);

// Eq 17: the 4×4 Bézier control net of the same surface, B = M · G · Mᵀ with
// M = [[1,0,0,0],[1,0,1/3,0],[0,1,0,-1/3],[0,1,0,0]]. Row-major, rows of constant u index
// (control point (iu, iv) at [iu * 4 + iv]), as scene::Patch.
std::array<Vec3, 16> coons_to_bezier(const CoonsPatch& patch);
scene::Patch coons_to_bezier_patch(const CoonsPatch& patch,
                                   const scene::Color& color = {1.0, 1.0, 1.0});

// How the twist vectors of a grid are chosen.
enum class TwistRule {
  kThesisCross,        // eq 16: P^uv = P^u × P^v (as the thesis; not invariant under scaling)
  kZero,               // Ferguson patches: P^uv = 0
  kCentralDifference,  // ¼·(P[i+1][j+1] − P[i+1][j−1] − P[i−1][j+1] + P[i−1][j−1])
};

struct CoonsGridOptions {
  bool closed_u = false;  // the grid wraps around in i (row rows−1 joins row 0)
  bool closed_v = false;  // the grid wraps around in j
  TwistRule twist = TwistRule::kThesisCross;
};

// The Coons patches interpolating a grid of points, points[i * cols + j], i running along u and
// j along v. Tangents by central differences (eq 15; the thesis prints the u and v indices of
// eq 15 swapped with respect to eq 14, here the u tangent is the difference along i, the
// direction u runs in), one-sided differences on open borders. Patches are returned row-major
// over the cells ((rows−1 or rows) × (cols−1 or cols) of them). Throws rpu::Error on a grid
// smaller than 2 × 2, a size mismatch or non-finite points.
std::vector<CoonsPatch> coons_grid(const std::vector<Vec3>& points, int rows, int cols,
                                   const CoonsGridOptions& options = {});

// The same grid as Bézier patches (eq 17 for every cell).
std::vector<scene::Patch> coons_grid_bezier(const std::vector<Vec3>& points, int rows, int cols,
                                            const CoonsGridOptions& options = {},
                                            const scene::Color& color = {1.0, 1.0, 1.0});

}  // namespace rpu::patch
