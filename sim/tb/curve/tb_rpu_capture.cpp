// rpu_capture against rpu::ref::capture_unit: the curve points the model's IP selects on
// curve12 (hits and near misses), random points over the whole range, t edge values, and (every
// eighth item) random edge vectors, eye and W over their whole ranges, so that every product bit
// and every sign/depth combination (e.g. all signs with depth < 0) occurs;
// most of these put every dot product near zero, where a flipped product bit flips its sign.
#include <algorithm>
#include <deque>
#include <memory>

#include "Vrpu_capture.h"
#include "model/units.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "tb_common.h"

namespace {

using namespace rpu;
using sim::i128;

struct Item {
  int i, j;
  ref::WVec3 X;
  i128 t;
  ref::CaptureOut want;
  ref::RayGenOut ray;
  ref::CameraDesc cam;
  bool random_edges = false;
  unsigned tag = 0;
};

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_capture");
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_capture>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_capture");
  std::mt19937_64 rng(seed);

  const scene::CompiledScene sc = scene::compile_scene(
      scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/curve12.json"));
  const ref::HwParams p;
  const ref::ModelScene m = ref::quantize_scene(sc, p);
  const int CW = p.coord_w, XW = CW + 3, EW = p.edge_w(), TW = p.t_w();
  const long count = sim::vector_count(100000);

  std::deque<Item> items;
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
      const Vec3 world = scene::curve_point(sc.curve_segments[k_seg].geom,
                                            std::uniform_real_distribution<double>(0, 1)(rng));
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

  sim::reset(*top, *ctx);
  const auto put3 = [&](auto& port, const ref::WVec3& v, int w) {
    sim::put_vec3(port, v.x, v.y, v.z, w);
  };
  std::deque<Item> pending;
  long matched = 0, cycle = 0, hits = 0;
  const long total = static_cast<long>(items.size());
  while (matched < total) {
    const bool issue = !items.empty() && (rng() % 100) < 85;
    top->valid_i = issue;
    if (issue) {
      const Item& it = items.front();
      const ref::RayGenOut& ray = it.ray;
      put3(top->x_i, it.X, XW);
      sim::put(top->t_i, it.t, TW);
      put3(top->eye_i, ref::widen(it.cam.eye), CW);
      put3(top->e_left_i, ray.e_left, EW);
      put3(top->e_right_i, ray.e_right, EW);
      put3(top->e_top_i, ray.e_top, EW);
      put3(top->e_bottom_i, ray.e_bottom, EW);
      put3(top->w_i, ref::widen(it.cam.w), EW);
      top->tag_i = static_cast<unsigned>(pending.size() & 1);
      pending.push_back(it);
      pending.back().tag = top->tag_i;
      items.pop_front();
    }
    sim::tick(*top, *ctx);
    ++cycle;
    if (top->valid_o) {
      const Item it = pending.front();
      pending.pop_front();
      const ref::CaptureOut& w = it.want;
      const unsigned signs = w.signs[0] | (w.signs[1] << 1) | (w.signs[2] << 2) | (w.signs[3] << 3);
      const i128 depth = sim::get_signed(top->depth_o, CW + 4 + EW + 2);
      if (top->hit_o != w.hit || top->t_in_range_o != w.t_in_range || top->signs_o != signs ||
          depth != w.depth || top->tag_o != it.tag) {
        if (it.random_edges) {
          const auto pv = [](const char* n, const ref::WVec3& v) {
            std::printf("  %s = (%s, %s, %s)\n", n, sim::to_string(v.x).c_str(),
                        sim::to_string(v.y).c_str(), sim::to_string(v.z).c_str());
          };
          std::printf("random-edge item:\n");
          pv("e_left", it.ray.e_left);
          pv("e_right", it.ray.e_right);
          pv("e_top", it.ray.e_top);
          pv("e_bottom", it.ray.e_bottom);
          pv("eye", ref::widen(it.cam.eye));
          pv("w", ref::widen(it.cam.w));
        }
        std::printf("FAILURE cycle %ld item %ld: pixel (%d,%d) X = (%s, %s, %s) t = %s\n"
                    "  expected hit %d t_ok %d signs %x depth %s tag %u\n"
                    "  actual   hit %d t_ok %d signs %x depth %s tag %u\n",
                    cycle, matched, it.i, it.j, sim::to_string(it.X.x).c_str(),
                    sim::to_string(it.X.y).c_str(), sim::to_string(it.X.z).c_str(),
                    sim::to_string(it.t).c_str(), w.hit, w.t_in_range, signs,
                    sim::to_string(w.depth).c_str(), it.tag, top->hit_o, top->t_in_range_o,
                    top->signs_o, sim::to_string(depth).c_str(), static_cast<unsigned>(top->tag_o));
        return 1;
      }
      hits += w.hit;
      ++matched;
    }
    if (cycle > 4 * total + 1000) {
      std::printf("FAILURE: timeout, %ld of %ld matched\n", matched, total);
      return 1;
    }
  }
  top->final();
  std::printf("rpu_capture: matched %ld items (%ld hits) in %ld cycles\n", matched, hits, cycle);
  return 0;
}
