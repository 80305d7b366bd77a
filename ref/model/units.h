// All unit twins: one C++ twin per hardware unit of the ray-processing unit (ARCHITECTURE.md),
// with the RTL module's parameters (HwParams) and ports (its structs). Each twin lives in
// ref/model/<module>.h/.cpp, named after rtl/<module>.v and beside sim/tb/tb_<module>.cpp
// (table: docs/reference-model.md); this header includes them all.
#pragma once

#include "model/datapath.h"
#include "model/rpu_candidate.h"
#include "model/rpu_capture.h"
#include "model/rpu_chord.h"
#include "model/rpu_cordic.h"
#include "model/rpu_curve_point.h"
#include "model/rpu_fifo.h"
#include "model/rpu_guide_pair.h"
#include "model/rpu_ip.h"
#include "model/rpu_ip_step.h"
#include "model/rpu_ray_gen.h"
#include "model/rpu_ray_plane.h"
#include "model/rpu_resolve.h"
#include "model/rpu_sphere.h"
#include "model/rpu_sqrt.h"
#include "model/rpu_texture.h"
#include "model/rpu_top.h"
