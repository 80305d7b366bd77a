// Twin of rtl/surface/rpu_surface_ip.v
#include "model/surface/rpu_surface_ip.h"

#include "model/surface/rpu_indicator.h"

namespace rpu::ref {

WVec3 surface_candidate(const HwParams& p, const SurfaceSetupOut& piece, std::uint64_t m) {
  return piece.lA + scale_truncate(piece.lAB, static_cast<i128>(m), p.n);
}

namespace {

bool inside_at(const HwParams& p, const SurfaceDesc& s, const SurfaceSetupOut& piece,
               std::uint64_t m, Overflow& ovf) {
  return indicator_unit(p, s, surface_candidate(p, piece, m), piece.x_negative, piece.last_turn,
                        ovf);
}

}  // namespace

SurfaceIpState surface_ip_start(const HwParams& p, const SurfaceDesc& s,
                                const SurfaceSetupOut& piece, Overflow& ovf) {
  SurfaceIpState st;
  st.lo_inside = inside_at(p, s, piece, 0, ovf);
  st.hi_inside = inside_at(p, s, piece, std::uint64_t{1} << p.n, ovf);
  return st;
}

void surface_ip_step(const HwParams& p, const SurfaceDesc& s, const SurfaceSetupOut& piece,
                     SurfaceIpState& st, Overflow& ovf, SurfaceIpStepTrace* trace) {
  const int k = st.k + 1;
  const int bits = p.surface_step_bits(k);
  const int J = 1 << bits;
  int done = 0;  // bits of τ fixed after step k
  for (int i = 1; i <= k; ++i) done += p.surface_step_bits(i);
  const int shift = p.n - done;  // δ_k = 2^-done = 2^shift τ-index units
  st.k = k;
  if (st.miss) return;
  SurfaceIpStepTrace local;
  auto& in = trace ? trace->inside : local.inside;
  in[0] = st.lo_inside;
  in[J] = st.hi_inside;
  for (int j = 1; j < J; ++j)
    in[j] = inside_at(p, s, piece, st.tau + (static_cast<std::uint64_t>(j) << shift), ovf);
  // The lowest j < J with s_j ≠ s_{j+1} (a priority encoder over the J change bits).
  int eta = -1;
  for (int j = 0; j < J && eta < 0; ++j)
    if (in[j] != in[j + 1]) eta = j;
  if (trace) trace->eta = eta;
  if (eta < 0) {  // only possible at step 1: later intervals have ends that differ
    st.miss = true;
    return;
  }
  st.tau += static_cast<std::uint64_t>(eta) << shift;
  st.lo_inside = in[eta];
  st.hi_inside = in[eta + 1];
}

SurfaceIpState surface_ip(const HwParams& p, const SurfaceDesc& s, const SurfaceSetupOut& piece,
                          Overflow& ovf) {
  SurfaceIpState st = surface_ip_start(p, s, piece, ovf);
  while (st.k < p.surface_steps() && !st.miss) surface_ip_step(p, s, piece, st, ovf);
  return st;
}

}  // namespace rpu::ref
