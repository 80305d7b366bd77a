// rpu_surface_top (setup → sign search → X and depth) against its twin
// rpu::ref::process_surface_piece, bit for bit: piece valid, hit, overflow, pieces, τ_K, X, depth,
// the tag and the latency (ref::surface_top_latency) of every work item, in order.
// Work items: every surface of scenes/surf_*.json quantised at this build's parameters, each ray
// with every piece index the host issues for its type (and now and then one beyond, never
// valid). Rays, in batches that share an eye (the camera ports are constants while items are in
// flight; a batch drains before the next one changes them):
//   - the scene's camera: pixels at or beside the projection of random points of the surface,
//     any pixels, image-border pixels, rays grazing the bounding sphere, rays aimed at points of
//     the range planes (x = 0 and the end plane; the slab's y_min, y_max) or a few llsb beside;
//   - the same with the indicator fields redrawn within rpu_indicator's port contract (lanes
//     that overflow) and, for a third of them, a saturating local frame (to_local_s lowered);
//   - an eye inside the bounding sphere (pieces that begin inside the surface), random
//     directions; W stays the camera's.
// An item is taken when valid_i and ready_o (the iterative form's admission). A last batch is
// offered at full load and its rate is checked against the form's interval
// (ref::surface_ip_interval). RPU_VECTORS scales the ray counts (default 1).
#include <algorithm>
#include <deque>
#include <vector>

#include "Vrpu_surface_top.h"
#include "model/surface/rpu_surface_latency.h"
#include "model/surface/rpu_surface_top.h"
#include "model/surface/rpu_surface_setup.h"
#include "tb_surface_common.h"

namespace {

const ref::HwParams kP = sim::tb_params();
const int CW = kP.coord_w, DirW = kP.dir_w(), LW = kP.surf_w, MW = kP.surf_mant_w();
const int KF = kP.surf_const_frac(), AW = kP.angle_w, EdgeW = kP.edge_w();
const int DepthW = kP.depth_w();
constexpr int kTurns = 8;  // rpu_indicator's turn lanes (the top's Turns default)
const char* const* const kTypeName = sim::kSurfaceTypeName;

struct Item {
  int surf = 0;
  sim::SurfRay ray;
  int piece = 0;
  const ref::SurfaceDesc* d = nullptr;
  ref::SurfacePieceResult want;
};

struct Batch {
  std::string what;
  ref::CameraDesc cam;  // eye and W for the batch
  std::vector<Item> items;
  bool full_load = false;
};

}  // namespace

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_surface_top> tb("tb_rpu_surface_top", argc, argv);
  auto& rng = tb.rng;
  const long latency = ref::surface_top_latency(kP, SURF_IND);
  const int interval = ref::surface_ip_interval(kP, SURF_IND);
  const long scale = std::max<long>(1, tb.vectors(1));
  std::printf("tb_rpu_surface_top: n %d, n1 %d, first step %d bits, %d indicators, %s, latency %ld, "
              "interval %d\n", kP.n, kP.n1, kP.surface_first_bits(), ref::surface_ip_lanes(kP, SURF_IND),
              kP.unrolled ? "unrolled" : "iterative", latency, interval);

  std::deque<scene::CompiledScene> scenes;
  const std::vector<sim::SurfCase> cases = sim::load_surface_cases(kP, scenes);

  // ---- the batches ----
  std::vector<Batch> batches;
  std::deque<ref::SurfaceDesc> edited;  // stable addresses
  const auto make_items = [&](Batch& b, const std::vector<sim::SurfRay>& rays, bool edit) {
    for (const sim::SurfRay& r : rays) {
      const ref::SurfaceDesc* dp = &cases[static_cast<size_t>(r.surf)].d;
      if (edit) {  // the indicator fields redrawn; a third with a saturating local frame
        edited.push_back(sim::edit_indicator_fields(*dp, kP, kTurns, rng));
        if (rng() % 3 == 0) edited.back().to_local_s -= 1 + static_cast<int>(rng() % 3);
        dp = &edited.back();
      }
      const ref::SurfaceDesc& d = *dp;
      for (int piece : sim::piece_indices(d, rng)) {
        b.items.push_back(
            {r.surf, r, piece, &d, ref::process_surface_piece(kP, b.cam, r.vhat, d, piece)});
      }
    }
  };
  for (int s = 0; s < static_cast<int>(cases.size()); ++s) {
    const sim::SurfCase& S = cases[static_cast<size_t>(s)];
    {  // the camera's rays, then more with edited descriptors (the same eye: one batch)
      Batch b{S.name + " camera", S.cam, {}, false};
      std::vector<sim::SurfRay> rays, edit_rays;
      sim::camera_rays(kP, S, s, static_cast<int>(110 * scale), rng, rays);
      sim::camera_rays(kP, S, s, static_cast<int>(30 * scale), rng, edit_rays);
      make_items(b, rays, false);
      make_items(b, edit_rays, true);
      batches.push_back(std::move(b));
    }
    {
      Batch b{S.name + " eye inside", S.cam, {}, false};
      b.cam.eye = sim::inside_eye(S, rng);
      std::vector<sim::SurfRay> rays;
      sim::inside_rays(kP, b.cam.eye, s, static_cast<int>(30 * scale), rng, rays);
      make_items(b, rays, false);
      batches.push_back(std::move(b));
    }

  }
  {  // full load: the first surface's camera rays, offered every cycle
    Batch b{cases[0].name + " full load", cases[0].cam, {}, true};
    std::vector<sim::SurfRay> rays;
    sim::camera_rays(kP, cases[0], 0, static_cast<int>(4 * ref::surface_ip_pass_latency(kP)), rng,
                     rays);
    make_items(b, rays, false);
    batches.push_back(std::move(b));
  }

  // ---- what the items exercise ----
  sim::Tally by_src(sim::kRaySourceName, {"items", "valid pieces", "hits", "with overflow"});
  sim::Tally by_type(sim::kSurfaceTypeName, {"hits", "missed pieces"});  // of the valid pieces
  long n_pieces[4] = {};
  for (const Batch& b : batches)
    for (const Item& it : b.items) {
      const ref::SurfacePieceResult& w = it.want;
      by_src.add(it.ray.src, 1, w.valid, w.hit, w.overflow);
      by_type.add(static_cast<int>(it.d->type), w.valid && w.hit, w.valid && !w.hit);
      ++n_pieces[std::clamp(w.pieces, 0, 3)];
    }
  const long n_items = by_src.total(0), n_valid = by_src.total(1), n_ovf = by_src.total(3);
  std::printf("tb_rpu_surface_top: %zu surfaces, %zu batches, %ld items: %ld pieces valid, %ld "
              "hits, %ld overflow; pairs with 0/1/2/3 pieces %ld/%ld/%ld/%ld\n",
              cases.size(), batches.size(), n_items, n_valid, by_src.total(2), n_ovf, n_pieces[0],
              n_pieces[1], n_pieces[2], n_pieces[3]);
  by_src.print("per ray source");
  by_type.print("valid pieces per surface type");
  if (tb.weak(by_type.too_weak({0, 1}, 10))) return 1;
  if (n_pieces[2] == 0 || n_pieces[3] == 0 || n_valid == n_items || n_ovf < 10)
    return tb.fail("the vectors are too weak (no pair of 2 or 3 pieces, no invalid piece or under "
                   "10 overflows)");

  // ---- run: one batch after the other, each drained before the next changes eye and W ----
  sim::Stream<Vrpu_surface_top, Item> s{.latency = latency};
  s.inputs = [](sim::Inputs& in, Vrpu_surface_top& t, const Item& it) {
    const ref::SurfaceDesc& d = *it.d;
    in.vec("vhat", t.vhat_i, it.ray.vhat, DirW).vec("bound_c0", t.bound_c0_i, d.bound.c0, CW);
    in("bound_r2", t.bound_r2_i, d.bound.R2, kP.r2_w()).vec("origin", t.origin_i, d.origin, CW);
    in.fields("to_local", t.to_local_i, d.to_local, MW)("to_local_s", t.to_local_s_i, d.to_local_s, 7);
    in("y_min", t.y_min_i, d.y_min, LW)("y_max", t.y_max_i, d.y_max, LW);
    in("end_angle", t.end_angle_i, static_cast<i128>(d.end_angle), AW)("end_cos", t.end_cos_i, d.end_cos, KF + 2);
    in("end_sin", t.end_sin_i, d.end_sin, KF + 2)("piece", t.piece_i, it.piece, 2);
    sim::indicator_inputs(in, t, kP, d);
  };
  const Batch* batch = nullptr;
  s.outputs = [&](sim::Outputs& o, const Vrpu_surface_top& t, const Item& it) {
    const ref::SurfacePieceResult& e = it.want;
    o("valid", t.piece_valid_o, e.valid, 1)("hit", t.hit_o, e.hit, 1)("ovf", t.ovf_o, e.overflow, 1);
    o("pieces", t.pieces_o, e.pieces, 2)("tau", t.tau_o, static_cast<i128>(e.tau), kP.n);
    o.vec("X", t.x_o, e.X, CW).s("depth", t.depth_o, e.depth, DepthW);
    fixed::Overflow ovf;
    const ref::SurfaceSetupOut su = ref::surface_setup(kP, batch->cam.eye, it.ray.vhat, *it.d, it.piece, ovf);
    o.note("setup: A'", sim::str(su.A)).note("B'-A'", sim::str(su.AB)).note("lA'", sim::str(su.lA));
    o.note("lB'-lA'", sim::str(su.lAB)).note("s", sim::str(su.s_lo) + ".." + sim::str(su.s_hi));
    o.note("x_negative", std::to_string(su.x_negative)).note("last_turn", std::to_string(su.last_turn));
  };
  s.what = [&](const Item& it) {
    const sim::SurfCase& S = cases[static_cast<size_t>(it.surf)];
    return "batch " + batch->what + ": " + S.name + " (" + kTypeName[static_cast<int>(S.d.type)] +
           "), " + sim::kRaySourceName[it.ray.src] + " ray, pixel (" + std::to_string(it.ray.i) +
           ", " + std::to_string(it.ray.j) + "), piece " + std::to_string(it.piece) + ", eye " +
           sim::str(batch->cam.eye) + " W " + sim::str(batch->cam.w);
  };
  tb.reset();
  for (const Batch& b : batches) {
    batch = &b;
    sim::put_vec3(tb.top().eye_i, b.cam.eye, CW);
    sim::put_vec3(tb.top().w_i, b.cam.w, EdgeW);
    s.traffic.valid_pct = b.full_load ? 100 : 80;
    s.timeout = static_cast<long>(b.items.size()) * 4 * (interval + 1) + 4 * latency;
    const sim::RunResult r = tb.run(b.items, s);
    if (!r) return 1;
    if (b.full_load) {
      // Offered every cycle from an empty ring, the iterative form takes exactly the items an
      // ideal admission takes: a slot is free when its phase has no returns due (each accepted
      // item returns `interval - 1` more times, one ring period apart). The span from the first
      // item taken to the last must be that schedule's, to the cycle (a slot freed late or
      // early changes it); the unrolled form takes one item per cycle.
      const long n = static_cast<long>(b.items.size()), ring = ref::surface_ip_pass_latency(kP);
      const long span = r.last_taken - r.first_taken + 1;
      long want = n;
      if (!kP.unrolled) {
        std::vector<int> due(static_cast<size_t>(ring), 0);
        long taken = 0, t = 0, first = -1, last = -1;
        for (; taken < n; ++t) {
          int& d = due[static_cast<size_t>(t % ring)];
          if (d > 0) { --d; continue; }
          d = interval - 1;
          if (first < 0) first = t;
          last = t;
          ++taken;
        }
        want = last - first + 1;
      }
      std::printf("tb_rpu_surface_top: full load: %ld items accepted in %ld cycles (%.3f cycles "
                  "per item; interval %d; the ideal admission: %ld cycles)\n",
                  n, span, static_cast<double>(span) / static_cast<double>(n), interval, want);
      if (span != want)
        return tb.fail("full load took %ld cycles for %ld items, the ideal admission %ld", span, n,
                       want);
    }
  }
  return tb.pass();
}
