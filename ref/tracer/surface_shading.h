// Pictures of surface renderings (`rpu render --shade`, docs/surfaces.md "Shading"): Lambert
// shading with the normal of the indicator's continuous form (central differences in the local
// frame, taken to world by the rotation, faced toward the eye) and a light at the eye,
// I = ambient + (1 − ambient)·(n·l). Only for looking at: the default images keep exact flat
// colours (README "Command line") for pixel comparison.
#pragma once

#include <vector>

#include "image/frame.h"
#include "scene/compiled_scene.h"

namespace rpu::tracer {

// Unit world normal of surface `s` at the world point X, faced toward the eye (n·v ≤ 0 for the
// ray direction v). A zero vector when the gradient vanishes or is not finite.
Vec3 surface_normal(const scene::CompiledSurface& s, const Vec3& X, const Vec3& v);

// Rescales the RGB (3 floats per pixel, row-major) of every pixel of `frame` won by a surface
// by its Lambert factor; the hit point is recovered from the pixel's depth along its centre ray.
void shade_surface_pixels(std::vector<float>& rgb, const image::Frame& frame,
                          const scene::CompiledScene& sc);

}  // namespace rpu::tracer
