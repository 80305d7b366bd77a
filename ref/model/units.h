// One C++ twin per hardware unit of the ray-processing unit (ARCHITECTURE.md), with the RTL
// module's parameters (HwParams) and ports (the structs below). Integer arithmetic only; every
// format is in docs/fixed-point.md and every narrowing is a named fixed:: operation.
#pragma once

#include <array>
#include <cstdint>

#include "model/descriptors.h"

namespace rpu::ref {

using fixed::Overflow;

// Wide integer vector for intermediates (format named where it is produced).
struct WVec3 {
  i128 x = 0, y = 0, z = 0;
  bool operator==(const WVec3&) const = default;
};

// ---- square root with the parameterised radicand width (rtl/rpu_sqrt) ----
// floor(sqrt(x)) for a radicand of format width `format_w`. When sqrt_w > 0 and the format is
// wider, the radicand is shifted right by an even 2s first and the root shifted left by s.
// A negative or over-wide radicand saturates and sets the overflow flag.
i128 sqrt_unit(i128 x, int format_w, int sqrt_w, Overflow& ovf);

// ---- ray generator (rtl/rpu_ray_gen) ----
struct RayGenOut {
  IVec3 v;                // unnormalised direction of the pixel centre, Q(4.FV)
  IVec3 vhat;             // v / |v|, Q(2.FV)
  WVec3 e_left, e_right;  // PVP edge vectors E_left(i), E_left(i+1), Q(4.FE+14)
  WVec3 e_top, e_bottom;  // E_top(j), E_top(j+1), Q(4.FE+14)
};
RayGenOut ray_generator(const HwParams& p, const CameraDesc& cam, int i, int j);

// ---- sphere unit: pred_1 and the search interval (rtl/rpu_sphere) ----
struct SearchInterval {
  bool pred1 = false;  // the ray meets the interpolation sphere in front of the eye
  i128 tc = 0;         // v̂·q, LSB (distance along the ray to the closest approach)
  i128 half_chord = 0; // sqrt(R² - |q × v̂|²), LSB
  WVec3 A, B;          // interval end points, LSB (saturated to coord_w)
  WVec3 AB;            // B - A, LSB
  i128 alpha = 0;      // t(τ = 0) = (A - p1)·d / L², Q(3.FT)
  i128 beta = 0;       // t(1) - t(0) = (B - A)·d / L², Q(3.FT)
};
SearchInterval sphere_unit(const HwParams& p, const IVec3& eye, const IVec3& vhat,
                           const SegmentDesc& s, Overflow& ovf);

// ---- chord parameter (part of rtl/rpu_sphere and rtl/rpu_texture) ----
// t = floor(dot · inv_m · 2^-(inv_s - FT)), saturated to Q(3.FT), for dot = (x - p1)·d (LSB²);
// inv_s < FT (segments with L² < 2^(FT-IW+3)) makes it an exact left shift.
i128 chord_parameter(const HwParams& p, const SegmentDesc& s, i128 dot, Overflow& ovf);

// ---- guide unit: g_k(t) of the closed form (rtl/rpu_guide) ----
// w = t(1-t) in Q(0.FT) (t clamped to [0, 1] first); returns g in LSB.
i128 guide_weight(const HwParams& p, i128 t);
i128 guide_unit(const HwParams& p, const GuideDesc& g, i128 L2, i128 w, Overflow& ovf);

// ---- curve point s(t) from the two guides (rtl/rpu_curve_point) ----
WVec3 curve_point_unit(const HwParams& p, const SegmentDesc& s, i128 t, i128 g1, i128 g2);

// ---- candidate evaluator (rtl/rpu_candidate) ----
struct Candidate {
  i128 t = 0;     // chord parameter, Q(3.FT)
  WVec3 X;        // curve point s(t), LSB
  WVec3 pr;       // ray point pr(τ), LSB
  i128 md = 0;    // |pr - X| (LSB) or |pr - X|² (LSB²) by the metric
};
// m is the candidate's τ index: τ = m · 2^-n, 0 ≤ m ≤ 2^n.
Candidate candidate_evaluator(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                              std::uint64_t m, Overflow& ovf);

// ---- IP step and the K-step process (rtl/rpu_ip_step, rtl/rpu_ip) ----
struct IpState {
  std::uint64_t tau = 0;  // τ index of the selected interval's start, n bits
  Candidate lo, hi;       // the selected interval's end candidates
  int k = 0;              // steps done
};
struct IpStepTrace {
  std::array<i128, 257> md{};  // md_j, j = 0..J
  std::array<i128, 256> sd{};  // sd_j = md_j + md_{j+1}
  int eta = 0;
};
// The initial state (step 0): candidates τ = 0 and τ = 1 evaluated.
IpState ip_start(const HwParams& p, const SegmentDesc& s, const SearchInterval& si, Overflow& ovf);
// Step k = state.k + 1: J - 1 new candidates, pair sums, lowest-index argmin.
IpState ip_step(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                const IpState& state, Overflow& ovf, IpStepTrace* trace = nullptr);
// The same step updating `state` in place (the model's hot loop).
void ip_step_in_place(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                      IpState& state, Overflow& ovf, IpStepTrace* trace = nullptr);
// Lowest-index argmin of the pair sums (rtl/rpu_argmin): strict < keeps the first minimum.
int argmin_lowest(const i128* sd, int count);

// The K-step process in both hardware forms: unrolled (stage k is its own unit with its shift
// n - n1·k wired in) or iterative (one step unit, a step counter selects the shift). They are
// the same arithmetic; `ip_process` picks by p.unrolled, and tests prove the forms equal.
IpState ip_process_unrolled(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                            Overflow& ovf);
IpState ip_process_iterative(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                             Overflow& ovf);
inline IpState ip_process(const HwParams& p, const SegmentDesc& s, const SearchInterval& si,
                          Overflow& ovf) {
  return p.unrolled ? ip_process_unrolled(p, s, si, ovf) : ip_process_iterative(p, s, si, ovf);
}

// ---- capture unit: the PVP plane-sign test (rtl/rpu_capture) ----
struct CaptureOut {
  bool hit = false;
  bool t_in_range = false;
  i128 depth = 0;  // c = (X - h)·W, Q(.FE) in LSB
  std::array<bool, 4> signs{};  // left, right, top, bottom tests passed
};
CaptureOut capture_unit(const HwParams& p, const CameraDesc& cam, const RayGenOut& ray,
                        const WVec3& X, i128 t);

// ---- texture path (rtl/rpu_ray_plane, rtl/rpu_texture) ----
struct PlanePoint {
  bool valid = false;  // the ray meets z = 0 in front of the eye, within the coordinate range
  WVec3 p0;            // LSB, z = 0
  i128 depth = 0;      // (p0 - h)·W, same format as CaptureOut::depth
};
PlanePoint ray_plane_unit(const HwParams& p, const CameraDesc& cam, const IVec3& vhat);
struct TextureOut {
  bool pr1 = false, pr2 = false, pr3 = false;
  bool covers = false;  // pr1 ∧ (pr2 ∨ pr3)
  i128 t = 0;
  WVec3 X;
};
TextureOut texture_unit(const HwParams& p, const SegmentDesc& s, const WVec3& p0, Overflow& ovf);

// ---- pixel resolve (rtl/rpu_resolve): nearest hit, equal depth → lower primitive id ----
struct Resolve {
  bool any = false;
  i128 depth = 0;
  std::int32_t primitive = -1;
  void offer(i128 d, std::int32_t id) {
    if (!any || d < depth || (d == depth && id < primitive)) {
      any = true;
      depth = d;
      primitive = id;
    }
  }
};

// ---- one work item through the whole curve pipeline ----
struct PairResult {
  bool hit = false;
  bool overflow = false;
  i128 depth = 0;
  std::uint64_t tau = 0;   // τ_K index
  i128 t = 0;              // chord parameter of the test point
  WVec3 X;                 // the test point
  SearchInterval interval;
};
PairResult process_curve_pair(const HwParams& p, const CameraDesc& cam, const RayGenOut& ray,
                              const SegmentDesc& s);
inline PairResult process_curve_pair(const HwParams& p, const CameraDesc& cam,
                                     const SegmentDesc& s, int i, int j) {
  return process_curve_pair(p, cam, ray_generator(p, cam, i, j), s);
}

}  // namespace rpu::ref
