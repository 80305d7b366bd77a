// The double-precision ray tracer: the yardstick for the fixed-point model and the RTL.
//   kIdeal     (`--backend float`):    per segment, the curve point of closest approach to the
//                                      pixel-centre ray by a global search, then the PVP capture.
//   kIterative (`--backend float-ip`): the seeds' iterative process exactly (docs/algorithms.md
//                                      §1.2).
// Vector textures (docs/algorithms.md §2) have no iteration and render the same in both methods.
// Vector-described surfaces (docs/algorithms.md §3) are traced by tracer/surface_tracer.h in both
// methods.
#pragma once

#include <cstdint>

#include "image/frame.h"
#include "model/hw_params.h"
#include "scene/compiled_scene.h"

namespace rpu::tracer {

enum class Method { kIdeal, kIterative };

struct FloatOptions {
  Method method = Method::kIdeal;
  int n = 16;            // result bits of the iterative process
  int n1 = 2;            // bits per step; K = n / n1 steps
  // Surfaces: bits of the sign search's first step, 0 = n1 (the seed's search); the later steps
  // take n1 bits, the last one what remains of n (ref::HwParams::surface_step_bits).
  int surf_n1_first = ref::HwParams{}.surf_n1_first;
  bool binning = true;   // screen-space binning of curve segments (never changes the image)
  bool grid = true;      // texture classification grid (never changes the image)
  int threads = 0;       // 0 = all hardware threads
};

// Largest n1: a step divides its interval into 2^n1 sub-intervals and evaluates 2^n1 − 1 new
// candidates in parallel (docs/algorithms.md §1.2); 256 is already far beyond what an FPGA
// datapath would replicate.
inline constexpr int kMaxN1 = 8;

// Validates n and n1 (1 ≤ n1 ≤ kMaxN1, n1 ≤ n ≤ 52, n a multiple of n1) and the surfaces' first
// step (seed = 0, or 1 ≤ surf_n1_first ≤ its table maximum; a value past n takes all n bits in
// step 1); throws rpu::Error naming the flag.
void check_ip_parameters(int n, int n1, int surf_n1_first = 0);

struct RenderStats {
  std::uint64_t pairs_tested = 0;          // ray/curve-segment pairs examined after binning
  std::uint64_t pairs_hit = 0;             // of those, pairs whose test point was captured
  std::uint64_t texture_pairs_tested = 0;  // ray/texture-segment pairs listed by the grid
  std::uint64_t surface_pairs_tested = 0;  // ray/surface pairs (every pixel × every surface)
  std::uint64_t surface_pieces = 0;        // pieces of the pairs that met the bounding sphere
  std::uint64_t surface_pairs_hit = 0;     // ray/surface pairs with a hit
  std::uint64_t surface_evaluations = 0;   // surface inside tests evaluated
};

image::Frame render_float(const scene::CompiledScene& scene, const FloatOptions& options,
                          RenderStats* stats = nullptr);

// ---- one ray/segment pair, exposed for tests and benchmarks ----

struct PairResult {
  bool hit = false;
  double depth = 0.0;  // c of the captured point
  double t = 0.0;      // chord parameter of the test point
  Vec3 point;          // the test point s(t)
};

// The interpolation sphere test pred_1 and the search interval (docs/algorithms.md §1.2 steps 1–2):
// the roots t1 ≤ t2 of ray/sphere, t1 clamped to 0 when the eye is inside. False when the ray
// misses the sphere or meets it only behind the eye.
bool interpolation_interval(const Vec3& eye, const Vec3& v, const scene::Segment& s, double& t1,
                            double& t2);

// The iterative process on pixel (i, j) against one segment; `tau` receives τ_K.
PairResult iterative_pair(const scene::CameraFrame& cam, const scene::Segment& s, int i, int j,
                          int n, int n1, double* tau = nullptr);

// Ideal semantics on pixel (i, j): the curve point nearest to the pixel-centre ray in angle
// (64 samples, then golden-section refinement of the three best local minima), then capture.
PairResult ideal_pair(const scene::CameraFrame& cam, const scene::Segment& s, int i, int j);

// Conservative cull: false only when the pixel's pyramid cannot meet the segment's
// interpolation sphere (so no point of its curve can be captured).
bool pvp_may_meet_sphere(const scene::CameraFrame& cam, const scene::Segment& s, int i, int j);

// Texture predicates pr1 ∧ (pr2 ∨ pr3) of docs/algorithms.md §2 for the plane point p0.
bool texture_covers(const scene::CompiledSegment& s, const Vec3& p0);

}  // namespace rpu::tracer
