#include "volume_cmd.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

#include "builtin_scenes.h"
#include "common/error.h"
#include "common/limits.h"
#include "patch/volume.h"

namespace rpu::app {

int run_volume(const std::string& scene_argument, const VolumeOptions& options,
               std::ostream& out) {
  if (options.slices < 1 || options.slices > 100000)
    throw Error("--slices", fmt::format("{} is out of range [1, 100000]", options.slices));
  if (options.slice_grid < 1 || options.slice_grid > 4096)
    throw Error("--slice-grid", fmt::format("{} is out of range [1, 4096]", options.slice_grid));
  const scene::Scene scene = load_scene_argument(scene_argument);
  patch::require_bezier(scene.patches, scene.source);

  // The work, from the patches and the flags, before any of it is done (README, "Limits").
  const long long work = patch::volume_work(scene.patches, options.slice_grid, options.slices);
  if (work > limits::kMaxVolumeWork) {
    int fits = 0;  // the largest --slice-grid within the budget, if any
    for (int lo = 1, hi = options.slice_grid - 1; lo <= hi;) {
      const int mid = lo + (hi - lo) / 2;
      if (patch::volume_work(scene.patches, mid, options.slices) <= limits::kMaxVolumeWork) fits = mid, lo = mid + 1;
      else hi = mid - 1;
    }
    throw Error(scene.source, fmt::format(
        "measuring {} patches with --slices {} at --slice-grid {} takes about {} work units; at "
        "most {} (README, \"Limits\"); {}", scene.patches.size(), options.slices,
        options.slice_grid, work,
        limits::kMaxVolumeWork,
        fits > 0 ? fmt::format("--slice-grid {} or less fits", fits)
                 : std::string("lower --slices, or the model has too many patches (or of too high "
                               "a degree) at any --slice-grid")));
  }

  // Scale invariance: the model is measured scaled by a power of two 2^k (exact) that brings its
  // largest coordinate into [1, 2), and every volume is scaled back by 2^(−3k). A volume that
  // then leaves the range of normal doubles is refused, not printed as 0 or infinity.
  double largest = 0;
  for (const auto& p : scene.patches)
    for (const Vec3& c : p.control_points)
      largest = std::max({largest, std::fabs(c.x), std::fabs(c.y), std::fabs(c.z)});
  if (!(largest > 0.0))
    throw Error(scene.source, "every control point is at the origin: the patches enclose no volume");
  const int k = -std::ilogb(largest);
  std::vector<scene::Patch> patches = scene.patches;
  for (auto& p : patches)
    for (Vec3& c : p.control_points) c = Vec3{std::ldexp(c.x, k), std::ldexp(c.y, k), std::ldexp(c.z, k)};
  const auto world = [&](double v) {
    const double w = std::ldexp(v, -3 * k);
    if (v != 0.0 && !(std::isfinite(w) && std::fabs(w) >= std::numeric_limits<double>::min()))
      throw Error(scene.source, fmt::format(
          "the volume is about {:.6g}·2^{} in world units, outside the range of double precision "
          "numbers (2^-1022 to 2^1024); scale the model into range", v, -3 * k));
    return w;
  };

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

  const double exact_signed = world(patch::exact_volume(patches));
  // Orientation: a closed, consistent model is either outward (positive) or inward (negative)
  // everywhere; inward models are reported with the signs flipped.
  const double sign = exact_signed < 0 ? -1.0 : 1.0;
  const double exact = sign * exact_signed;
  // The second route needs the plane caps of accepted openings (eq 21's form does not).
  const double gauss = sign * world(patch::exact_volume_gauss(patches) +
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
  // Twelve decimals for volumes of ordinary size (as docs/patches.md's tables), thirteen
  // significant digits in scientific notation for very small or very large ones, so that no
  // model prints as 0.000000000000.
  const bool fixed = std::fabs(exact) >= 1e-3 && std::fabs(exact) < 1e12;
  auto row = [&](const std::string& method, double value, bool reference = false) {
    const std::string error =
        reference ? "(reference)"
                  : (exact != 0 ? fmt::format("{:+.3e} %", 100.0 * (value - exact) / exact)
                                : std::string("-"));
    out << (fixed ? fmt::format("{:<46} {:>22.12f}  {}\n", method, value, error)
                  : fmt::format("{:<46} {:>22.12e}  {}\n", method, value, error));
  };
  out << fmt::format("{:<46} {:>22}  {}\n", "method", "volume", "error vs exact");
  row("exact, Bernstein integrals (eqs 21, 25-27)", exact, true);
  row(closure.z_planar_openings.empty() ? "exact check, Gauss-Legendre of (1/3) S.n"
                                        : "exact check, Gauss-Legendre of (1/3) S.n + caps",
      gauss);
  for (int n : {10, 100})
    row(fmt::format("graphical {}x{} (eq 23, midpoint nodes)", n, n),
        sign * world(patch::graphical_volume(patches, n, n, patch::GraphicalNodes::kMidpoint)));
  for (int n : {10, 100})
    row(fmt::format("graphical {}x{} (eqs 23-24 as printed)", n, n),
        sign * world(patch::graphical_volume(patches, n, n, patch::GraphicalNodes::kThesisEq24)));
  const patch::SliceVolume slices = patch::slice_volume(patches, options.slices, options.slice_grid);
  row(fmt::format("slices: trapezoid, {} intervals along z", slices.slices), sign * world(slices.trapezoid));
  row(fmt::format("slices: Cavalieri, {} slabs along z", slices.slices), sign * world(slices.cavalieri));
  return 0;
}

}  // namespace rpu::app
