#include "sweep_yosys.h"

#include <unistd.h>

#include <algorithm>
#include <regex>
#include <sstream>

#include <fmt/format.h>

#include "common/error.h"
#include "common/input_file.h"
#include "sweep_process.h"

namespace rpu::app {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The file of an RTL module: the entry of the RTL file list rtl/rpu.f named after it (one module
// per file, rtl/README.md).
fs::path module_file(const std::string& module) {
  const fs::path rtl = fs::path(RPU_SOURCE_DIR) / "rtl";
  const fs::path list = rtl / "rpu.f";
  std::istringstream in(read_input_file(list.string(), "RTL file list"));
  for (std::string line; std::getline(in, line);) {
    line = line.substr(0, line.find("//"));
    const size_t b = line.find_first_not_of(" \t\r"), e = line.find_last_not_of(" \t\r");
    if (b == std::string::npos || line[b] == '+' || line[b] == '-') continue;  // +incdir+
    const fs::path entry = line.substr(b, e - b + 1);
    if (entry.stem() == module && entry.extension() == ".v") return rtl / entry;
  }
  throw Error(list.string(), "no such RTL module: " + module);
}

// A header the module includes: the file of that name under rtl/ (rtl/rpu.f's include
// directories are rtl/'s subdirectories).
fs::path header_file(const std::string& name) {
  const fs::path rtl = fs::path(RPU_SOURCE_DIR) / "rtl";
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(rtl, ec); !ec && it != fs::end(it);
       it.increment(ec))
    if (it->path().filename() == name) return it->path();
  throw Error(rtl.string(), "no such RTL header: " + name);
}

// The integer parameters the module's Verilog declares, in its file or a header it includes
// (rpu_top's list is rtl/top/rpu_top_params.vh).
std::vector<std::string> module_parameters(const std::string& module) {
  const fs::path file = module_file(module);
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) throw Error(file.string(), "no such RTL module");
  std::string text = read_input_file(file.string(), "RTL module");
  const std::regex inc("`include\\s+\"([^\"]+)\"");
  std::string headers;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), inc); it != std::sregex_iterator();
       ++it)
    headers += read_input_file(header_file((*it)[1]).string(), "RTL header");
  text += headers;
  std::vector<std::string> names;
  const std::regex re("parameter\\s+integer\\s+([A-Za-z0-9_]+)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator();
       ++it)
    names.push_back((*it)[1]);
  return names;
}

}  // namespace

YosysRunner::YosysRunner(const SweepSpec& spec, fs::path cache_dir, int jobs)
    : spec_(spec),
      cache_(std::move(cache_dir)),
      jobs_(std::max(1, jobs)),
      declared_(module_parameters(spec.yosys_module)) {}

void YosysRunner::measure(const SweepConfig& c, json& row) {
  const std::string& module = spec_.yosys_module;
  row["yosys_module"] = module;
  row["yosys_basis"] = module;
  std::vector<std::string> argv = {
      (fs::path(RPU_SOURCE_DIR) / "scripts" / "synth_hier.py").string(), "-j",
      std::to_string(jobs_), "-t", std::to_string(spec_.yosys_timeout), "--cache",
      cache_.string()};
  std::string key = module;
  for (const ref::HwParamInfo& d : ref::hw_param_table()) {
    if (d.verilog.empty() ||
        std::find(declared_.begin(), declared_.end(), d.verilog) == declared_.end())
      continue;
    const std::string value = verilog_value(d, c.params);
    argv.push_back("-G");
    argv.push_back(fmt::format("{}={}", d.verilog, value));
    key += fmt::format(" {}={}", d.verilog, value);
  }
  // One report and log per parameter set of the module; configurations that share it run the
  // flow one after another (the second finds every derived module in the cache).
  const fs::path runs = cache_ / "runs";
  const fs::path base = runs / (module + "-" + hash_hex(key));
  std::mutex* mu;
  {
    std::lock_guard<std::mutex> lock(table_mu_);
    mu = &key_mu_[base.string()];
  }
  std::lock_guard<std::mutex> key_lock(*mu);
  std::error_code ec;
  fs::create_directories(runs, ec);
  if (ec) throw Error(runs.string(), "cannot create the Yosys cache directory: " + ec.message());
  const fs::path report = base.string() + ".json";
  const fs::path log = base.string() + ".log";
  // Another process (a job of the same sweep) may run the same parameter set: each writes its
  // own report and moves it into place.
  const fs::path tmp = fmt::format("{}.{}.tmp", report.string(), ::getpid());
  fs::remove(tmp, ec);
  argv.insert(argv.end(), {"--json", tmp.string(), module});
  row["yosys_log"] = fs::relative(log, cache_.parent_path()).string();
  const int rc = run_child(argv, {log.string(), log.string()});
  if (!fs::exists(tmp, ec))
    throw Error("yosys", fmt::format("{}: scripts/synth_hier.py failed (status {}), see {}",
                                     module, rc, log.string()));
  fs::rename(tmp, report, ec);
  if (ec) throw Error(report.string(), "cannot store the Yosys report: " + ec.message());
  const json r = json::parse(read_input_file(report.string(), "Yosys report"), nullptr, false);
  if (r.is_discarded() || !r.is_object() || !r.contains("status"))
    throw Error(report.string(), "not a report of scripts/synth_hier.py");
  row["yosys_derived_modules"] = r.value("derived_modules", 0);
  row["yosys_synthesised"] = r.value("synthesised", 0);
  row["yosys_seconds"] = r.value("wall_seconds", 0.0);
  if (r["status"] != "ok") {
    const std::string first = r.contains("failures") && !r["failures"].empty()
                                  ? r["failures"][0].get<std::string>()
                                  : std::string("no reason given");
    row["yosys_status"] = first.find(": timeout") != std::string::npos ? "timeout" : "failed";
    row["yosys_error"] = first;
    for (const char* k : {"lut_sites", "lut", "srl", "lutram", "ff", "dsp", "bram", "carry4",
                          "sta_ns"})
      row[k] = nullptr;
    return;
  }
  const json& t = r["totals"];
  row["yosys_status"] = "ok";
  row["lut_sites"] = t["lut_sites"];
  row["lut"] = t["lut"].get<long long>() + t["inv"].get<long long>();
  row["srl"] = t["srl"];
  row["lutram"] = t["lutram"];
  row["ff"] = t["ff"];
  row["dsp"] = t["dsp"];
  row["bram"] = t["bram36"];
  row["carry4"] = t["carry4"];
  row["sta_ns"] = r.contains("sta_ns") ? r["sta_ns"] : json(nullptr);
}

}  // namespace rpu::app
