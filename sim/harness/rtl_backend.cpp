#include "rtl_backend.h"

#include <spawn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

#include <fmt/format.h>

#include "common/error.h"
#include "common/output_file.h"
#include "stream_file.h"
#include "top_ports.h"

extern char** environ;

namespace {
// The fault the fault-injected build's RTL reads at time zero (RtlOptions::fault).
int g_rtl_fault = 0;
}  // namespace

// DPI import of rtl/curve/rpu_ip_step.v and rtl/top/rpu_resolve.v in the RPU_FAULT build.
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

StreamRecord run_systemc(const FrameSchedule& f, const RtlOptions& o, std::string* config) {
  if (f.params != systemc_params() || o.fault)
    throw Error("--systemc", "the SystemC model is built for " + describe(systemc_params()) +
                             " only (add --ip iterative at the default widths)");
  const std::string exe = o.sc_exe.empty() ? (self_dir() / "rpu_sc").string() : o.sc_exe;
  if (!std::filesystem::exists(exe))
    throw Error("--systemc", "the SystemC harness " + exe + " is not built (configure with "
                "RPU_SIM=ON and SystemC installed)");
  *config = "systemc:" + describe(f.params);
  return run_external(exe, f, o);
}

}  // namespace

std::string describe_rtl_configs() {
  std::string s;
  for (const RtlConfig& c : rtl_configs())
    s += fmt::format("  {}{}{}: {}\n", c.name, c.fault ? " (fault-injected, tests only)" : "",
                     c.traceable ? " (FST-traceable)" : "", describe(c.params));
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
  const FrameSchedule f = schedule_frame(sc, m, o.ref);
  Scoreboard sb(f, m, o.max_reports);
  RtlRender out;
  const RtlConfig* cfg = nullptr;
  for (const RtlConfig& c : rtl_configs())
    if (c.fault == (o.fault != 0) && c.params == m.params) cfg = &c;
  if (o.systemc || !o.external_exe.empty()) {
    out.harness = o.systemc ? "systemc" : "c++ (external)";
    StreamRecord r;
    if (o.systemc) {
      r = run_systemc(f, o, &out.config);
    } else {
      r = run_external(o.external_exe, f, o);
      out.config = std::filesystem::path(o.external_exe).filename().string();
    }
    for (const ItemResult& x : r.results) sb.on_result(x);
    for (const PixelResult& x : r.pixels) sb.on_pixel(x);
    out.stats = r.stats;
    if (r.stats.timed_out) sb.note("TIMEOUT in the " + out.harness + " harness");
  } else {
    if (!cfg) {
      std::string names;
      for (const RtlConfig& c : rtl_configs())
        if (c.fault == (o.fault != 0)) names += (names.empty() ? "" : ", ") + c.name;
      throw Error("--backend rtl", fmt::format("no Verilated rpu_top{} for {} (this build has: "
                                               "{}; `rpu config` lists their parameters, "
                                               "sim/harness/CMakeLists.txt adds others)",
                                               o.fault ? " with an injected fault" : "",
                                               describe(m.params), names.empty() ? "none" : names));
    }
    out.harness = "c++";
    out.config = cfg->name;
    g_rtl_fault = o.fault;  // read by the RTL when the model is built
    auto top = cfg->make(o.x_seed);
    out.stats = cosim_frame(*top, f, sb, o.cosim);
  }
  out.frame = sb.frame();
  out.item_mismatches = sb.item_mismatches();
  out.pixel_mismatches = sb.pixel_mismatches();
  out.reports = sb.reports();
  out.first_bad = sb.first_bad_pixel();
  out.ok = sb.ok() && !out.stats.timed_out;
  if (o.trace_pixel) {
    if (!cfg || !cfg->traceable)
      throw Error("--trace-pixel", fmt::format("the configuration {} is not built with FST "
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
      auto top = cfg->make(o.x_seed);  // destroyed (the FST closed) at the end of this block
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
