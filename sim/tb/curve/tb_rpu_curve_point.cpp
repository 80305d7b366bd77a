// rpu_curve_point against its twin (rpu::ref::curve_point_unit) on the real segments of
// scenes/curve12.json and scenes/polyline9.json (load_scene + compile_scene + quantize_scene at
// the verilated parameters): edge values of t per segment, then seeded random t over Q(3.FT)
// with g1, g2 from the guide unit's twin at that t (exact and pre-shifted square roots), and
// the X of every such item checked to fit the CW+3-bit port. Then random values over the full
// port range, where X may exceed CW+3 bits: compared modulo 2^(CW+3), which checks every
// internal product and floor. Random valid gaps and junk on idle cycles; X, tag and latency of
// every item compared in order.
#include <algorithm>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "Vrpu_curve_point.h"
#include "model/descriptors.h"
#include "model/units.h"
#include "scene/compiled_scene.h"
#include "scene/scene_json.h"
#include "tb_common.h"

#ifndef COORD_W
#define COORD_W 24
#endif
#ifndef T_FRAC
#define T_FRAC 24
#endif
#ifndef UNIT_FRAC
#define UNIT_FRAC 16
#endif
#ifndef TAG_W
#define TAG_W 1
#endif
#ifndef VECTORS
#define VECTORS 100000
#endif
#ifndef RPU_SOURCE_DIR
#error "RPU_SOURCE_DIR must name the source tree (for scenes/)"
#endif

namespace {

using namespace rpu;
using rpu::sim::i128;
using rpu::sim::u128;

constexpr int kCW = COORD_W, kFT = T_FRAC, kFU = UNIT_FRAC, kTagW = TAG_W;
constexpr int kTW = kFT + 3, kDW = kCW + 1, kUW = kFU + 2, kGW = kCW + 2, kXW = kCW + 3;


struct Op {
  ref::SegmentDesc seg;  // p1, d, guide[0].u, guide[1].u are used
  i128 t = 0, g1 = 0, g2 = 0;
  bool full_range = false;  // X compared modulo 2^XW
};

struct Item {
  Op op;
  ref::WVec3 x;
  std::uint32_t tag;
  long issued;
};

// Bit fields of a port of any size (scalar or VlWide): the low `width` bits of v at `lsb`.
template <class T>
void set_field(T& port, int lsb, int width, i128 v) {
  const u128 m = fixed::max_unsigned(width) << lsb;
  u128 cur = static_cast<u128>(port);
  cur = (cur & ~m) | ((static_cast<u128>(v) << lsb) & m);
  port = static_cast<T>(cur);
}
template <std::size_t N>
void set_field(VlWide<N>& port, int lsb, int width, i128 v) {
  for (int k = 0; k < width; ++k) {
    const int bit = lsb + k;
    const std::uint32_t b = static_cast<std::uint32_t>((static_cast<u128>(v) >> k) & 1);
    port[bit / 32] = (port[bit / 32] & ~(1u << (bit % 32))) | (b << (bit % 32));
  }
}
template <class T>
u128 get_field(const T& port, int lsb, int width) {
  return (static_cast<u128>(port) >> lsb) & fixed::max_unsigned(width);
}
template <std::size_t N>
u128 get_field(const VlWide<N>& port, int lsb, int width) {
  u128 u = 0;
  for (int k = 0; k < width; ++k) {
    const int bit = lsb + k;
    u |= static_cast<u128>((port[bit / 32] >> (bit % 32)) & 1u) << k;
  }
  return u;
}
i128 sign_extend(u128 u, int width) {
  const u128 sign = u128{1} << (width - 1);
  return static_cast<i128>((u ^ sign) - sign);
}
template <class P>
void set_vec(P& port, int width, const ref::IVec3& v) {
  set_field(port, 0, width, v.x);
  set_field(port, width, width, v.y);
  set_field(port, 2 * width, width, v.z);
}

i128 random_bits(std::mt19937_64& rng, int width) {
  const u128 bits = (static_cast<u128>(rng()) << 64) | rng();
  return static_cast<i128>(bits & fixed::max_unsigned(width));
}
// Signed, spread over magnitudes (a random width 1..width), extremes included.
i128 random_signed(std::mt19937_64& rng, int width) {
  switch (rng() % 16) {
    case 0: return fixed::max_signed(width);
    case 1: return fixed::min_signed(width);
    default: {
      const int w = 1 + static_cast<int>(rng() % static_cast<unsigned>(width));
      const i128 u = random_bits(rng, w);
      return u > fixed::max_signed(w) ? u - (i128{1} << w) : u;
    }
  }
}
ref::IVec3 random_vec(std::mt19937_64& rng, int width) {
  return {static_cast<fixed::i64>(random_signed(rng, width)),
          static_cast<fixed::i64>(random_signed(rng, width)),
          static_cast<fixed::i64>(random_signed(rng, width))};
}

// t over Q(3.FT): mostly inside [0, 1], some near its ends, the rest anywhere.
i128 random_t(std::mt19937_64& rng) {
  const i128 one = i128{1} << kFT;
  switch (rng() % 8) {
    case 0: return static_cast<i128>(rng() % 17) - 8;
    case 1: return one + static_cast<i128>(rng() % 17) - 8;
    case 2:
    case 3: return random_bits(rng, kTW) + fixed::min_signed(kTW);
    default: return random_bits(rng, kFT + 1) % (one + 1);
  }
}

}  // namespace

int main(int argc, char** argv) {
  auto ctx = sim::make_context("tb_rpu_curve_point");
  ctx->commandArgs(argc, argv);
  auto top = std::make_unique<Vrpu_curve_point>(ctx.get());
  const std::uint64_t seed = sim::test_seed("tb_rpu_curve_point");
  std::mt19937_64 rng(seed);
  const long random_count = sim::vector_count(VECTORS);

  ref::HwParams p;
  p.coord_w = kCW;
  p.t_frac = kFT;
  p.unit_frac = kFU;
  p.validate();
  const int kLatency = ref::curve_point_latency(p);  // its header: products of t, of u, the sum

  // ---- the scenes' segments ----
  std::vector<ref::SegmentDesc> segs;
  for (const char* name : {"curve12", "polyline9"}) {
    const scene::CompiledScene sc = scene::compile_scene(
        scene::load_scene(std::string(RPU_SOURCE_DIR) + "/scenes/" + name + ".json"));
    const ref::ModelScene m = ref::quantize_scene(sc, p);
    segs.insert(segs.end(), m.curve_segments.begin(), m.curve_segments.end());
    segs.insert(segs.end(), m.texture_segments.begin(), m.texture_segments.end());
  }
  // g from the guide unit's twin at weight w, with an exact or a pre-shifted square root.
  const auto guides = [&](const ref::SegmentDesc& s, i128 t_for_g, int sqrt_w, Op& op) {
    ref::HwParams pg = p;
    pg.sqrt_w = sqrt_w;
    const i128 w = ref::guide_weight(pg, t_for_g);
    fixed::Overflow ovf;
    op.g1 = ref::guide_unit(pg, s.guide[0], s.L2, w, ovf);
    op.g2 = ref::guide_unit(pg, s.guide[1], s.L2, w, ovf);
  };

  // ---- the operand list ----
  std::deque<Op> ops;
  const i128 one = i128{1} << kFT;
  for (const ref::SegmentDesc& s : segs)
    for (i128 t : {i128{0}, i128{1}, one / 2, one - 1, one, one + 1, i128{-1},
                   fixed::max_signed(kTW), fixed::min_signed(kTW)})
      for (int sw : {0, 40}) {
        Op op;
        op.seg = s;
        op.t = t;
        guides(s, t, sw, op);
        ops.push_back(op);
      }
  const long edge_count = static_cast<long>(ops.size());
  const int sqrt_ws[] = {0, 0, 0, 32, 40, 48};
  for (long k = 0; k < random_count; ++k) {
    Op op;
    op.seg = segs[rng() % segs.size()];
    op.t = random_t(rng);
    const int sw = sqrt_ws[rng() % 6];
    if (rng() % 10 == 0) {  // g of another t in [0, 1] (t in [0, 1] too)
      op.t = random_bits(rng, kFT + 1) % (one + 1);
      guides(op.seg, random_bits(rng, kFT + 1) % (one + 1), sw, op);
    } else {
      guides(op.seg, op.t, sw, op);
    }
    ops.push_back(op);
  }
  const long full_count = std::max<long>(random_count / 10, 1000);
  for (long k = 0; k < full_count; ++k) {
    Op op;
    op.full_range = true;
    op.seg.p1 = random_vec(rng, kCW);
    op.seg.d = random_vec(rng, kDW);
    op.seg.guide[0].u = random_vec(rng, kUW);
    op.seg.guide[1].u = random_vec(rng, kUW);
    op.t = random_signed(rng, kTW);
    op.g1 = random_signed(rng, kGW);
    op.g2 = random_signed(rng, kGW);
    ops.push_back(op);
  }

  // ---- drive and check ----
  sim::reset(*top, *ctx);
  std::deque<Item> expected;
  long matched = 0, cycle = 0, wrapped = 0;
  i128 max_abs_x = 0;  // over the scene vectors
  const long total = static_cast<long>(ops.size());
  const std::uint32_t tag_mask = kTagW >= 32 ? 0xFFFFFFFFu : ((1u << kTagW) - 1);
  while (matched < total) {
    const bool issue = !ops.empty() && (rng() % 100) < 85;
    top->valid_i = issue;
    Op op;
    if (issue) {
      op = ops.front();
      ops.pop_front();
    } else {  // junk on idle cycles: must not matter
      op.seg.p1 = random_vec(rng, kCW);
      op.seg.d = random_vec(rng, kDW);
      op.seg.guide[0].u = random_vec(rng, kUW);
      op.seg.guide[1].u = random_vec(rng, kUW);
      op.t = random_signed(rng, kTW);
      op.g1 = random_signed(rng, kGW);
      op.g2 = random_signed(rng, kGW);
    }
    set_vec(top->p1_i, kCW, op.seg.p1);
    set_vec(top->d_i, kDW, op.seg.d);
    set_vec(top->u1_i, kUW, op.seg.guide[0].u);
    set_vec(top->u2_i, kUW, op.seg.guide[1].u);
    set_field(top->t_i, 0, kTW, op.t);
    set_field(top->g1_i, 0, kGW, op.g1);
    set_field(top->g2_i, 0, kGW, op.g2);
    const std::uint32_t this_tag = static_cast<std::uint32_t>(rng()) & tag_mask;
    set_field(top->tag_i, 0, kTagW, this_tag);
    if (issue) {
      const ref::WVec3 x = ref::curve_point_unit(p, op.seg, op.t, op.g1, op.g2);
      for (i128 c : {x.x, x.y, x.z}) {
        if (op.full_range) {
          wrapped += !fixed::fits_signed(c, kXW);
          continue;
        }
        if (!fixed::fits_signed(c, kXW)) {
          std::printf("FAILURE: the twin's X component %s does not fit CW+3 = %d bits (t %s g1 %s "
                      "g2 %s)\n", sim::to_string(c).c_str(), kXW, sim::to_string(op.t).c_str(),
                      sim::to_string(op.g1).c_str(), sim::to_string(op.g2).c_str());
          return 1;
        }
        max_abs_x = std::max(max_abs_x, c < 0 ? -c : c);
      }
      expected.push_back({op, x, this_tag, cycle});
    }
    sim::tick(*top, *ctx);
    ++cycle;
    if (top->valid_o) {
      if (expected.empty()) {
        std::printf("FAILURE cycle %ld: valid_o with no operand outstanding\n", cycle);
        return 1;
      }
      const Item want = expected.front();
      expected.pop_front();
      const i128 want_c[3] = {want.x.x, want.x.y, want.x.z};
      i128 got_c[3];
      bool ok = true;
      for (int c = 0; c < 3; ++c) {
        const u128 bits = get_field(top->x_o, c * kXW, kXW);
        got_c[c] = sign_extend(bits, kXW);
        // Full-range items: the low XW bits (the port's value modulo 2^XW).
        const i128 want_cmp = want.op.full_range
                                  ? sign_extend(static_cast<u128>(want_c[c]) &
                                                    fixed::max_unsigned(kXW), kXW)
                                  : want_c[c];
        ok = ok && got_c[c] == want_cmp;
      }
      const std::uint32_t got_tag = static_cast<std::uint32_t>(get_field(top->tag_o, 0, kTagW));
      const long latency = cycle - want.issued;
      if (!ok || got_tag != want.tag || latency != kLatency) {
        const ref::SegmentDesc& s = want.op.seg;
        std::printf("FAILURE cycle %ld item %ld (%s): t %s g1 %s g2 %s\n", cycle, matched,
                    want.op.full_range ? "full range, modulo 2^XW" : "scene",
                    sim::to_string(want.op.t).c_str(), sim::to_string(want.op.g1).c_str(),
                    sim::to_string(want.op.g2).c_str());
        std::printf("  p1 (%lld %lld %lld) d (%lld %lld %lld) u1 (%lld %lld %lld) u2 (%lld %lld "
                    "%lld)\n",
                    (long long)s.p1.x, (long long)s.p1.y, (long long)s.p1.z, (long long)s.d.x,
                    (long long)s.d.y, (long long)s.d.z, (long long)s.guide[0].u.x,
                    (long long)s.guide[0].u.y, (long long)s.guide[0].u.z,
                    (long long)s.guide[1].u.x, (long long)s.guide[1].u.y,
                    (long long)s.guide[1].u.z);
        std::printf("  expected X (%s %s %s) tag %u latency %d\n",
                    sim::to_string(want_c[0]).c_str(), sim::to_string(want_c[1]).c_str(),
                    sim::to_string(want_c[2]).c_str(), want.tag, kLatency);
        std::printf("  got      X (%s %s %s) tag %u latency %ld\n",
                    sim::to_string(got_c[0]).c_str(), sim::to_string(got_c[1]).c_str(),
                    sim::to_string(got_c[2]).c_str(), got_tag, latency);
        return 1;
      }
      ++matched;
    }
    if (cycle > 4 * total + 1000) {
      std::printf("FAILURE: timeout after %ld cycles, %ld of %ld matched\n", cycle, matched, total);
      return 1;
    }
  }
  top->final();
  std::printf("rpu_curve_point CoordW=%d TFrac=%d UnitFrac=%d TagW=%d latency %d: matched %ld "
              "items (%zu segments: %ld edges + %ld random scene items, max |X| = %.4f·2^CW; "
              "%ld full-range items modulo 2^(CW+3), %ld components beyond CW+3 bits) in %ld "
              "cycles\n",
              kCW, kFT, kFU, kTagW, kLatency, matched, segs.size(), edge_count, random_count,
              static_cast<double>(max_abs_x) / static_cast<double>(i128{1} << kCW), full_count,
              wrapped, cycle);
  return 0;
}
