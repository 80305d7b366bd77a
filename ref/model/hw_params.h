// Hardware parameters of the ray-processing unit, shared by the model, the RTL and the CLI.
// Every derived width of the datapath follows from these (docs/fixed-point.md).
//
// The parameters themselves are one table, hw_params.def (name, flag, sweep key, Verilog name,
// default, range, meaning): the fields of HwParams below and hw_param_table() are generated from
// it, and every other list of parameters (flags, sweep keys, JSON, job files, the RTL registry,
// the docs tables) walks that table.
#pragma once

#include <algorithm>

#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rpu::ref {

enum class Metric { kAbs, kSquared };  // md = |pr - s| (seed) or |pr - s|² (no square root)

// Each parameter's range in the table as constants: hw_range::coord_w_min, ::coord_w_max, ...
namespace hw_range {
#define RPU_HW_PARAM(field, type, key, flag, verilog, symbol, def, kind, lo, hi, ...) \
  inline constexpr int field##_min = lo, field##_max = hi;
#include "model/hw_params.def"
#undef RPU_HW_PARAM
}  // namespace hw_range

struct HwParams {
  // One member per entry of hw_params.def, with its default: n, n1, coord_w (CW), dir_frac (FV),
  // t_frac (FT), unit_frac (FU), edge_frac (FE), inv_w (IW), sqrt_w (SW), metric, unrolled (ip),
  // surf_w (LW), angle_w (AW), surf_n1_first (n1s), surfaces.
#define RPU_HW_PARAM(field, type, key, flag, verilog, symbol, def, ...) type field = def;
#include "model/hw_params.def"
#undef RPU_HW_PARAM

  bool operator==(const HwParams&) const = default;  // the same hardware (every parameter)

  int K() const { return n / n1; }
  int J() const { return 1 << n1; }

  // Surfaces: the steps of the sign search (docs/surfaces.md, "The search on a piece"). Step 1
  // takes surf_n1_first bits (seed: n1; at most n, so a short n takes all its bits in step 1),
  // each later step n1 and the last one what remains of n: surface_steps() steps, step k
  // dividing its interval into 2^surface_step_bits(k).
  int surface_first_bits() const { return surf_n1_first == 0 ? n1 : std::min(surf_n1_first, n); }
  int surface_steps() const { return 1 + (n - surface_first_bits() + n1 - 1) / n1; }
  int surface_step_bits(int k) const {
    if (k == 1) return surface_first_bits();
    return std::min(n1, n - surface_first_bits() - n1 * (k - 2));
  }
  // Indicator evaluations of one work item: the ends, then 2^b − 1 new candidates per step. The
  // hardware evaluates them all, hit or miss, so this is the cost of every item.
  int surface_evaluations() const {
    int e = 2;
    for (int k = 1; k <= surface_steps(); ++k) e += (1 << surface_step_bits(k)) - 1;
    return e;
  }

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
  // The candidate evaluator in the chord's 2-D frame (docs/fixed-point.md, "The candidate in the
  // chord's frame"): fixed formats, in units of the chord length L, independent of the widths
  // above (the frame is scale-free). FX: frame coordinates x, y; FG: the guides' offsets ĝ = g/L;
  // FW: w = t(1−t); FP: t, c2·t, s2·t into the guide products; EM: the frame vectors' mantissa
  // magnitude bits; FA: a flat guide's 1/(2η); FC: c2, s2. The offsets (and md) of step k keep
  // md_frac(k) = min(kFrameMdFracMax, kFrameMdFracBase + n1·k) fraction bits: the interval
  // shrinks by 2^-n1 per step, and so does the resolution the argmin needs.
  static constexpr int kFrameFrac = 24;
  static constexpr int kFrameGuideFrac = 17;
  static constexpr int kFrameWFrac = 28;
  static constexpr int kFrameProdFrac = 23;
  static constexpr int kFrameMant = 16;
  static constexpr int kFrameFlatFrac = 24;
  static constexpr int kFrameCosFrac = 16;
  static constexpr int kFrameMdFracBase = 14;
  static constexpr int kFrameMdFracMax = 20;
  static_assert(kFrameFrac >= kFrameGuideFrac && kFrameFrac >= kFrameMdFracMax &&
                kFrameWFrac >= kFrameGuideFrac && 2 * kFrameGuideFrac >= kFrameWFrac);
  // An arc guide's radicand η² + w with η ≤ 16 (kFlatRatio): below 2^(2·FG + 9).
  // The candidate's input widths (signed): x, y (|x| < 4), t, c2·t, s2·t (|t| < 8), W (|w| < 128),
  // a flat guide's offset (|ĝ| < 4).
  static constexpr int kCandXW = kFrameFrac + 3;
  static constexpr int kCandTW = kFrameProdFrac + 4;
  static constexpr int kCandWW = kFrameWFrac + 8;
  static constexpr int kCandAW = kFrameGuideFrac + 3;
  static constexpr int frame_radicand_w() { return 2 * kFrameGuideFrac + 9; }
  int md_frac(int k) const { return std::min(kFrameMdFracMax, kFrameMdFracBase + n1 * k); }
  // Upper limits of the widths a user may raise (the table's maxima; validate() checks them).
  static constexpr int kMaxCoordW = hw_range::coord_w_max;
  static constexpr int kMaxDirFrac = hw_range::dir_frac_max;
  int dir_w() const { return 2 + dir_frac; }             // v̂: Q(2.FV)
  int t_w() const { return 3 + t_frac; }                  // t: Q(3.FT)
  int unit_w() const { return 2 + unit_frac; }            // u: Q(2.FU)
  int edge_w() const { return kEdgeInt + edge_frac + kRayGuard; }  // E: Q(4.FE+14)
  int diff_w() const { return coord_w + 1; }              // d, q, A - p1, ...
  int guide_radicand_w() const { return 2 * coord_w + 10; }  // h² + L²w with h ≤ 16 L
  int dist_radicand_w() const { return 2 * coord_w + 8; }    // |pr - X|²
  int sphere_radicand_w() const { return 2 * coord_w + 5; }  // R² - |q|² + tc²
  // rpu_top's port widths (rtl/rpu_top.v's derived parameters; sim/harness/rtl_types.h).
  int ray_dir_w() const { return kDirInt + dir_frac + kRayGuard; }  // VgW: v, dx, dy Q(4.FV+14)
  int point_w() const { return coord_w + 3; }             // XW: the curve point X
  int ray_point_w() const { return coord_w + 2; }         // PRW: the ray point pr, a guide's g
  int guide_h_w() const { return coord_w + 5; }           // HW: a guide's h (or a, b)
  int r2_w() const { return 2 * coord_w + 1; }            // R2W: R² of the enclosing sphere
  int l2_w() const { return 2 * coord_w + 3; }            // L2W: L² = |d|²
  int guide_desc_w() const { return 2 + guide_h_w() + coord_w + t_frac + 3 * unit_w(); }  // GdW
  int camera_desc_w() const { return 9 * ray_dir_w() + 12 * edge_w() + 3 * coord_w; }    // CamW
  // SegW: {texture, primitive, p1, d, c0, R2, L2, inv_m, inv_s, two guides, the frame
  // descriptor, two frame guides}
  static constexpr int frame_desc_w() {  // {e1, e2, s, c2, s2, a1, a2}: `RPU_FRDW
    return 6 * (kFrameMant + 2) + 6 + 2 * (kFrameCosFrac + 2) + 2 * (kFrameFlatFrac - 3);
  }
  static constexpr int frame_guide_w() { return 2 + kFrameGuideFrac + 5 + frame_radicand_w(); }
  int segment_desc_w(int prim_w) const {
    return 1 + prim_w + 3 * coord_w + 3 * diff_w() + 3 * coord_w + r2_w() + l2_w() + inv_w + 7 +
           2 * guide_desc_w() + frame_desc_w() + 2 * frame_guide_w();
  }
  int depth_w() const { return coord_w + 4 + edge_w() + 2; }  // DepthW: (X - h)·W
  // Surfaces: guard bits G of the scaled local coordinates (x·k floored to G bits below the
  // local LSB before squaring), the fraction bits KF of the per-surface scale constants in
  // (0, 1] (Q(1.KF)), the mantissa width MW of the other constants (block floating point, as
  // inv_m), the fraction bits SF of the piece parameter s ∈ [0, 1], and the CORDIC width w (its
  // inputs |v| ≤ 2^(w-2) = 2^(LW+G+2): the scaled coordinates and the spiral's offsets fit).
  static constexpr int kSurfGuard = 2;
  static constexpr int kMaxSurfW = hw_range::surf_w_max;
  int surf_const_frac() const { return surf_w; }
  int surf_mant_w() const { return surf_w + 2; }
  int surf_cut_frac() const { return surf_w + 2; }
  int surf_cordic_w() const { return surf_w + kSurfGuard + 4; }
  int surf_desc_w() const { return 15 * surf_w + 61; }    // the indicator's word, `RPU_SDW
  // SurfDW: a descriptor of rpu_top's surface RAM (rtl/top/rpu_surf_desc.vh): {primitive, c0,
  // R2, origin, M, M's shift, y_min, y_max, end angle, end cos, end sin, indicator word}
  int surface_ram_desc_w(int prim_w) const {
    return prim_w + 6 * coord_w + r2_w() + 9 * surf_mant_w() + 7 + 2 * surf_w + angle_w +
           2 * (surf_const_frac() + 2) + surf_desc_w();
  }

  // Throws rpu::Error naming the flag when a value or combination is invalid: first each
  // parameter against its range in the table, then the combinations.
  void validate() const;
  std::string describe() const;  // one "name = value" line each, for `rpu config`
  std::string summary() const;   // one line, "n 16 n1 2 ... ip unrolled surf_w 24 angle_w 20"
};

// ---------------------------------------------------------------------------------------------
// The table (hw_params.def), one entry per parameter in the canonical order.

enum class HwParamId {
#define RPU_HW_PARAM(field, ...) field,
#include "model/hw_params.def"
#undef RPU_HW_PARAM
};

enum class HwParamKind {
  kRange,       // an integer in [min, max]
  kRangeOrOff,  // an integer in [min, max], or the one named value of choices (sqrt_w 0 = exact)
  kChoice,      // one of the named values of choices (metric abs|squared, ip unrolled|iterative)
};

struct HwChoice {
  std::string name;   // as flags and sweep files take it ("abs", "iterative", "exact")
  int value = 0;      // the member's value as an int (the Verilog parameter's value)
  std::string gloss;  // what `rpu config` adds in parentheses ("" = nothing)
};

struct HwParamInfo {
  HwParamId id;
  std::string_view field, key, flag, verilog, symbol;
  int def;  // the default as an int
  HwParamKind kind;
  int min, max;
  std::vector<HwChoice> choices;
  std::string_view constraint, what, meaning;
  int (*get)(const HwParams&);    // the member as an int
  void (*set)(HwParams&, int);    // the member from an int (any int; validate() judges it)

  bool legal(int v) const;              // in its range (alone; not the combinations)
  void check(int v) const;              // throws rpu::Error(flag, ...) unless legal
  const HwChoice* choice(int v) const;  // the named value v, or null
  const HwChoice* choice(std::string_view name) const;
  std::string choice_list() const;      // "abs or squared"
  std::string text(int v) const;        // as flags and JSON give it: "16", "abs"
  std::string describe(int v) const;    // as `rpu config` shows it: "exact (no pre-shift)"
  std::string range_text() const;       // "1–40", "0, 16–126", "abs, squared"
  std::string default_text() const;     // "16", "0 (exact)", "abs"
};

const std::vector<HwParamInfo>& hw_param_table();
const HwParamInfo& hw_param(HwParamId id);
const HwParamInfo* find_hw_param_key(std::string_view key);       // by sweep/JSON key
const HwParamInfo* find_hw_param_verilog(std::string_view name);  // by Verilog name
std::string hw_param_keys();  // "n, n1, ..., angle_w": every key, for messages

// The defaults with the given Verilog parameters set (a Verilated configuration's parameters;
// sim/harness/CMakeLists.txt generates the calls). Throws rpu::Error for an unknown name.
HwParams hw_params_from_verilog(std::initializer_list<std::pair<std::string_view, int>> values);

// The parameter tables of the docs, generated (`rpu config --markdown`): docs/fixed-point.md's
// "| name | flag | default | range | meaning |" table, and the rows of README.md's
// "| parameter | flag | default | meaning |" table for these parameters.
std::string hw_params_markdown();
std::string hw_params_readme_rows();

}  // namespace rpu::ref
