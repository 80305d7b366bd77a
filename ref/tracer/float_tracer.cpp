#include "tracer/float_tracer.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <thread>

#include <fmt/format.h>

#include "common/error.h"
#include "common/parallel.h"
#include "scene/screen_bins.h"
#include "tracer/sphere_interval.h"
#include "tracer/surface_tracer.h"

namespace rpu::tracer {

using scene::CameraFrame;
using scene::CompiledScene;
using scene::CompiledSegment;
using scene::Segment;

void check_ip_parameters(int n, int n1, int surf_n1_first) {
  if (n1 < 1 || n1 > kMaxN1)
    throw Error("--n1", fmt::format("bits per step must be in [1, {}], got {}", kMaxN1, n1));
  if (n < 1 || n > 52) throw Error("--n", fmt::format("result bits must be in [1, 52], got {}", n));
  if (n % n1 != 0)
    throw Error("--n", fmt::format("n = {} is not a multiple of n1 = {} (K = n/n1 steps)", n, n1));
  if (surf_n1_first < 0 || surf_n1_first > ref::hw_range::surf_n1_first_max)
    throw Error("--surf-n1-first", fmt::format("first-step bits must be seed (0) or in [1, {}], "
                                               "got {}", ref::hw_range::surf_n1_first_max,
                                               surf_n1_first));
}

bool interpolation_interval(const Vec3& eye, const Vec3& v, const Segment& s, double& t1,
                            double& t2) {
  return sphere_interval(eye, v, s.c0, s.R, t1, t2);
}

PairResult iterative_pair(const CameraFrame& cam, const Segment& s, int i, int j, int n, int n1,
                          double* tau_out) {
  PairResult r;
  const Vec3 v = cam.ray_direction(i, j);
  double t1, t2;
  if (!interpolation_interval(cam.eye, v, s, t1, t2)) return r;
  const Vec3 A = cam.eye + v * t1, B = cam.eye + v * t2;
  const Vec3 AB = B - A;
  // Chord parameter of the plane through pr(τ), linear in τ: t(τ) = alpha + beta·τ.
  const double alpha = scene::chord_parameter(s, A);
  const double beta = dot(AB, s.d) / s.L2;
  const auto md = [&](double tau) {  // md = |pr(τ) - s(t(τ))|
    const Vec3 pr = A + AB * tau;
    return length(pr - scene::curve_point(s, alpha + beta * tau));
  };
  const int J = 1 << n1;
  const int K = n / n1;
  double tau = 0.0;
  double md_lo = md(0.0), md_hi = md(1.0);
  std::array<double, (1 << kMaxN1) + 1> m;
  for (int k = 1; k <= K; ++k) {
    const double delta = std::ldexp(1.0, -n1 * k);
    m[0] = md_lo;
    m[J] = md_hi;
    for (int jj = 1; jj < J; ++jj) m[jj] = md(tau + jj * delta);
    int eta = 0;
    double best = m[0] + m[1];
    for (int jj = 1; jj < J; ++jj) {
      const double sd = m[jj] + m[jj + 1];
      if (sd < best) {  // strict: the lowest index wins ties
        best = sd;
        eta = jj;
      }
    }
    tau += eta * delta;
    md_lo = m[eta];
    md_hi = m[eta + 1];
  }
  if (tau_out) *tau_out = tau;
  const double t = alpha + beta * tau;
  r.t = t;
  if (!(t >= 0.0 && t <= 1.0)) return r;
  r.point = scene::curve_point(s, t);
  r.hit = scene::capture_test(cam, i, j, r.point, r.depth);
  return r;
}

bool pvp_may_meet_sphere(const CameraFrame& cam, const Segment& s, int i, int j) {
  const Vec3 v = cam.ray_direction(i, j);
  const Vec3 q = s.c0 - cam.eye;
  const double qq = length_squared(q);
  if (qq <= s.R * s.R * (1.0 + 1e-9)) return true;  // eye inside (or on) the sphere
  const double qlen = std::sqrt(qq);
  const double cos_theta = std::clamp(dot(v, q) / (length(v) * qlen), -1.0, 1.0);
  const double theta = std::acos(cos_theta);
  const double sphere = std::asin(std::min(1.0, s.R / qlen));
  // Every ray through the pixel is within asin(σ/√2) of the centre ray (|v + Δ| ≥ 1).
  const double pixel = std::asin(std::min(1.0, cam.sigma * 0.7071067811865476));
  return theta <= sphere + pixel + 1e-9;
}

PairResult ideal_pair(const CameraFrame& cam, const Segment& s, int i, int j) {
  PairResult r;
  const Vec3 vhat = normalize(cam.ray_direction(i, j));
  // tan² of the angle at the eye between the ray and X - h; +inf behind the eye.
  const auto metric = [&](double t) {
    const Vec3 q = scene::curve_point(s, t) - cam.eye;
    const double along = dot(q, vhat);
    if (!(along > 0.0)) return std::numeric_limits<double>::infinity();
    const double perp2 = std::max(0.0, length_squared(q) - along * along);
    return perp2 / (along * along);
  };
  constexpr int kSamples = 64;
  std::array<double, kSamples + 1> f{};
  for (int k = 0; k <= kSamples; ++k) f[k] = metric(static_cast<double>(k) / kSamples);
  // Local minima of the samples, best three refined.
  std::array<int, 3> cand{-1, -1, -1};
  for (int k = 0; k <= kSamples; ++k) {
    const bool left = k == 0 || f[k] <= f[k - 1];
    const bool right = k == kSamples || f[k] <= f[k + 1];
    if (!(left && right) || !std::isfinite(f[k])) continue;
    for (int c = 0; c < 3; ++c) {
      if (cand[c] < 0 || f[k] < f[cand[c]]) {
        for (int m = 2; m > c; --m) cand[m] = cand[m - 1];
        cand[c] = k;
        break;
      }
    }
  }
  double best_t = -1.0, best_f = std::numeric_limits<double>::infinity();
  constexpr double kInvPhi = 0.6180339887498949;
  for (int c : cand) {
    if (c < 0) continue;
    double lo = std::max(0, c - 1) / static_cast<double>(kSamples);
    double hi = std::min(kSamples, c + 1) / static_cast<double>(kSamples);
    double x1 = hi - kInvPhi * (hi - lo), x2 = lo + kInvPhi * (hi - lo);
    double f1 = metric(x1), f2 = metric(x2);
    for (int it = 0; it < 60 && hi - lo > 1e-15; ++it) {
      if (f1 <= f2) {
        hi = x2; x2 = x1; f2 = f1;
        x1 = hi - kInvPhi * (hi - lo); f1 = metric(x1);
      } else {
        lo = x1; x1 = x2; f1 = f2;
        x2 = lo + kInvPhi * (hi - lo); f2 = metric(x2);
      }
    }
    // Keep the best of the refined point and the sample itself.
    const double tc = static_cast<double>(c) / kSamples;
    const double tm = 0.5 * (lo + hi), fm = metric(tm);
    const double t = fm <= f[c] ? tm : tc, fv = std::min(fm, f[c]);
    if (fv < best_f) {
      best_f = fv;
      best_t = t;
    }
  }
  if (best_t < 0.0) return r;
  r.t = best_t;
  r.point = scene::curve_point(s, best_t);
  r.hit = scene::capture_test(cam, i, j, r.point, r.depth);
  return r;
}

bool texture_covers(const CompiledSegment& cs, const Vec3& p0) {
  const Segment& s = cs.geom;
  // pr1: p0 between the planes through p1 and p2 perpendicular to d (the chord midpoint's signs,
  // seed 001 eqs 7–9; a point on either plane counts as between).
  const double f1 = dot(p0 - s.p1, s.d), f2 = dot(p0 - s.p2, s.d);
  if (!(f1 >= 0.0 && f2 <= 0.0)) return false;
  const double w2 = cs.half_width * cs.half_width;
  // pr2: round caps at the end points (eq 10).
  if (length_squared(s.p1 - p0) <= w2 || length_squared(s.p2 - p0) <= w2) return true;
  // pr3: the curve point on the guide line through p0 within w_0 (eqs 15–24).
  const double t_hat = f1 / s.L2;
  return length_squared(scene::curve_point(s, t_hat) - p0) <= w2;
}

namespace {

struct Hit {
  double depth = std::numeric_limits<double>::infinity();
  std::int32_t primitive = image::kBackground;
  // Nearest first; equal depths: lower primitive id first.
  void offer(double d, std::int32_t id) {
    if (d < depth || (d == depth && id < primitive)) {
      depth = d;
      primitive = id;
    }
  }
};

void shade_textures(const CompiledScene& sc, const FloatOptions& o, int i, int j, Hit& hit,
                    std::uint64_t& tested) {
  if (sc.texture_segments.empty()) return;
  const CameraFrame& cam = sc.camera;
  const Vec3 v = cam.ray_direction(i, j);
  if (v.z == 0.0) return;  // parallel to the plane
  const double t0 = -cam.eye.z / v.z;
  if (!(t0 > 0.0)) return;  // plane behind the eye (or the eye on it)
  Vec3 p0 = cam.eye + v * t0;
  p0.z = 0.0;
  // depth c = (p0 - h)·W = t0·(v·W) = t0 because v·W = 1.
  const auto test = [&](const CompiledSegment& s) {
    ++tested;
    if (s.primitive < hit.primitive || t0 < hit.depth) {
      if (texture_covers(s, p0)) hit.offer(t0, s.primitive);
    }
  };
  if (o.grid) {
    for (auto k : sc.texture_grid.lookup(p0.x, p0.y)) test(sc.texture_segments[k]);
  } else {
    for (const auto& s : sc.texture_segments) test(s);
  }
}

}  // namespace

image::Frame render_float(const CompiledScene& sc, const FloatOptions& o, RenderStats* stats) {
  if (o.method == Method::kIterative) check_ip_parameters(o.n, o.n1, o.surf_n1_first);
  scene::check_surface_budget(sc);
  const CameraFrame& cam = sc.camera;
  image::Frame frame(cam.width, cam.height);
  const scene::ScreenBins bins(cam, sc.curve_segments, 8, o.binning);
  const SurfaceTracer surfaces(sc, o.method, o.n, o.n1, o.surf_n1_first);
  std::atomic<std::uint64_t> tested{0}, hits{0}, texture_tested{0};
  SurfaceStats surface_stats;
  std::mutex surface_mutex;
  struct Row {
    const CompiledScene* sc;
    const FloatOptions* o;
    const scene::ScreenBins* bins;
    const SurfaceTracer* surfaces;
    image::Frame* frame;
    std::uint64_t tested = 0, hits = 0, texture = 0;
    SurfaceStats surface{};
    void operator()(int j) {
      const CameraFrame& cam = sc->camera;
      for (int i = 0; i < cam.width; ++i) {
        Hit hit;
        for (auto k : bins->segments_for_pixel(i, j)) {
          const CompiledSegment& cs = sc->curve_segments[k];
          ++tested;
          PairResult r;
          if (o->method == Method::kIterative) {
            r = iterative_pair(cam, cs.geom, i, j, o->n, o->n1);
          } else if (pvp_may_meet_sphere(cam, cs.geom, i, j)) {
            r = ideal_pair(cam, cs.geom, i, j);
          }
          if (r.hit) {
            ++hits;
            hit.offer(r.depth, cs.primitive);
          }
        }
        shade_textures(*sc, *o, i, j, hit, texture);
        double surface_depth = 0.0;
        std::int32_t surface_id = image::kBackground;
        if (!surfaces->empty() && surfaces->trace_pixel(i, j, surface_depth, surface_id, surface))
          hit.offer(surface_depth, surface_id);
        const size_t idx = frame->index(i, j);
        frame->primitive[idx] = hit.primitive;
        frame->depth[idx] = hit.primitive == image::kBackground ? 0.0 : hit.depth;
      }
    }
  };
  parallel_rows(cam.height, o.threads, Row{&sc, &o, &bins, &surfaces, &frame},
                [&](const Row& r) {
                  tested += r.tested;
                  hits += r.hits;
                  texture_tested += r.texture;
                  const std::lock_guard<std::mutex> lock(surface_mutex);
                  surface_stats += r.surface;
                });
  if (stats) {
    stats->pairs_tested = tested;
    stats->pairs_hit = hits;
    stats->texture_pairs_tested = texture_tested;
    stats->surface_pairs_tested = surface_stats.pairs_tested;
    stats->surface_pieces = surface_stats.pieces;
    stats->surface_pairs_hit = surface_stats.pairs_hit;
    stats->surface_evaluations = surface_stats.evaluations;
  }
  return frame;
}

}  // namespace rpu::tracer
