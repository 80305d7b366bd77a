// The baseline of docs/algorithms.md §4: Martin, Cohen, Fish, Shirley, "Practical ray tracing of
// trimmed NURBS surfaces", Journal of Graphics Tools 5(1), 2000. Every patch is refined into Bézier
// sub-patches (knot insertion to full multiplicity, then de Casteljau subdivision until each
// sub-patch is flat), each sub-patch's control net bounds it (convex hull; NURBS: positive
// weights); a bounding-volume hierarchy over the sub-patches' boxes is traversed front to back
// by each ray, and Newton's method on the two-plane form of the ray (= S_x = S_y = 0,
// refiners.h `newton`) starts at the parameter centre of every leaf whose box the ray meets.
// Evaluation is PatchSurface's, the same as the thesis's refiners.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/limits.h"
#include "patch/patch_surface.h"
#include "patch/ray_frame.h"
#include "patch/refiners.h"

namespace rpu::patch {

// The plane through the eye perpendicular to the camera's forward axis: points with
// W·(P − eye) <= 0 are behind the eye, where no ray of the camera goes.
struct EyePlane {
  Vec3 eye, forward;
};

struct MartinOptions {
  // A sub-patch is flat when its control points deviate from the bilinear surface through its
  // corner points by at most `flatness` of its box diagonal.
  double flatness = 0.05;
  int max_depth = 10;        // subdivisions (u and v together) below each Bézier piece
  // With the camera's eye plane: sub-patches wholly behind it are dropped, and a flat sub-patch
  // that straddles it is split further (up to eye_plane_depth more levels), so that Newton's
  // start, the leaf's parameter centre, lies in front of the eye wherever the leaf can be seen.
  std::optional<EyePlane> eye_plane;
  int eye_plane_depth = 12;
  // Budgets (limits.h): Bézier pieces per patch after knot insertion, leaves in all; past them
  // the constructor throws rpu::Error(where, ...) before allocating more.
  long long max_pieces_per_patch = limits::kMaxMartinPiecesPerPatch;
  long long max_leaves = limits::kMaxMartinLeaves;
  std::string where = "patches";
  // Martin: a few Newton steps from the leaf's centre, converged as the thesis refiners are
  // (render_patches passes PatchRenderOptions::refine.tolerance_pixels).
  RefineOptions newton{.tolerance_pixels = 1e-2, .max_newton_iterations = 8};
};

struct MartinLeaf {
  int patch = 0;
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;  // normalised parameter rectangle
  Vec3 lo, hi;                            // box of the sub-patch's control points
};

struct MartinNode {
  Vec3 lo, hi;
  int first = 0;  // leaf: index into leaves; inner: index of the left child (right = left + 1)
  int count = 0;  // leaf: number of leaves (> 0); inner: 0
};

struct MartinStats {
  std::int64_t box_tests = 0, newton_starts = 0, newton_converged = 0, evaluations = 0;
};

class MartinBvh {
 public:
  MartinBvh(const std::vector<PatchSurface>& patches, const MartinOptions& options = {});

  struct Hit {
    bool hit = false;
    int patch = -1;
    double u = 0, v = 0, depth = 0;
  };
  // Nearest hit along the ray (depth = c > t_min).
  Hit intersect(const std::vector<PatchSurface>& patches, const RayFrame& ray, MartinStats& stats,
                double t_min = 1e-9) const;

  const std::vector<MartinLeaf>& leaves() const { return leaves_; }
  const std::vector<MartinNode>& nodes() const { return nodes_; }

 private:
  MartinOptions options_;
  std::vector<MartinLeaf> leaves_;
  std::vector<MartinNode> nodes_;
};

}  // namespace rpu::patch
