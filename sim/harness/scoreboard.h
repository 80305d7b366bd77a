// The co-simulation's checker: every result record against the model's, in order (so a lost,
// duplicated or reordered item is caught by its id), and every pixel of the pixel stream
// against the model's resolve. Builds the RTL's frame from the pixel stream.
#pragma once

#include <string>
#include <vector>

#include "frame_schedule.h"
#include "image/frame.h"

namespace rpu::sim {

// What the cycle loop (cosim_frame) hands the results to: the checker, or a recorder.
class ResultSink {
 public:
  virtual ~ResultSink() = default;
  virtual void on_result(const ItemResult& actual) = 0;
  virtual void on_pixel(const PixelResult& actual) = 0;
  virtual bool done() const = 0;
  virtual void note(const std::string& line) = 0;
  virtual std::size_t results() const = 0;
  virtual std::size_t pixels() const = 0;
  virtual std::size_t hits() const = 0;
};

class Scoreboard final : public ResultSink {
 public:
  // max_reports: mismatches reported in full (the model's stages included); all are counted.
  Scoreboard(const FrameSchedule& f, const ref::ModelScene& m, int max_reports = 8);

  void on_result(const ItemResult& actual) override;
  void on_pixel(const PixelResult& actual) override;
  bool done() const override {
    return results_ == f_.items.size() && pixels_ == f_.expected_pixels.size();
  }
  bool ok() const { return item_mismatches_ == 0 && pixel_mismatches_ == 0 && done(); }

  std::size_t results() const override { return results_; }
  std::size_t pixels() const override { return pixels_; }
  std::size_t item_mismatches() const { return item_mismatches_; }
  std::size_t pixel_mismatches() const { return pixel_mismatches_; }
  std::size_t hits() const override { return hits_; }
  const std::vector<std::string>& reports() const { return reports_; }
  // The first mismatching pixel (-1, -1 if none): what --trace-pixel would take.
  std::pair<int, int> first_bad_pixel() const { return first_bad_; }
  void note(const std::string& line) override { reports_.push_back(line); }
  // The RTL's image: background where no pixel result arrived (pixels without work items).
  const image::Frame& frame() const { return frame_; }

 private:
  void report(std::string text, int i, int j);
  const FrameSchedule& f_;
  const ref::ModelScene& m_;
  int max_reports_;
  std::size_t results_ = 0, pixels_ = 0, item_mismatches_ = 0, pixel_mismatches_ = 0, hits_ = 0;
  std::vector<std::string> reports_;
  std::pair<int, int> first_bad_{-1, -1};
  image::Frame frame_;
};

}  // namespace rpu::sim
