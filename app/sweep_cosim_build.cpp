#include "sweep_cosim_build.h"

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

}  // namespace
#endif

bool has_builtin_rtl(const ref::HwParams& p) {
#if RPU_HAVE_RTL
  for (const auto& rc : sim::rtl_configs())
    if (!rc.fault && rc.params == p) return true;
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
  size_t need = 0;
  std::error_code ec;
  for (const SweepConfig* c : todo) {
    try {
      c->params.validate();
    } catch (const Error&) {
      continue;
    }
    if (has_builtin_rtl(c->params)) continue;
    if (!fs::exists(dir / ("cosim_" + cosim_name(*c)), ec)) ++need;
    if (!list.empty()) list += ';';
    list += cosim_name(*c);
    list += ':';
    list += verilog_params(*c);
  }
  if (need > 0) {
    const fs::path log = dir / "build.log";
    std::cerr << fmt::format("rpu sweep: Verilating {} configurations into {} (log: {})\n", need,
                             dir.string(), log.string());
    fs::create_directories(dir, ec);
    if (ec) throw Error(dir.string(), "cannot create the build directory: " + ec.message());
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
