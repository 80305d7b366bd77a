// cosim_<name>: the C++ harness of one Verilated configuration as a program of its own, built on
// demand by `rpu sweep` for configurations the rpu executable does not contain. Reads a job file
// (descriptors and work items, stream_file.h), runs it cycle by cycle, and writes every result
// and pixel record with the cycle counts; `rpu` checks them with the scoreboard, as for rpu_sc.
#include <cstdio>

#include "cosim.h"
#include "stream_file.h"
#include "top_ports.h"

namespace {

using namespace rpu::sim;

// Keeps every record; done when the job's pixel count has arrived.
class Recorder final : public ResultSink {
 public:
  Recorder(StreamRecord& r, std::size_t want_pixels) : r_(r), want_(want_pixels) {}
  void on_result(const ItemResult& a) override {
    r_.results.push_back(a);
    hits_ += a.hit;
  }
  void on_pixel(const PixelResult& a) override { r_.pixels.push_back(a); }
  bool done() const override { return r_.pixels.size() >= want_; }
  void note(const std::string& line) override { std::fprintf(stderr, "%s\n", line.c_str()); }
  std::size_t results() const override { return r_.results.size(); }
  std::size_t pixels() const override { return r_.pixels.size(); }
  std::size_t hits() const override { return hits_; }

 private:
  StreamRecord& r_;
  std::size_t want_, hits_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s JOB STREAMS (written and read by `rpu sweep`)\n", argv[0]);
    return 2;
  }
  try {
    const FrameSchedule f = read_job(argv[1]);
    const RtlConfig& cfg = rtl_configs().front();
    if (cfg.params != f.params) {
      std::fprintf(stderr, "%s: error: built for other parameters than the job's\n", argv[0]);
      return 1;
    }
    StreamRecord rec;
    Recorder sink(rec, f.expected_pixels.size());
    auto top = cfg.make(0);
    rec.stats = cosim_frame(*top, f, sink);
    write_streams(argv[2], rec);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: error: %s\n", argv[0], e.what());
    return 1;
  }
  return 0;
}
