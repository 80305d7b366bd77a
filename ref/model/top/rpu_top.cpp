// Twin of rtl/top/rpu_top.v | sim/tb/top/tb_rpu_top.cpp | sim/tests/top/rpu_top.cmake
#include "model/top/rpu_top.h"

#include "model/curve/rpu_capture.h"
#include "model/curve/rpu_frame.h"
#include "model/curve/rpu_ip.h"
#include "model/curve/rpu_test_point.h"

namespace rpu::ref {

PairResult process_curve_pair(const HwParams& p, const CameraDesc& cam, const RayGenOut& ray,
                              const SegmentDesc& s) {
  PairResult r;
  Overflow ovf;
  r.interval = sphere_unit(p, cam.eye, ray.vhat, s, ovf);
  if (r.interval.pred1) {
    const PairFrame f = frame_unit(p, s, r.interval, ovf);
    const IpState st = ip_process(p, s, f, ovf);
    r.tau = st.tau;
    const TestPoint tp = test_point_unit(p, s, r.interval, st.tau, ovf);
    r.t = tp.t;
    r.X = tp.X;
    const CaptureOut c = capture_unit(p, cam, ray, r.X, r.t);
    r.hit = c.hit;
    r.depth = c.depth;
  }
  r.overflow = ovf.flag;
  return r;
}

}  // namespace rpu::ref
