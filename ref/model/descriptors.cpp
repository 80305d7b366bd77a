#include "model/descriptors.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "common/error.h"
#include "model/surface/surface_descriptors.h"

namespace rpu::ref {
namespace {

// Minimum quantised segment length: shorter segments cannot be told from their rounding.
constexpr double kMinSegmentLsb = 8.0;
// Positions use at most this fraction of the signed range, leaving headroom for the sums of
// the datapath (pr, X between range-limited end points plus guide offsets).
constexpr double kRangeUse = 0.875;

i64 round_to(double v, int frac, const char* what) {
  const double s = std::ldexp(v, frac);
  if (!(std::fabs(s) < 9.0e18)) throw Error(what, "value out of the 64-bit descriptor range");
  return static_cast<i64>(std::llround(s));
}

IVec3 quantize_vec(const Vec3& v, int frac, const char* what) {
  return {round_to(v.x, frac, what), round_to(v.y, frac, what), round_to(v.z, frac, what)};
}

struct Bounds {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi = -lo;
  void add(const Vec3& p, double r = 0.0) {
    lo = {std::min(lo.x, p.x - r), std::min(lo.y, p.y - r), std::min(lo.z, p.z - r)};
    hi = {std::max(hi.x, p.x + r), std::max(hi.y, p.y + r), std::max(hi.z, p.z + r)};
  }
};

[[noreturn]] void fov_too_wide(const std::string& source, double reach, double limit) {
  throw Error(source + ": camera.fov_deg",
              fmt::format("field of view too wide for the ray generator's direction format (a "
                          "pixel direction component reaches {:.3g}; limit {})", reach, limit));
}

void check_dir(const IVec3& v, int frac, int int_bits, const std::string& source) {
  const i64 limit = i64{1} << (frac + int_bits - 1);
  for (i64 c : {v.x, v.y, v.z})
    if (c >= limit || c <= -limit)
      fov_too_wide(source, std::ldexp(static_cast<double>(c), -frac), 1 << (int_bits - 1));
}

SegmentDesc quantize_segment(const scene::CompiledSegment& cs, const Normalization& norm,
                             const HwParams& p, const std::string& where) {
  SegmentDesc s;
  s.primitive = cs.primitive;
  s.p1 = norm.position(cs.geom.p1);
  const IVec3 p2 = norm.position(cs.geom.p2);
  s.d = {p2.x - s.p1.x, p2.y - s.p1.y, p2.z - s.p1.z};
  s.L2 = i128{s.d.x} * s.d.x + i128{s.d.y} * s.d.y + i128{s.d.z} * s.d.z;
  const double L = std::sqrt(static_cast<double>(s.L2));
  if (L < kMinSegmentLsb)
    throw Error(where, fmt::format("segment quantises to {:.3g} LSB (minimum {}): coord_w = {} is "
                                   "too small to hold this scene",
                                   L, kMinSegmentLsb, p.coord_w));
  // Centre: floor of the midpoint (within √3/2 LSB of it); radius grown by 2 LSB + 2^-20 so the
  // quantised sphere still holds the whole curve.
  s.c0 = {(s.p1.x + p2.x) >> 1, (s.p1.y + p2.y) >> 1, (s.p1.z + p2.z) >> 1};
  const double R = 0.5 * L * (1.0 + 0x1p-20) + 2.0;
  s.R2 = static_cast<i128>(std::ceil(R * R));
  // 1/L² = inv_m · 2^-inv_s with 2^(IW-2) < inv_m ≤ 2^(IW-1): an integer division.
  s.inv_s = p.inv_w - 2 + fixed::bit_length(static_cast<fixed::u128>(s.L2));
  s.inv_m = static_cast<i64>(
      fixed::udiv(fixed::u128{1} << s.inv_s, static_cast<fixed::u128>(s.L2), p.inv_w));
  for (int k = 0; k < 2; ++k) {
    const scene::Guide& g = cs.geom.guide[k];
    GuideDesc& q = s.guide[k];
    if (g.straight) continue;
    q.u = quantize_vec(g.u, p.unit_frac, "guide direction");
    const double h = g.h * norm.scale;
    if (h <= HwParams::kFlatRatio * L) {
      q.mode = GuideMode::kArc;
      q.h = static_cast<i64>(std::llround(h));
    } else {
      q.a = static_cast<i64>(std::llround(static_cast<double>(s.L2) / (2.0 * h)));
      q.b = static_cast<i64>(std::llround(std::ldexp(static_cast<double>(s.L2) / (4.0 * h * h), p.t_frac)));
      q.mode = q.a > 0 ? GuideMode::kFlat : GuideMode::kStraight;
    }
  }
  if (cs.half_width > 0.0) {
    const double w = cs.half_width * norm.scale;
    s.w0_2 = static_cast<i128>(std::llround(w * w));
    s.round_join = cs.round_join;
  }
  return s;
}

// The chord's 2-D frame of a quantised curve segment (docs/fixed-point.md, "The candidate in the
// chord's frame"). e1 is the first curved guide's direction (else the second's, else a fixed
// perpendicular of d), made exactly perpendicular to the quantised d in double; e2 = d̂ × e1.
FrameDesc quantize_frame(const scene::CompiledSegment& cs, const SegmentDesc& s,
                         const Normalization& norm) {
  FrameDesc f;
  const scene::Segment& g = cs.geom;
  const double L = std::sqrt(static_cast<double>(s.L2));
  const Vec3 dh = normalize(Vec3{static_cast<double>(s.d.x), static_cast<double>(s.d.y),
                                 static_cast<double>(s.d.z)});
  Vec3 e1;
  if (s.guide[0].mode != GuideMode::kStraight) {
    e1 = g.guide[0].u;
  } else if (s.guide[1].mode != GuideMode::kStraight) {
    e1 = g.guide[1].u;
  } else {
    e1 = cross(dh, std::fabs(dh.x) > 0.5 ? Vec3{0, 1, 0} : Vec3{1, 0, 0});
  }
  e1 = normalize(e1 - dh * dot(e1, dh));
  const Vec3 e2 = cross(dh, e1);
  // |e/L| ≤ 1/L < 2^-(bit_length(ceil L) - 1): |m| < 2^(EM+1), EM + 2 signed bits (18).
  f.s = HwParams::kFrameMant +
        fixed::bit_length(static_cast<fixed::u128>(static_cast<i64>(std::ceil(L))));
  const double sc = std::ldexp(1.0, f.s) / L;
  f.e1 = {std::llround(e1.x * sc), std::llround(e1.y * sc), std::llround(e1.z * sc)};
  f.e2 = {std::llround(e2.x * sc), std::llround(e2.y * sc), std::llround(e2.z * sc)};
  if (s.guide[1].mode != GuideMode::kStraight) {
    f.c2 = std::llround(std::ldexp(dot(g.guide[1].u, e1), HwParams::kFrameCosFrac));
    f.s2 = std::llround(std::ldexp(dot(g.guide[1].u, e2), HwParams::kFrameCosFrac));
  }
  for (int k = 0; k < 2; ++k) {
    FrameGuide& q = f.guide[k];
    q.mode = s.guide[k].mode;
    const double eta = g.guide[k].h * norm.scale / L;
    if (q.mode == GuideMode::kArc) {
      q.eta = std::llround(std::ldexp(eta, HwParams::kFrameGuideFrac));
      q.eta2 = q.eta * q.eta;
    } else if (q.mode == GuideMode::kFlat) {
      q.a = std::llround(std::ldexp(1.0 / (2.0 * eta), HwParams::kFrameFlatFrac));
    }
  }
  return f;
}

// Bits to add to a width so that `have` LSBs per pixel reach Precision::kHold.
int bits_to_hold(double have) {
  return have >= Precision::kHold ? 0
                                  : static_cast<int>(std::ceil(std::log2(Precision::kHold / have)));
}

Precision precision_of(const scene::CompiledScene& sc, const Normalization& norm,
                       const HwParams& p) {
  Precision pr;
  const double sigma = sc.camera.sigma;
  pr.direction_lsb_per_pixel = std::ldexp(sigma, p.dir_frac);
  // The nearest interpolation sphere (texture: its region) in front of or around the eye. A
  // sphere holding the eye has geometry arbitrarily near it, as any perspective view may; the
  // position criterion is about cameras far from the scene, so those spheres do not count.
  // A surface counts by its bounding sphere.
  double nearest = std::numeric_limits<double>::infinity();
  const char* nearest_kind = "segment";
  const auto consider = [&](const Vec3& c0, double R, const char* kind) {
    const double d = length(c0 - sc.camera.eye) - R;
    if (d > 0.0 && d < nearest) {
      nearest = d;
      nearest_kind = kind;
    }
  };
  for (const auto& s : sc.curve_segments) consider(s.geom.c0, s.geom.R, "segment");
  for (const auto& s : sc.texture_segments) consider(s.geom.c0, s.geom.R + s.half_width, "segment");
  for (const auto& s : sc.surfaces) consider(s.centre, s.radius, "surface");
  if (std::isfinite(nearest)) pr.position_lsb_per_pixel = sigma * nearest * norm.scale;
  const bool pos_low = pr.position_lsb_per_pixel > 0 && pr.position_lsb_per_pixel < Precision::kHold;
  const bool dir_low = pr.direction_lsb_per_pixel < Precision::kHold;
  if (pos_low) pr.coord_w_needed = p.coord_w + bits_to_hold(pr.position_lsb_per_pixel);
  if (dir_low) pr.dir_frac_needed = p.dir_frac + bits_to_hold(pr.direction_lsb_per_pixel);
  if (!pos_low && !dir_low) return pr;
  std::string what, raise;
  if (pos_low) {
    what = fmt::format("{:.0f} position LSBs (coord_w = {}) at the nearest {}",
                       pr.position_lsb_per_pixel, p.coord_w, nearest_kind);
    raise = fmt::format("--coord-w {}", pr.coord_w_needed);
  }
  if (dir_low) {
    what += fmt::format("{}{:.0f} direction LSBs (dir_frac = {})", what.empty() ? "" : " and ",
                        pr.direction_lsb_per_pixel, p.dir_frac);
    raise += fmt::format("{}--dir-frac {}", raise.empty() ? "" : " and ", pr.dir_frac_needed);
  }
  const double worst = std::min(pos_low ? pr.position_lsb_per_pixel : Precision::kHold,
                                dir_low ? pr.direction_lsb_per_pixel : Precision::kHold);
  const bool can_raise = (!pos_low || pr.coord_w_needed <= HwParams::kMaxCoordW) &&
                         (!dir_low || pr.dir_frac_needed <= HwParams::kMaxDirFrac);
  const std::string fix =
      can_raise ? "raise " + raise
                : "move the camera nearer the scene, narrow the image or widen the field of view "
                  "(the widths needed, " + raise + ", exceed their limits)";
  if (worst < Precision::kRefuse)
    throw Error(sc.source + ": camera",
                fmt::format("a pixel spans only {}, below the {:.0f} the fixed-point model needs "
                            "to resolve a pixel (the camera is far from the scene or the pixels "
                            "are tiny); {}", what, Precision::kRefuse, fix));
  pr.warning = fmt::format("{}: a pixel spans only {}; below {:.0f} the model may differ from "
                           "float-ip on more than 0.1 % of hit pixels; {}", sc.source, what,
                           Precision::kHold, fix);
  return pr;
}

}  // namespace

IVec3 Normalization::position(const Vec3& p) const {
  const Vec3 q = (p - offset) * scale;
  return {static_cast<i64>(std::llround(q.x)), static_cast<i64>(std::llround(q.y)),
          static_cast<i64>(std::llround(q.z))};
}

void require_built_kinds(const ModelScene& m) {
  if (!m.params.surfaces && !m.surfaces.empty())
    throw Error(m.source + ": surfaces",
                fmt::format("the scene has {} surface{}, but this build has no surface path "
                            "(--surfaces off): build it with --surfaces on, or drop the "
                            "surfaces", m.surfaces.size(), m.surfaces.size() == 1 ? "" : "s"));
}

ModelScene quantize_scene(const scene::CompiledScene& sc, const HwParams& p) {
  p.validate();
  ModelScene m;
  m.source = sc.source;
  m.params = p;
  // Normalisation: the bounding box of the eye, every interpolation sphere, every texture
  // region and every surface's bounding sphere, centred and scaled into kRangeUse of the signed
  // coord_w range.
  Bounds b;
  b.add(sc.camera.eye);
  for (const auto& s : sc.curve_segments) b.add(s.geom.c0, s.geom.R);
  for (const auto& s : sc.texture_segments) b.add(s.geom.c0, s.geom.R + s.half_width);
  for (const auto& s : sc.surfaces) b.add(s.centre, s.radius);
  const Vec3 centre = (b.lo + b.hi) * 0.5;
  const double half = std::max({b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z}) * 0.5;
  m.norm.offset = centre;
  if (!sc.texture_segments.empty()) m.norm.offset.z = 0.0;  // keep the texture plane at z = 0
  const double reach = half + std::fabs(centre.z - m.norm.offset.z);
  m.norm.scale = reach > 0.0 ? kRangeUse * std::ldexp(1.0, p.coord_w - 1) / reach : 1.0;

  const scene::CameraFrame& cam = sc.camera;
  // A field of view near 180° makes the pixel directions huge: refuse it here, in the words of
  // check_dir below, before any of them is rounded into the 64-bit descriptor format.
  const double reach_x = cam.half, reach_y = cam.half * cam.height / cam.width;
  const double dir_limit = 1 << (HwParams::kDirInt - 1);
  if (!(reach_x < dir_limit && reach_y < dir_limit))
    fov_too_wide(sc.source, std::max(reach_x, reach_y), dir_limit);
  CameraDesc& c = m.camera;
  c.width = cam.width;
  c.height = cam.height;
  c.eye = m.norm.position(cam.eye);
  const double s = cam.sigma;
  const Vec3 v0 = cam.W + cam.U * ((0.5 - 0.5 * cam.width) * s) + cam.V * ((0.5 * cam.height - 0.5) * s);
  const int fv = p.dir_frac + HwParams::kRayGuard, fe = p.edge_frac + HwParams::kRayGuard;
  c.v0 = quantize_vec(v0, fv, "camera");
  c.dx = quantize_vec(cam.U * s, fv, "camera");
  c.dy = quantize_vec(cam.V * -s, fv, "camera");
  // Edge vectors E_left(i) = U − x_i·W and E_top(j) = y_j·W − V with x_i = (2i − width)·σ/2,
  // y_j = (height − 2j)·σ/2, all from one rounded half-pixel step swh = W·σ/2: the hardware's
  // el0 − i·sw is then exactly U − (2i − width)·swh, so an edge whose x_i is representable (the
  // centre edges always) is exactly the plane of docs/algorithms.md §1.1, and a point on it is
  // captured by the pixel to its right / below (left and top edges inclusive). Rounding el0 and
  // sw separately left a residual W term that moved such points one column or row over (issue 11,
  // item 10).
  const IVec3 swh = quantize_vec(cam.W * (0.5 * s), fe, "camera");
  const IVec3 u = quantize_vec(cam.U, fe, "camera"), vq = quantize_vec(cam.V, fe, "camera");
  c.el0 = {u.x + cam.width * swh.x, u.y + cam.width * swh.y, u.z + cam.width * swh.z};
  c.et0 = {cam.height * swh.x - vq.x, cam.height * swh.y - vq.y, cam.height * swh.z - vq.z};
  c.sw = {2 * swh.x, 2 * swh.y, 2 * swh.z};
  c.w = quantize_vec(cam.W, fe, "camera");
  // Every pixel direction and edge vector must fit Q(4.F): check the image corners.
  const auto at = [](const IVec3& o, const IVec3& a, i64 ka, const IVec3& b2, i64 kb) {
    return IVec3{o.x + a.x * ka + b2.x * kb, o.y + a.y * ka + b2.y * kb, o.z + a.z * ka + b2.z * kb};
  };
  for (i64 i : {i64{0}, i64{cam.width - 1}})
    for (i64 j : {i64{0}, i64{cam.height - 1}})
      check_dir(at(c.v0, c.dx, i, c.dy, j), fv, HwParams::kDirInt, sc.source);
  const IVec3 zero{};
  check_dir(at(c.el0, c.sw, -cam.width, zero, 0), fe, HwParams::kEdgeInt, sc.source);
  check_dir(at(c.et0, c.sw, -cam.height, zero, 0), fe, HwParams::kEdgeInt, sc.source);
  check_dir(c.el0, fe, HwParams::kEdgeInt, sc.source);
  check_dir(c.et0, fe, HwParams::kEdgeInt, sc.source);

  const auto where = [&](const scene::CompiledSegment& cs) {
    const auto& prim = sc.primitives.at(static_cast<size_t>(cs.primitive));
    return fmt::format("{}: {}[{}].points[{}]", sc.source,
                       prim.kind == scene::Primitive::Kind::kCurve ? "curves" : "textures",
                       prim.index, cs.index);
  };
  for (const auto& cs : sc.curve_segments) {
    m.curve_segments.push_back(quantize_segment(cs, m.norm, p, where(cs)));
    m.curve_segments.back().frame = quantize_frame(cs, m.curve_segments.back(), m.norm);
  }
  for (const auto& cs : sc.texture_segments)
    m.texture_segments.push_back(quantize_segment(cs, m.norm, p, where(cs)));
  for (const auto& cs : sc.surfaces) {
    const auto& prim = sc.primitives.at(static_cast<size_t>(cs.primitive));
    m.surfaces.push_back(quantize_surface(
        cs, m.norm, p, fmt::format("{}: surfaces[{}]", sc.source, prim.index)));
  }
  // After the segments, whose message names the segment that does not fit.
  m.precision = precision_of(sc, m.norm, p);
  return m;
}

}  // namespace rpu::ref
