// Hardware descriptors: the scene compiler's constants quantised once, fed unchanged to the
// bit-accurate model and to the RTL. Every field's format is in docs/fixed-point.md.
#pragma once

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
  std::int32_t primitive = 0;
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
};

// Quantises a compiled scene for the given parameters. Throws rpu::Error when the parameters
// cannot hold the scene (a segment shorter than a few LSBs, a field of view too wide for the
// direction format, a camera so far from the scene or a pixel so small that a pixel spans fewer
// than Precision::kRefuse LSBs), naming the segment or parameter and the width to raise.
ModelScene quantize_scene(const scene::CompiledScene& scene, const HwParams& params);

}  // namespace rpu::ref
