// What the co-simulation feeds rpu_top for one frame and what it must get back: the packed
// descriptors (camera register, segment RAM, surface RAM), the frame's work items in pixel
// order (curve segments from the screen bins, texture segments from the classification grid at
// the model's own ray/plane point, every piece of every surface: exactly the work items
// `render_ref` processes), and per item and per pixel the reference model's result.
#pragma once

#include <string>
#include <vector>

#include "model/descriptors.h"
#include "model/ref_renderer.h"
#include "rtl_types.h"
#include "scene/compiled_scene.h"

namespace rpu::sim {

struct FrameSchedule {
  ref::HwParams params;
  Bits camera;                        // cam_data_i
  std::vector<Bits> segments;         // seg_data_i at address k: curves, then textures
  std::vector<Bits> surfaces;         // surf_data_i at address k: the scene's surfaces
  std::vector<WorkItem> items;        // pixel order; a pixel's items are consecutive
  std::vector<ItemResult> expected;   // the model's result of items[k]
  int width = 0, height = 0;
  std::vector<PixelResult> expected_pixels;  // one per pixel with at least one item
  std::size_t curve_items = 0, texture_items = 0, surface_items = 0;
  void count(const WorkItem& it) {
    (it.surface ? surface_items : it.texture ? texture_items : curve_items)++;
  }
};

// Throws rpu::Error when the scene does not fit rpu_top (more than 2^SegAddrW segments or
// 2^SurfAddrW surfaces, an image side over 2^IdxW). Uses all cores (ref.threads).
FrameSchedule schedule_frame(const scene::CompiledScene& sc, const ref::ModelScene& m,
                             const ref::RefOptions& ref);

// The model's intermediate values of one work item, stage by stage (ray generator, sphere
// unit or ray/plane unit, every IP step, capture or texture predicates), for a mismatch report.
std::string explain_item(const ref::ModelScene& m, const WorkItem& item);

// The packed descriptors (formats: docs/fixed-point.md, packing: docs/rtl.md).
Bits pack_camera(const ref::HwParams& p, const ref::CameraDesc& c);
Bits pack_segment(const ref::HwParams& p, const ref::SegmentDesc& s, bool texture);
Bits pack_surface(const ref::HwParams& p, const ref::SurfaceDesc& s);

}  // namespace rpu::sim
