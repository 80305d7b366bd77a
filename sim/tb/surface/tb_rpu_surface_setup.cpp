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
// each ray with every piece index 0..2 (and some with 3, never valid); latency and tag checked.
// pred1, pieces, piece_valid and the overflow bit are compared always; s_lo, s_hi, A', B' − A', lA', lB' − lA', x_negative and last_turn
// when the piece is valid (the twin leaves them zero otherwise; the RTL's are don't-care).
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <numbers>
#include <string>
#include <vector>

#include "Vrpu_surface_setup.h"
#include "model/surface/rpu_surface_setup.h"
#include "model/surface/rpu_surface_setup_latency.h"
#include "tb_surface_common.h"

namespace {

using fixed::i64;
using scene::SurfaceType;

constexpr double kTwoPi = 2.0 * std::numbers::pi;

const ref::HwParams kP = sim::tb_params();
const int CW = kP.coord_w, FV = kP.dir_frac, DirW = kP.dir_w(), DiffW = kP.diff_w();
const int R2W = kP.r2_w(), LW = kP.surf_w, MW = kP.surf_mant_w(), KF = kP.surf_const_frac();
const int ConstW = KF + 2, SF = kP.surf_cut_frac(), SW = SF + 1, AW = kP.angle_w;
constexpr int kShW = 7;

enum Source { kPixel, kThrough, kInside, kGrazing, kPlane, kEndAngle, kSaturating, kSources };
const char* const kSourceName[kSources] = {"camera pixel", "through sphere", "eye inside",
                                           "grazing", "range plane", "end-angle variant",
                                           "saturating frame"};

struct Expected {
  ref::SurfaceSetupOut o;
  bool ovf = false;
};

struct Item {
  Source src;
  int surf;  // index into the surface list
  int i, j;  // pixel (camera rays) or vector index
  int piece;
  ref::IVec3 eye, vhat;
  const ref::SurfaceDesc* s;
  Expected want = {};
};
Expected expected(const Item& it) {
  Expected e;
  fixed::Overflow ovf;
  e.o = ref::surface_setup(kP, it.eye, it.vhat, *it.s, it.piece, ovf);
  e.ovf = ovf.flag;
  return e;
}

using sim::fits_signed3;
// The item's inputs must be representable on the ports (every scene-derived value is).
bool fits_ports(const Item& it) {
  const ref::SurfaceDesc& s = *it.s;
  bool ok = fits_signed3(it.eye, CW) && fits_signed3(it.vhat, DirW) &&
            fits_signed3(s.bound.c0, CW) && fits_signed3(s.origin, CW) &&
            sim::fits_unsigned(s.bound.R2, R2W) && s.to_local_s >= 0 &&
            s.to_local_s < (1 << kShW) && fixed::fits_signed(s.y_min, LW) &&
            fixed::fits_signed(s.y_max, LW) && s.end_angle < (std::uint64_t{1} << AW) &&
            fixed::fits_signed(s.end_cos, ConstW) && fixed::fits_signed(s.end_sin, ConstW) &&
            it.piece >= 0 && it.piece < 4;
  for (i64 m : s.to_local) ok = ok && fixed::fits_signed(m, MW);
  return ok;
}

using sim::random_unit;
using sim::round3;
using sim::to_vec;
ref::IVec3 quantise_dir(const Vec3& d) { return sim::quantise_dir(kP, d); }

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
  sim::Testbench<Vrpu_surface_setup> tb("tb_rpu_surface_setup", argc, argv);
  auto& rng = tb.rng;
  const long scale = std::max<long>(1, tb.vectors(1));  // RPU_VECTORS multiplies the counts

  std::deque<scene::CompiledScene> scenes;
  std::deque<ref::SurfaceDesc> variants;
  // Each scene twice: as written, and with every surface turned by (23°, 37°, 61°) more about
  // x, y, z, so every entry of the local-frame matrix is nonzero (the scenes' own placements
  // leave some at zero, e.g. M[1][0] after a 90° turn about x, and their products untested).
  std::vector<sim::SurfCase> surfs = sim::load_surface_cases(kP, scenes);
  for (const sim::SurfCase& s : sim::load_surface_cases(kP, scenes, true)) surfs.push_back(s);
  std::printf("%zu surfaces:", surfs.size());
  for (const sim::SurfCase& s : surfs)
    std::printf(" %s (%s, to_local_s %d, end angle %llu)", s.name.c_str(),
                scene::surface_type_name(s.d.type), s.d.to_local_s,
                static_cast<unsigned long long>(s.d.end_angle));
  std::printf("\n");

  std::vector<Item> items;
  const auto add_ray = [&](Source src, int si, int i, int j, const ref::IVec3& eye,
                           const ref::IVec3& vhat, const ref::SurfaceDesc* d) {
    if (vhat.x == 0 && vhat.y == 0 && vhat.z == 0) return;
    for (int piece = 0; piece < 3; ++piece) items.push_back({src, si, i, j, piece, eye, vhat, d});
    if (rng() % 16 == 0) {  // piece 3: never valid
      items.push_back(items.back());
      items.back().piece = 3;
    }
  };

  for (int si = 0; si < static_cast<int>(surfs.size()); ++si) {
    const sim::SurfCase& S = surfs[static_cast<size_t>(si)];
    const ref::SurfaceDesc* d = &S.d;
    const ref::CameraDesc& cam = S.cam;
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
        if (!fits_signed3(eye, CW)) continue;
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
        if (length(to_vec(eye) - c0) > 0.9 * R || !fits_signed3(eye, CW)) continue;
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
  sim::Tally by_src(kSourceName, {"items", "with pred1", "valid pieces", "with overflow"});
  long pieces_hist[4] = {}, xneg[2] = {}, last[2] = {}, slab_full = 0, slab_dy0 = 0;
  long cut_at_end = 0, cut_at_start = 0, slab_lo0 = 0, slab_hi1 = 0, slab_inner = 0;
  for (Item& it : items) {
    if (!fits_ports(it))
      return tb.fail("a %s vector does not fit the ports (surface %s, eye %s, vhat %s)",
                     kSourceName[it.src], surfs[static_cast<size_t>(it.surf)].name.c_str(),
                     sim::str(it.eye).c_str(), sim::str(it.vhat).c_str());
    const Expected e = it.want = expected(it);
    by_src.add(it.src, 1, e.o.sphere.pred1, e.o.valid, e.ovf);
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
  by_src.print("per source");
  std::printf("  rays with 0/1/2/3 pieces: %ld / %ld / %ld / %ld; azimuth pieces x_negative 0/1: "
              "%ld / %ld, last_turn 0/1: %ld / %ld; azimuth rays with the x = 0 cut at s = 0: %ld, "
              "at s = 1: %ld\n  slab pieces: [0, 1] %ld, from 0 %ld, to 1 %ld, "
              "inside (0, 1) %ld, with dy = 0: %ld\n",
              pieces_hist[0], pieces_hist[1], pieces_hist[2], pieces_hist[3], xneg[0], xneg[1],
              last[0], last[1], cut_at_start, cut_at_end, slab_full, slab_lo0, slab_hi1,
              slab_inner, slab_dy0);

  std::shuffle(items.begin(), items.end(), rng);  // mix the sources and surfaces

  sim::Stream<Vrpu_surface_setup, Item> st{.latency = ref::surface_setup_latency(kP)};
  st.inputs = [](sim::Inputs& in, Vrpu_surface_setup& t, const Item& it) {
    const ref::SurfaceDesc& s = *it.s;
    in.vec("eye", t.eye_i, it.eye, CW).vec("vhat", t.vhat_i, it.vhat, DirW).vec("c0", t.c0_i, s.bound.c0, CW);
    in("R2", t.r2_i, s.bound.R2, R2W).vec("origin", t.origin_i, s.origin, CW);
    in.fields("to_local", t.to_local_i, s.to_local, MW)("to_local_s", t.to_local_s_i, s.to_local_s, kShW);
    in("type", t.type_i, static_cast<int>(s.type), 3)("y_min", t.y_min_i, s.y_min, LW)("y_max", t.y_max_i, s.y_max, LW);
    in("end_angle", t.end_angle_i, static_cast<i128>(s.end_angle), AW)("end_cos", t.end_cos_i, s.end_cos, ConstW);
    in("end_sin", t.end_sin_i, s.end_sin, ConstW)("piece", t.piece_i, it.piece, 2);
  };
  st.outputs = [](sim::Outputs& o, const Vrpu_surface_setup& t, const Item& it) {
    const ref::SurfaceSetupOut& w = it.want.o;
    o("pred1", t.pred1_o, w.sphere.pred1, 1)("pieces", t.pieces_o, w.pieces, 2);
    o("piece_valid", t.piece_valid_o, w.valid, 1)("overflow", t.ovf_o, it.want.ovf, 1);
    o("s_lo", t.s_lo_o, w.s_lo, SW, w.valid)("s_hi", t.s_hi_o, w.s_hi, SW, w.valid);
    o.vec("A'", t.a_o, w.A, CW, w.valid).vec("B' - A'", t.ab_o, w.AB, DiffW, w.valid);
    o.vec("lA'", t.la_o, w.lA, LW, w.valid).vec("lB' - lA'", t.lab_o, w.lAB, LW + 1, w.valid);
    o("x_negative", t.x_negative_o, w.x_negative, 1, w.valid)("last_turn", t.last_turn_o, w.last_turn, 1, w.valid);
    o.note("A", sim::str(w.sphere.A)).note("B", sim::str(w.sphere.B)).note("la", sim::str(w.la));
    o.note("lb", sim::str(w.lb));
  };
  st.what = [&](const Item& it) {
    return std::string(kSourceName[it.src]) + ", surface " + surfs[static_cast<size_t>(it.surf)].name +
           ", " + std::to_string(it.i) + "/" + std::to_string(it.j) + ", piece " + std::to_string(it.piece);
  };
  if (!tb.run(items, st)) return 1;
  long valid_pieces = 0;
  for (const Item& it : items) valid_pieces += it.want.o.valid;
  return tb.pass("CoordW=%d DirFrac=%d SurfW=%d AngleW=%d, latency %ld, %ld valid pieces", CW, FV,
                 LW, AW, st.latency, valid_pieces);
}
