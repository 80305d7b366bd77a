// Hardware parameters of the ray-processing unit, shared by the model, the RTL and the CLI.
// Every derived width of the datapath follows from these (docs/fixed-point.md).
#pragma once

#include <string>

namespace rpu::ref {

enum class Metric { kAbs, kSquared };  // md = |pr - s| (seed) or |pr - s|² (no square root)

struct HwParams {
  int n = 16;            // result bits of the iterative process τ
  int n1 = 2;            // bits per step: 2^n1 sub-intervals (docs/algorithms.md §1.2); K = n / n1
  int coord_w = 24;      // CW: signed width of positions (scene normalised into it), LSB = 1 unit
  int dir_frac = 24;     // FV: fraction bits of the ray direction v̂ (|v̂| ≈ 1)
  int t_frac = 24;       // FT: fraction bits of the chord parameter t and of w = t(1-t)
  int unit_frac = 16;    // FU: fraction bits of the guide unit vectors u_k
  int edge_frac = 16;    // FE: fraction bits of the PVP edge vectors and the camera axis W
  int inv_w = 18;        // IW: mantissa bits of 1/L² (normalised, block floating point)
  int sqrt_w = 0;        // widest radicand a square-root unit takes (0 = as wide as needed);
                         // wider operands are pre-shifted right by an even amount
  Metric metric = Metric::kAbs;
  bool unrolled = true;  // K step units in a pipeline (one pair per cycle), or one step unit
                         // reused K times (iterative); the results are identical
  // Vector-described surfaces (docs/algorithms.md §3; docs/fixed-point.md, "Surfaces").
  int surf_w = 24;       // LW: signed width of surface-local coordinates; each surface is scaled
                         // by a power of two so that its bounding box fills a quarter of it
  int angle_w = 20;      // AW: bits of a binary angle (2^AW = one full turn) in the indicators

  bool operator==(const HwParams&) const = default;  // the same hardware (every parameter)

  int K() const { return n / n1; }
  int J() const { return 1 << n1; }

  // Derived widths (docs/fixed-point.md).
  static constexpr int kDirInt = 4;   // integer bits (incl. sign) of the unnormalised direction v
  static constexpr int kEdgeInt = 4;  // integer bits (incl. sign) of edge vectors
  static constexpr int kFlatRatio = 16;  // guides with h > 16·L use the series form
  // Guard bits of the ray generator's linear terms (v0 + i·dx + j·dy, el0 - i·σW, ...): image
  // sides are < 2^14, so i·(rounding of dx) stays below one LSB of the output format.
  static constexpr int kRayGuard = 14;
  // Fraction bits kept of the sphere unit's cross product q × v̂ before it is squared: the
  // squared ray distance |q × v̂|² is then exact to about 2^(2-G)·R LSB² (docs/fixed-point.md).
  static constexpr int kSphereGuard = 2;
  // Upper limits of the widths a user may raise (validate() checks them).
  static constexpr int kMaxCoordW = 40;
  static constexpr int kMaxDirFrac = 40;
  int dir_w() const { return 2 + dir_frac; }             // v̂: Q(2.FV)
  int t_w() const { return 3 + t_frac; }                  // t: Q(3.FT)
  int unit_w() const { return 2 + unit_frac; }            // u: Q(2.FU)
  int edge_w() const { return kEdgeInt + edge_frac + kRayGuard; }  // E: Q(4.FE+14)
  int diff_w() const { return coord_w + 1; }              // d, q, A - p1, ...
  int guide_radicand_w() const { return 2 * coord_w + 10; }  // h² + L²w with h ≤ 16 L
  int dist_radicand_w() const { return 2 * coord_w + 8; }    // |pr - X|²
  int sphere_radicand_w() const { return 2 * coord_w + 5; }  // R² - |q|² + tc²
  // Surfaces: guard bits G of the scaled local coordinates (x·k floored to G bits below the
  // local LSB before squaring), the fraction bits KF of the per-surface scale constants in
  // (0, 1] (Q(1.KF)), the mantissa width MW of the other constants (block floating point, as
  // inv_m), the fraction bits SF of the piece parameter s ∈ [0, 1], and the CORDIC width w (its
  // inputs |v| ≤ 2^(w-2) = 2^(LW+G+2): the scaled coordinates and the spiral's offsets fit).
  static constexpr int kSurfGuard = 2;
  static constexpr int kMaxSurfW = 36;
  int surf_const_frac() const { return surf_w; }
  int surf_mant_w() const { return surf_w + 2; }
  int surf_cut_frac() const { return surf_w + 2; }
  int surf_cordic_w() const { return surf_w + kSurfGuard + 4; }

  // Throws rpu::Error naming the flag when a value or combination is invalid.
  void validate() const;
  std::string describe() const;  // one "name = value" line each, for `rpu config`
};

}  // namespace rpu::ref
