// All unit twins: one C++ twin per hardware unit of the ray-processing unit (docs/rtl.md),
// with the RTL module's parameters (HwParams) and ports (its structs). Each twin lives in
// ref/model/S/<module>.h/.cpp, named after rtl/S/<module>.v and at the path of
// sim/tb/S/tb_<module>.cpp (S the subsystem: common, curve, texture, surface, top; table:
// docs/reference-model.md); this header includes them all.
#pragma once

#include "model/common/rpu_cordic.h"
#include "model/common/rpu_fifo.h"
#include "model/common/rpu_sqrt.h"
#include "model/curve/rpu_candidate.h"
#include "model/curve/rpu_capture.h"
#include "model/curve/rpu_chord.h"
#include "model/curve/rpu_curve_point.h"
#include "model/curve/rpu_frame.h"
#include "model/curve/rpu_guide_pair.h"
#include "model/curve/rpu_ip.h"
#include "model/curve/rpu_ip_step.h"
#include "model/curve/rpu_sphere.h"
#include "model/curve/rpu_test_point.h"
#include "model/datapath.h"
#include "model/surface/rpu_indicator.h"
#include "model/surface/rpu_surface_ip.h"
#include "model/surface/rpu_surface_setup.h"
#include "model/surface/rpu_surface_top.h"
#include "model/texture/rpu_ray_plane.h"
#include "model/texture/rpu_texture.h"
#include "model/top/rpu_ray_gen.h"
#include "model/top/rpu_resolve.h"
#include "model/top/rpu_top.h"
