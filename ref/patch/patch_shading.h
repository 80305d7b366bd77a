// Pictures of patch renderings (`rpu render --shade`): Lambert shading with the surface normal
// S_u × S_v at the hit and a light at the eye, I = ambient + (1 − ambient)·|n·l|. Only for
// looking at: the default images keep exact flat colours (README "Command line") for pixel
// comparison.
#pragma once

#include <vector>

#include "patch/patch_surface.h"
#include "patch/tessellated_reference.h"
#include "scene/camera.h"

namespace rpu::patch {

inline constexpr double kShadeAmbient = 0.15;

// Rescales the RGB (3 floats per pixel, row-major) of every pixel `hits` marks as a patch hit
// by its Lambert factor.
void shade_patch_pixels(std::vector<float>& rgb, const PatchHitMap& hits,
                        const std::vector<PatchSurface>& surfaces, const scene::CameraFrame& camera);

}  // namespace rpu::patch
