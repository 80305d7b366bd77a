// Hardware descriptors: the scene compiler's constants quantised once, fed unchanged to the
// bit-accurate model and to the RTL. Every field's format is in docs/fixed-point.md.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "common/vec3.h"
#include "fixed/fixed.h"
#include "model/hw_params.h"
#include "scene/compiled_scene.h"

namespace rpu::ref {

using fixed::i128;
using fixed::i64;

// An integer vector; its format (fraction bits) is named by the field that holds it.
struct IVec3 {
  i64 x = 0, y = 0, z = 0;
  bool operator==(const IVec3&) const = default;
};

// World → datapath: x_q = round((x - offset) · scale). Images are invariant to it.
struct Normalization {
  Vec3 offset;
  double scale = 1.0;  // LSBs per world unit
  IVec3 position(const Vec3& p) const;  // rounded to the LSB
};

enum class GuideMode : std::uint8_t { kStraight = 0, kArc = 1, kFlat = 2 };

struct GuideDesc {
  GuideMode mode = GuideMode::kStraight;
  IVec3 u;      // u_k, Q(2.FU)
  i64 h = 0;    // guide height h_k, LSB (arc)
  i64 a = 0;    // L²/(2h), LSB (flat)
  i64 b = 0;    // L²/(4h²), Q(0.FT) (flat)
};

// The chord's 2-D frame of a curve segment (docs/fixed-point.md, "The candidate in the chord's
// frame"): unit vectors e1, e2 ⊥ d (e1 along the first curved guide, e2 = d̂ × e1), stored as
// e/L = m · 2^-s with |m| < 2^(EM+1), the second guide's direction in the frame, and each guide's
// shape in units of L (η = h/L).
struct FrameGuide {
  GuideMode mode = GuideMode::kStraight;  // as GuideDesc::mode
  i64 eta = 0;    // η, Q(.FG) (arc)
  i64 eta2 = 0;   // eta², Q(.2FG) (arc): the root of eta2 is eta exactly, so ĝ(w = 0) = 0
  i64 a = 0;      // 1/(2η), Q(.FA) (flat)
};
struct FrameDesc {
  IVec3 e1, e2;   // mantissas of e1/L, e2/L
  int s = 0;      // their exponent: e/L = m · 2^-s, s = EM + bit_length(ceil L)
  i64 c2 = 0, s2 = 0;  // u2·e1, u2·e2, Q(1.FC) (0 when the second guide is straight)
  FrameGuide guide[2];
};

struct SegmentDesc {
  IVec3 p1;         // LSB
  IVec3 d;          // p2 - p1, LSB
  IVec3 c0;         // interpolation-sphere centre, LSB
  i128 R2 = 0;      // interpolation-sphere radius², LSB², rounded up with a margin
  i128 L2 = 0;      // |d|², LSB² (exact)
  i64 inv_m = 0;    // 1/L² ≈ inv_m · 2^-inv_s, inv_m normalised to IW bits
  int inv_s = 0;
  GuideDesc guide[2];
  i128 w0_2 = 0;    // texture half-width², LSB² (textures only)
  bool round_join = false;  // textures: covers = (pr1 ∧ pr3) ∨ pr2 (else the seed's eq 25)
  FrameDesc frame;  // the chord's 2-D frame (curves only)
  std::int32_t primitive = 0;
};

// A per-surface constant of any magnitude in block floating point (as 1/L²): value = m · 2^-s,
// the mantissa a signed HwParams::surf_mant_w()-bit integer, 2^(MW-3) ≤ |m| ≤ 2^(MW-2), or 0.
// A product x·c is floor(x · m · 2^-(s - keep)), keeping `keep` fraction bits (const_product).
struct ScaledConst {
  i64 m = 0;
  int s = 0;
  bool operator==(const ScaledConst&) const = default;
};

// The spiral and snail evaluate their turns in parallel lanes: phi_max ≤ 16π (the scene reader's
// limit) needs at most 8 (turns m = 0..7 in range at any azimuth).
inline constexpr int kSurfaceTurnLanes = 8;

// A vector-described surface (docs/algorithms.md §3, docs/surfaces.md) quantised for the surface
// path (rpu_surface_setup, rpu_indicator, rpu_surface_ip). "llsb" is the surface's local LSB:
// 2^local_frac llsb per local unit, local_frac chosen per surface so that its local bounding box
// fills a quarter of the signed LW range. Formats: docs/fixed-point.md, "Surfaces".
struct SurfaceDesc {
  scene::SurfaceType type = scene::SurfaceType::kEllipsoid;
  std::int32_t primitive = 0;
  // The bounding sphere in the sphere unit's port format (c0, R2 in LSB, LSB²); d = 0, so the
  // sphere unit's chord parameters α, β are 0 and unused.
  SegmentDesc bound;
  // World LSB → llsb: local = floor(M · (X − origin) · 2^-to_local_s), M's entries normalised to
  // signed MW bits as one block (rotationᵀ / scale folded with 2^local_frac / S).
  IVec3 origin;                // the placement `position`, LSB (rounded)
  std::array<i64, 9> to_local{};  // M, row-major
  int to_local_s = 0;
  int local_frac = 0;          // F (compiler and tests only: the datapath never shifts by it)
  // Slab (ellipsoid, relief ellipsoid, rocket): the piece is the part with y_min ≤ y ≤ y_max.
  i64 y_min = 0, y_max = 0;    // llsb
  // Azimuth range (spiral, snail): φ ∈ [0, phi_max]; phi_max = full_turns turns + end_angle.
  int full_turns = 0;          // floor(phi_max / 2π)
  std::uint64_t end_angle = 0; // phi_max mod 2π, binary angle (AW bits); 0: no second plane
  i64 end_cos = 0, end_sin = 0;  // cos, sin of end_angle, Q(1.KF): the end plane's
                                 // x·cos − z·sin = 0
  // Ellipsoid: (x·sx)² + (y·sy)² + (z·sz)² < r2 with sx = m/a, sy = m/b, sz = m/c, m = min(a,b,c).
  // Relief ellipsoid: (x·sx)² + (z·sz)² < k'²·(r2 − (y·sy)²), sx = m/(a·kmax), sy = m/b,
  //   sz = m/(c·kmax), kmax = d + |e|, m = min(a·kmax, b, c·kmax), k' = k/kmax.
  // Spiral: the section test (u·sx)² + (w·sy)² < r2 with sx = m/c, sy = m/b, m = min(b, c).
  i64 sx = 0, sy = 0, sz = 0;  // Q(1.KF), in (0, 1]
  i128 r2 = 0;                 // (m · 2^(F+G))², (llsb·2^G)², rounded
  // Relief: k' = kd + ke2·(sin(10φ + 9y) + sin(10φ − 9y)) (= d' + e'·sin 10φ·cos 9y).
  i64 kd = 0, ke2 = 0;         // d/kmax, e/(2·kmax), Q(1.KF)
  ScaledConst y_angle;         // 9y in binary-angle units per llsb: 9·2^(AW−F)/(2π)
  // Spiral: axis point (rho0 + aφ, kφ); snail: radius aφ (φ_m from ψ and m in binary angle).
  i64 rho0 = 0;                // R, llsb
  i64 a_turn = 0, k_turn = 0;  // 2π·a, 2π·k: llsb per full turn of φ
  // Rocket: fins a + (sin 5ψ − 1)·y·d/c (y ≤ 0), cylinder a, cone a − (y − b)·a/e (y ≥ b).
  i64 rocket_a = 0, rocket_b = 0;  // a, b, llsb
  ScaledConst fin, cone;       // d/c, a/e
};

struct CameraDesc {
  IVec3 eye;        // h, LSB
  IVec3 v0;         // direction of pixel (0,0)'s centre, Q(4.FV+14) (unnormalised)
  IVec3 dx, dy;     // per-column and per-row increments of v, Q(4.FV+14)
  IVec3 el0;        // left-edge vector of column 0: U + half·W, Q(4.FE+14)
  IVec3 et0;        // top-edge vector of row 0: (H/2)·σ·W - V, Q(4.FE+14)
  IVec3 sw;         // σ·W, Q(4.FE+14)
  IVec3 w;          // W, Q(4.FE+14)
  int width = 0, height = 0;
};

// How finely the quantised scene resolves a pixel (docs/fixed-point.md, "Cameras far from the
// scene"): the pixel footprint at the nearest segment in position LSBs, and the pixel angle in
// direction LSBs. The model's positions and ray directions err by a few LSBs, so a pixel must
// span many of both for the model to decide pixel membership as the float tracer does.
struct Precision {
  double position_lsb_per_pixel = 0;   // σ · (distance eye → nearest sphere) · scale; 0 = n/a
  double direction_lsb_per_pixel = 0;  // σ · 2^dir_frac
  // Below kHold of either, ref may differ from float-ip on more than the documented 0.1 % of
  // hit pixels (measured: docs/fixed-point.md); below kRefuse most hits would be wrong, and the
  // scene is refused.
  static constexpr double kHold = 4096.0;
  static constexpr double kRefuse = 64.0;
  // Widths that would reach kHold (0 when the current width already does).
  int coord_w_needed = 0;
  int dir_frac_needed = 0;
  // "" when both reach kHold; otherwise one line for a warning, naming the widths to raise.
  std::string warning;
};

struct ModelScene {
  std::string source;
  HwParams params;
  Normalization norm;
  Precision precision;
  CameraDesc camera;
  std::vector<SegmentDesc> curve_segments;    // same order as CompiledScene::curve_segments
  std::vector<SegmentDesc> texture_segments;  // same order as CompiledScene::texture_segments
  std::vector<SurfaceDesc> surfaces;          // same order as CompiledScene::surfaces
};

// Quantises a compiled scene for the given parameters. Throws rpu::Error when the parameters
// cannot hold the scene (a segment shorter than a few LSBs, a field of view too wide for the
// direction format, a camera so far from the scene or a pixel so small that a pixel spans fewer
// than Precision::kRefuse LSBs), naming the segment or parameter and the width to raise.
ModelScene quantize_scene(const scene::CompiledScene& scene, const HwParams& params);

// Throws rpu::Error when the scene has a kind of primitive the parameters build no path for
// (surfaces with `surfaces` off): the renderers call it, so such a build never returns an image
// without those primitives. The hardware's own answer to such an item is
// unbuilt_surface_result (model/top/rpu_top.h).
void require_built_kinds(const ModelScene& m);

}  // namespace rpu::ref
