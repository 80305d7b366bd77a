// rpu_capture against rpu::ref::capture_unit: the curve points the model's IP selects on
// curve12 (hits and near misses), random points over the whole range, t edge values, and (every
// eighth item) random edge vectors, eye and W over their whole ranges, so that every product bit
// and every sign/depth combination (e.g. all signs with depth < 0) occurs;
// most of these put every dot product near zero, where a flipped product bit flips its sign.
#include <algorithm>
#include <vector>

#include "Vrpu_capture.h"
#include "tb_base.h"

struct Item {
  int i, j;
  ref::WVec3 X;
  i128 t;
  ref::CaptureOut want;
  ref::RayGenOut ray;
  ref::CameraDesc cam;
  bool random_edges = false;
};

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_capture> tb("tb_rpu_capture", argc, argv);
  auto& rng = tb.rng;
  const auto [sc, p, m] = sim::quantized_demo_scene("curve12");
  const int CW = p.coord_w, XW = CW + 3, EW = p.edge_w(), TW = p.t_w();
  const long count = tb.vectors(100000);

  std::vector<Item> items;
  const i128 one = i128{1} << p.t_frac;
  const i128 top_coord = (i128{1} << (CW - 1)) - 1;
  std::uniform_int_distribution<int> pi(0, m.camera.width - 1), pj(0, m.camera.height - 1);
  for (long k = 0; k < count; ++k) {
    Item it;
    it.i = pi(rng);
    it.j = pj(rng);
    const int kind = static_cast<int>(k % 4);
    it.cam = m.camera;
    it.ray = ref::ray_generator(p, m.camera, it.i, it.j);
    if (k % 8 == 7) {
      // Random edge vectors, eye, W and X over their whole signed ranges.
      const auto rs = [&](int w) {
        return static_cast<std::int64_t>(static_cast<i128>(rng() & ((std::uint64_t{1} << w) - 1)) -
                                         (i128{1} << (w - 1)));
      };
      const auto rv = [&](int w) { return ref::WVec3{rs(w), rs(w), rs(w)}; };
      it.random_edges = true;
      it.cam.eye = {rs(CW), rs(CW), rs(CW)};
      it.X = rv(XW);
      if (rng() % 4 != 0) {
        // Near-zero dot products, so that every product bit can flip a sign: q = X − h has one
        // component ±1, each vector is q × r (r small: |q × r| < 2^(EW−1)) plus a small
        // multiple of that axis, so q·E is that small multiple (sign-exact, depth 0 included).
        const int axis = static_cast<int>(rng() % 3);
        i128* xc[] = {&it.X.x, &it.X.y, &it.X.z};
        const std::int64_t hc[] = {it.cam.eye.x, it.cam.eye.y, it.cam.eye.z};
        const int sgn = rng() % 2 ? 1 : -1;
        *xc[axis] = hc[axis] + sgn;
        const ref::WVec3 q{it.X.x - it.cam.eye.x, it.X.y - it.cam.eye.y, it.X.z - it.cam.eye.z};
        const auto near0 = [&]() {
          const ref::WVec3 r{static_cast<i128>(rng() % 31) - 15, static_cast<i128>(rng() % 31) - 15,
                             static_cast<i128>(rng() % 31) - 15};
          ref::WVec3 e{q.y * r.z - q.z * r.y, q.z * r.x - q.x * r.z, q.x * r.y - q.y * r.x};
          const int k = static_cast<int>(rng() % 20);
          const i128 t = static_cast<i128>(rng() % ((std::uint64_t{2} << k) + 1)) - (i128{1} << k);
          i128* ec[] = {&e.x, &e.y, &e.z};
          *ec[axis] += t;  // q·e = ±t
          const i128 lim = i128{1} << (EW - 1);
          for (i128* c : ec) *c = std::clamp<i128>(*c, -lim, lim - 1);
          return e;
        };
        it.ray.e_left = near0();
        it.ray.e_right = near0();
        it.ray.e_top = near0();
        it.ray.e_bottom = near0();
        const ref::WVec3 w = near0();
        it.cam.w = {static_cast<std::int64_t>(w.x), static_cast<std::int64_t>(w.y),
                    static_cast<std::int64_t>(w.z)};
      } else {
        it.ray.e_left = rv(EW);
        it.ray.e_right = rv(EW);
        it.ray.e_top = rv(EW);
        it.ray.e_bottom = rv(EW);
        it.cam.w = {rs(EW), rs(EW), rs(EW)};
      }
      const i128 ts[] = {0, one, one + 1, -1, one / 2};
      it.t = ts[rng() % 5];
    } else if (kind <= 1) {
      // The model's own test point on a pixel at or beside the projection of the curve.
      const size_t k_seg = rng() % m.curve_segments.size();
      const auto& s = m.curve_segments[k_seg];
      const Vec3 world =
          scene::curve_point(sc.curve_segments[k_seg].geom, sim::uniform(rng, 0, 1));
      int ci, cj;
      if (scene::project_to_pixel(sc.camera, world, ci, cj)) {
        it.i = std::clamp(ci + static_cast<int>(rng() % 3) - 1, 0, m.camera.width - 1);
        it.j = std::clamp(cj + static_cast<int>(rng() % 3) - 1, 0, m.camera.height - 1);
      }
      const ref::PairResult r = ref::process_curve_pair(p, m.camera, s, it.i, it.j);
      it.X = r.X;
      it.t = r.t;
    } else {
      std::uniform_int_distribution<long long> coord(-static_cast<long long>(top_coord) * 2,
                                                     static_cast<long long>(top_coord) * 2);
      it.X = {coord(rng), coord(rng), coord(rng)};
      const i128 ts[] = {0, one, one + 1, -1, fixed::max_signed(TW), fixed::min_signed(TW), one / 2};
      it.t = kind == 2 ? ts[rng() % 7] : static_cast<i128>(rng() % (2 * one)) - one / 2;
    }
    it.want = ref::capture_unit(p, it.cam, it.ray, it.X, it.t);
    items.push_back(it);
  }

  long hits = 0;
  for (const Item& it : items) hits += it.want.hit;

  sim::Stream<Vrpu_capture, Item> s{.latency = sim::kSameLatency};
  s.inputs = [&](sim::Inputs& in, Vrpu_capture& t, const Item& it) {
    in.vec("X", t.x_i, it.X, XW)("t", t.t_i, it.t, TW).vec("eye", t.eye_i, it.cam.eye, CW);
    in.vec("e_left", t.e_left_i, it.ray.e_left, EW).vec("e_right", t.e_right_i, it.ray.e_right, EW);
    in.vec("e_top", t.e_top_i, it.ray.e_top, EW).vec("e_bottom", t.e_bottom_i, it.ray.e_bottom, EW);
    in.vec("w", t.w_i, it.cam.w, EW);
  };
  s.outputs = [&](sim::Outputs& o, const Vrpu_capture& t, const Item& it) {
    const ref::CaptureOut& w = it.want;
    const unsigned signs = w.signs[0] | (w.signs[1] << 1) | (w.signs[2] << 2) | (w.signs[3] << 3);
    o("hit", t.hit_o, w.hit, 1)("t_in_range", t.t_in_range_o, w.t_in_range, 1)("signs", t.signs_o, signs, 4);
    o.s("depth", t.depth_o, w.depth, p.depth_w());
  };
  s.what = [](const Item& it) {
    return "pixel (" + std::to_string(it.i) + ", " + std::to_string(it.j) + ")" +
           (it.random_edges ? ", random edge vectors" : "");
  };
  return tb.check(items, s, "%ld hits", hits);
}
