// `rpu volume SCENE`: the volume enclosed by the scene's Bézier patches, exact and by the
// approximations the thesis compares (seed 003, table 6): graphical integration (eq 23) at
// 10×10 and 100×100 nodes per patch, and the trapezoid / Cavalieri slice method.
#pragma once

#include <iosfwd>
#include <string>

namespace rpu::app {

struct VolumeOptions {
  int slices = 10;               // slice intervals of the trapezoid / Cavalieri method
  int slice_grid = 256;          // tessellation per patch side for the cross-section areas
  bool no_closure_check = false; // print the numbers for an open or inconsistent model (warning)
  bool planar_openings = false;  // accept openings in planes z = const as capped (eq 21 needs
                                 // no caps there; the thesis's tubes around Oz)
};

// Prints the table on `out`; warnings on stderr. Returns the exit status (0). Throws rpu::Error
// for a scene without patches, with non-Bézier patches, or (without no_closure_check) with
// patches that do not close a consistently oriented surface.
int run_volume(const std::string& scene_argument, const VolumeOptions& options, std::ostream& out);

}  // namespace rpu::app
