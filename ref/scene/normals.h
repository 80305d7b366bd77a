// Normals of a polyline when the scene file gives none (docs/algorithms.md §1, "Normals when
// the input has none").
#pragma once

#include <vector>

#include "common/vec3.h"

namespace rpu::scene {

// For each point: T = p_{i+1} - p_{i-1}; n_i = the component of (p_{i+1} - p_i) + (p_{i-1} - p_i)
// perpendicular to T, normalised (it points to the concave side). Open ends use the reflected
// neighbour (2p_1 - p_2). Where that component vanishes (locally straight) the normal is a
// deterministic perpendicular of T: within the plane z = 0 when `planar` (textures), otherwise
// T × e for the coordinate axis e least aligned with T.
std::vector<Vec3> derive_normals(const std::vector<Vec3>& points, bool closed, bool planar);

// A unit normal perpendicular to the chord d, as above (within z = 0 when `planar`): at both ends
// of a segment it makes both guides straight ("smooth": false). Zero when d has no direction.
Vec3 chord_perpendicular(const Vec3& d, bool planar);

}  // namespace rpu::scene
