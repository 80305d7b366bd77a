#include "sweep_yosys.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <fstream>
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

// The integer parameters the module's Verilog declares.
std::vector<std::string> module_parameters(const std::string& module) {
  const fs::path file = module_file(module);
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) throw Error(file.string(), "no such RTL module");
  const std::string text = read_input_file(file.string(), "RTL module");
  std::vector<std::string> names;
  const std::regex re("parameter\\s+integer\\s+([A-Za-z0-9_]+)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator();
       ++it)
    names.push_back((*it)[1]);
  return names;
}

// A count from the report: a whole number, or null (empty, "timeout", too large for 64 bits).
json count(const std::map<std::string, std::string>& m, const char* column) {
  const auto it = m.find(column);
  if (it == m.end()) return nullptr;
  long long v = 0;
  const char* end = it->second.data() + it->second.size();
  const auto [ptr, ec] = std::from_chars(it->second.data(), end, v);
  // Whole numbers; a fraction ("12.5 s") is cut off as before.
  if (ec != std::errc() || (ptr != end && *ptr != '.') || v < 0) return nullptr;
  return v;
}

// BRAM36 may be fractional (a RAMB18 is half of one).
json fraction(const std::map<std::string, std::string>& m, const char* column) {
  const auto it = m.find(column);
  if (it == m.end() || it->second.empty() || !std::isdigit(static_cast<unsigned char>(it->second[0])))
    return nullptr;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(it->second.c_str(), &end);
  if (errno != 0 || *end != '\0' || !std::isfinite(v)) return nullptr;
  return v;
}

}  // namespace

std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> f;
  std::string cur;
  bool quoted = false;
  for (size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (quoted) {
      if (c != '"') cur += c;
      else if (k + 1 < line.size() && line[k + 1] == '"') cur += line[++k];  // "" → "
      else quoted = false;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      f.push_back(cur);
      cur.clear();
    } else if (c != '\r') {
      cur += c;
    }
  }
  f.push_back(cur);
  return f;
}

YosysRunner::YosysRunner(const SweepSpec& spec, fs::path cache_dir)
    : spec_(spec), cache_(std::move(cache_dir)), declared_(module_parameters(spec.yosys_module)) {}

void YosysRunner::measure(const SweepConfig& c, json& row) {
  const std::string& module = spec_.yosys_module;
  row["yosys_module"] = module;
  std::vector<std::string> overrides;
  std::string key = module;
  for (const ref::HwParamInfo& d : ref::hw_param_table()) {
    if (d.verilog.empty() ||
        std::find(declared_.begin(), declared_.end(), d.verilog) == declared_.end())
      continue;
    const std::string value = verilog_value(d, c.params);
    overrides.push_back(fmt::format("{}:{}={}", module, d.verilog, value));
    key += fmt::format(" {}={}", d.verilog, value);
  }
  const fs::path dir = cache_ / (module + "-" + hash_hex(key));
  const fs::path csv = dir / "row.csv";
  std::mutex* mu;
  {
    std::lock_guard<std::mutex> lock(table_mu_);
    mu = &key_mu_[dir.string()];
  }
  std::lock_guard<std::mutex> key_lock(*mu);
  row["yosys_cache"] = fs::relative(dir, cache_.parent_path()).string();
  std::error_code ec;
  if (!fs::exists(csv, ec)) {
    fs::create_directories(dir, ec);
    if (ec) throw Error(dir.string(), "cannot create the Yosys cache directory: " + ec.message());
    const fs::path tmp = dir / "row.tmp";
    fs::remove(tmp, ec);
    std::vector<std::string> argv = {
        (fs::path(RPU_SOURCE_DIR) / "scripts" / "yosys_report.sh").string(), "-t",
        std::to_string(spec_.yosys_timeout), "-c", tmp.string()};
    for (const std::string& g : overrides) {
      argv.push_back("-G");
      argv.push_back(g);
    }
    argv.push_back(module);
    const int rc = run_child(argv, {(dir / "table.md").string(), (dir / "log.txt").string()});
    if (rc != 0 && !fs::exists(tmp, ec))
      throw Error("yosys", fmt::format("{} failed (status {}), see {}", module, rc,
                                       (dir / "log.txt").string()));
    fs::rename(tmp, csv, ec);
    if (ec) throw Error(csv.string(), "cannot store the Yosys report: " + ec.message());
  } else {
    row["yosys_cached"] = true;
  }
  std::ifstream in(csv);
  std::string header, line;
  std::getline(in, header);
  std::getline(in, line);
  const auto h = csv_fields(header);
  const auto f = csv_fields(line);
  std::map<std::string, std::string> m;
  for (size_t k = 0; k < h.size() && k < f.size(); ++k) m[h[k]] = f[k];
  row["lut"] = count(m, "LUT");
  row["ff"] = count(m, "FF");
  row["dsp"] = count(m, "DSP48E1");
  row["carry4"] = count(m, "CARRY4");
  row["bram"] = fraction(m, "BRAM36");
  row["longest_path_levels"] = count(m, "Longest path (levels)");
  row["yosys_seconds"] = count(m, "Yosys s");
  row["yosys_status"] = row["lut"].is_null() ? (m.count("LUT") && !m["LUT"].empty() ? m["LUT"] : "failed")
                                             : "ok";
  if (spec_.scale_ip_candidates && row["yosys_status"] == "ok") {
    const int J = 1 << c.params.n1, K = c.params.n / c.params.n1;
    const int evaluators = c.params.unrolled ? K * (J - 1) + 2 : J + 1;
    for (const char* k : {"lut", "ff", "dsp", "carry4", "bram"}) {
      row[std::string("module_") + k] = row[k];
      if (!row[k].is_null()) row[k] = row[k].get<double>() * evaluators;
    }
    row["yosys_basis"] = fmt::format("{} x {} candidate evaluators", module, evaluators);
  } else {
    row["yosys_basis"] = module;
  }
}

}  // namespace rpu::app
