#include "volume_cmd.h"

#include <fmt/format.h>

#include <cmath>
#include <iostream>

#include "builtin_scenes.h"
#include "common/error.h"
#include "patch/volume.h"

namespace rpu::app {

int run_volume(const std::string& scene_argument, const VolumeOptions& options,
               std::ostream& out) {
  if (options.slices < 1 || options.slices > 100000)
    throw Error("--slices", fmt::format("{} is out of range [1, 100000]", options.slices));
  if (options.slice_grid < 1 || options.slice_grid > 4096)
    throw Error("--slice-grid", fmt::format("{} is out of range [1, 4096]", options.slice_grid));
  const scene::Scene scene = load_scene_argument(scene_argument);
  const auto& patches = scene.patches;
  patch::require_bezier(patches, scene.source);

  const patch::ClosureReport closure =
      patch::check_closed_surface(patches, 1e-9, options.planar_openings);
  if (!closure.closed || !closure.consistent) {
    if (!options.no_closure_check)
      throw Error(scene.source + ": " + closure.problem.substr(0, closure.problem.find(':')),
                  closure.problem.substr(closure.problem.find(':') + 2) +
                      (options.planar_openings || !closure.consistent
                           ? " (--no-closure-check prints the numbers anyway)"
                           : " (--planar-openings accepts openings in planes z = const; "
                             "--no-closure-check prints the numbers anyway)"));
    std::cerr << "rpu: warning: " << scene.source << ": " << closure.problem
              << "; the numbers below are not the volume of a solid\n";
  }

  const double exact_signed = patch::exact_volume(patches);
  // Orientation: a closed, consistent model is either outward (positive) or inward (negative)
  // everywhere; inward models are reported with the signs flipped.
  const double sign = exact_signed < 0 ? -1.0 : 1.0;
  const double exact = sign * exact_signed;
  // The second route needs the plane caps of accepted openings (eq 21's form does not).
  const double gauss = sign * (patch::exact_volume_gauss(patches) +
                               patch::cap_volume_term(patches, closure.z_planar_openings));

  int max_u = 0, max_v = 0;
  for (const auto& p : patches) {
    max_u = std::max(max_u, p.degree_u);
    max_v = std::max(max_v, p.degree_v);
  }
  const std::string openings =
      closure.z_planar_openings.empty()
          ? std::string()
          : fmt::format(" (capped by planes z = const at {} open edges)",
                        closure.z_planar_openings.size());
  out << fmt::format("{}: {} Bézier patches (degree up to {}x{}), {}{}, normals {}\n",
                     scene.source, patches.size(), max_u, max_v,
                     closure.closed && closure.consistent ? "closed" : "NOT closed", openings,
                     sign > 0 ? "outward" : "inward (signs flipped below)");
  auto row = [&](const std::string& method, double value, bool reference = false) {
    const std::string error =
        reference ? "(reference)"
                  : (exact != 0 ? fmt::format("{:+.3e} %", 100.0 * (value - exact) / exact)
                                : std::string("-"));
    out << fmt::format("{:<46} {:>22.12f}  {}\n", method, value, error);
  };
  out << fmt::format("{:<46} {:>22}  {}\n", "method", "volume", "error vs exact");
  row("exact, Bernstein integrals (eqs 21, 25-27)", exact, true);
  row(closure.z_planar_openings.empty() ? "exact check, Gauss-Legendre of (1/3) S.n"
                                        : "exact check, Gauss-Legendre of (1/3) S.n + caps",
      gauss);
  for (int n : {10, 100})
    row(fmt::format("graphical {}x{} (eq 23, midpoint nodes)", n, n),
        sign * patch::graphical_volume(patches, n, n, patch::GraphicalNodes::kMidpoint));
  for (int n : {10, 100})
    row(fmt::format("graphical {}x{} (eqs 23-24 as printed)", n, n),
        sign * patch::graphical_volume(patches, n, n, patch::GraphicalNodes::kThesisEq24));
  const patch::SliceVolume slices = patch::slice_volume(patches, options.slices, options.slice_grid);
  row(fmt::format("slices: trapezoid, {} intervals along z", slices.slices), sign * slices.trapezoid);
  row(fmt::format("slices: Cavalieri, {} slabs along z", slices.slices), sign * slices.cavalieri);
  return 0;
}

}  // namespace rpu::app
