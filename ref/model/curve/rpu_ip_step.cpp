// Twin of rtl/curve/rpu_ip_step.v | sim/tb/curve/tb_rpu_ip.cpp (-DIP_STEP=1) |
// sim/tests/curve/rpu_ip.cmake
#include "model/curve/rpu_ip_step.h"

#include <array>
#include <vector>

namespace rpu::ref {

int argmin_lowest(const i128* sd, int count) {
  int best = 0;
  for (int j = 1; j < count; ++j)
    if (sd[j] < sd[best]) best = j;
  return best;
}

FrameState frame_state(const HwParams& p, const PairFrame& f, std::uint64_t m0) {
  const i128 m = static_cast<i128>(m0);
  const int n = p.n;
  FrameState s;
  s.X = (f.x0 << n) + f.x1 * m;
  s.Y = (f.y0 << n) + f.y1 * m;
  s.T = (f.alpha << n) + f.beta * m;
  s.C2 = (f.c2a << n) + f.c2b * m;
  s.S2 = (f.s2a << n) + f.s2b * m;
  s.W = f.w[0] + f.w[1] * m + f.w[2] * m * m;
  s.SW = f.w[1] + 2 * f.w[2] * m;
  for (int k = 0; k < 2; ++k) {
    s.A[k] = f.a[k][0] + f.a[k][1] * m + f.a[k][2] * m * m;
    s.SA[k] = f.a[k][1] + 2 * f.a[k][2] * m;
  }
  return s;
}

IpState ip_start(const HwParams& p, const SegmentDesc& s, const PairFrame& f, Overflow& ovf) {
  IpState st;
  st.lo = candidate_evaluator(p, s.frame, f, 0, 0, ovf);
  st.hi = candidate_evaluator(p, s.frame, f, std::uint64_t{1} << p.n, 0, ovf);
  return st;
}

void ip_step_in_place(const HwParams& p, const SegmentDesc& s, const PairFrame& f,
                      IpState& st, Overflow& ovf, IpStepTrace* trace) {
  const int J = p.J();
  const int k = st.k + 1;
  const int shift = p.n - p.n1 * k;  // δ_k = 2^-(n1·k) = 2^shift τ-index units
  // The J - 1 new candidates (j = 1..J-1); the ends are the previous interval's lo and hi.
  thread_local std::vector<Candidate> cand;
  if (cand.size() < static_cast<size_t>(J) + 1) cand.resize(static_cast<size_t>(J) + 1);
  for (int j = 1; j < J; ++j)
    cand[j] = candidate_evaluator(p, s.frame, f, st.tau + (static_cast<std::uint64_t>(j) << shift),
                                  k, ovf);
  const auto md = [&](int j) { return j == 0 ? st.lo.md : j == J ? st.hi.md : cand[j].md; };
  std::array<i128, 256> sd;  // uninitialised: only [0, J) is written and read
  for (int j = 0; j < J; ++j) sd[j] = md(j) + md(j + 1);
  const int eta = argmin_lowest(sd.data(), J);
  if (trace) {
    for (int j = 0; j <= J; ++j) trace->md[j] = md(j);
    for (int j = 0; j < J; ++j) trace->sd[j] = sd[j];
    trace->eta = eta;
  }
  st.k = k;
  st.tau += static_cast<std::uint64_t>(eta) << shift;
  if (eta + 1 < J) st.hi = cand[eta + 1];  // else hi stays the previous hi
  if (eta > 0) st.lo = cand[eta];          // else lo stays the previous lo
}

IpState ip_step(const HwParams& p, const SegmentDesc& s, const PairFrame& f,
                const IpState& state, Overflow& ovf, IpStepTrace* trace) {
  IpState next = state;
  ip_step_in_place(p, s, f, next, ovf, trace);
  return next;
}

}  // namespace rpu::ref
