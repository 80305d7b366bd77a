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
// Items are offered with random gaps and junk on the inputs between them; an item is taken when
// valid_i and ready_o (the iterative form's admission). A last batch is offered at full load and
// its rate is checked against the form's interval (ref::surface_ip_interval).
// RPU_VECTORS scales the ray counts (default 1); RPU_SEED sets the seed.
#include <algorithm>
#include <deque>
#include <memory>

#include "Vrpu_surface_top.h"
#include "model/surface/rpu_surface_latency.h"
#include "model/surface/rpu_surface_top.h"
#include "tb_surface_common.h"

#ifndef RPU_SOURCE_DIR
#error "RPU_SOURCE_DIR must be defined (see sim/tests/surface/rpu_surface_top.cmake)"
#endif
#ifndef IP_N
#define IP_N 16
#endif
#ifndef IP_N1
#define IP_N1 2
#endif
#ifndef UNROLLED
#define UNROLLED 0
#endif
#ifndef TAG_W
#define TAG_W 16
#endif

namespace {

using namespace rpu;
using sim::i128;
using sim::u128;

ref::HwParams make_params() {
  ref::HwParams p;
  p.n = IP_N;
  p.n1 = IP_N1;
  p.unrolled = UNROLLED != 0;
  p.validate();
  return p;
}
const ref::HwParams kP = make_params();
const int CW = kP.coord_w, DirW = kP.dir_w(), LW = kP.surf_w, MW = kP.surf_mant_w();
const int KF = kP.surf_const_frac(), AW = kP.angle_w, EdgeW = kP.edge_w();
const int DepthW = CW + 4 + EdgeW + 2;
constexpr int kTagW = TAG_W;
constexpr int kTurns = 8;  // rpu_indicator's turn lanes (the top's Turns default)
const char* const kTypeName[] = {"ellipsoid", "relief", "spiral", "snail", "rocket"};

struct Item {
  int surf = 0;
  sim::SurfRay ray;
  int piece = 0;
  const ref::SurfaceDesc* d = nullptr;
  ref::SurfacePieceResult want;
  std::uint32_t tag = 0;
  long issued = 0;
};

struct Batch {
  std::string what;
  ref::CameraDesc cam;  // eye and W for the batch
  std::vector<Item> items;
  bool full_load = false;
};

void drive_item(Vrpu_surface_top& top, const Item& it) {
  const ref::SurfaceDesc& s = *it.d;
  sim::PortBits v;
  v.add3(it.ray.vhat, DirW);
  v.to(top.vhat_i);
  sim::PortBits c0;
  c0.add3(s.bound.c0, CW);
  c0.to(top.bound_c0_i);
  sim::put(top.bound_r2_i, s.bound.R2, 2 * CW + 1);
  sim::PortBits org;
  org.add3(s.origin, CW);
  org.to(top.origin_i);
  sim::PortBits m;
  for (const auto e : s.to_local) m.add(e, MW);
  m.to(top.to_local_i);
  top.to_local_s_i = static_cast<unsigned>(s.to_local_s);
  sim::put(top.y_min_i, s.y_min, LW);
  sim::put(top.y_max_i, s.y_max, LW);
  sim::put(top.end_angle_i, static_cast<i128>(s.end_angle), AW);
  sim::put(top.end_cos_i, s.end_cos, KF + 2);
  sim::put(top.end_sin_i, s.end_sin, KF + 2);
  sim::drive_indicator_fields(top, kP, s);
  top.piece_i = static_cast<unsigned>(it.piece);
  sim::put(top.tag_i, it.tag, kTagW);
}

void drive_junk(Vrpu_surface_top& top, std::mt19937_64& rng) {
  const auto r = [&](int w) { return sim::random_bits(rng, w); };
  sim::PortBits v;
  v.add(r(3 * DirW), 3 * DirW);
  v.to(top.vhat_i);
  sim::PortBits c0;
  c0.add(r(3 * CW), 3 * CW);
  c0.to(top.bound_c0_i);
  sim::put(top.bound_r2_i, r(2 * CW + 1), 2 * CW + 1);
  sim::PortBits org;
  org.add(r(3 * CW), 3 * CW);
  org.to(top.origin_i);
  sim::PortBits m;
  for (int k = 0; k < 9; ++k) m.add(r(MW), MW);
  m.to(top.to_local_i);
  top.to_local_s_i = static_cast<unsigned>(r(7));
  sim::put(top.y_min_i, r(LW), LW);
  sim::put(top.y_max_i, r(LW), LW);
  sim::put(top.end_angle_i, r(AW), AW);
  sim::put(top.end_cos_i, r(KF + 2), KF + 2);
  sim::put(top.end_sin_i, r(KF + 2), KF + 2);
  sim::drive_indicator_junk(top, kP, rng);
  top.type_i = static_cast<unsigned>(r(3));
  top.piece_i = static_cast<unsigned>(r(2));
  sim::put(top.tag_i, r(kTagW), kTagW);
}

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_surface_top");
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_surface_top>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_surface_top");
  std::mt19937_64 rng(seed);
  const long latency = ref::surface_top_latency(kP);
  const int interval = ref::surface_ip_interval(kP);
  const long scale = std::max<long>(1, sim::vector_count(1));
  std::printf("tb_rpu_surface_top: n %d, n1 %d, %s, latency %ld, interval %d\n", kP.n, kP.n1,
              kP.unrolled ? "unrolled" : "iterative", latency, interval);

  std::deque<scene::CompiledScene> scenes;
  const std::vector<sim::SurfCase> cases = sim::load_surface_cases(RPU_SOURCE_DIR, kP, scenes);

  // ---- the batches ----
  std::vector<Batch> batches;
  std::uint32_t tag = 0;
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
        Item it;
        it.surf = r.surf;
        it.ray = r;
        it.piece = piece;
        it.d = &d;
        it.want = ref::process_surface_piece(kP, b.cam, r.vhat, d, piece);
        it.tag = tag++ & static_cast<std::uint32_t>((1ull << kTagW) - 1);
        b.items.push_back(it);
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
  long n_items = 0, n_valid = 0, n_hit = 0, n_ovf = 0, n_type_hit[5] = {}, n_type_miss[5] = {},
       n_src[sim::kRaySources] = {}, n_src_hit[sim::kRaySources] = {}, n_pieces[4] = {};
  for (const Batch& b : batches)
    for (const Item& it : b.items) {
      const int t = static_cast<int>(it.d->type);
      ++n_items;
      n_valid += it.want.valid;
      n_hit += it.want.hit;
      n_ovf += it.want.overflow;
      ++n_src[it.ray.src];
      n_src_hit[it.ray.src] += it.want.hit;
      ++n_pieces[std::clamp(it.want.pieces, 0, 3)];
      if (it.want.valid) ++(it.want.hit ? n_type_hit[t] : n_type_miss[t]);
    }
  std::printf("tb_rpu_surface_top: %zu surfaces, %zu batches, %ld items: %ld pieces valid, %ld hits, "
              "%ld overflow; pairs with 0/1/2/3 pieces %ld/%ld/%ld/%ld\n  hits/items per source:",
              cases.size(), batches.size(), n_items, n_valid, n_hit, n_ovf, n_pieces[0],
              n_pieces[1], n_pieces[2], n_pieces[3]);
  for (int k = 0; k < sim::kRaySources; ++k)
    std::printf(" %s %ld/%ld,", sim::kRaySourceName[k], n_src_hit[k], n_src[k]);
  std::printf("\n  hit/missed valid pieces per type:");
  for (int t = 0; t < 5; ++t) std::printf(" %s %ld/%ld,", kTypeName[t], n_type_hit[t], n_type_miss[t]);
  std::printf("\n");
  for (int t = 0; t < 5; ++t)
    if (n_type_hit[t] < 10 || n_type_miss[t] < 10) {
      std::printf("FAILURE: the vectors are too weak: %s has %ld hits and %ld missed pieces\n",
                  kTypeName[t], n_type_hit[t], n_type_miss[t]);
      return 1;
    }
  if (n_pieces[2] == 0 || n_pieces[3] == 0 || n_valid == n_items || n_ovf < 10) {
    std::printf("FAILURE: the vectors are too weak (no pair of 2 or 3 pieces, no invalid piece or "
                "under 10 overflows)\n");
    return 1;
  }

  // ---- run ----
  sim::reset(*top, *ctx);
  long cycle = 0, matched = 0;
  for (const Batch& b : batches) {
    sim::PortBits eye, w;
    eye.add3(b.cam.eye, CW);
    eye.to(top->eye_i);
    w.add3(b.cam.w, EdgeW);
    w.to(top->w_i);
    std::deque<Item> pending(b.items.begin(), b.items.end()), expected;
    const long start = cycle;
    long first_issue = -1, last_issue = -1;
    size_t done = 0;
    while (done < b.items.size()) {
      const bool offer = !pending.empty() && (b.full_load || rng() % 100 < 80);
      top->valid_i = offer;
      if (offer) drive_item(*top, pending.front());
      else drive_junk(*top, rng);
      const bool taken = offer && top->ready_o;  // ready_o: registers only, settled
      sim::tick(*top, *ctx);
      if (taken) {
        Item it = pending.front();
        pending.pop_front();
        it.issued = cycle;
        if (first_issue < 0) first_issue = cycle;
        last_issue = cycle;
        expected.push_back(it);
      }
      ++cycle;
      if (top->valid_o) {
        if (expected.empty()) {
          std::printf("FAILURE cycle %ld: valid_o with no item outstanding (batch %s)\n", cycle,
                      b.what.c_str());
          return 1;
        }
        const Item it = expected.front();
        expected.pop_front();
        const ref::SurfacePieceResult& e = it.want;
        const bool pv = top->piece_valid_o, hit = top->hit_o, ovf = top->ovf_o;
        const int pieces = static_cast<int>(top->pieces_o);
        const auto tau = static_cast<std::uint64_t>(sim::get_unsigned(top->tau_o, kP.n));
        const ref::WVec3 x{sim::get_comp(top->x_o, 0, CW), sim::get_comp(top->x_o, 1, CW),
                           sim::get_comp(top->x_o, 2, CW)};
        const i128 depth = sim::get_signed(top->depth_o, DepthW);
        const auto got_tag = static_cast<std::uint32_t>(sim::get_unsigned(top->tag_o, kTagW));
        const bool ok = pv == e.valid && hit == e.hit && ovf == e.overflow && pieces == e.pieces &&
                        tau == e.tau && x == e.X && depth == e.depth && got_tag == it.tag &&
                        cycle - it.issued == latency;
        if (!ok) {
          const sim::SurfCase& S = cases[static_cast<size_t>(it.surf)];
          std::printf(
              "FAILURE cycle %ld item %ld (batch %s): %s (%s), %s ray, pixel (%d, %d), piece %d\n"
              "  inputs   eye %s vhat %s W %s tag %u\n"
              "  expected valid %d hit %d ovf %d pieces %d tau %llu X %s depth %s latency %ld\n"
              "  actual   valid %d hit %d ovf %d pieces %d tau %llu X %s depth %s latency %ld "
              "tag %u\n",
              cycle, matched, b.what.c_str(), S.name.c_str(),
              kTypeName[static_cast<int>(S.d.type)], sim::kRaySourceName[it.ray.src], it.ray.i,
              it.ray.j, it.piece, sim::str(b.cam.eye).c_str(), sim::str(it.ray.vhat).c_str(),
              sim::str(b.cam.w).c_str(), it.tag, e.valid, e.hit, e.overflow, e.pieces,
              static_cast<unsigned long long>(e.tau), sim::str(e.X).c_str(),
              sim::to_string(e.depth).c_str(), latency, pv, hit, ovf, pieces,
              static_cast<unsigned long long>(tau), sim::str(x).c_str(),
              sim::to_string(depth).c_str(), cycle - it.issued, got_tag);
          fixed::Overflow o;
          const ref::SurfaceSetupOut su =
              ref::surface_setup(kP, b.cam.eye, it.ray.vhat, *it.d, it.piece, o);
          std::printf("  (twin setup: A' %s B'-A' %s lA' %s lB'-lA' %s s %s..%s x_negative %d "
                      "last_turn %d)\n",
                      sim::str(su.A).c_str(), sim::str(su.AB).c_str(), sim::str(su.lA).c_str(),
                      sim::str(su.lAB).c_str(), sim::to_string(su.s_lo).c_str(),
                      sim::to_string(su.s_hi).c_str(), su.x_negative, su.last_turn);
          return 1;
        }
        ++matched;
        ++done;
      }
      if (cycle - start > static_cast<long>(b.items.size()) * 4 * (interval + 1) + 4 * latency) {
        std::printf("FAILURE: timeout in batch %s after %ld cycles, %zu of %zu matched\n",
                    b.what.c_str(), cycle - start, done, b.items.size());
        return 1;
      }
    }
    if (b.full_load) {
      // Accepted items per cycle while offered every cycle; the iterative form takes bursts of
      // up to one ring period, so the rate over n items is n / (n + ring gaps) ≥ 1 / interval
      // within one ring period's slack.
      const long n = static_cast<long>(b.items.size());
      const long span = last_issue - first_issue + 1;
      const long bound = ((n + ref::surface_ip_pass_latency(kP) - 1) / ref::surface_ip_pass_latency(kP)) *
                             ref::surface_ip_pass_latency(kP) * interval;
      std::printf("tb_rpu_surface_top: full load: %ld items accepted in %ld cycles (%.3f cycles "
                  "per item; interval %d)\n",
                  n, span, static_cast<double>(span) / static_cast<double>(n), interval);
      if (span > bound) {
        std::printf("FAILURE: full load took %ld cycles for %ld items (at most %ld expected)\n",
                    span, n, bound);
        return 1;
      }
    }
  }
  top->valid_i = 0;
  for (long k = 0; k < latency + 8; ++k) {
    sim::tick(*top, *ctx);
    if (top->valid_o) {
      std::printf("FAILURE: valid_o after the last item\n");
      return 1;
    }
  }
  std::printf("tb_rpu_surface_top: matched %ld items (%ld cycles)\n", matched, cycle);
  return 0;
}
