#include "rtl_backend.h"

#include <spawn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <filesystem>
#include <thread>

#include <fmt/format.h>

#include "common/error.h"
#include "common/output_file.h"
#include "frame_share.h"
#include "stream_file.h"
#include "top_ports.h"

extern char** environ;

namespace {
// The fault the fault-injected build's RTL reads at time zero (RtlOptions::fault).
int g_rtl_fault = 0;
}  // namespace

// DPI import of the fault-injected build's copies of rpu_ip_step and rpu_resolve (rtl_fault.cmake).
extern "C" int rpu_fault() { return g_rtl_fault; }

namespace rpu::sim {

namespace {

// Every parameter of the table, "n 16 n1 2 ... surf_w 24 angle_w 20".
std::string describe(const ref::HwParams& p) { return p.summary(); }

std::filesystem::path self_dir() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::current_path() : exe.parent_path();
}

// Runs a harness executable (rpu_sc, or a sweep's cosim_<name>) on the schedule; returns its
// recorded streams.
StreamRecord run_external(const std::string& exe, const FrameSchedule& f, const RtlOptions& o) {
  std::error_code ec;
  const auto dir = std::filesystem::temp_directory_path(ec) /
                   fmt::format("rpu_sc_{}_{}", ::getpid(), reinterpret_cast<std::uintptr_t>(&f));
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error(dir.string(), "cannot create the co-simulation work directory");
  const std::string job = (dir / "job.bin").string(), out = (dir / "streams.bin").string();
  write_job(job, f);
  std::vector<std::string> args = {exe, job, out};
  if (o.fault) args.push_back("--fault");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, exe.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
    throw Error(exe, "cannot start the harness");
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::filesystem::remove_all(dir, ec);
    throw Error(exe, fmt::format("the harness failed (status {})",
                                 WIFEXITED(status) ? WEXITSTATUS(status) : -1));
  }
  StreamRecord r = read_streams(out);
  std::filesystem::remove_all(dir, ec);
  return r;
}

// The SystemC harness executable (rpu_sc, beside this program unless RtlOptions::sc_exe).
std::string systemc_exe(const RtlOptions& o) {
  const std::string exe = o.sc_exe.empty() ? (self_dir() / "rpu_sc").string() : o.sc_exe;
  if (!std::filesystem::exists(exe))
    throw Error("--systemc", "the SystemC harness " + exe + " is not built (configure with "
                "RPU_SIM=ON and SystemC installed)");
  return exe;
}

}  // namespace

std::string describe_rtl_configs() {
  std::string s;
  for (const RtlConfig& c : rtl_configs())
    s += fmt::format("  {}{}{}{}: {}\n", c.name, c.fault ? " (fault-injected, tests only)" : "",
                     c.traceable ? " (FST-traceable)" : "", c.axi ? " (in the AXI shell, --axi)" : "",
                     describe(c.params));
  return s.empty() ? "  (none: configure with RPU_SIM=ON)\n" : s;
}

RtlRender render_rtl(const scene::CompiledScene& sc, const ref::ModelScene& m,
                     const RtlOptions& o) {
  // Where the waveform goes is checked before the co-simulation, not after it.
  if (o.trace_pixel) {
    check_output_path(o.trace_path, "waveform");
    // Verilator's FST writer maps its temporary hierarchy file into memory: past a file-size
    // limit the process would die of SIGBUS instead of reporting a failed write.
    struct rlimit fsize {};
    if (::getrlimit(RLIMIT_FSIZE, &fsize) == 0 && fsize.rlim_cur != RLIM_INFINITY)
      throw Error("--trace-pixel",
                  fmt::format("waveforms need an unlimited file size, but it is limited to {} "
                              "bytes (ulimit -f): Verilator's FST writer maps its files into "
                              "memory and cannot report a write past the limit",
                              static_cast<unsigned long long>(fsize.rlim_cur)));
  }
  ref::require_built_kinds(m);
  const FrameSchedule f = schedule_frame(sc, m, o.ref);
  RtlRender out;
  // The frame runs on the configuration built for speed; --trace-pixel on the traceable one
  // (a separate build: trace code slows every cycle).
  const RtlConfig* cfg = nullptr;
  const RtlConfig* trace_cfg = nullptr;
  for (const RtlConfig& c : rtl_configs()) {
    if (c.fault != (o.fault != 0) || c.axi != o.axi || c.params != m.params) continue;
    if (!cfg || (cfg->traceable && !c.traceable)) cfg = &c;
    if (c.traceable && !trace_cfg) trace_cfg = &c;
  }
  const bool external = o.systemc || !o.external_exe.empty();
  if (external) {
    out.harness = o.systemc ? "systemc" : "c++ (external)";
    if (o.systemc) {
      if (f.params != systemc_params() || o.fault)
        throw Error("--systemc", "the SystemC model is built for " + describe(systemc_params()) +
                                 " only (add --ip iterative at the default widths)");
      out.config = "systemc:" + describe(f.params);
    } else {
      out.config = std::filesystem::path(o.external_exe).filename().string();
    }
  } else if (o.merge_shards.empty()) {
    if (!cfg) {
      std::string names;
      for (const RtlConfig& c : rtl_configs())
        if (c.fault == (o.fault != 0) && c.axi == o.axi)
          names += (names.empty() ? "" : ", ") + c.name;
      throw Error(o.axi ? "--axi" : "--backend rtl",
                  fmt::format("no Verilated rpu_top{} for {} (this build has: "
                                               "{}; `rpu config` lists their parameters, "
                                               "sim/harness/CMakeLists.txt adds others)",
                                               o.fault ? " with an injected fault"
                                               : o.axi ? " in its AXI shell" : "",
                                               describe(m.params), names.empty() ? "none" : names));
    }
    out.harness = "c++";
    out.config = cfg->name;
  }
  g_rtl_fault = o.fault;  // read by the RTL when a model is built

  // The shares: the whole frame split over --jobs instances, one share of --shard I/N, or the
  // shares of the shard files being merged.
  std::vector<FrameShare> shares;
  std::vector<ShardRecord> merged;
  if (!o.merge_shards.empty()) {
    const std::uint64_t digest = schedule_digest(f);
    for (const std::string& path : o.merge_shards) merged.push_back(read_shard(path));
    const int count = merged.front().share.count;
    const std::vector<FrameShare> want = split_frame(f, count);
    std::vector<int> seen(static_cast<std::size_t>(count), -1);
    for (std::size_t k = 0; k < merged.size(); ++k) {
      const ShardRecord& r = merged[k];
      const std::string& path = o.merge_shards[k];
      if (r.digest != digest)
        throw Error(path, "is a shard of another frame (another scene, size or hardware "
                          "parameters than this command's)");
      if (r.share.count != count)
        throw Error(path, fmt::format("is share {} of {}, but {} is a share of {}", r.share.index,
                                      r.share.count, o.merge_shards.front(), count));
      const FrameShare& w = want[static_cast<std::size_t>(r.share.index)];
      if (r.share.index < 0 || r.share.index >= count || r.share.first_item != w.first_item ||
          r.share.end_item != w.end_item || r.share.first_pixel != w.first_pixel ||
          r.share.end_pixel != w.end_pixel)
        throw Error(path, "holds a share this frame does not cut (a corrupt or foreign shard)");
      int& prev = seen[static_cast<std::size_t>(r.share.index)];
      if (prev >= 0)
        throw Error(path, fmt::format("repeats share {} of {} (also in {})", r.share.index, count,
                                      o.merge_shards[static_cast<std::size_t>(prev)]));
      prev = static_cast<int>(k);
    }
    std::string missing;
    for (int k = 0; k < count; ++k)
      if (seen[static_cast<std::size_t>(k)] < 0) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
    if (!missing.empty())
      throw Error("--merge-shards", fmt::format("{} {} of {} {} missing",
                                                missing.find(',') == std::string::npos ? "share" : "shares",
                                                missing, count,
                                                missing.find(',') == std::string::npos ? "is" : "are"));
    std::sort(merged.begin(), merged.end(),
              [](const ShardRecord& a, const ShardRecord& b) { return a.share.index < b.share.index; });
    for (const ShardRecord& r : merged) shares.push_back(r.share);
    out.harness = "shards";
    out.config = merged.front().config;
  } else if (o.shard) {
    const auto [index, count] = *o.shard;
    if (count < 1 || index < 0 || index >= count)
      throw Error("--shard", fmt::format("must be I/N with 0 <= I < N, got {}/{}", index, count));
    shares.push_back(split_frame(f, count)[static_cast<std::size_t>(index)]);
  } else {
    const int jobs = std::max(1, std::min<int>(o.jobs, static_cast<int>(std::max<std::size_t>(
                                                           1, f.expected_pixels.size()))));
    shares = split_frame(f, jobs);
  }

  // Each share as a frame of its own, checked by its own scoreboard.
  struct Run {
    FrameSchedule f;
    std::unique_ptr<Scoreboard> sb;
    CosimStats stats;
    StreamRecord rec;  // --shard: what is written
    std::exception_ptr error;
  };
  std::vector<Run> runs(shares.size());
  for (std::size_t k = 0; k < shares.size(); ++k) {
    runs[k].f = share_schedule(f, shares[k]);
    runs[k].sb = std::make_unique<Scoreboard>(runs[k].f, m, o.max_reports);
  }
  // Records every stream word and forwards it to the share's scoreboard (--shard).
  class Tee final : public ResultSink {
   public:
    Tee(Scoreboard& sb, StreamRecord& r) : sb_(sb), r_(r) {}
    void on_result(const ItemResult& a) override { r_.results.push_back(a); sb_.on_result(a); }
    void on_pixel(const PixelResult& a) override { r_.pixels.push_back(a); sb_.on_pixel(a); }
    bool done() const override { return sb_.done(); }
    void note(const std::string& line) override { sb_.note(line); }
    std::size_t results() const override { return sb_.results(); }
    std::size_t pixels() const override { return sb_.pixels(); }
    std::size_t hits() const override { return sb_.hits(); }

   private:
    Scoreboard& sb_;
    StreamRecord& r_;
  };
  const auto run_one = [&](Run& run) {
    try {
      if (!merged.empty()) {
        const ShardRecord& r = merged[static_cast<std::size_t>(&run - runs.data())];
        for (const ItemResult& x : r.streams.results) run.sb->on_result(x);
        for (const PixelResult& x : r.streams.pixels) run.sb->on_pixel(x);
        run.stats = r.streams.stats;
      } else if (external) {
        StreamRecord r = run_external(o.systemc ? systemc_exe(o) : o.external_exe, run.f, o);
        for (const ItemResult& x : r.results) run.sb->on_result(x);
        for (const PixelResult& x : r.pixels) run.sb->on_pixel(x);
        run.stats = r.stats;
        if (o.shard) run.rec = std::move(r);
      } else {
        auto top = cfg->make(o.x_seed);
        Tee tee(*run.sb, run.rec);
        ResultSink& sink = o.shard ? static_cast<ResultSink&>(tee) : *run.sb;
        run.stats = cosim_frame(*top, run.f, sink, o.cosim);
      }
      if (run.stats.timed_out) run.sb->note("TIMEOUT in the " + out.harness + " harness");
    } catch (...) {
      run.error = std::current_exception();
    }
  };
  const auto t0 = std::chrono::steady_clock::now();
  if (runs.size() == 1) {
    run_one(runs[0]);
  } else {
    std::vector<std::thread> pool;
    for (Run& run : runs) pool.emplace_back(run_one, std::ref(run));
    for (std::thread& t : pool) t.join();
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const Run& run : runs)
    if (run.error) std::rethrow_exception(run.error);

  // The frame from every share's pixels; the statistics summed over the instances (the frame's
  // own duration on N units is the longest instance: frame_cycles).
  out.frame = image::Frame(f.width, f.height);
  CosimStats& st = out.stats;
  bool ok = true;
  for (const Run& run : runs) {
    const image::Frame& part = run.sb->frame();
    for (std::size_t k = 0; k < part.primitive.size(); ++k)
      if (part.primitive[k] != image::kBackground) {
        out.frame.primitive[k] = part.primitive[k];
        out.frame.depth[k] = part.depth[k];
      }
    const CosimStats& s = run.stats;
    out.instances.push_back(s);
    st.cycles += s.cycles;
    st.load_cycles += s.load_cycles;
    st.items += s.items;
    st.curve_items += s.curve_items;
    st.texture_items += s.texture_items;
    st.surface_items += s.surface_items;
    st.pixels += s.pixels;
    st.hits += s.hits;
    st.stall_cycles += s.stall_cycles;
    st.latency_cycles = std::max(st.latency_cycles, s.latency_cycles);
    st.timed_out = st.timed_out || s.timed_out;
    out.frame_cycles = std::max(out.frame_cycles, s.cycles);
    out.item_mismatches += run.sb->item_mismatches();
    out.pixel_mismatches += run.sb->pixel_mismatches();
    for (const std::string& r : run.sb->reports())
      if (static_cast<int>(out.reports.size()) < o.max_reports) out.reports.push_back(r);
    if (out.first_bad.first < 0) out.first_bad = run.sb->first_bad_pixel();
    ok = ok && run.sb->ok() && !s.timed_out;
  }
  // Merged shards ran on other processes or machines: their own longest cycle loop.
  st.sim_seconds = wall;
  if (!merged.empty()) {
    st.sim_seconds = 0;
    for (const Run& run : runs) st.sim_seconds = std::max(st.sim_seconds, run.stats.sim_seconds);
  }
  out.ok = ok;
  if (o.shard) {
    ShardRecord r;
    r.digest = schedule_digest(f);
    r.share = shares.front();
    r.config = out.config;
    r.streams = std::move(runs.front().rec);
    r.streams.stats = runs.front().stats;
    write_shard(o.shard_out, r);
  }
  if (o.trace_pixel) {
    if (!trace_cfg)
      throw Error("--trace-pixel", fmt::format("no configuration for {} is built with FST "
                                               "tracing (traceable ones: see `rpu config`)",
                                               cfg ? cfg->name : describe(m.params)));
    const auto [ti, tj] = *o.trace_pixel;
    if (ti < 0 || tj < 0 || ti >= f.width || tj >= f.height)
      throw Error("--trace-pixel", fmt::format("pixel ({},{}) is outside the {}x{} image", ti, tj,
                                               f.width, f.height));
    // The waveform goes to a temporary beside --trace-out and is renamed over it only when it
    // was written: the FST writer reports no errors, so the file must exist and hold something.
    const std::string tmp = temporary_path_beside(o.trace_path);
    bool traced = false;
    {
      auto top = trace_cfg->make(o.x_seed);  // destroyed (the FST closed) at the end of this block
      traced = trace_pixel(*top, f, m, ti, tj, tmp, &out.trace_log);
    }
    struct stat st {};
    const bool written = ::stat(tmp.c_str(), &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0;
    if (!traced) {
      ::unlink(tmp.c_str());
      out.trace_log = fmt::format("pixel ({},{}) has no work items (background by schedule); no "
                                  "waveform written\n", ti, tj);
    } else if (!written) {
      ::unlink(tmp.c_str());
      throw Error(o.trace_path, "the waveform (--trace-out) could not be written (full disk or "
                                "file-size limit?)");
    } else {
      commit_temporary(tmp, o.trace_path);
      // The log names the file the user asked for, not the temporary.
      for (size_t at; (at = out.trace_log.find(tmp)) != std::string::npos;)
        out.trace_log.replace(at, tmp.size(), o.trace_path);
    }
  }
  return out;
}

}  // namespace rpu::sim
