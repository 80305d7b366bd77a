#include "model/hw_params.h"

#include <fmt/format.h>

#include "common/error.h"

namespace rpu::ref {
namespace {

void check_range(const char* flag, const char* what, int v, int lo, int hi) {
  if (v < lo || v > hi)
    throw Error(flag, fmt::format("{} must be in [{}, {}], got {}", what, lo, hi, v));
}

}  // namespace

void HwParams::validate() const {
  check_range("--n1", "bits per step", n1, 1, 8);
  check_range("--n", "result bits", n, 1, 40);
  if (n % n1 != 0)
    throw Error("--n", fmt::format("n = {} is not a multiple of n1 = {} (K = n/n1 steps)", n, n1));
  check_range("--coord-w", "coordinate width", coord_w, 12, kMaxCoordW);
  check_range("--dir-frac", "direction fraction bits", dir_frac, 8, kMaxDirFrac);
  check_range("--t-frac", "chord-parameter fraction bits", t_frac, 8, 48);
  check_range("--unit-frac", "guide-direction fraction bits", unit_frac, 8, 40);
  check_range("--edge-frac", "edge-vector fraction bits", edge_frac, 8, 40);
  check_range("--inv-w", "1/L² mantissa width", inv_w, 8, 40);
  if (sqrt_w != 0) check_range("--sqrt-w", "square-root radicand width", sqrt_w, 16, 126);
  check_range("--surf-w", "surface-local coordinate width", surf_w, 16, kMaxSurfW);
  check_range("--angle-w", "binary-angle width", angle_w, 12, 32);
  // The surface CORDIC runs AW micro-rotations on surf_cordic_w() = LW + 6 bits; it takes at
  // most its width + 4 stages (rpu_cordic.h).
  if (angle_w > surf_cordic_w() + 4)
    throw Error("--angle-w", fmt::format("angle_w = {} needs more CORDIC stages than a {}-bit "
                                         "CORDIC takes (surf_w = {}: at most {})", angle_w,
                                         surf_cordic_w(), surf_w, surf_cordic_w() + 4));
  // The widest intermediate products must fit 126 bits (the model's __int128 and a sane RTL).
  const int alpha_product = 2 * diff_w() + 3 + inv_w + 1;  // ((A - p1)·d)·m
  if (alpha_product > 126)
    throw Error("--coord-w", fmt::format("coord_w = {} with inv_w = {} needs a {}-bit product "
                                         "(limit 126)", coord_w, inv_w, alpha_product));
  const int edge_product = (coord_w + 5) + (edge_w() + 15) + 2;  // q·E(i)
  if (edge_product > 126)
    throw Error("--edge-frac", fmt::format("edge_frac = {} with coord_w = {} needs a {}-bit "
                                           "product (limit 126)", edge_frac, coord_w, edge_product));
  const int weight_product = 2 * coord_w + 3 + t_frac;  // L²·w in the guide unit
  if (weight_product > 126)
    throw Error("--t-frac", fmt::format("t_frac = {} with coord_w = {} needs a {}-bit product "
                                        "L²·w (limit 126)", t_frac, coord_w, weight_product));
}

std::string HwParams::describe() const {
  return fmt::format(
      "n          = {}\nn1         = {}\nK          = {}\nper step   = {} sub-intervals, {} candidate "
      "points ({} new after the first step)\ncoord_w    = {}\ndir_frac   = {}\nt_frac     = {}\nunit_frac  = {}\n"
      "edge_frac  = {}\ninv_w      = {}\nsqrt_w     = {}\nmetric     = {}\nip         = {}\n"
      "surf_w     = {}\nangle_w    = {}\n",
      n, n1, K(), J(), J() + 1, J() - 1, coord_w, dir_frac, t_frac, unit_frac, edge_frac, inv_w,
      sqrt_w == 0 ? std::string("exact (no pre-shift)") : std::to_string(sqrt_w),
      metric == Metric::kAbs ? "abs" : "squared",
      unrolled ? "unrolled (K step units, one pair per cycle)" : "iterative (one step unit, K passes)",
      surf_w, angle_w);
}

}  // namespace rpu::ref
