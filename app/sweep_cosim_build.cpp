#include "sweep_cosim_build.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>

#include <fmt/format.h>

#include "common/error.h"
#include "sweep_process.h"
#if RPU_HAVE_RTL
#include "rtl_backend.h"
#include "stream_file.h"
#include "top_ports.h"
#endif

namespace rpu::app {

namespace fs = std::filesystem;

#if RPU_HAVE_RTL
namespace {

// The executable of a configuration; the job-file format is part of its name, so that
// executables built by an earlier rpu that wrote another format are not reused.
std::string cosim_name(const SweepConfig& c) {
  return fmt::format("c{}_j{}", c.id, sim::kJobFileVersion);
}

// "N=16,N1=2,..." for RPU_COSIM_CONFIGS: every parameter of the table that has a Verilog name
// (sim/harness/CMakeLists.txt passes rpu_top those it declares).
std::string verilog_params(const SweepConfig& c) {
  std::string out;
  for (const ref::HwParamInfo& d : ref::hw_param_table())
    if (!d.verilog.empty())
      out += fmt::format("{}{}={}", out.empty() ? "" : ",", d.verilog, verilog_value(d, c.params));
  return out;
}

// An exclusive lock on a file, held until destroyed. Concurrent `rpu sweep --config` jobs (a
// Slurm array, GNU parallel over hosts) share DIR/rtl_build: without it two of them would run
// CMake and Ninja in one build tree at once. fcntl's record locks rather than flock: NFS takes
// them to the server, so they hold across hosts (flock's are local to one host on some
// systems). A record lock belongs to this process, not the descriptor; the descriptor is
// close-on-exec, so CMake and Ninja do not hold it open after rpu.
class BuildLock {
 public:
  explicit BuildLock(const fs::path& file)
      : fd_(::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
    if (fd_ < 0)
      throw Error(file.string(), std::string("cannot open the build lock: ") +
                                     std::strerror(errno));
    struct flock whole {};
    whole.l_type = F_WRLCK;
    whole.l_whence = SEEK_SET;  // l_start = l_len = 0: the whole file
    int err = ::fcntl(fd_, F_SETLK, &whole) == 0 ? 0 : errno;
    if (err == EACCES || err == EAGAIN) {  // held: say why rpu waits (a build takes minutes)
      std::cerr << fmt::format("rpu sweep: waiting for another rpu sweep's co-simulation build "
                               "(lock {})\n", file.string());
      do {
        err = ::fcntl(fd_, F_SETLKW, &whole) == 0 ? 0 : errno;
      } while (err == EINTR);
    }
    if (err != 0) {
      ::close(fd_);
      throw Error(file.string(),
                  std::string("cannot lock the build directory: ") + std::strerror(err));
    }
  }
  ~BuildLock() { ::close(fd_); }
  BuildLock(const BuildLock&) = delete;
  BuildLock& operator=(const BuildLock&) = delete;

 private:
  int fd_;
};

}  // namespace
#endif

bool has_builtin_rtl(const ref::HwParams& p) {
#if RPU_HAVE_RTL
  for (const auto& rc : sim::rtl_configs())
    if (!rc.fault && !rc.axi && rc.params == p) return true;
#else
  (void)p;
#endif
  return false;
}

std::map<std::string, std::string> build_cosim(const std::vector<const SweepConfig*>& todo,
                                               const fs::path& out_dir, int jobs) {
  std::map<std::string, std::string> exes;
#if RPU_HAVE_RTL
  const fs::path dir = out_dir / "rtl_build";
  std::string list;
  std::vector<const SweepConfig*> external;  // valid, without a built-in model
  for (const SweepConfig* c : todo) {
    try {
      c->params.validate();
    } catch (const Error&) {
      continue;
    }
    if (has_builtin_rtl(c->params)) continue;
    external.push_back(c);
    if (!list.empty()) list += ';';
    list += cosim_name(*c);
    list += ':';
    list += verilog_params(*c);
  }
  if (external.empty()) return exes;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw Error(dir.string(), "cannot create the build directory: " + ec.message());
  // What is missing is counted, built and looked up only under the lock: an executable another
  // job built while this one waited is not built again, and one still being linked is not taken.
  const BuildLock lock(dir / ".lock");
  size_t need = 0;
  for (const SweepConfig* c : external)
    if (!fs::exists(dir / ("cosim_" + cosim_name(*c)), ec)) ++need;
  if (need > 0) {
    const fs::path log = dir / "build.log";
    std::cerr << fmt::format("rpu sweep: Verilating {} configurations into {} (log: {})\n", need,
                             dir.string(), log.string());
    int rc = run_child({"cmake", "-S", RPU_SOURCE_DIR, "-B", dir.string(), "-G", "Ninja",
                        "-DRPU_COSIM_ONLY=ON", "-DRPU_COSIM_CONFIGS=" + list},
                       {log.string(), log.string(), false});
    if (rc == 0)
      rc = run_child({"ninja", "-C", dir.string(), "-k", "0", "-j", std::to_string(std::max(1, jobs))},
                     {log.string(), log.string(), true});
    if (rc != 0)
      std::cerr << "rpu sweep: some co-simulation builds failed; their rows say so (see the log)\n";
  }
  for (const SweepConfig* c : todo) {
    const fs::path exe = dir / ("cosim_" + cosim_name(*c));
    if (fs::exists(exe, ec)) exes[c->id] = exe.string();
  }
#else
  (void)todo;
  (void)out_dir;
  (void)jobs;
#endif
  return exes;
}

}  // namespace rpu::app
