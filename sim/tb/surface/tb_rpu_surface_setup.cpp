// rpu_surface_setup against its twin rpu::ref::surface_setup, on real SurfaceDescs: every surface
// of scenes/surf_{ellipsoid,relief,spiral,snail,rocket,mix}.json quantised at the parameters of
// this build, and again with every surface turned by (23°, 37°, 61°) more (no zero entry in its
// local-frame matrix), driven with
//   - random pixels of the scene's own camera (the model's ray generator), mostly pairs whose
//     bounding sphere is met, some that miss;
//   - random rays through the bounding sphere from outside it, and from an eye inside it;
//   - grazing rays (the sphere's discriminant within a hair of zero, both signs);
//   - rays along the range boundaries: in (or a few llsb off) the plane x = 0 and the end plane of
//     the spiral and snail, in and parallel to the slab planes y = y_min, y_max of the others
//     (the unrotated scenes give exact dy = 0 and f_x = 0 there);
//   - the spiral's and snail's descriptors with other end angles (below, at and above half a
//     turn, none), their end_cos / end_sin quantised as the compiler does;
//   - every descriptor with a smaller block shift to_local_s (M up to 2^8 times too large), so
//     that la and lb saturate (the overflow flag) for points far enough from the origin;
// each ray with every piece index 0..2 (and some with 3, never valid). Random valid gaps, junk on
// the inputs between items; latency and tag checked. pred1, pieces, piece_valid and the overflow
// bit are compared always; s_lo, s_hi, A', B' − A', lA', lB' − lA', x_negative and last_turn
// when the piece is valid (the twin leaves them zero otherwise; the RTL's are don't-care).
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "Vrpu_surface_setup.h"
#include "model/surface/rpu_surface_setup.h"
#include "model/surface/rpu_surface_setup_latency.h"
#include "model/units.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "tb_common.h"

#ifndef COORD_W
#define COORD_W 24
#endif
#ifndef DIR_FRAC
#define DIR_FRAC 24
#endif
#ifndef T_FRAC
#define T_FRAC 24
#endif
#ifndef INV_W
#define INV_W 18
#endif
#ifndef SQRT_W
#define SQRT_W 0
#endif
#ifndef SURF_W
#define SURF_W 24
#endif
#ifndef ANGLE_W
#define ANGLE_W 20
#endif
#ifndef TAG_W
#define TAG_W 8
#endif

namespace {

using namespace rpu;
using fixed::i64;
using fixed::u128;
using scene::SurfaceType;
using sim::i128;

constexpr double kTwoPi = 2.0 * std::numbers::pi;

ref::HwParams make_params() {
  ref::HwParams p;
  p.coord_w = COORD_W;
  p.dir_frac = DIR_FRAC;
  p.t_frac = T_FRAC;
  p.inv_w = INV_W;
  p.sqrt_w = SQRT_W;
  p.surf_w = SURF_W;
  p.angle_w = ANGLE_W;
  p.validate();
  return p;
}

const ref::HwParams kP = make_params();
const int CW = kP.coord_w, FV = kP.dir_frac, DirW = kP.dir_w(), DiffW = kP.diff_w();
const int R2W = 2 * CW + 1, LW = kP.surf_w, MW = kP.surf_mant_w(), KF = kP.surf_const_frac();
const int KW = KF + 2, SF = kP.surf_cut_frac(), SW = SF + 1, AW = kP.angle_w;
constexpr int kShW = 7;

enum Source { kPixel, kThrough, kInside, kGrazing, kPlane, kEndAngle, kSaturating, kSources };
const char* const kSourceName[kSources] = {"camera pixel", "through sphere", "eye inside",
                                           "grazing", "range plane", "end-angle variant",
                                           "saturating frame"};

struct Surf {
  std::string name;                   // scene file and surface index
  const scene::CompiledSurface* cs;   // frame and bounding sphere (world, local)
  ref::Normalization norm;
  ref::SurfaceDesc d;
};

struct Item {
  Source src;
  int surf = 0;     // index into the surface list
  int i = 0, j = 0;  // pixel (camera rays) or vector index
  int piece = 0;
  ref::IVec3 eye, vhat;
  const ref::SurfaceDesc* s = nullptr;
};

struct Expected {
  ref::SurfaceSetupOut o;
  bool ovf = false;
};
Expected expected(const Item& it) {
  Expected e;
  fixed::Overflow ovf;
  e.o = ref::surface_setup(kP, it.eye, it.vhat, *it.s, it.piece, ovf);
  e.ovf = ovf.flag;
  return e;
}

// A little-endian bit buffer: fields appended LSB first, then copied into a port of any width.
struct Bits {
  std::array<std::uint32_t, 32> w{};
  int n = 0;
  void add(i128 v, int width) {
    const u128 u = static_cast<u128>(v);
    for (int b = 0; b < width; ++b, ++n) {
      const bool bit = b < 128 ? ((u >> b) & 1) != 0 : v < 0;
      if (bit) w[static_cast<size_t>(n / 32)] |= 1u << (n % 32);
    }
  }
};
template <std::size_t N>
void put_bits(VlWide<N>& port, const Bits& b) {
  for (std::size_t k = 0; k < N; ++k) port[k] = b.w[k];
}
template <class T>
void put_bits(T& port, const Bits& b) {
  port = static_cast<T>(b.w[0] | (static_cast<std::uint64_t>(b.w[1]) << 32));
}
// A `w`-bit field (the value's low bits) into a port of exactly that width: Verilator expects
// the bits above the port's width to be zero.
template <class P>
void put_field(P& port, i128 v, int w) {
  Bits b;
  b.add(v, w);
  put_bits(port, b);
}
template <class P>
void put_vec(P& port, i128 x, i128 y, i128 z, int w) {
  Bits b;
  b.add(x, w);
  b.add(y, w);
  b.add(z, w);
  put_bits(port, b);
}
template <class P>
ref::WVec3 get_vec(const P& port, int w) {
  const u128 u = sim::get_unsigned(port, 3 * w);
  const auto comp = [&](int k) {
    const u128 c = (u >> (k * w)) & fixed::max_unsigned(w), sign = u128{1} << (w - 1);
    return static_cast<i128>((c ^ sign) - sign);
  };
  return {comp(0), comp(1), comp(2)};
}

std::string str(i128 v) { return sim::to_string(v); }
std::string str(const ref::WVec3& v) {
  std::string s("(");  // appended piecewise (GCC 12 warns falsely on "(" + std::string)
  s += str(v.x);
  s += ", ";
  s += str(v.y);
  s += ", ";
  s += str(v.z);
  s += ")";
  return s;
}
std::string str(const ref::IVec3& v) { return str(ref::WVec3{v.x, v.y, v.z}); }

bool fits3(const ref::IVec3& v, int w) {
  return fixed::fits_signed(v.x, w) && fixed::fits_signed(v.y, w) && fixed::fits_signed(v.z, w);
}
// The item's inputs must be representable on the ports (every scene-derived value is).
bool fits_ports(const Item& it) {
  const ref::SurfaceDesc& s = *it.s;
  bool ok = fits3(it.eye, CW) && fits3(it.vhat, DirW) && fits3(s.bound.c0, CW) &&
            fits3(s.origin, CW) && s.bound.R2 >= 0 &&
            fixed::fits_unsigned(static_cast<u128>(s.bound.R2), R2W) && s.to_local_s >= 0 &&
            s.to_local_s < (1 << kShW) && fixed::fits_signed(s.y_min, LW) &&
            fixed::fits_signed(s.y_max, LW) && s.end_angle < (std::uint64_t{1} << AW) &&
            fixed::fits_signed(s.end_cos, KW) && fixed::fits_signed(s.end_sin, KW) &&
            it.piece >= 0 && it.piece < 4;
  for (i64 m : s.to_local) ok = ok && fixed::fits_signed(m, MW);
  return ok;
}

// A unit direction quantised as the ray generator's v̂ (Q(2.FV)).
ref::IVec3 quantise_dir(const Vec3& d) {
  const Vec3 u = normalize(d);
  return {std::llround(std::ldexp(u.x, FV)), std::llround(std::ldexp(u.y, FV)),
          std::llround(std::ldexp(u.z, FV))};
}
Vec3 to_vec(const ref::IVec3& v) {
  return {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)};
}

// A random unit vector.
Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Vec3 u;
  do u = {g(rng), g(rng), g(rng)};
  while (length(u) < 1e-6);
  return normalize(u);
}

// The end plane's cos, sin as the compiler quantises them (surface_descriptors.cpp).
ref::SurfaceDesc with_end_angle(ref::SurfaceDesc d, std::uint64_t end) {
  d.end_angle = end;
  const double a = kTwoPi * static_cast<double>(end) / std::ldexp(1.0, AW);
  d.end_cos = std::llround(std::ldexp(std::cos(a), KF));
  d.end_sin = std::llround(std::ldexp(std::sin(a), KF));
  return d;
}

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_surface_setup");
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_surface_setup>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_surface_setup");
  std::mt19937_64 rng(seed);
  const long latency = ref::surface_setup_latency(kP);
  const long scale = std::max<long>(1, sim::vector_count(1));  // RPU_VECTORS multiplies the counts

  // ---- the scenes' surfaces (their descriptors and variants live in a deque: stable) ----
  std::deque<scene::CompiledScene> scenes;
  std::deque<ref::SurfaceDesc> variants;
  std::vector<Surf> surfs;
  std::vector<ref::CameraDesc> cams;  // per surface: its scene's camera
  // Each scene twice: as written, and with every surface turned by (23°, 37°, 61°) more about
  // x, y, z, so every entry of the local-frame matrix is nonzero (the scenes' own placements
  // leave some at zero, e.g. M[1][0] after a 90° turn about x, and their products untested).
  for (int turned = 0; turned < 2; ++turned) {
    for (const char* name : {"surf_ellipsoid", "surf_relief", "surf_spiral", "surf_snail",
                             "surf_rocket", "surf_mix"}) {
      scene::Scene sc =
          scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/" + name + ".json");
      if (turned)
        for (scene::Surface& s : sc.surfaces)
          s.rotation_deg = {s.rotation_deg.x + 23.0, s.rotation_deg.y + 37.0,
                            s.rotation_deg.z + 61.0};
      scenes.push_back(scene::compile_scene(sc));
      const ref::ModelScene m = ref::quantize_scene(scenes.back(), kP);
      for (size_t k = 0; k < m.surfaces.size(); ++k) {
        surfs.push_back({std::string(name) + (turned ? "/turned[" : "[") + std::to_string(k) + "]",
                         &scenes.back().surfaces[k], m.norm, m.surfaces[k]});
        cams.push_back(m.camera);
      }
    }
  }
  std::printf("%zu surfaces:", surfs.size());
  for (const Surf& s : surfs)
    std::printf(" %s (%s, to_local_s %d, end angle %llu)", s.name.c_str(),
                scene::surface_type_name(s.d.type), s.d.to_local_s,
                static_cast<unsigned long long>(s.d.end_angle));
  std::printf("\n");

  std::vector<Item> items;
  const auto add_ray = [&](Source src, int si, int i, int j, const ref::IVec3& eye,
                           const ref::IVec3& vhat, const ref::SurfaceDesc* d) {
    if (vhat.x == 0 && vhat.y == 0 && vhat.z == 0) return;
    for (int piece = 0; piece < 3; ++piece) {
      Item it;
      it.src = src;
      it.surf = si;
      it.i = i;
      it.j = j;
      it.piece = piece;
      it.eye = eye;
      it.vhat = vhat;
      it.s = d;
      items.push_back(it);
    }
    if (rng() % 16 == 0) {  // piece 3: never valid
      items.push_back(items.back());
      items.back().piece = 3;
    }
  };

  for (int si = 0; si < static_cast<int>(surfs.size()); ++si) {
    const Surf& S = surfs[static_cast<size_t>(si)];
    const ref::SurfaceDesc* d = &S.d;
    const ref::CameraDesc& cam = cams[static_cast<size_t>(si)];
    std::uniform_real_distribution<double> u01(0.0, 1.0);

    // ---- camera pixels: 1500 rays meeting the sphere, 400 missing it ----
    {
      int hits = 0, misses = 0;
      for (int tries = 0; tries < 400000 && (hits < 1500 * scale || misses < 400 * scale); ++tries) {
        const int i = static_cast<int>(rng() % static_cast<u128>(cam.width));
        const int j = static_cast<int>(rng() % static_cast<u128>(cam.height));
        const ref::IVec3 vhat = ref::ray_generator(kP, cam, i, j).vhat;
        fixed::Overflow ovf;
        const bool pred1 = ref::sphere_unit(kP, cam.eye, vhat, d->bound, ovf).pred1;
        if (pred1 ? hits++ < 1500 * scale : misses++ < 400 * scale)
          add_ray(kPixel, si, i, j, cam.eye, vhat, d);
      }
    }

    // ---- rays through the bounding sphere: eye outside (1.1 R .. 6 R) and inside (< 0.95 R) ----
    const Vec3 c0 = to_vec(d->bound.c0);
    const double R = std::sqrt(static_cast<double>(d->bound.R2));
    const double lim = std::ldexp(1.0, CW - 1) - 2.0;
    const auto in_range = [&](const Vec3& v) {
      return std::fabs(v.x) < lim && std::fabs(v.y) < lim && std::fabs(v.z) < lim;
    };
    const auto round3 = [](const Vec3& v) {
      return ref::IVec3{std::llround(v.x), std::llround(v.y), std::llround(v.z)};
    };
    for (int n = 0; n < 1200 * scale; ++n) {
      const bool inside = n % 4 == 3;
      const Vec3 e = c0 + random_unit(rng) * (inside ? 0.95 * R * std::cbrt(u01(rng))
                                                     : R * (1.1 + 4.9 * u01(rng)));
      const Vec3 t = c0 + random_unit(rng) * (0.95 * R * std::cbrt(u01(rng)));
      if (!in_range(e)) continue;
      const ref::IVec3 eye = round3(e);
      add_ray(inside ? kInside : kThrough, si, n, 0, eye, quantise_dir(t - to_vec(eye)), d);
    }

    // ---- grazing rays: impact parameter R·(1 + ε), ε a hair either side of zero ----
    for (int n = 0; n < 400 * scale; ++n) {
      const Vec3 uhat = random_unit(rng);
      const double L = R * (1.5 + 3.0 * u01(rng));
      const Vec3 e = c0 - uhat * L;
      if (!in_range(e)) continue;
      const ref::IVec3 eye = round3(e);
      Vec3 w = cross(uhat, random_unit(rng));
      if (length(w) < 1e-3) continue;
      w = normalize(w);
      const double eps = (u01(rng) - 0.5) * std::ldexp(1.0, -static_cast<int>(rng() % 24));
      const double b = R * L / std::sqrt(L * L - R * R) * (1.0 + eps);
      add_ray(kGrazing, si, n, 0, eye, quantise_dir(c0 + w * b - to_vec(eye)), d);
    }

    // ---- rays along the range boundaries (local frame → world LSB) ----
    const scene::CompiledSurface& cs = *S.cs;
    const double lr = cs.local_radius;
    const double llsb = std::ldexp(1.0, -d->local_frac);  // one llsb in local units
    const auto world = [&](const Vec3& l) { return S.norm.position(cs.local_to_world(l)); };
    const bool azimuth = d->type == SurfaceType::kSpiral || d->type == SurfaceType::kSnail;
    const auto plane_rays = [&](const ref::SurfaceDesc* dd) {
      // Plane n·x = off through the local origin, in-plane unit vectors p, q.
      std::vector<std::array<Vec3, 3>> planes;  // {normal, p, q}
      if (azimuth) {
        planes.push_back({Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}});
        const double a = kTwoPi * static_cast<double>(dd->end_angle) / std::ldexp(1.0, AW);
        planes.push_back(
            {Vec3{std::cos(a), 0, -std::sin(a)}, Vec3{0, 1, 0}, Vec3{std::sin(a), 0, std::cos(a)}});
      }
      for (int n = 0; n < 300 * scale; ++n) {
        Vec3 le, lt;
        const int kind = static_cast<int>(rng() % 4);
        const double off = kind == 0 ? 0.0 : (static_cast<double>(rng() % 7) - 3.0) * llsb;
        if (azimuth) {
          const auto& pl = planes[static_cast<size_t>(n % planes.size())];
          // Eye in the plane (or `off` beside it) outside the sphere, target in it inside.
          const auto in_plane = [&](double rad) {
            const double a = u01(rng) * kTwoPi;
            return cs.local_centre + pl[1] * (rad * std::cos(a)) + pl[2] * (rad * std::sin(a));
          };
          le = in_plane(lr * (1.2 + 2.0 * u01(rng)));
          lt = in_plane(lr * 0.9 * u01(rng));
          // project onto the plane through the local origin, then offset
          le = le - pl[0] * dot(le, pl[0]) + pl[0] * off;
          lt = lt - pl[0] * dot(lt, pl[0]) + pl[0] * (kind == 3 ? -off : off);
        } else {
          // A slab plane y = y_min or y_max (or between), the ray parallel to it or crossing
          // it at a shallow angle.
          const double yb = static_cast<double>(n % 2 ? dd->y_max : dd->y_min) * llsb;
          const double y = kind == 2 ? yb + (u01(rng) - 0.5) * lr * 0.2 : yb + off;
          const Vec3 dir = random_unit(rng);
          Vec3 flat = normalize(Vec3{dir.x, 0, dir.z});
          le = Vec3{cs.local_centre.x, y, cs.local_centre.z} - flat * (lr * (1.2 + 2.0 * u01(rng)));
          lt = Vec3{cs.local_centre.x + (u01(rng) - 0.5) * lr, y, cs.local_centre.z} +
               Vec3{0, kind == 3 ? off * 8.0 : 0.0, 0};
        }
        const ref::IVec3 eye = world(le);
        if (!fits3(eye, CW)) continue;
        // World direction of the local one (exact in-plane for the unrotated scenes when the
        // target is rounded the same way).
        const Vec3 wdir = to_vec(world(lt)) - to_vec(eye);
        if (length(wdir) < 1.0) continue;
        add_ray(kPlane, si, n, kind, eye, quantise_dir(wdir), dd);
      }
    };
    plane_rays(d);

    // ---- the spiral's and snail's x = 0 cut exactly at an end: the eye inside the sphere with
    // la.x = 0 and the ray leaving into x < 0 (a cut at s = 0), or the ray ending with lb.x = 0
    // after starting in x < 0 (a cut at s = 1); both leave an empty interval ----
    if (azimuth) {
      for (int n = 0; n < 300 * scale; ++n) {
        ref::IVec3 eye = round3(c0 + random_unit(rng) * (0.6 * R * std::cbrt(u01(rng))));
        const bool at_end = n % 2 == 1;
        eye.x = at_end ? d->origin.x - 1 - static_cast<i64>(rng() % 20)
                       : d->origin.x + static_cast<i64>(rng() % 2);
        if (length(to_vec(eye) - c0) > 0.9 * R || !fits3(eye, CW)) continue;
        ref::IVec3 vhat = quantise_dir(random_unit(rng));
        if (!at_end) {
          vhat.x = -std::abs(vhat.x) - 1;
        } else {
          // floor(v̂.x·t2·2^-FV) = origin.x − eye.x + 1: B lands one LSB past the plane.
          for (int iter = 0; iter < 3; ++iter) {
            fixed::Overflow ovf;
            const ref::SearchInterval si = ref::sphere_unit(kP, eye, vhat, d->bound, ovf);
            const double t2 = static_cast<double>(si.tc + si.half_chord);
            if (t2 <= 0) break;
            const double want = static_cast<double>(d->origin.x - eye.x) + 1.5;
            vhat.x = static_cast<i64>(std::floor(std::ldexp(want, FV) / t2));
          }
        }
        add_ray(kPlane, si, n, 4 + at_end, eye, vhat, d);
      }
    }

    // ---- the spiral's and snail's end plane at other angles ----
    if (azimuth) {
      const std::uint64_t turn = std::uint64_t{1} << AW, half = turn >> 1;
      const std::vector<std::uint64_t> ends = {0, 1, half / 3, half - 1, half, half + 1,
                                               turn - turn / 7, turn - 1,
                                               1 + rng() % (turn - 1), 1 + rng() % (turn - 1)};
      for (std::uint64_t end : ends) {
        variants.push_back(with_end_angle(*d, end));
        const ref::SurfaceDesc* vd = &variants.back();
        for (int n = 0; n < 150 * scale; ++n) {
          const Vec3 e = c0 + random_unit(rng) * (n % 5 == 4 ? 0.9 * R * u01(rng)
                                                             : R * (1.1 + 3.0 * u01(rng)));
          const Vec3 t = c0 + random_unit(rng) * (0.9 * R * std::cbrt(u01(rng)));
          if (!in_range(e)) continue;
          const ref::IVec3 eye = round3(e);
          add_ray(kEndAngle, si, n, static_cast<int>(end), eye, quantise_dir(t - to_vec(eye)), vd);
        }
        plane_rays(vd);
      }
    }

    // ---- a smaller block shift: la, lb saturate for points far from the origin ----
    for (int k = 1; k <= 8; ++k) {
      ref::SurfaceDesc sd = *d;
      sd.to_local_s = std::max(0, sd.to_local_s - k);
      variants.push_back(sd);
      const ref::SurfaceDesc* vd = &variants.back();
      for (int n = 0; n < 100 * scale; ++n) {
        const Vec3 e = c0 + random_unit(rng) * (R * (1.1 + 3.0 * u01(rng)));
        const Vec3 t = c0 + random_unit(rng) * (0.9 * R * std::cbrt(u01(rng)));
        if (!in_range(e)) continue;
        const ref::IVec3 eye = round3(e);
        add_ray(kSaturating, si, n, k, eye, quantise_dir(t - to_vec(eye)), vd);
      }
    }
  }

  // ---- statistics of what is driven ----
  long per_src[kSources] = {}, per_src_pred[kSources] = {}, per_src_valid[kSources] = {};
  long per_src_ovf[kSources] = {};
  long pieces_hist[4] = {}, xneg[2] = {}, last[2] = {}, slab_full = 0, slab_dy0 = 0;
  long cut_at_end = 0, cut_at_start = 0, slab_lo0 = 0, slab_hi1 = 0, slab_inner = 0;
  for (const Item& it : items) {
    if (!fits_ports(it)) {
      std::printf("FAILURE: a %s vector does not fit the ports (surface %s, eye %s, vhat %s)\n",
                  kSourceName[it.src], surfs[static_cast<size_t>(it.surf)].name.c_str(),
                  str(it.eye).c_str(), str(it.vhat).c_str());
      return 1;
    }
    const Expected e = expected(it);
    ++per_src[it.src];
    per_src_pred[it.src] += e.o.sphere.pred1;
    per_src_valid[it.src] += e.o.valid;
    per_src_ovf[it.src] += e.ovf;
    if (it.piece == 0) ++pieces_hist[e.o.pieces];
    if (e.o.valid) {
      const bool az = it.s->type == SurfaceType::kSpiral || it.s->type == SurfaceType::kSnail;
      if (az) {
        ++xneg[e.o.x_negative];
        ++last[e.o.last_turn];
        cut_at_start += it.piece == 0 && e.o.la.x == 0 && e.o.lb.x < 0;
        cut_at_end += it.piece == 0 && e.o.la.x < 0 && e.o.lb.x == 0;
      } else {
        slab_full += e.o.s_lo == 0 && e.o.s_hi == (i128{1} << SF);
        slab_lo0 += e.o.s_lo == 0;
        slab_hi1 += e.o.s_hi == (i128{1} << SF);
        slab_inner += e.o.s_lo > 0 && e.o.s_hi < (i128{1} << SF);
        slab_dy0 += e.o.lb.y == e.o.la.y;
      }
    }
  }
  for (int k = 0; k < kSources; ++k)
    std::printf("  %-18s %7ld items, %7ld with pred1, %7ld valid pieces, %5ld with overflow\n",
                kSourceName[k], per_src[k], per_src_pred[k], per_src_valid[k], per_src_ovf[k]);
  std::printf("  rays with 0/1/2/3 pieces: %ld / %ld / %ld / %ld; azimuth pieces x_negative 0/1: "
              "%ld / %ld, last_turn 0/1: %ld / %ld; azimuth rays with the x = 0 cut at s = 0: %ld, "
              "at s = 1: %ld\n  slab pieces: [0, 1] %ld, from 0 %ld, to 1 %ld, "
              "inside (0, 1) %ld, with dy = 0: %ld\n",
              pieces_hist[0], pieces_hist[1], pieces_hist[2], pieces_hist[3], xneg[0], xneg[1],
              last[0], last[1], cut_at_start, cut_at_end, slab_full, slab_lo0, slab_hi1,
              slab_inner, slab_dy0);

  // ---- drive and check ----
  std::shuffle(items.begin(), items.end(), rng);  // mix the sources and surfaces
  sim::reset(*top, *ctx);
  struct Pending {
    size_t index;
    long cycle;
    std::uint32_t tag;
    Expected want;
  };
  std::deque<Pending> pending;
  const u128 tag_mask = fixed::max_unsigned(TAG_W);
  long matched = 0, cycle = 0, valid_pieces = 0;
  size_t next = 0;
  const long total = static_cast<long>(items.size());
  const auto junk = [&] { return static_cast<i128>((static_cast<u128>(rng()) << 64) | rng()); };
  while (matched < total) {
    const bool issue = next < items.size() && (rng() % 100) < 85;
    top->valid_i = issue;
    if (issue) {
      const Item& it = items[next];
      const ref::SurfaceDesc& s = *it.s;
      put_vec(top->eye_i, it.eye.x, it.eye.y, it.eye.z, CW);
      put_vec(top->vhat_i, it.vhat.x, it.vhat.y, it.vhat.z, DirW);
      put_vec(top->c0_i, s.bound.c0.x, s.bound.c0.y, s.bound.c0.z, CW);
      put_field(top->r2_i, s.bound.R2, R2W);
      put_vec(top->origin_i, s.origin.x, s.origin.y, s.origin.z, CW);
      Bits m;
      for (i64 v : s.to_local) m.add(v, MW);
      put_bits(top->to_local_i, m);
      top->to_local_s_i = static_cast<CData>(s.to_local_s);
      top->type_i = static_cast<CData>(s.type);
      put_field(top->y_min_i, s.y_min, LW);
      put_field(top->y_max_i, s.y_max, LW);
      put_field(top->end_angle_i, static_cast<i128>(s.end_angle), AW);
      put_field(top->end_cos_i, s.end_cos, KW);
      put_field(top->end_sin_i, s.end_sin, KW);
      top->piece_i = static_cast<CData>(it.piece);
      const std::uint32_t tag = static_cast<std::uint32_t>(next & tag_mask);
      put_field(top->tag_i, tag, TAG_W);
      pending.push_back({next, cycle, tag, expected(it)});
      ++next;
    } else {  // junk on the data inputs: nothing may depend on them
      put_vec(top->eye_i, junk(), junk(), junk(), CW);
      put_vec(top->vhat_i, junk(), junk(), junk(), DirW);
      put_vec(top->c0_i, junk(), junk(), junk(), CW);
      put_field(top->r2_i, junk() & static_cast<i128>(fixed::max_unsigned(R2W)), R2W);
      put_vec(top->origin_i, junk(), junk(), junk(), CW);
      Bits m;
      for (int k = 0; k < 9; ++k) m.add(junk(), MW);
      put_bits(top->to_local_i, m);
      top->to_local_s_i = static_cast<CData>(rng() & 0x7F);
      top->type_i = static_cast<CData>(rng() & 7);
      put_field(top->y_min_i, junk(), LW);
      put_field(top->y_max_i, junk(), LW);
      put_field(top->end_angle_i, junk(), AW);
      put_field(top->end_cos_i, junk(), KW);
      put_field(top->end_sin_i, junk(), KW);
      top->piece_i = static_cast<CData>(rng() & 3);
      put_field(top->tag_i, junk() & static_cast<i128>(tag_mask), TAG_W);
    }
    sim::tick(*top, *ctx);
    ++cycle;
    if (top->valid_o) {
      if (pending.empty()) {
        std::printf("FAILURE cycle %ld: valid_o with no item outstanding\n", cycle);
        return 1;
      }
      const Pending pd = pending.front();
      pending.pop_front();
      const Item& it = items[pd.index];
      const ref::SurfaceSetupOut& w = pd.want.o;
      const bool want_ovf = pd.want.ovf;
      ref::SurfaceSetupOut got;
      got.sphere.pred1 = top->pred1_o;
      got.valid = top->piece_valid_o;
      got.pieces = top->pieces_o;
      got.s_lo = static_cast<i128>(sim::get_unsigned(top->s_lo_o, SW));
      got.s_hi = static_cast<i128>(sim::get_unsigned(top->s_hi_o, SW));
      got.A = get_vec(top->a_o, CW);
      got.AB = get_vec(top->ab_o, DiffW);
      got.lA = get_vec(top->la_o, LW);
      got.lAB = get_vec(top->lab_o, LW + 1);
      got.x_negative = top->x_negative_o;
      got.last_turn = top->last_turn_o;
      const bool got_ovf = top->ovf_o;
      const std::uint32_t got_tag = static_cast<std::uint32_t>(sim::get_unsigned(top->tag_o, TAG_W));
      const char* field = nullptr;
      if (cycle - pd.cycle != latency) field = "latency";
      else if (got_tag != pd.tag) field = "tag";
      else if (got.sphere.pred1 != w.sphere.pred1) field = "pred1";
      else if (got.pieces != w.pieces) field = "pieces";
      else if (got.valid != w.valid) field = "piece_valid";
      else if (got_ovf != want_ovf) field = "overflow";
      else if (w.valid && got.s_lo != w.s_lo) field = "s_lo";
      else if (w.valid && got.s_hi != w.s_hi) field = "s_hi";
      else if (w.valid && !(got.A == w.A)) field = "A'";
      else if (w.valid && !(got.AB == w.AB)) field = "B' - A'";
      else if (w.valid && !(got.lA == w.lA)) field = "lA'";
      else if (w.valid && !(got.lAB == w.lAB)) field = "lB' - lA'";
      else if (w.valid && got.x_negative != w.x_negative) field = "x_negative";
      else if (w.valid && got.last_turn != w.last_turn) field = "last_turn";
      if (field) {
        const ref::SurfaceDesc& s = *it.s;
        std::printf("FAILURE cycle %ld item %zu (%s, surface %s, %d/%d, piece %d): %s differs "
                    "(issued at cycle %ld, latency %ld expected %ld; tag %u expected %u)\n",
                    cycle, pd.index, kSourceName[it.src],
                    surfs[static_cast<size_t>(it.surf)].name.c_str(), it.i, it.j, it.piece, field,
                    pd.cycle, cycle - pd.cycle, latency, got_tag, pd.tag);
        std::printf("  inputs:   eye %s vhat %s c0 %s R2 %s origin %s to_local_s %d type %d "
                    "y_min %lld y_max %lld end_angle %llu end_cos %lld end_sin %lld\n",
                    str(it.eye).c_str(), str(it.vhat).c_str(), str(s.bound.c0).c_str(),
                    str(s.bound.R2).c_str(), str(s.origin).c_str(), s.to_local_s,
                    static_cast<int>(s.type), static_cast<long long>(s.y_min),
                    static_cast<long long>(s.y_max), static_cast<unsigned long long>(s.end_angle),
                    static_cast<long long>(s.end_cos), static_cast<long long>(s.end_sin));
        std::printf("  to_local:");
        for (i64 v : s.to_local) std::printf(" %lld", static_cast<long long>(v));
        std::printf("\n  twin's intermediates: A %s B %s la %s lb %s\n", str(w.sphere.A).c_str(),
                    str(w.sphere.B).c_str(), str(w.la).c_str(), str(w.lb).c_str());
        for (int k = 0; k < 2; ++k) {
          const ref::SurfaceSetupOut& v = k == 0 ? w : got;
          std::printf("  %s pred1 %d pieces %d valid %d overflow %d s_lo %s s_hi %s A' %s "
                      "B'-A' %s lA' %s lB'-lA' %s x_negative %d last_turn %d\n",
                      k == 0 ? "expected:" : "actual:  ", v.sphere.pred1, v.pieces, v.valid,
                      k == 0 ? want_ovf : got_ovf, str(v.s_lo).c_str(), str(v.s_hi).c_str(),
                      str(v.A).c_str(), str(v.AB).c_str(), str(v.lA).c_str(), str(v.lAB).c_str(),
                      v.x_negative, v.last_turn);
        }
        return 1;
      }
      ++matched;
      valid_pieces += w.valid;
    }
    if (cycle > 4 * total + 1000) {
      std::printf("FAILURE: timeout after %ld cycles, %ld of %ld matched\n", cycle, matched, total);
      return 1;
    }
  }
  top->final();
  std::printf("rpu_surface_setup CoordW=%d DirFrac=%d SurfW=%d AngleW=%d: latency %ld, matched %ld "
              "items (%ld valid pieces) in %ld cycles\n",
              CW, FV, LW, AW, latency, matched, valid_pieces, cycle);
  return 0;
}
