// rpu_resolve against rpu::ref::Resolve: random pixels with 0..12 work items each (random hits,
// depths and primitive ids drawn from small pools so that exact depth ties, and ties of both
// depth and id, are common; edge depths; misses carrying nearer depths and smaller ids than the
// winner), driven with random valid_i gaps and random ready_i backpressure in phases (from a
// free-flowing consumer to long stalls). The scoreboard pops one expected result per output
// handshake: nothing lost, duplicated or reordered, every field equal to the twin's. Protocol
// checks: a held output (valid_o && !ready_i) stays valid and unchanged; ready_o only drops after
// a cycle in which the output was held (full throughput otherwise) and never follows the inputs
// combinationally; no output after the last. In "rude" phases the driver puts garbage on the
// input with valid_i high whenever ready_o is low: it must not be taken.
#include <deque>
#include <memory>
#include <vector>

#include "Vrpu_resolve.h"
#include "model/units.h"
#include "tb_common.h"

#ifndef PIX_W
#define PIX_W 28
#endif
#ifndef DEPTH_W
#define DEPTH_W 64
#endif
#ifndef PRIM_W
#define PRIM_W 16
#endif

namespace {

using namespace rpu;
using sim::i128;
using sim::u128;

constexpr int kPixW = PIX_W, kDepthW = DEPTH_W, kPrimW = PRIM_W;
static_assert(kPrimW <= 31, "the twin's primitive id is an int32");

struct WorkItem {
  bool hit;
  i128 depth;
  std::int32_t prim;
};

struct Pixel {
  u128 pixel;
  std::vector<WorkItem> items;
  bool any;
  i128 depth;
  std::int32_t prim;
};

i128 sign_extend(u128 bits, int w) {
  const u128 m = w >= 128 ? ~u128{0} : (u128{1} << w) - 1;
  const u128 sign = u128{1} << (w - 1);
  return static_cast<i128>(((bits & m) ^ sign) - sign);
}

u128 mask(int w) { return w >= 128 ? ~u128{0} : (u128{1} << w) - 1; }

// Writes a `w`-bit field, upper bits of the port cleared.
template <class T>
void put_field(T& port, i128 v, int w) {
  sim::put(port, static_cast<i128>(static_cast<u128>(v) & mask(w)), w);
}

std::string hex(u128 v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%llx%016llx", static_cast<unsigned long long>(v >> 64),
                static_cast<unsigned long long>(v));
  std::string s(buf);
  const auto nz = s.find_first_not_of('0');
  return "0x" + (nz == std::string::npos ? std::string("0") : s.substr(nz));
}

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_resolve");
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_resolve>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_resolve");
  std::mt19937_64 rng(seed);
  const long count = sim::vector_count(100000);
  const auto pct = [&](int p) { return static_cast<int>(rng() % 100) < p; };
  const auto rand128 = [&] { return (static_cast<u128>(rng()) << 64) | rng(); };

  // ---- stimulus and the twin's answers ----
  const i128 dmin = sign_extend(u128{1} << (kDepthW - 1), kDepthW);
  const i128 dmax = sign_extend(mask(kDepthW) >> 1, kDepthW);
  const std::int32_t pmax = static_cast<std::int32_t>((std::int64_t{1} << kPrimW) - 1);
  const auto any_depth = [&]() -> i128 {
    if (pct(15)) {
      const i128 edges[] = {dmin, dmin + 1, dmax, dmax - 1, 0, 1, -1};
      return edges[rng() % 7];
    }
    const int w = 2 + static_cast<int>(rng() % (kDepthW - 1));  // spread over magnitudes
    return sign_extend(rand128(), w);
  };
  const auto any_prim = [&]() -> std::int32_t {
    if (pct(20)) return pct(50) ? 0 : pmax;
    return static_cast<std::int32_t>(rng() & static_cast<std::uint64_t>(pmax));
  };

  std::vector<Pixel> pixels;  // only pixels with work items produce a result
  long n_items = 0, n_hits = 0, n_depth_ties = 0, n_full_ties = 0, n_empty = 0, n_nohit = 0;
  u128 pix = rand128() & mask(kPixW);
  for (long k = 0; k < count; ++k) {
    pix = (pix + 1 + (pct(10) ? rng() % 1000 : 0)) & mask(kPixW);
    const int n = static_cast<int>(rng() % 13);
    if (n == 0) {
      ++n_empty;
      continue;
    }
    // Per-pixel pools: a few depths and ids, so that ties are frequent.
    std::vector<i128> dpool(1 + rng() % 3);
    for (auto& d : dpool) d = any_depth();
    std::vector<std::int32_t> ppool(1 + rng() % 4);
    for (auto& q : ppool) q = any_prim();
    const int hit_pct = std::vector<int>{0, 10, 50, 90, 100}[rng() % 5];
    const bool pooled_depth = pct(75), pooled_prim = pct(60);

    Pixel px{pix, {}, false, 0, 0};
    ref::Resolve r;
    for (int m = 0; m < n; ++m) {
      WorkItem it;
      it.hit = pct(hit_pct);
      it.depth = pooled_depth ? dpool[rng() % dpool.size()] : any_depth();
      it.prim = pooled_prim ? ppool[rng() % ppool.size()] : any_prim();
      if (it.hit) {
        if (r.any && it.depth == r.depth) {
          ++n_depth_ties;
          if (it.prim == r.primitive) ++n_full_ties;
        }
        r.offer(it.depth, it.prim);
        ++n_hits;
      }
      px.items.push_back(it);
    }
    n_items += n;
    px.any = r.any;
    px.depth = r.any ? r.depth : 0;
    px.prim = r.any ? r.primitive : 0;
    if (!r.any) ++n_nohit;
    pixels.push_back(std::move(px));
  }

  // ---- simulation ----
  top->valid_i = 0;
  top->ready_i = 0;
  top->last_i = 0;
  top->hit_i = 0;
  sim::reset(*top, *ctx);

  const auto report_pixel = [&](const Pixel& px) {
    std::printf("  inputs: pixel %s, %zu work items {hit, depth, primitive}:\n",
                hex(px.pixel).c_str(), px.items.size());
    for (const WorkItem& it : px.items)
      std::printf("    {%d, %s, %d}\n", it.hit, sim::to_string(it.depth).c_str(), it.prim);
    std::printf("  expected: pixel %s any_hit %d depth %s primitive %d\n", hex(px.pixel).c_str(),
                px.any, sim::to_string(px.depth).c_str(), px.prim);
  };

  size_t in_pix = 0, in_item = 0;  // next work item to present
  size_t out_pix = 0;              // next expected result
  bool presenting = false;
  int valid_pct = 100, ready_pct = 100;
  bool rude = false;
  long phase_left = 0, cycle = 0, stall_cycles = 0;
  bool held = false;  // last cycle ended with valid_o && !ready_i
  u128 held_pixel = 0;
  i128 held_depth = 0;
  unsigned held_any = 0, held_prim = 0;
  bool prev_ready_i = true;
  const long limit = 40 * n_items + 10000;

  while (out_pix < pixels.size()) {
    if (phase_left-- <= 0) {  // a new traffic phase
      phase_left = 1 + static_cast<long>(rng() % 3000);
      valid_pct = std::vector<int>{100, 100, 95, 70, 30, 5}[rng() % 6];
      ready_pct = std::vector<int>{100, 100, 95, 70, 50, 20, 3, 0}[rng() % 8];
      rude = pct(30);
      if (ready_pct == 0) phase_left = 1 + phase_left % 40;  // a full stall, short
    }
    // Input: a presented item stays on valid_i, unchanged, until it is taken. In "rude" phases
    // the driver breaks that rule while ready_o is low (ready_o is a register, so it is known
    // before the inputs are driven): valid_i high with garbage, which must not be taken.
    if (!presenting && in_pix < pixels.size() && pct(valid_pct)) presenting = true;
    const bool ready_before = top->ready_o;
    const bool garbage = rude && !ready_before && pct(70);
    top->valid_i = presenting || garbage;
    if (presenting && !garbage) {
      const Pixel& px = pixels[in_pix];
      const WorkItem& it = px.items[in_item];
      put_field(top->pixel_i, static_cast<i128>(px.pixel), kPixW);
      top->last_i = in_item + 1 == px.items.size();
      top->hit_i = it.hit;
      put_field(top->depth_i, it.depth, kDepthW);
      put_field(top->primitive_i, it.prim, kPrimW);
    } else {  // garbage on the data lines while idle or not ready
      put_field(top->pixel_i, static_cast<i128>(rand128()), kPixW);
      top->last_i = rng() & 1;
      top->hit_i = rng() & 1;
      put_field(top->depth_i, any_depth(), kDepthW);
      put_field(top->primitive_i, static_cast<i128>(rng()), kPrimW);
    }
    const bool ready_i = pct(ready_pct);
    top->ready_i = ready_i;
    top->clk_i = 0;
    top->eval();

    const bool valid_o = top->valid_o, ready_o = top->ready_o;
    const u128 o_pixel = sim::get_unsigned(top->pixel_o, kPixW);
    const unsigned o_any = top->any_hit_o;
    const i128 o_depth = sim::get_signed(top->depth_o, kDepthW);
    const unsigned o_prim = static_cast<unsigned>(sim::get_unsigned(top->primitive_o, kPrimW));

    // Protocol: a held output stays valid and unchanged; ready_o drops only after a hold.
    if (held && (!valid_o || o_pixel != held_pixel || o_any != held_any || o_depth != held_depth ||
                 o_prim != held_prim)) {
      std::printf("FAILURE cycle %ld: output changed while held (valid_o && !ready_i)\n"
                  "  held:  pixel %s any_hit %u depth %s primitive %u\n"
                  "  now:   valid %d pixel %s any_hit %u depth %s primitive %u\n",
                  cycle, hex(held_pixel).c_str(), held_any, sim::to_string(held_depth).c_str(),
                  held_prim, valid_o, hex(o_pixel).c_str(), o_any, sim::to_string(o_depth).c_str(),
                  o_prim);
      return 1;
    }
    if (ready_o != ready_before) {
      std::printf("FAILURE cycle %ld: ready_o depends combinationally on the inputs\n", cycle);
      return 1;
    }
    if (!ready_o && prev_ready_i) {
      std::printf("FAILURE cycle %ld: ready_o low although ready_i was high last cycle\n", cycle);
      return 1;
    }

    if (valid_o && ready_i) {  // output handshake: the scoreboard
      if (out_pix >= pixels.size()) {
        std::printf("FAILURE cycle %ld: extra result pixel %s after all %zu expected\n", cycle,
                    hex(o_pixel).c_str(), pixels.size());
        return 1;
      }
      const Pixel& px = pixels[out_pix];
      if (o_pixel != px.pixel || o_any != static_cast<unsigned>(px.any) || o_depth != px.depth ||
          o_prim != static_cast<unsigned>(px.prim)) {
        std::printf("FAILURE cycle %ld result %zu (lost, duplicated, reordered or wrong):\n", cycle,
                    out_pix);
        report_pixel(px);
        std::printf("  actual:   pixel %s any_hit %u depth %s primitive %u\n",
                    hex(o_pixel).c_str(), o_any, sim::to_string(o_depth).c_str(), o_prim);
        return 1;
      }
      ++out_pix;
    }
    held = valid_o && !ready_i;
    held_pixel = o_pixel;
    held_any = o_any;
    held_depth = o_depth;
    held_prim = o_prim;
    prev_ready_i = ready_i;
    if (!ready_o) ++stall_cycles;
    if (presenting && !garbage && ready_o) {  // input handshake
      presenting = false;
      if (++in_item == pixels[in_pix].items.size()) {
        in_item = 0;
        ++in_pix;
      }
    }

    sim::tick(*top, *ctx);
    ++cycle;
    if (cycle > limit) {
      std::printf("FAILURE: timeout at cycle %ld, %zu of %zu results, %zu of %zu pixels issued\n",
                  cycle, out_pix, pixels.size(), in_pix, pixels.size());
      return 1;
    }
  }
  // Drained: nothing more may come out.
  top->valid_i = 0;
  top->ready_i = 1;
  for (int k = 0; k < 64; ++k) {
    top->clk_i = 0;
    top->eval();
    if (top->valid_o) {
      std::printf("FAILURE cycle %ld: extra result pixel %s after all %zu expected\n", cycle,
                  hex(sim::get_unsigned(top->pixel_o, kPixW)).c_str(), pixels.size());
      return 1;
    }
    sim::tick(*top, *ctx);
    ++cycle;
  }
  top->final();
  std::printf("rpu_resolve (PixW %d, DepthW %d, PrimW %d): matched %zu items (pixel results; %ld "
              "pixels drawn, %ld without work items; %ld work items, %ld hits, %ld depth ties, %ld "
              "depth+id ties, %ld pixels without a hit) in %ld cycles, ready_o low %ld cycles\n",
              kPixW, kDepthW, kPrimW, out_pix, count, n_empty, n_items, n_hits, n_depth_ties,
              n_full_ties, n_nohit, cycle, stall_cycles);
  return 0;
}
