#include "scoreboard.h"

#include <fmt/format.h>

namespace rpu::sim {

namespace {
std::string dec(i128 v) { return fixed::to_decimal(v); }
}  // namespace

Scoreboard::Scoreboard(const FrameSchedule& f, const ref::ModelScene& m, int max_reports)
    : f_(f), m_(m), max_reports_(max_reports), frame_(f.width, f.height) {}

void Scoreboard::report(std::string text, int i, int j) {
  if (first_bad_.first < 0) first_bad_ = {i, j};
  if (static_cast<int>(reports_.size()) < max_reports_) reports_.push_back(std::move(text));
}

void Scoreboard::on_result(const ItemResult& a) {
  if (results_ >= f_.items.size()) {
    ++item_mismatches_;
    report(fmt::format("MISMATCH: result after the last item: {}", a.describe()), a.i, a.j);
    return;
  }
  const ItemResult& e = f_.expected[results_];
  const WorkItem& item = f_.items[results_];
  ++results_;
  hits_ += a.hit;
  if (a == e) return;
  ++item_mismatches_;
  if (a.id != e.id) {
    report(fmt::format("MISMATCH: result id {} where item {} was due (lost, duplicated or "
                       "reordered)\n  expected {}\n  actual   {}", a.id, e.id, e.describe(),
                       a.describe()), e.i, e.j);
    return;
  }
  report(fmt::format("MISMATCH: pixel ({},{}) work item {} ({} {} {}, primitive {})\n"
                     "  expected {}\n  actual   {}\n  model stages:\n{}",
                     e.i, e.j, e.id, item.kind(), item.surface ? "at" : "segment", e.seg,
                     e.primitive,
                     e.describe(), a.describe(), explain_item(m_, item)),
         e.i, e.j);
}

void Scoreboard::on_pixel(const PixelResult& a) {
  if (a.i >= 0 && a.i < frame_.width && a.j >= 0 && a.j < frame_.height) {
    const size_t idx = frame_.index(a.i, a.j);
    frame_.primitive[idx] = a.hit ? static_cast<std::int32_t>(a.primitive) : image::kBackground;
    frame_.depth[idx] = a.hit ? static_cast<double>(a.depth) : 0.0;
  }
  if (pixels_ >= f_.expected_pixels.size()) {
    ++pixel_mismatches_;
    report(fmt::format("MISMATCH: pixel result ({},{}) after the last pixel", a.i, a.j), a.i,
           a.j);
    return;
  }
  const PixelResult& e = f_.expected_pixels[pixels_++];
  if (a.i == e.i && a.j == e.j && a.hit == e.hit && a.depth == e.depth &&
      a.primitive == e.primitive)
    return;
  ++pixel_mismatches_;
  report(fmt::format("MISMATCH: pixel ({},{}) resolve\n  expected pixel ({},{}) hit {} depth {} "
                     "primitive {}\n  actual   pixel ({},{}) hit {} depth {} primitive {}",
                     e.i, e.j, e.i, e.j, e.hit ? 1 : 0, dec(e.depth), e.primitive, a.i, a.j,
                     a.hit ? 1 : 0, dec(a.depth), a.primitive),
         e.i, e.j);
}

}  // namespace rpu::sim
