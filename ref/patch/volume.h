// Volume enclosed by a closed model of Bézier patches (seed 003, eqs 18-27, table 6).
//
// The thesis sums "curvilinear prisms" around the axis Oz (eqs 18-20), which is the divergence
// theorem with the field (x, y, 0)/2:
//   V = ½ Σ_patches ∬_[0,1]² (x·A + y·B) du dv,  A = Y_u Z_v − Z_u Y_v,  B = Z_u X_v − X_u Z_v
// (eqs 21-22; A and B are the x and y components of S_u × S_v). For Bézier patches the integrand
// is a polynomial and the integral is a finite sum of products of Bernstein integrals (eqs 25-27):
// the exact volume. Volumes are signed: positive when S_u × S_v points out of the body on every
// patch, negative when every patch points inward. check_closed_surface() tells whether that sign
// means anything (closed, consistently oriented).
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace rpu::patch {

// Throws rpu::Error ("patches[k]: ...") unless every patch is a Bézier patch with a complete
// control net (the volume code needs the polynomial form).
void require_bezier(const std::vector<scene::Patch>& patches, const std::string& source);

// Eqs 21, 25-27: the exact value of the thesis's integral, as sums of closed-form Bernstein
// product integrals ∫ B_i B'_j B_k = C·(s)!(N−s)!/(N+1)!.
double exact_volume(const std::vector<scene::Patch>& patches);

// A second exact value by a different route: V = ⅓ Σ ∬ S·(S_u × S_v) du dv (the field (x,y,z)/3)
// with Gauss–Legendre quadrature of an order that integrates the polynomial exactly, surface
// points and derivatives from PatchSurface. Equals exact_volume() on a closed surface.
double exact_volume_gauss(const std::vector<scene::Patch>& patches);

// Node placement of the graphical integration.
enum class GraphicalNodes {
  kMidpoint,    // u_i = (i + ½)/n: the midpoint rule, error O(1/n²) (what table 6's numbers show)
  kThesisEq24,  // u_i = i/(n − 1) with weight 1/n, as eqs 23-24 print it: error O(1/n)
};

// Eq 23: the thesis's integrand sampled on n × m nodes per patch.
double graphical_volume(const std::vector<scene::Patch>& patches, int n, int m,
                        GraphicalNodes nodes = GraphicalNodes::kMidpoint);

// The slice method the thesis compares against (trapezoid and Cavalieri, its ref [94]): the
// areas of cross-sections z = const (each patch tessellated on a grid × grid net, the section of
// the triangle mesh taken exactly and its signed area by the shoelace formula), then
//   trapezoid: `slices` equal intervals between the lowest and the highest z, planes at both
//              ends (nudged inside by 1e-9 of the height so a flat cap counts);
//   cavalieri: `slices` slabs of the same height, each with the area at its middle.
// The shape between the planes is ignored, which is where the method loses accuracy.
struct SliceVolume {
  int slices = 0;
  double z_min = 0, z_max = 0;
  double trapezoid = 0, cavalieri = 0;
};
SliceVolume slice_volume(const std::vector<scene::Patch>& patches, int slices, int grid = 256);

// The work of `rpu volume` (app/volume_cmd.cpp) in units of one control point visited by an
// evaluation or one term of the exact sums (limits::kMaxVolumeWork): the exact Bernstein sums
// ((n+1)(m+1))³ per patch, the Gauss–Legendre check, the graphical integration at 10×10 and
// 100×100 nodes with both node rules, and the slice method at `slice_grid` with `slices`
// intervals (two passes of (grid+1)² samples, 2·grid² triangles, and the planes' crossings).
long long volume_work(const std::vector<scene::Patch>& patches, int slice_grid, int slices = 10);

// Closedness and orientation: every patch boundary edge (sampled at 9 points, collapsed edges
// skipped) must be met by another patch edge traversed in the opposite direction (then the
// normals agree across it). `problem` names the first failure ("patches[3]: edge v = 0 ...").
//
// With `allow_z_planar_openings`, an unmatched edge lying in a plane z = const is accepted and
// listed instead: the opening it bounds is taken as closed by that plane. Eq 21's field has no
// z component, so such caps add nothing to exact_volume() (the thesis's tubes around Oz need no
// end caps); exact_volume_gauss() needs cap_volume_term() added.
struct PatchEdge {
  int patch = 0;
  int edge = 0;  // 0: v = 0 (u 0→1), 1: u = 1 (v 0→1), 2: v = 1 (u 1→0), 3: u = 0 (v 1→0)
};
struct ClosureReport {
  bool closed = true;      // every edge has a partner (or is an accepted planar opening)
  bool consistent = true;  // no partner runs in the same direction (flipped neighbour)
  int open_edges = 0, flipped_edges = 0;
  std::vector<PatchEdge> z_planar_openings;  // accepted openings (allow_z_planar_openings)
  std::string problem;
};
ClosureReport check_closed_surface(const std::vector<scene::Patch>& patches,
                                   double relative_tolerance = 1e-9,
                                   bool allow_z_planar_openings = false);

// The contribution of the plane caps closing `openings` to ⅓ ∬ S·n: for a cap at height z0
// bounded by the reversed patch edges, ⅓·z0·(signed area) = −⅓·z0·½ Σ ∫ (x y' − y x') dt along
// the edges (exact Gauss–Legendre along each polynomial edge).
double cap_volume_term(const std::vector<scene::Patch>& patches,
                       const std::vector<PatchEdge>& openings);

}  // namespace rpu::patch
