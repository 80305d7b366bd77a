#include "frame_schedule.h"

#include <fmt/format.h>

#include "common/error.h"
#include "common/parallel.h"
#include "frame_word.h"
#include "guide_word.h"
#include "model/units.h"
#include "scene/classification_grid.h"
#include "scene/screen_bins.h"
#include "surface_word.h"

namespace rpu::sim {

namespace {

std::string dec(i128 v) { return fixed::to_decimal(v); }
std::string vec(const ref::WVec3& v) {
  return "(" + dec(v.x) + ", " + dec(v.y) + ", " + dec(v.z) + ")";
}
std::string vec(const ref::IVec3& v) {
  return "(" + dec(v.x) + ", " + dec(v.y) + ", " + dec(v.z) + ")";
}

// A result's point X from the model's vector.
template <class V>
void set_x(ItemResult& e, const V& x) {
  e.X[0] = x.x;
  e.X[1] = x.y;
  e.X[2] = x.z;
}

// The fields a curve pair's and a surface piece's results share: hit, overflow, depth, τ, X.
template <class R>
ItemResult hit_result(const R& r) {
  ItemResult e;
  e.hit = r.hit;
  e.overflow = r.overflow;
  e.depth = r.depth;
  e.tau = r.tau;
  set_x(e, r.X);
  return e;
}

ItemResult curve_result(const ref::PairResult& r) {
  ItemResult e = hit_result(r);
  e.pred1 = r.interval.pred1;
  e.t = r.t;
  return e;
}

// A surface piece's expected result: the piece's valid bit is pred_1, t stays 0.
ItemResult surface_result(const ref::SurfacePieceResult& r) {
  ItemResult e = hit_result(r);
  e.surface = true;
  e.pieces = r.pieces;
  e.pred1 = r.valid;
  return e;
}

}  // namespace

// The camera register in the layout of rtl/top/rpu_cam_desc.vh, most significant field first.
Bits pack_camera(const ref::HwParams& p, const ref::CameraDesc& c) {
  const TopWidths w(p);
  Concat cam;
  cam.add3(c.v0.x, c.v0.y, c.v0.z, w.VgW);
  cam.add3(c.dx.x, c.dx.y, c.dx.z, w.VgW);
  cam.add3(c.dy.x, c.dy.y, c.dy.z, w.VgW);
  cam.add3(c.el0.x, c.el0.y, c.el0.z, w.EgW);
  cam.add3(c.et0.x, c.et0.y, c.et0.z, w.EgW);
  cam.add3(c.sw.x, c.sw.y, c.sw.z, w.EgW);
  cam.add3(c.w.x, c.w.y, c.w.z, w.EgW);
  cam.add3(c.eye.x, c.eye.y, c.eye.z, w.CW);
  return cam.bits();
}

// A segment descriptor in the layout of rtl/top/rpu_seg_desc.vh (its guides: rtl/curve/
// rpu_guide_desc.vh), most significant field first.
Bits pack_segment(const ref::HwParams& p, const ref::SegmentDesc& s, bool texture) {
  const TopWidths w(p);
  Concat d;
  d.add(texture ? 1 : 0, 1);
  d.add(s.primitive, TopWidths::kPrimW);
  d.add3(s.p1.x, s.p1.y, s.p1.z, w.CW);
  d.add3(s.d.x, s.d.y, s.d.z, w.DW);
  // A texture's c0 is unused: its x holds the join (1: round), the bit rpu_texture reads.
  d.add3(texture ? (s.round_join ? 1 : 0) : s.c0.x, texture ? 0 : s.c0.y, texture ? 0 : s.c0.z,
         w.CW);
  d.add(texture ? s.w0_2 : s.R2, w.R2W);  // a texture's w0_2 rides in the R2 field
  d.add(s.L2, w.L2W);
  d.add(s.inv_m, p.inv_w);
  d.add(s.inv_s, 7);
  for (const ref::GuideDesc& g : s.guide) add_guide(d, p, g);
  // The frame descriptor and frame guides (0 for a texture), rtl/curve/rpu_frame.v, rpu_ip.v.
  const ref::FrameDesc f = texture ? ref::FrameDesc{} : s.frame;
  add_frame_desc(d, f);
  for (const ref::FrameGuide& g : f.guide) add_frame_guide(d, g);
  return d.bits();
}

// A descriptor of the surface RAM in the layout of rtl/top/rpu_surf_desc.vh, most significant
// field first.
Bits pack_surface(const ref::HwParams& p, const ref::SurfaceDesc& s) {
  const TopWidths w(p);
  const int mw = p.surf_mant_w(), kf = p.surf_const_frac();
  Concat d;
  d.add(s.primitive, TopWidths::kPrimW);
  d.add3(s.bound.c0.x, s.bound.c0.y, s.bound.c0.z, w.CW);
  d.add(s.bound.R2, w.R2W);
  d.add3(s.origin.x, s.origin.y, s.origin.z, w.CW);
  for (int k = 8; k >= 0; --k) d.add(s.to_local[static_cast<size_t>(k)], mw);  // entry 0 lowest
  d.add(s.to_local_s, 7);
  d.add(s.y_min, p.surf_w);
  d.add(s.y_max, p.surf_w);
  d.add(static_cast<i128>(s.end_angle), p.angle_w);
  d.add(s.end_cos, kf + 2);
  d.add(s.end_sin, kf + 2);
  add_surface_desc(d, p, s);
  return d.bits();
}

FrameSchedule schedule_frame(const scene::CompiledScene& sc, const ref::ModelScene& m,
                             const ref::RefOptions& o) {
  const ref::HwParams& p = m.params;
  const ref::CameraDesc& cam = m.camera;
  const std::size_t nseg = m.curve_segments.size() + m.texture_segments.size();
  if (nseg > (std::size_t{1} << TopWidths::kSegAddrW))
    throw Error(m.source, fmt::format("{} segments, but rpu_top's segment RAM holds {} "
                                      "(SegAddrW {})", nseg, 1 << TopWidths::kSegAddrW,
                                      TopWidths::kSegAddrW));
  if (m.surfaces.size() > (std::size_t{1} << TopWidths::kSurfAddrW))
    throw Error(m.source, fmt::format("{} surfaces, but rpu_top's surface RAM holds {} "
                                      "(SurfAddrW {})", m.surfaces.size(),
                                      1 << TopWidths::kSurfAddrW, TopWidths::kSurfAddrW));
  if (cam.width > (1 << TopWidths::kIdxW) || cam.height > (1 << TopWidths::kIdxW))
    throw Error(m.source, fmt::format("image {}x{} exceeds rpu_top's pixel index range {}",
                                      cam.width, cam.height, 1 << TopWidths::kIdxW));
  FrameSchedule f;
  f.params = p;
  f.width = cam.width;
  f.height = cam.height;
  f.camera = pack_camera(p, cam);
  for (const auto& s : m.curve_segments) f.segments.push_back(pack_segment(p, s, false));
  for (const auto& s : m.texture_segments) f.segments.push_back(pack_segment(p, s, true));
  for (const auto& s : m.surfaces) f.surfaces.push_back(pack_surface(p, s));
  const auto tex_base = static_cast<std::uint32_t>(m.curve_segments.size());

  const scene::ScreenBins bins(sc.camera, sc.curve_segments, 8, o.binning);
  const scene::ClassificationGrid grid =
      scene::ClassificationGrid::build(sc.texture_segments, 2.0, 2.0 / m.norm.scale);
  // Row by row on all cores, then joined in pixel order.
  struct Row {
    std::vector<WorkItem> items;
    std::vector<ItemResult> expected;
  };
  std::vector<Row> rows(static_cast<size_t>(cam.height));
  struct Job {
    const ref::ModelScene* m;
    const ref::RefOptions* o;
    const scene::ScreenBins* bins;
    const scene::ClassificationGrid* grid;
    std::vector<Row>* rows;
    std::uint32_t tex_base;
    void operator()(int j) {
      const ref::HwParams& p = m->params;
      Row& row = (*rows)[static_cast<size_t>(j)];
      for (int i = 0; i < m->camera.width; ++i) {
        const size_t first = row.items.size();
        const ref::RayGenOut ray = ref::ray_generator(p, m->camera, i, j);
        for (auto k : bins->segments_for_pixel(i, j)) {
          const ref::SegmentDesc& s = m->curve_segments[k];
          ItemResult e = curve_result(ref::process_curve_pair(p, m->camera, ray, s));
          e.seg = static_cast<std::uint32_t>(k);
          e.primitive = static_cast<std::uint32_t>(s.primitive);
          row.items.push_back({0, i, j, e.seg, false, false});
          row.expected.push_back(e);
        }
        if (!m->texture_segments.empty()) {
          const ref::PlanePoint pp = ref::ray_plane_unit(p, m->camera, ray.vhat);
          if (pp.valid) {
            const auto test = [&](std::size_t k) {
              const ref::SegmentDesc& s = m->texture_segments[k];
              ref::Overflow flag;
              const ref::TextureOut t = ref::texture_unit(p, s, pp.p0, flag);
              ItemResult e;
              e.texture = true;
              e.seg = tex_base + static_cast<std::uint32_t>(k);
              e.primitive = static_cast<std::uint32_t>(s.primitive);
              e.pred1 = true;
              e.hit = t.covers;
              e.overflow = flag.flag;
              e.depth = pp.depth;
              e.t = t.t;
              set_x(e, t.X);
              row.items.push_back({0, i, j, e.seg, false, true});
              row.expected.push_back(e);
            };
            if (o->grid) {
              const double x = static_cast<double>(pp.p0.x) / m->norm.scale + m->norm.offset.x;
              const double y = static_cast<double>(pp.p0.y) / m->norm.scale + m->norm.offset.y;
              for (auto k : grid->lookup(x, y)) test(k);
            } else {
              for (std::size_t k = 0; k < m->texture_segments.size(); ++k) test(k);
            }
          }
        }
        // Every piece of every surface, as render_ref (the host issues 1 or 3 per pair).
        for (std::size_t k = 0; k < m->surfaces.size(); ++k) {
          const ref::SurfaceDesc& s = m->surfaces[k];
          const int pieces = ref::surface_piece_items(s.type);
          for (int q = 0; q < pieces; ++q) {
            // A build without the surface path answers every piece alike (rpu_top.h).
            ItemResult e = surface_result(
                p.surfaces ? ref::process_surface_piece(p, m->camera, ray.vhat, s, q)
                           : ref::unbuilt_surface_result());
            e.seg = static_cast<std::uint32_t>(k);
            e.piece = q;
            e.primitive = p.surfaces ? static_cast<std::uint32_t>(s.primitive) : 0;
            WorkItem it{0, i, j, e.seg, false, false};
            it.surface = true;
            it.piece = q;
            row.items.push_back(it);
            row.expected.push_back(e);
          }
        }
        if (row.items.size() > first) {
          row.items.back().last = true;
          row.expected.back().last = true;
        }
      }
    }
  };
  parallel_rows(cam.height, o.threads, Job{&m, &o, &bins, &grid, &rows, tex_base},
                     [](const Job&) {});
  std::uint32_t id = 0;
  for (Row& row : rows) {
    for (size_t k = 0; k < row.items.size(); ++k) {
      WorkItem it = row.items[k];
      ItemResult e = row.expected[k];
      it.id = e.id = id++;
      e.i = it.i;
      e.j = it.j;
      f.count(it);
      f.items.push_back(it);
      f.expected.push_back(e);
    }
  }
  // Expected pixels: Resolve over each pixel's expected items (what render_ref does).
  ref::Resolve r;
  for (size_t k = 0; k < f.expected.size(); ++k) {
    const ItemResult& e = f.expected[k];
    if (e.hit) r.offer(e.depth, static_cast<std::int32_t>(e.primitive));
    if (e.last) {
      f.expected_pixels.push_back({e.i, e.j, r.any, r.any ? r.depth : 0,
                                   r.any ? static_cast<std::uint32_t>(r.primitive) : 0u});
      r = ref::Resolve{};
    }
  }
  return f;
}

std::string explain_item(const ref::ModelScene& m, const WorkItem& item) {
  const ref::HwParams& p = m.params;
  const ref::RayGenOut ray = ref::ray_generator(p, m.camera, item.i, item.j);
  std::string s = fmt::format("    ray generator: v {} vhat {}\n", vec(ray.v), vec(ray.vhat));
  s += fmt::format("      edges: left {} right {} top {} bottom {}\n", vec(ray.e_left),
                   vec(ray.e_right), vec(ray.e_top), vec(ray.e_bottom));
  const auto ncurve = m.curve_segments.size();
  if (item.surface) {
    if (item.seg >= m.surfaces.size()) return s + "    (no such surface)\n";
    if (!p.surfaces)
      return s + "    (this build has no surface path: no piece, no hit, the overflow bit)\n";
    const ref::SurfaceDesc& sd = m.surfaces[item.seg];
    fixed::Overflow ovf;
    const ref::SurfaceSetupOut su =
        ref::surface_setup(p, m.camera.eye, ray.vhat, sd, item.piece, ovf);
    s += fmt::format("    surface setup: valid {} pieces {} pred1 {} A {} B {} lA {} lB {} s {}..{} "
                     "A' {} B'-A' {} ovf {}\n", su.valid ? 1 : 0, su.pieces,
                     su.sphere.pred1 ? 1 : 0, vec(su.sphere.A), vec(su.sphere.B), vec(su.la),
                     vec(su.lb), dec(su.s_lo), dec(su.s_hi), vec(su.A), vec(su.AB),
                     ovf.flag ? 1 : 0);
    if (!su.valid) return s + "    (no such piece: the search does not run)\n";
    const ref::SurfacePieceResult r =
        ref::process_surface_piece(p, m.camera, ray.vhat, sd, item.piece);
    s += fmt::format("    search: hit {} tau {} X {} depth {} ovf {}\n", r.hit ? 1 : 0, r.tau,
                     vec(r.X), dec(r.depth), r.overflow ? 1 : 0);
    return s;
  }
  if (item.seg < ncurve) {
    const ref::SegmentDesc& sd = m.curve_segments[item.seg];
    ref::Overflow ovf;
    const ref::SearchInterval si = ref::sphere_unit(p, m.camera.eye, ray.vhat, sd, ovf);
    s += fmt::format("    sphere unit: pred1 {} tc {} half_chord {} A {} B {} alpha {} beta {} "
                     "ovf {}\n", si.pred1 ? 1 : 0, dec(si.tc), dec(si.half_chord), vec(si.A),
                     vec(si.B), dec(si.alpha), dec(si.beta), ovf.flag ? 1 : 0);
    if (!si.pred1) return s + "    (no pred1: the IP and capture do not run)\n";
    const ref::PairFrame f = ref::frame_unit(p, sd, si, ovf);
    s += fmt::format("    frame unit: x0 {} x1 {} y0 {} y1 {} w [{} {} {}]\n", dec(f.x0), dec(f.x1),
                     dec(f.y0), dec(f.y1), dec(f.w[0]), dec(f.w[1]), dec(f.w[2]));
    ref::IpState st = ref::ip_start(p, sd, f, ovf);
    s += fmt::format("    IP step 0: tau {} lo md {} | hi md {}\n", st.tau, dec(st.lo.md),
                     dec(st.hi.md));
    for (int k = 1; k <= p.K(); ++k) {
      ref::IpStepTrace tr;
      st = ref::ip_step(p, sd, f, st, ovf, &tr);
      std::string sums;
      for (int q = 0; q < p.J(); ++q) sums += (q ? " " : "") + dec(tr.sd[static_cast<size_t>(q)]);
      s += fmt::format("    IP step {}: sums [{}] eta {} -> tau {} lo md {} | hi md {} ovf {}\n",
                       k, sums, tr.eta, st.tau, dec(st.lo.md), dec(st.hi.md), ovf.flag ? 1 : 0);
    }
    const ref::TestPoint tp = ref::test_point_unit(p, sd, si, st.tau, ovf);
    s += fmt::format("    test point: t {} X {}\n", dec(tp.t), vec(tp.X));
    const ref::CaptureOut c = ref::capture_unit(p, m.camera, ray, tp.X, tp.t);
    s += fmt::format("    capture: signs L{} R{} T{} B{} t_in_range {} hit {} depth {}\n",
                     c.signs[0] ? 1 : 0, c.signs[1] ? 1 : 0, c.signs[2] ? 1 : 0,
                     c.signs[3] ? 1 : 0, c.t_in_range ? 1 : 0, c.hit ? 1 : 0, dec(c.depth));
    return s;
  }
  const ref::SegmentDesc& sd = m.texture_segments[item.seg - ncurve];
  const ref::PlanePoint pp = ref::ray_plane_unit(p, m.camera, ray.vhat);
  s += fmt::format("    ray/plane: valid {} p0 {} depth {}\n", pp.valid ? 1 : 0, vec(pp.p0),
                   dec(pp.depth));
  if (!pp.valid) return s + "    (the ray misses the plane: the texture unit's result is zero)\n";
  ref::Overflow ovf;
  const ref::TextureOut t = ref::texture_unit(p, sd, pp.p0, ovf);
  s += fmt::format("    texture: pr1 {} pr2 {} pr3 {} covers {} t {} X {} ovf {}\n",
                   t.pr1 ? 1 : 0, t.pr2 ? 1 : 0, t.pr3 ? 1 : 0, t.covers ? 1 : 0, dec(t.t),
                   vec(t.X), ovf.flag ? 1 : 0);
  return s;
}

}  // namespace rpu::sim
