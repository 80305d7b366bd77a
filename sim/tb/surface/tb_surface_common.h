// Shared by the surface testbenches: the demo scenes' surfaces quantised at the build's
// parameters, the rays the IP and top benches drive (camera pixels, image-border pixels, grazing
// rays, rays in the range planes, eyes inside the bounding sphere), and the indicator fields of a
// SurfaceDesc, redrawn or on the ports rpu_surface_ip and rpu_surface_top share with rpu_indicator.
#pragma once

#include <array>
#include <cmath>
#include <deque>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "model/surface/rpu_surface_setup.h"
#include "model/units.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "scene/surface_geometry.h"
#include "surface_word.h"
#include "tb_base.h"

namespace rpu::sim {

inline const char* const kSurfaceScenes[] = {"surf_ellipsoid", "surf_relief", "surf_spiral",
                                             "surf_snail",     "surf_rocket", "surf_mix"};
inline const char* const kSurfaceTypeName[] = {"ellipsoid", "relief", "spiral", "snail", "rocket"};

// One surface of a demo scene, with its scene's camera.
struct SurfCase {
  std::string name;  // scene file and surface index
  const scene::CompiledScene* scene = nullptr;
  const scene::CompiledSurface* cs = nullptr;
  ref::Normalization norm;
  ref::SurfaceDesc d;
  ref::CameraDesc cam;
};

// The demo scenes with surfaces; every surface of them at `p` (load_surface_cases), `turned`:
// by (23°, 37°, 61°) more about x, y, z (named <scene>/turned[k]); the compiled scenes live in
// `keep` (a deque: stable addresses).
inline std::vector<SurfCase> load_surface_cases(const ref::HwParams& p,
                                                std::deque<scene::CompiledScene>& keep,
                                                bool turned = false) {
  std::vector<SurfCase> out;
  for (const char* name : kSurfaceScenes) {
    scene::Scene sc = demo_scene(name);
    for (scene::Surface& s : sc.surfaces)
      if (turned) s.rotation_deg = s.rotation_deg + Vec3{23.0, 37.0, 61.0};
    keep.push_back(scene::compile_scene(sc));
    const ref::ModelScene m = ref::quantize_scene(keep.back(), p);
    for (size_t k = 0; k < m.surfaces.size(); ++k)
      out.push_back({std::string(name) + (turned ? "/turned[" : "[") + std::to_string(k) + "]",
                     &keep.back(), &keep.back().surfaces[k], m.norm, m.surfaces[k], m.camera});
  }
  return out;
}

// A point R(φ, v) of the surface's seed (SurfaceGeometry::point), local units, at random
// parameters over their whole ranges.
inline Vec3 random_seed_point(const scene::Surface& s, std::mt19937_64& rng) {
  const scene::SurfaceParams& q = s.p;
  double phi = uniform(rng, 0, 2 * std::numbers::pi), v = 0;
  switch (s.type) {
    case scene::SurfaceType::kEllipsoid:
    case scene::SurfaceType::kReliefEllipsoid: v = uniform(rng, q.y_min, q.y_max); break;
    case scene::SurfaceType::kSpiral:
    case scene::SurfaceType::kSnail:
      phi = uniform(rng, 0, q.phi_max);
      v = uniform(rng, 0, 2 * std::numbers::pi);
      break;
    case scene::SurfaceType::kRocket: v = uniform(rng, -q.c, q.b + q.e); break;
  }
  return scene::SurfaceGeometry(s).point(phi, v);
}

enum RaySource { kPixelNear, kPixelAny, kBorder, kGrazing, kPlane, kInsideEye, kRaySources };
inline const char* const kRaySourceName[kRaySources] = {
    "pixel near the surface", "any pixel", "image border", "grazing", "range plane",
    "eye inside the sphere"};

struct SurfRay {
  RaySource src = kPixelAny;
  int surf = 0;
  int i = -1, j = -1;  // the camera pixel, or −1
  ref::IVec3 eye, vhat;
};

// Rays of one surface from its scene's camera eye: `count` of them, about 45 % camera pixels at
// or beside the projection of a random point of the surface, 10 % any pixel, 10 % image-border
// pixels, 15 % grazing the bounding sphere (impact parameter R·(1 + ε), |ε| down to 2^-24), 20 %
// aimed at points of the range planes inside the sphere (spiral, snail: the planes x = 0 and of
// the end angle; the others: y = y_min, y_max), on them or a few llsb beside them.
inline void camera_rays(const ref::HwParams& p, const SurfCase& S, int surf, int count,
                        std::mt19937_64& rng, std::vector<SurfRay>& out) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const ref::CameraDesc& cam = S.cam;
  const scene::CompiledSurface& cs = *S.cs;
  const scene::SurfaceGeometry geom(cs.surface);
  const double llsb = std::ldexp(1.0, -S.d.local_frac);
  const Vec3 c0 = to_vec(S.d.bound.c0);
  const double R = std::sqrt(static_cast<double>(S.d.bound.R2));
  const auto pixel = [&](RaySource src, int i, int j) {
    out.push_back({src, surf, i, j, cam.eye, ref::ray_generator(p, cam, i, j).vhat});
  };
  const auto aim = [&](RaySource src, const Vec3& target) {
    const ref::IVec3 v = quantise_dir(p, target - to_vec(cam.eye));
    if (v.x != 0 || v.y != 0 || v.z != 0) out.push_back({src, surf, -1, -1, cam.eye, v});
  };
  for (int n = 0; n < count; ++n) {
    const int kind = static_cast<int>(rng() % 100);
    if (kind < 45) {
      int i, j;
      const Vec3 l = random_seed_point(cs.surface, rng);
      if (!scene::project_to_pixel(S.scene->camera, cs.local_to_world(l), i, j)) continue;
      i = std::clamp(i + static_cast<int>(rng() % 5) - 2, 0, cam.width - 1);
      j = std::clamp(j + static_cast<int>(rng() % 5) - 2, 0, cam.height - 1);
      pixel(kPixelNear, i, j);
    } else if (kind < 55) {
      pixel(kPixelAny, static_cast<int>(rng() % static_cast<unsigned>(cam.width)),
            static_cast<int>(rng() % static_cast<unsigned>(cam.height)));
    } else if (kind < 65) {
      const int e = static_cast<int>(rng() % 4), w = cam.width, h = cam.height;
      const int i = e == 0 ? 0 : e == 1 ? w - 1 : static_cast<int>(rng() % static_cast<unsigned>(w));
      const int j = e == 2 ? 0 : e == 3 ? h - 1 : static_cast<int>(rng() % static_cast<unsigned>(h));
      pixel(kBorder, i, j);
    } else if (kind < 80) {
      // A tangent point of the sphere seen from the eye, pushed out or in by R·ε.
      const Vec3 e = to_vec(cam.eye);
      const Vec3 u = normalize(c0 - e);
      Vec3 w = cross(u, random_unit(rng));
      if (length(w) < 1e-3) continue;
      w = normalize(w);
      const double L = length(c0 - e);
      if (L <= R) continue;
      const double eps = (u01(rng) - 0.5) * std::ldexp(1.0, -static_cast<int>(rng() % 24));
      const double b = R * L / std::sqrt(L * L - R * R) * (1.0 + eps);
      aim(kGrazing, c0 + w * b);
    } else {
      // A point of a range plane inside the local bounding sphere (or `off` llsb beside it).
      const double off = rng() % 3 == 0 ? 0.0 : (static_cast<double>(rng() % 9) - 4.0) * llsb;
      const Vec3 lc = cs.local_centre;
      const double lr = cs.local_radius * 0.95 * std::cbrt(u01(rng));
      Vec3 l;
      if (geom.has_azimuth_range()) {
        const double a = rng() % 2 ? 0.0 : geom.end_azimuth();  // plane of azimuth a: normal
        const Vec3 nrm{std::cos(a), 0, -std::sin(a)};           // (cos a, 0, −sin a)
        l = lc + random_unit(rng) * lr;
        l = l - nrm * dot(l, nrm) + nrm * off;
      } else {
        const double yb = static_cast<double>(rng() % 2 ? S.d.y_max : S.d.y_min) * llsb;
        l = lc + random_unit(rng) * lr;
        l.y = yb + off;
      }
      aim(kPlane, (cs.local_to_world(l) - S.norm.offset) * S.norm.scale);  // world LSB
    }
  }
}

// Rays from an eye inside the bounding sphere (within 0.9 R of its centre) in random directions.
inline ref::IVec3 inside_eye(const SurfCase& S, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const double R = std::sqrt(static_cast<double>(S.d.bound.R2));
  return round3(to_vec(S.d.bound.c0) + random_unit(rng) * (0.9 * R * std::cbrt(u01(rng))));
}
inline void inside_rays(const ref::HwParams& p, const ref::IVec3& eye, int surf, int count,
                        std::mt19937_64& rng, std::vector<SurfRay>& out) {
  for (int n = 0; n < count; ++n)
    out.push_back({kInsideEye, surf, -1, -1, eye, quantise_dir(p, random_unit(rng))});
}

// The piece indices a ray is issued with: every piece the host issues for the type, and now
// and then one beyond them (never valid).
inline std::vector<int> piece_indices(const ref::SurfaceDesc& d, std::mt19937_64& rng) {
  std::vector<int> v;
  const int items = ref::surface_piece_items(d.type);
  for (int k = 0; k < items; ++k) v.push_back(k);
  if (rng() % 16 == 0) v.push_back(items < 3 ? items + static_cast<int>(rng() % (3 - items)) : 2);
  return v;
}

// The indicator fields of a descriptor redrawn within rpu_indicator's port contract (its type
// and the setup's fields kept): the spiral's and snail's turn constants over their whole width
// (the lane offsets saturate: overflow), the rocket's fin and cone constants, the scales and r2
// of the quadrics; full_turns < turns. whole_ports (rpu_indicator's own testbench): also the
// scales over their whole ports, any shift of the ScaledConsts and r2 at its top.
inline ref::SurfaceDesc edit_indicator_fields(ref::SurfaceDesc s, const ref::HwParams& p,
                                              int turns, std::mt19937_64& rng,
                                              bool whole_ports = false) {
  const int lw = p.surf_w, kf = p.surf_const_frac(), mw = p.surf_mant_w();
  const auto unit_scale = [&] {  // mostly in (0, 1]
    return static_cast<std::int64_t>(whole_ports && rng() % 4 == 0
                                         ? random_bits(rng, kf + 1)
                                         : 1 + random_bits(rng, kf) % (i128{1} << kf));
  };
  const auto scaled = [&] {
    ref::ScaledConst c;
    c.m = static_cast<std::int64_t>(random_magnitude(rng, mw));
    c.s = static_cast<int>(whole_ports && rng() % 4 == 0
                               ? rng() % 128
                               : rng() % static_cast<unsigned>(2 * lw + 8));
    return c;
  };
  const i128 r2_max = i128{1} << (2 * lw);
  const auto r2 = [&] {
    return whole_ports && rng() % 8 == 0 ? r2_max - static_cast<i128>(rng() % 3)
                                         : random_bits(rng, 2 * lw + 1) % (r2_max + 1);
  };
  switch (s.type) {
    case scene::SurfaceType::kEllipsoid:
    case scene::SurfaceType::kReliefEllipsoid:
      s.sx = unit_scale();
      s.sy = unit_scale();
      s.sz = unit_scale();
      s.r2 = r2();
      s.kd = static_cast<std::int64_t>(random_magnitude(rng, kf + 2));
      s.ke2 = static_cast<std::int64_t>(random_magnitude(rng, kf + 2));
      s.y_angle = scaled();
      break;
    case scene::SurfaceType::kSpiral:
      s.sx = unit_scale();
      s.sy = unit_scale();
      s.r2 = r2();
      s.rho0 = static_cast<std::int64_t>(random_magnitude(rng, lw));
      [[fallthrough]];
    case scene::SurfaceType::kSnail:
      s.a_turn = static_cast<std::int64_t>(random_magnitude(rng, lw + 8));
      s.k_turn = static_cast<std::int64_t>(random_magnitude(rng, lw + 8));
      s.full_turns = static_cast<int>(rng() % static_cast<unsigned>(turns));
      break;
    case scene::SurfaceType::kRocket:
      s.rocket_a = static_cast<std::int64_t>(random_magnitude(rng, lw));
      s.rocket_b = static_cast<std::int64_t>(random_magnitude(rng, lw));
      s.fin = scaled();
      s.cone = scaled();
      break;
  }
  return s;
}

// The indicator fields of a SurfaceDesc on the desc_i port of rpu_indicator, rpu_surface_ip and
// rpu_surface_top: driven packed (surface_word.h), listed field by field in a mismatch report.
template <class Top>
void indicator_inputs(Inputs& in, Top& top, const ref::HwParams& p, const ref::SurfaceDesc& s) {
  if (in.mode() == Inputs::kList) {
    const auto n = [](i128 v) { return static_cast<long long>(v); };
    in.note("desc", fmt::format("type {} full_turns {} s ({}, {}, {}) r2 {} kd {} ke2 {} "
                                "y_angle {}·2^-{} rho0 {} a_turn {} k_turn {} rocket a {} b {} "
                                "fin {}·2^-{} cone {}·2^-{}",
                                static_cast<int>(s.type), s.full_turns, n(s.sx), n(s.sy), n(s.sz),
                                n(s.r2), n(s.kd), n(s.ke2), n(s.y_angle.m), s.y_angle.s, n(s.rho0),
                                n(s.a_turn), n(s.k_turn), n(s.rocket_a), n(s.rocket_b), n(s.fin.m),
                                s.fin.s, n(s.cone.m), s.cone.s));
    return;
  }
  in.bits("desc", top.desc_i, pack_surface_desc(p, s));
}

}  // namespace rpu::sim
