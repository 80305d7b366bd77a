// Twin of rtl/surface/rpu_surface_top.v
#include "model/surface/rpu_surface_top.h"

#include "model/surface/rpu_surface_ip.h"

namespace rpu::ref {

SurfacePieceResult process_surface_piece(const HwParams& p, const CameraDesc& cam,
                                         const IVec3& vhat, const SurfaceDesc& s, int piece) {
  SurfacePieceResult r;
  Overflow ovf;
  const SurfaceSetupOut su = surface_setup(p, cam.eye, vhat, s, piece, ovf);
  r.pieces = su.pieces;
  r.valid = su.valid;
  if (su.valid) {
    const SurfaceIpState st = surface_ip(p, s, su, ovf);
    if (!st.miss) {
      r.hit = true;
      r.tau = st.tau;
      r.X = su.A + scale_truncate(su.AB, static_cast<i128>(st.tau), p.n);  // pr(τ_K), LSB
      r.depth = dot(r.X - widen(cam.eye), widen(cam.w));
    }
  }
  r.overflow = ovf.flag;
  return r;
}

}  // namespace rpu::ref
