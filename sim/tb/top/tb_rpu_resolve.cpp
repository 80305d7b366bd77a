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
#include <vector>

#include "Vrpu_resolve.h"
#include "model/units.h"
#include "tb_base.h"

#ifndef PIX_W
#define PIX_W 28
#endif
#ifndef DEPTH_W
#define DEPTH_W 64
#endif
#ifndef PRIM_W
#define PRIM_W 16
#endif

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

struct Item {  // one work item as the unit takes it
  size_t pix;  // its pixel (pixels[pix]: the expected result follows its last item)
  WorkItem w;
  bool last;
};

u128 mask(int w) { return sim::low_bits(~u128{0}, w); }
i128 sign_extend(u128 bits, int w) { return sim::sign_extend(bits, w); }

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_resolve> tb("tb_rpu_resolve", argc, argv);
  auto& rng = tb.rng;
  const long count = tb.vectors(100000);
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

  std::vector<Item> items;
  for (size_t k = 0; k < pixels.size(); ++k)
    for (size_t m = 0; m < pixels[k].items.size(); ++m)
      items.push_back({k, pixels[k].items[m], m + 1 == pixels[k].items.size()});

  // Random valid_i gaps and ready_i backpressure in phases (from a free-flowing consumer to long
  // stalls); in "rude" phases garbage with valid_i high whenever ready_o is low (not to be taken).
  sim::Stream<Vrpu_resolve, Item> s;
  s.inputs = [&](sim::Inputs& in, Vrpu_resolve& t, const Item& it) {
    in("pixel", t.pixel_i, static_cast<i128>(pixels[it.pix].pixel), kPixW);
    in("last", t.last_i, it.last, 1)("hit", t.hit_i, it.w.hit, 1);
    in("depth", t.depth_i, it.w.depth, kDepthW)("primitive", t.primitive_i, it.w.prim, kPrimW);
  };
  s.outputs = [&](sim::Outputs& o, const Vrpu_resolve& t, const Item& it) {
    const Pixel& px = pixels[it.pix];
    o("pixel", t.pixel_o, static_cast<i128>(px.pixel), kPixW)("any_hit", t.any_hit_o, px.any, 1);
    o.s("depth", t.depth_o, px.depth, kDepthW)("primitive", t.primitive_o, px.prim, kPrimW);
  };
  s.yields = [](const Item& it) { return it.last; };
  s.what = [&](const Item& it) {
    std::string w = "pixel result " + std::to_string(it.pix) + " of " +
                    std::to_string(pixels[it.pix].items.size()) + " work items {hit, depth, primitive}:";
    for (const WorkItem& x : pixels[it.pix].items)
      w += " {" + std::to_string(x.hit) + ", " + sim::str(x.depth) + ", " + std::to_string(x.prim) + "}";
    return w;
  };
  s.traffic.phase_max = 3000;
  s.traffic.valid_table = {100, 100, 95, 70, 30, 5};
  s.traffic.ready_table = {100, 100, 95, 70, 50, 20, 3, 0};
  s.traffic.rude_pct = 30;
  s.timeout = 40 * static_cast<long>(items.size()) + 10000;
  long stall_cycles = 0;  // ready_o only drops after a cycle with the output held
  s.monitor = [&](const Vrpu_resolve& t, const sim::Cycle& c) -> std::string {
    stall_cycles += !t.ready_o;
    return !t.ready_o && c.prev_ready_i ? "ready_o low although ready_i was high last cycle" : "";
  };
  tb.top().valid_i = 0;
  tb.top().ready_i = 0;
  tb.top().last_i = 0;
  tb.top().hit_i = 0;
  if (!tb.run(items, s)) return 1;
  return tb.pass("pixel results: PixW %d, DepthW %d, PrimW %d; %ld pixels drawn, %ld without work "
                 "items; %ld work items, %ld hits, %ld depth ties, %ld depth+id ties, %ld pixels "
                 "without a hit; ready_o low %ld cycles",
                 kPixW, kDepthW, kPrimW, count, n_empty, n_items, n_hits, n_depth_ties, n_full_ties,
                 n_nohit, stall_cycles);
}
