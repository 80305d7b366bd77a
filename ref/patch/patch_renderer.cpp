// Rendering patches: the map methods' per-pixel refinement with the depth test and the
// silhouette rule, Martin's traversal, and the timed whole.
#include "patch/patch_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <numbers>
#include <random>

#include <fmt/format.h>

#include "common/error.h"
#include "common/limits.h"
#include "common/parallel.h"

namespace rpu::patch {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

Refiner refiner_for(const PatchRenderOptions& o, scene::PatchType t) {
  if (o.refiner) return *o.refiner;
  if (o.method == PatchMethod::kNewton) return Refiner::kNewton;
  switch (t) {
    case scene::PatchType::kBezier: return Refiner::kGradientDescent;
    case scene::PatchType::kBSpline: return Refiner::kSteepestDescent;
    case scene::PatchType::kNurbs: return Refiner::kNewtonCramer;
  }
  return Refiner::kNewton;
}

void add(PatchRenderStats& to, const PatchRenderStats& s) {
  to.hit_pixels += s.hit_pixels;
  to.starts += s.starts;
  to.converged += s.converged;
  to.iterations += s.iterations;
  to.evaluations += s.evaluations;
  to.silhouette_pixels += s.silhouette_pixels;
  to.silhouette_left_domain += s.silhouette_left_domain;
  to.silhouette_stalled += s.silhouette_stalled;
  to.silhouette_iteration_limit += s.silhouette_iteration_limit;
  to.silhouette_singular += s.silhouette_singular;
  to.neighbour_hits += s.neighbour_hits;
  to.fallback_starts += s.fallback_starts;
  to.fallback_converged += s.fallback_converged;
  to.box_tests += s.box_tests;
}

// Screen box of a patch's control points (image pixels), for the random-start candidates: the
// projected patch lies inside when every control point is in front of the eye.
struct ScreenBox {
  double x0 = 0, x1 = -1, y0 = 0, y1 = -1;
  bool everywhere = false;
};
ScreenBox screen_box(const scene::Patch& p, const scene::CameraFrame& cam) {
  ScreenBox b{1e300, -1e300, 1e300, -1e300, false};
  for (const Vec3& c : p.control_points) {
    const Vec3 q = c - cam.eye;
    const double w = dot(cam.W, q);
    if (!(w > 1e-12)) return {0, 0, 0, 0, true};
    const double x = dot(cam.U, q) / (w * cam.sigma) + 0.5 * cam.width;
    const double y = 0.5 * cam.height - dot(cam.V, q) / (w * cam.sigma);
    b.x0 = std::min(b.x0, x), b.x1 = std::max(b.x1, x), b.y0 = std::min(b.y0, y), b.y1 = std::max(b.y1, y);
  }
  return b;
}

struct Candidate {
  int patch;
  double u, v, depth;
};

// Two texels of the same patch start the same refinement unless they lie on different sheets
// (depths 2 % apart: the front and the back of a fold) or far apart in the domain (a closed
// patch's seam, u or v jumping between 0 and 1).
bool same_start(const Candidate& a, const MapTexel& t) {
  return a.patch == t.patch && std::fabs(a.u - t.u) < 0.1 && std::fabs(a.v - t.v) < 0.1 &&
         std::fabs(a.depth - t.depth) < 0.02 * a.depth;
}

struct PixelWorker {
  const std::vector<PatchSurface>* surfaces;
  const PreliminaryMap* map;
  const scene::CameraFrame* cam;
  const PatchRenderOptions* o;
  const std::vector<ScreenBox>* boxes;  // random starts only
  PatchHitMap* out;
  PatchRenderStats stats;

  // Eq 3: N random (u, v), the subset M′ within ε0 of the best g, each refined (best first).
  void random_starts(int patch, const RayFrame& ray, int i, int j, PatchPixel& best) {
    const PatchSurface& s = (*surfaces)[static_cast<size_t>(patch)];
    // The seed hashes (i, j, patch) in unsigned arithmetic (wraps by definition; an int product
    // overflows for large patch ids).
    std::mt19937 rng((static_cast<unsigned>(j) * 73856093u) ^ (static_cast<unsigned>(i) * 19349663u) ^
                     (static_cast<unsigned>(patch) * 83492791u));
    std::uniform_real_distribution<double> d(0.0, 1.0);
    struct Sample { double g, u, v; };
    std::vector<Sample> m(static_cast<size_t>(o->random_samples));
    double g_best = 1e300;
    for (Sample& x : m) {
      x.u = d(rng), x.v = d(rng);
      x.g = ray.g(s.point(x.u, x.v));
      ++stats.evaluations;
      g_best = std::min(g_best, x.g);
    }
    std::sort(m.begin(), m.end(), [](const Sample& a, const Sample& b) { return a.g < b.g; });
    const double depth = std::max(ray.depth(s.point(m[0].u, m[0].v)), 1e-300);
    const double eps = o->random_epsilon_pixels * ray.pixel_angle * depth;
    for (int k = 0; k < o->random_max_starts && k < static_cast<int>(m.size()); ++k) {
      if (m[static_cast<size_t>(k)].g - g_best > eps * eps) break;  // eq 3
      RefineResult r = gradient_descent(s, ray, m[static_cast<size_t>(k)].u,
                                        m[static_cast<size_t>(k)].v, o->refine);
      tally(r);
      r = fallback(r, s, ray);
      consider(r, patch, best);
    }
  }

  // A gradient refiner that ran out of budget (slow convergence where the ray meets the surface
  // at a grazing angle: g's condition number is κ(J)²) hands its last point to Newton.
  RefineResult fallback(const RefineResult& r, const PatchSurface& s, const RayFrame& ray) {
    if (r.status != RefineStatus::kIterationLimit || o->method != PatchMethod::kThesis ||
        !o->newton_fallback || refiner_for(*o, s.patch().type) == Refiner::kNewton)
      return r;
    RefineResult f = newton(s, ray, r.u, r.v, o->refine);
    ++stats.fallback_starts;
    stats.fallback_converged += f.converged();
    stats.iterations += f.iterations;
    stats.evaluations += f.evaluations;
    if (f.converged()) ++stats.converged;
    return f;
  }

  void tally(const RefineResult& r) {
    ++stats.starts;
    stats.converged += r.converged();
    stats.iterations += r.iterations;
    stats.evaluations += r.evaluations;
  }

  static void consider(const RefineResult& r, int patch, PatchPixel& best) {
    if (!r.converged() || !(r.depth > 1e-9)) return;
    if (!best.hit || r.depth < best.depth || (r.depth == best.depth && patch < best.patch))
      best = {true, patch, r.u, r.v, r.depth};
  }

  void operator()(int j) {
    static constexpr int kOrder[9][2] = {{0, 0}, {-1, 0}, {1, 0}, {0, -1}, {0, 1},
                                         {-1, -1}, {1, -1}, {-1, 1}, {1, 1}};
    for (int i = 0; i < cam->width; ++i) {
      const RayFrame ray = RayFrame::pixel_centre(*cam, i, j);
      PatchPixel best;
      const bool random = o->start == PatchStart::kRandom && o->method == PatchMethod::kThesis;
      if (random) {
        for (size_t k = 0; k < surfaces->size(); ++k) {
          const ScreenBox& b = (*boxes)[k];
          if (!b.everywhere && !(i + 0.5 >= b.x0 - 1 && i + 0.5 <= b.x1 + 1 && j + 0.5 >= b.y0 - 1 &&
                                 j + 0.5 <= b.y1 + 1))
            continue;
          if ((*surfaces)[k].patch().type == scene::PatchType::kBezier)
            random_starts(static_cast<int>(k), ray, i, j, best);
        }
      }
      const int a = map->map_x(i), b = map->map_y(j);
      const int own = map->at(a, b).patch;
      Candidate cand[9];
      int n = 0;
      for (const auto& off : kOrder) {
        const int x = a + off[0], y = b + off[1];
        if (x < 0 || y < 0 || x >= map->width || y >= map->height) continue;
        const MapTexel& t = map->at(x, y);
        if (t.patch < 0) continue;
        if (random && (*surfaces)[static_cast<size_t>(t.patch)].patch().type == scene::PatchType::kBezier)
          continue;
        bool seen = false;
        for (int k = 0; k < n; ++k) seen = seen || same_start(cand[k], t);
        if (!seen) cand[n++] = {t.patch, t.u, t.v, t.depth};
      }
      RefineStatus own_status = RefineStatus::kConverged;
      for (int k = 0; k < n; ++k) {
        const PatchSurface& s = (*surfaces)[static_cast<size_t>(cand[k].patch)];
        RefineResult r = refine(refiner_for(*o, s.patch().type), s, ray, cand[k].u,
                                cand[k].v, o->refine);
        tally(r);
        r = fallback(r, s, ray);
        if (cand[k].patch == own) own_status = r.status;
        consider(r, cand[k].patch, best);
      }
      if (best.hit) {
        ++stats.hit_pixels;
        if (own < 0) ++stats.neighbour_hits;
      } else if (own >= 0 && !random) {
        ++stats.silhouette_pixels;
        switch (own_status) {
          case RefineStatus::kLeftDomain: ++stats.silhouette_left_domain; break;
          case RefineStatus::kStalled: ++stats.silhouette_stalled; break;
          case RefineStatus::kIterationLimit: ++stats.silhouette_iteration_limit; break;
          case RefineStatus::kSingular: ++stats.silhouette_singular; break;
          case RefineStatus::kConverged: break;  // converged behind the eye
        }
      }
      out->at(i, j) = best;
    }
  }
};

}  // namespace

PatchMethod parse_patch_method(const std::string& text, const std::string& where) {
  if (text == "thesis") return PatchMethod::kThesis;
  if (text == "newton") return PatchMethod::kNewton;
  if (text == "martin") return PatchMethod::kMartin;
  throw Error(where, "unknown patch method '" + text + "' (thesis, martin, newton)");
}

const char* patch_method_name(PatchMethod m) {
  switch (m) {
    case PatchMethod::kThesis: return "thesis";
    case PatchMethod::kNewton: return "newton";
    case PatchMethod::kMartin: return "martin";
  }
  return "?";
}

std::vector<PatchSurface> prepare_surfaces(const std::vector<scene::Patch>& patches) {
  std::vector<PatchSurface> out;
  out.reserve(patches.size());
  for (const scene::Patch& p : patches) out.emplace_back(p);
  return out;
}

PatchHitMap refine_with_map(const std::vector<PatchSurface>& surfaces, const PreliminaryMap& map,
                            const scene::CameraFrame& camera, const PatchRenderOptions& options,
                            PatchRenderStats& stats) {
  PatchHitMap out;
  out.width = camera.width, out.height = camera.height;
  out.pixels.assign(static_cast<size_t>(camera.width) * camera.height, PatchPixel{});
  std::vector<ScreenBox> boxes;
  if (options.start == PatchStart::kRandom)
    for (const PatchSurface& s : surfaces) boxes.push_back(screen_box(s.patch(), camera));
  std::mutex mu;
  PixelWorker w{&surfaces, &map, &camera, &options, &boxes, &out, {}};
  parallel_rows(camera.height, options.threads, w, [&](const PixelWorker& done) {
    std::lock_guard<std::mutex> lock(mu);
    add(stats, done.stats);
  });
  return out;
}

PatchHitMap trace_martin(const std::vector<PatchSurface>& surfaces, const MartinBvh& bvh,
                         const scene::CameraFrame& camera, int threads, PatchRenderStats& stats) {
  PatchHitMap out;
  out.width = camera.width, out.height = camera.height;
  out.pixels.assign(static_cast<size_t>(camera.width) * camera.height, PatchPixel{});
  struct Row {
    const std::vector<PatchSurface>* surfaces;
    const MartinBvh* bvh;
    const scene::CameraFrame* cam;
    PatchHitMap* out;
    MartinStats ms;
    std::int64_t hits = 0;
    void operator()(int j) {
      for (int i = 0; i < cam->width; ++i) {
        const MartinBvh::Hit h = bvh->intersect(*surfaces, RayFrame::pixel_centre(*cam, i, j), ms);
        if (h.hit) {
          ++hits;
          out->at(i, j) = {true, h.patch, h.u, h.v, h.depth};
        }
      }
    }
  };
  std::mutex mu;
  parallel_rows(camera.height, threads, Row{&surfaces, &bvh, &camera, &out, {}},
                [&](const Row& r) {
                  std::lock_guard<std::mutex> lock(mu);
                  stats.hit_pixels += r.hits;
                  stats.starts += r.ms.newton_starts;
                  stats.converged += r.ms.newton_converged;
                  stats.evaluations += r.ms.evaluations;
                  stats.box_tests += r.ms.box_tests;
                });
  return out;
}

namespace {

// Screen pixels inside the rectangle of a box's projected corners (all of them when a corner is
// not in front of the eye): an upper bound on the pixel rays that meet the box.
long long box_pixels(const Vec3& lo, const Vec3& hi, const scene::CameraFrame& cam) {
  const long long all = static_cast<long long>(cam.width) * cam.height;
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (int k = 0; k < 8; ++k) {
    const Vec3 c{k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z};
    const Vec3 q = c - cam.eye;
    const double w = dot(cam.W, q);
    if (!(w > 0.0)) return all;
    const double x = dot(cam.U, q) / (w * cam.sigma) + 0.5 * cam.width;
    const double y = 0.5 * cam.height - dot(cam.V, q) / (w * cam.sigma);
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  const double w = std::clamp(std::ceil(x1) - std::floor(x0), 0.0, double(cam.width));
  const double h = std::clamp(std::ceil(y1) - std::floor(y0), 0.0, double(cam.height));
  if (!(x1 >= 0 && x0 <= cam.width && y1 >= 0 && y0 <= cam.height)) return 0;
  return static_cast<long long>(w) * static_cast<long long>(h);
}

long long pair_budget(long long per_pixel, const scene::CameraFrame& cam) {
  return std::max(limits::kMinPairBudget,
                  per_pixel * static_cast<long long>(cam.width) * cam.height);
}

// The patches and the camera in a frame centred on the eye and scaled by a power of two 2^k so
// that the farthest control point lies between 1 and 2·√3 from the eye: every method then runs at
// the same relative precision whatever the scene's scale, and the depths found are scaled back
// exactly (docs/patches.md, "Precision").
struct NormalisedScene {
  std::vector<PatchSurface> surfaces;
  scene::CameraFrame camera;
  double to_world = 1;  // world length of one unit of the frame (a power of two)
};

NormalisedScene normalise(const std::vector<PatchSurface>& surfaces, const scene::CameraFrame& cam,
                          const std::string& where) {
  // far: the largest coordinate difference from the eye (a length would underflow its squares
  // at tiny scales; the distance is at most √3 times this).
  double far = 0, largest = std::max({std::fabs(cam.eye.x), std::fabs(cam.eye.y), std::fabs(cam.eye.z)});
  for (const PatchSurface& s : surfaces)
    for (const Vec3& p : s.patch().control_points) {
      const Vec3 d = p - cam.eye;
      far = std::max({far, std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
      largest = std::max({largest, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    }
  // Precision rule: a pixel at the farthest control point must span at least
  // kMinUlpsPerPixel units in the last place of the largest coordinate (the rounding of the
  // scene's own numbers, and of every P − eye).
  const double ulp = std::max(std::ldexp(1.0, std::ilogb(largest) - 52),
                              std::numeric_limits<double>::denorm_min());
  const double pixel = cam.sigma * far;
  if (!(pixel >= kMinUlpsPerPixel * ulp))
    throw Error(where, fmt::format(
        "the patches are too small for double precision at their coordinates: a pixel at the "
        "farthest control point spans {:.3g} world units, {:.3g} units in the last place of the "
        "largest coordinate {:.3g}; at least {:g} are needed (docs/patches.md, \"Precision\"); "
        "move the scene and the camera nearer the origin or enlarge them",
        pixel, pixel / ulp, largest, kMinUlpsPerPixel));
  NormalisedScene n;
  const int k = -std::ilogb(far);  // 2^k·far in [1, 2)
  n.to_world = std::ldexp(1.0, -k);
  n.camera = cam;
  n.camera.eye = Vec3{0, 0, 0};
  n.surfaces.reserve(surfaces.size());
  for (const PatchSurface& s : surfaces) {
    scene::Patch p = s.patch();
    for (Vec3& c : p.control_points) {
      const Vec3 d = c - cam.eye;
      c = Vec3{std::ldexp(d.x, k), std::ldexp(d.y, k), std::ldexp(d.z, k)};
    }
    n.surfaces.emplace_back(p);
  }
  return n;
}

}  // namespace

long long patch_render_bytes(const scene::CameraFrame& camera, const PatchRenderOptions& o) {
  const long long pixels = static_cast<long long>(camera.width) * camera.height;
  long long bytes = pixels * (static_cast<long long>(sizeof(PatchPixel)) + kFrameBytesPerPixel);
  if (o.method == PatchMethod::kMartin) {
    bytes += o.martin.max_leaves * kMartinBytesPerLeaf;
  } else {
    const long long texels = static_cast<long long>(o.map.width > 0 ? o.map.width : camera.width) *
                             (o.map.height > 0 ? o.map.height : camera.height);
    bytes += texels * static_cast<long long>(sizeof(MapTexel)) + kMapChunkBytes;
  }
  return bytes;
}

void check_patch_render_bytes(const scene::CameraFrame& camera, const PatchRenderOptions& options) {
  const long long bytes = patch_render_bytes(camera, options);
  if (bytes > options.max_bytes)
    throw Error(options.where, fmt::format(
        "rendering the patches at {}x{} needs {} MiB (frame, image, hit map, {}); at most {} MiB "
        "(README, \"Limits\"); use a smaller --size{}", camera.width, camera.height, bytes >> 20,
        options.method == PatchMethod::kMartin ? "Martin's BVH" : "preliminary map",
        options.max_bytes >> 20,
        options.method == PatchMethod::kMartin ? "" : " or --patch-map-size"));
}

PatchRender render_patches(const std::vector<PatchSurface>& world_surfaces,
                           const scene::CameraFrame& world_camera, const PatchRenderOptions& options) {
  PatchRender r;
  const long long pixels = static_cast<long long>(world_camera.width) * world_camera.height;
  r.hits.width = world_camera.width, r.hits.height = world_camera.height;
  check_patch_render_bytes(world_camera, options);
  const double fov = 360.0 / std::numbers::pi * std::atan(world_camera.half);
  if (!(fov <= limits::kMaxPatchFovDeg + 1e-9))
    throw Error(options.where, fmt::format(
        "camera.fov_deg {:.9g} is wider than {:g}, the widest field of view the patch tracers "
        "are accurate at (docs/patches.md, \"Precision\")", fov, limits::kMaxPatchFovDeg));
  if (world_surfaces.empty()) {
    r.hits.pixels.assign(static_cast<size_t>(pixels), PatchPixel{});
    return r;
  }
  const NormalisedScene n = normalise(world_surfaces, world_camera, options.where);
  const std::vector<PatchSurface>& surfaces = n.surfaces;
  const scene::CameraFrame& camera = n.camera;
  if (options.method == PatchMethod::kMartin) {
    auto t0 = Clock::now();
    MartinOptions mo = options.martin;
    mo.newton.tolerance_pixels = options.refine.tolerance_pixels;
    mo.eye_plane = EyePlane{camera.eye, camera.W};
    mo.where = options.where;
    const MartinBvh bvh(surfaces, mo);
    r.stats.map_seconds = seconds_since(t0);
    r.stats.bvh_leaves = static_cast<std::int64_t>(bvh.leaves().size());
    r.stats.bvh_nodes = static_cast<std::int64_t>(bvh.nodes().size());
    long long pairs = 0;
    for (const MartinLeaf& l : bvh.leaves()) pairs += box_pixels(l.lo, l.hi, camera);
    const long long budget = pair_budget(limits::kMartinPairsPerPixel, camera);
    if (pairs > budget)
      throw Error(options.where, fmt::format(
          "Martin's traversal would test up to {} ray/sub-patch pairs ({:.1f} of its {} leaves "
          "per pixel at {}x{}); at most {} (README, \"Limits\"); use fewer overlapping patches "
          "or --patch-method thesis", pairs, double(pairs) / double(pixels), bvh.leaves().size(),
          camera.width, camera.height, budget));
    t0 = Clock::now();
    r.hits = trace_martin(surfaces, bvh, camera, options.threads, r.stats);
    r.stats.refine_seconds = seconds_since(t0);
  } else {
    // Pixels inside each patch's screen box (its projected control points, one pixel of margin
    // as the random starts use), summed over the patches (only the Bézier ones: `bezier_only`).
    const auto covered = [&](bool bezier_only) {
      long long pairs = 0;
      for (const PatchSurface& s : surfaces) {
        if (bezier_only && s.patch().type != scene::PatchType::kBezier) continue;
        const ScreenBox b = screen_box(s.patch(), camera);
        if (b.everywhere) {
          pairs += pixels;
          continue;
        }
        const double w = std::clamp(std::ceil(b.x1 + 1) - std::floor(b.x0 - 1), 0.0, double(camera.width));
        const double h = std::clamp(std::ceil(b.y1 + 1) - std::floor(b.y0 - 1), 0.0, double(camera.height));
        if (b.x1 + 1 < 0 || b.x0 - 1 > camera.width || b.y1 + 1 < 0 || b.y0 - 1 > camera.height) continue;
        pairs += static_cast<long long>(w) * static_cast<long long>(h);
      }
      return pairs;
    };
    // The map's rasterisation visits every texel under every patch (its overdraw); counted in
    // image pixels, the map's own size scaled in (a --patch-map-size other than the image's).
    {
      const long long texels = static_cast<long long>(options.map.width > 0 ? options.map.width : camera.width) *
                               (options.map.height > 0 ? options.map.height : camera.height);
      const long long pairs = static_cast<long long>(
          static_cast<double>(covered(false)) * static_cast<double>(texels) / static_cast<double>(pixels));
      const long long budget =
          std::max(limits::kMinPairBudget, limits::kMapPairsPerPixel * texels);
      if (pairs > budget)
        throw Error(options.where, fmt::format(
            "the preliminary map would rasterise up to {} texel/patch pairs ({:.1f} of the {} "
            "patches per texel of a {}-texel map); at most {} (README, \"Limits\"); use fewer "
            "overlapping patches", pairs, double(pairs) / double(texels), surfaces.size(), texels,
            budget));
    }
    if (options.start == PatchStart::kRandom && options.method == PatchMethod::kThesis) {
      const long long pairs = covered(true);
      const long long budget = pair_budget(limits::kRandomStartPairsPerPixel, camera);
      if (pairs > budget)
        throw Error(options.where, fmt::format(
            "random starts (eq 3) would sample up to {} ray/patch pairs ({:.1f} patches per pixel "
            "at {}x{}); at most {} (README, \"Limits\"); use fewer overlapping patches or "
            "--patch-start map", pairs, double(pairs) / double(pixels), camera.width,
            camera.height, budget));
    }
    auto t0 = Clock::now();
    MapOptions mo = options.map;
    mo.threads = options.threads;
    mo.where = options.where;
    const PreliminaryMap map = build_preliminary_map(surfaces, camera, mo);
    r.stats.map_seconds = seconds_since(t0);
    r.stats.map_triangles = map.triangles;
    t0 = Clock::now();
    r.hits = refine_with_map(surfaces, map, camera, options, r.stats);
    r.stats.refine_seconds = seconds_since(t0);
  }
  for (PatchPixel& p : r.hits.pixels) p.depth *= n.to_world;  // exact: a power of two
  return r;
}

}  // namespace rpu::patch
