// rpu_candidate against rpu::ref::candidate_unit at one Fo (the offsets' fraction bits of a step):
// real pairs of curve12 (every segment, pixels around its projection) through the frame unit at
// random and edge τ indices; a quarter of them with edited frame guides (arc η over [0, 16],
// flat, straight, the unused mode code 3); a quarter with every input drawn over its whole port
// width (t, c2·t, s2·t, w and the flat offsets beyond their clamps, offsets that saturate:
// ovf_o); random valid gaps and a random tag per item (checked). FO = 0: the iterative form's
// run-time Fo, drawn per item over [8, 20] (fo_i).
#include <vector>

#include "Vrpu_candidate.h"
#include "tb_ip_common.h"

#ifndef FO
#define FO 20
#endif

struct Item {
  size_t seg;
  int kind;  // 0 real, 1 edited guides, 2 random inputs
  int fo;    // the offsets' fraction bits
  ref::FrameDesc fd;
  ref::CandidateIn in;
  unsigned tag;
  ref::Candidate want;
  bool ovf;
};

namespace {

using H = ref::HwParams;

// A frame guide as the compiler forms it (η² exact), or the unused mode code 3.
ref::FrameGuide random_guide(std::mt19937_64& rng) {
  ref::FrameGuide g;
  switch (rng() % 4) {
    case 0: g.mode = ref::GuideMode::kStraight; break;
    case 1: g.mode = ref::GuideMode::kFlat; break;
    case 2: g.mode = static_cast<ref::GuideMode>(3); break;
    default: {
      g.mode = ref::GuideMode::kArc;
      const std::int64_t max = std::int64_t{16} << H::kFrameGuideFrac;
      const std::uint64_t r = rng() % 8;
      g.eta = r == 0 ? 0 : r == 1 ? max : static_cast<std::int64_t>(rng() % (max + 1));
      g.eta2 = g.eta * g.eta;
    }
  }
  return g;
}

}  // namespace

int main(int argc, char** argv) {
  sim::Testbench<Vrpu_candidate> tb("tb_rpu_candidate", argc, argv);
  auto& rng = tb.rng;
  const scene::CompiledScene sc = sim::compiled_demo_scene("curve12");
  ref::HwParams p = sim::tb_params();
  p.metric = METRIC ? ref::Metric::kSquared : ref::Metric::kAbs;
  const ref::ModelScene m = ref::quantize_scene(sc, p);
  const long count = tb.vectors(100000);
  const int MdW = METRIC ? 2 * H::kFrameMdFracMax + 3 : H::kFrameMdFracMax + 3;

  std::vector<Item> items;
  long n_kind[3] = {0, 0, 0}, n_sat = 0, n_arc = 0, n_flat = 0;
  while (static_cast<long>(items.size()) < count) {
    sim::SampledPair pair;
    if (!sim::sample_pred1_pair(sc, m, p, rng, pair)) continue;
    const ref::SegmentDesc& s = m.curve_segments[pair.seg];
    fixed::Overflow o0;
    const ref::PairFrame f = ref::frame_unit(p, s, pair.si, o0);
    for (int r = 0; r < 8; ++r) {
      Item it{pair.seg, static_cast<int>(rng() % 4), FO, s.frame, {},
              static_cast<unsigned>(rng() & 1), {}, false};
      if (FO == 0) it.fo = 8 + static_cast<int>(rng() % (H::kFrameMdFracMax - 7));
      it.kind = it.kind == 3 ? 0 : it.kind;
      const std::uint64_t full = std::uint64_t{1} << p.n;
      const std::uint64_t edges[] = {0, full, 1, full - 1, full / 2};
      const std::uint64_t mm = r < 2 ? edges[rng() % 5] : rng() % (full + 1);
      fixed::Overflow ovf;
      it.in = ref::candidate_inputs(p, f, mm, ovf);
      if (it.kind >= 1)
        for (ref::FrameGuide& g : it.fd.guide) g = random_guide(rng);
      if (it.kind == 2) {
        it.in.x = sim::random_signed(rng, H::kCandXW);
        it.in.y = sim::random_signed(rng, H::kCandXW);
        it.in.t = sim::random_signed(rng, H::kCandTW);
        it.in.c2t = sim::random_signed(rng, H::kCandTW);
        it.in.s2t = sim::random_signed(rng, H::kCandTW);
        it.in.w = sim::random_signed(rng, H::kCandWW);
        for (i128& a : it.in.a) a = sim::random_signed(rng, H::kCandAW);
      }
      fixed::Overflow o2;
      it.want = ref::candidate_unit(p, it.fd, it.in, it.fo, o2);
      it.ovf = o2.flag;
      ++n_kind[it.kind];
      n_sat += it.ovf ? 1 : 0;
      for (const ref::FrameGuide& g : it.fd.guide) {
        n_arc += g.mode == ref::GuideMode::kArc;
        n_flat += g.mode == ref::GuideMode::kFlat;
      }
      items.push_back(it);
    }
  }

  sim::Stream<Vrpu_candidate, Item> s{.latency = sim::kSameLatency, .tag_w = 0};  // its own tag
  s.inputs = [&](sim::Inputs& in, Vrpu_candidate& t, const Item& it) {
    in("fo", t.fo_i, it.fo, 5)("x", t.x_i, it.in.x, H::kCandXW)("y", t.y_i, it.in.y, H::kCandXW);
    in("t", t.t_i, it.in.t, H::kCandTW)("c2t", t.c2t_i, it.in.c2t, H::kCandTW);
    in("s2t", t.s2t_i, it.in.s2t, H::kCandTW)("w", t.w_i, it.in.w, H::kCandWW);
    in.fields("a", t.a_i, std::vector<i128>{it.in.a[0], it.in.a[1]}, H::kCandAW);
    in.bits("g1", t.g1_i, sim::pack_frame_guide(it.fd.guide[0]))
        .bits("g2", t.g2_i, sim::pack_frame_guide(it.fd.guide[1]));
    in.note("g1.mode", std::to_string(static_cast<int>(it.fd.guide[0].mode)))
        .note("g1.eta", sim::str(it.fd.guide[0].eta))
        .note("g2.mode", std::to_string(static_cast<int>(it.fd.guide[1].mode)))
        .note("g2.eta", sim::str(it.fd.guide[1].eta));
    in("tag", t.tag_i, it.tag, 1);
  };
  s.outputs = [&](sim::Outputs& o, const Vrpu_candidate& t, const Item& it) {
    o("md", t.md_o, it.want.md, MdW)("ovf", t.ovf_o, it.ovf, 1)("tag", t.tag_o, it.tag, 1);
  };
  s.what = [](const Item& it) {
    return "segment " + std::to_string(it.seg) +
           (it.kind == 1 ? " (edited guides)" : it.kind == 2 ? " (random inputs)" : "");
  };
  return tb.check(items, s,
                  "Fo %d, metric %d: %ld real, %ld with edited guides, %ld random; %ld "
                  "saturated; %ld arc and %ld flat guides",
                  FO, METRIC, n_kind[0], n_kind[1], n_kind[2], n_sat, n_arc, n_flat);
}
