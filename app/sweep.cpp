#include "sweep.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <regex>
#include <sstream>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "backends.h"
#include "demo.h"
#include "report_text.h"
#include "model/descriptors.h"
#include "model/ref_renderer.h"
#include "scene/compiled_scene.h"
#include "sweep_report.h"
#include "tracer/float_tracer.h"
#if RPU_HAVE_RTL
#include "rtl_backend.h"
#include "top_ports.h"
#endif

namespace rpu::app {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The hardware parameters a grid may name, in canonical order, with their Verilog names.
struct ParamName {
  const char* key;
  const char* verilog;
};
constexpr ParamName kParams[] = {
    {"n", "N"},           {"n1", "N1"},           {"coord_w", "CoordW"},  {"dir_frac", "DirFrac"},
    {"t_frac", "TFrac"},  {"unit_frac", "UnitFrac"}, {"edge_frac", "EdgeFrac"}, {"inv_w", "InvW"},
    {"sqrt_w", "SqrtW"},  {"metric", "Metric"},     {"ip", "Unrolled"}};

// A parameter's Verilog value: integers as they are, metric abs/squared 0/1, ip unrolled 1.
std::string verilog_value(const ParamName& pn, const json& params) {
  const json& v = params[pn.key];
  if (!v.is_string()) return v.dump();
  if (pn.key == std::string("ip")) return v == "unrolled" ? "1" : "0";
  return v == "abs" ? "0" : "1";
}

// Sets one parameter from a JSON value; `where` names it for errors.
void set_param(ref::HwParams& p, const std::string& key, const json& v, const std::string& where) {
  if (key == "metric" || key == "ip") {
    if (!v.is_string()) throw Error(where, "must be a string");
    const std::string s = v.get<std::string>();
    if (key == "metric") {
      if (s != "abs" && s != "squared") throw Error(where, "must be abs or squared");
      p.metric = s == "abs" ? ref::Metric::kAbs : ref::Metric::kSquared;
    } else {
      if (s != "unrolled" && s != "iterative") throw Error(where, "must be unrolled or iterative");
      p.unrolled = s == "unrolled";
    }
    return;
  }
  if (!v.is_number_integer()) throw Error(where, "must be an integer");
  const int x = v.get<int>();
  int* field = key == "n"           ? &p.n
               : key == "n1"        ? &p.n1
               : key == "coord_w"   ? &p.coord_w
               : key == "dir_frac"  ? &p.dir_frac
               : key == "t_frac"    ? &p.t_frac
               : key == "unit_frac" ? &p.unit_frac
               : key == "edge_frac" ? &p.edge_frac
               : key == "inv_w"     ? &p.inv_w
               : key == "sqrt_w"    ? &p.sqrt_w
                                    : nullptr;
  if (!field) throw Error(where, "unknown hardware parameter");
  *field = x;
}

std::string hash_hex(const std::string& s) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a 64
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return fmt::format("{:016x}", h);
}

struct Spec {
  std::string path;
  std::vector<std::string> scenes;
  int width = 64, height = 64;
  std::vector<std::pair<std::string, std::vector<json>>> grid;  // in file order
  ref::HwParams base;
  bool rtl = true;
  int rtl_width = 32, rtl_height = 32;
  // Verilate configurations the rpu executable does not contain (RPU_COSIM_ONLY build under
  // DIR/rtl_build, one cosim_<id> per configuration, kept across runs).
  bool rtl_build = false;
  bool yosys = false;
  std::string yosys_module = "rpu_ip_step";
  int yosys_timeout = 3600;
  // "scale": "ip_candidates" — the module is rpu_candidate and the row's resources are its
  // counts times the candidate evaluators of the configuration's K-step process
  // (K·(2^n1 − 1) + 2 unrolled, 2^n1 + 1 iterative): the dominant cost, synthesised once per
  // width set instead of the whole IP (hours per configuration).
  bool scale_ip_candidates = false;
  std::string fingerprint;  // what a stored result must match to be reused
};

std::pair<int, int> read_size(const json& v, const std::string& where) {
  if (!v.is_array() || v.size() != 2 || !v[0].is_number_integer() || !v[1].is_number_integer() ||
      v[0].get<int>() < 1 || v[1].get<int>() < 1 || v[0].get<int>() > 16384 ||
      v[1].get<int>() > 16384)
    throw Error(where, "must be [width, height] with 1..16384 each");
  return {v[0].get<int>(), v[1].get<int>()};
}

Spec parse_spec(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path, "cannot open the sweep file");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::parse_error& e) {
    throw Error(path, std::string("not valid JSON: ") + e.what());
  }
  Spec s;
  s.path = path;
  if (!j.is_object()) throw Error(path, "must be a JSON object");
  for (const auto& [k, v] : j.items())
    if (k != "scenes" && k != "resolution" && k != "grid" && k != "base" && k != "rtl" &&
        k != "yosys" && k != "description")
      throw Error(path + ": " + k, "unknown key (scenes, resolution, grid, base, rtl, yosys, "
                                   "description)");
  if (!j.contains("scenes") || !j["scenes"].is_array() || j["scenes"].empty())
    throw Error(path + ": scenes", "must be a non-empty array of scene files or builtin:NAME");
  for (size_t k = 0; k < j["scenes"].size(); ++k) {
    if (!j["scenes"][k].is_string())
      throw Error(fmt::format("{}: scenes[{}]", path, k), "must be a string");
    std::string sc = j["scenes"][k].get<std::string>();
    // Relative scene files are relative to the sweep file.
    if (!sc.starts_with("builtin:") && fs::path(sc).is_relative() && !fs::exists(sc))
      sc = (fs::path(path).parent_path() / sc).string();
    s.scenes.push_back(sc);
  }
  if (j.contains("resolution"))
    std::tie(s.width, s.height) = read_size(j["resolution"], path + ": resolution");
  if (j.contains("base")) {
    if (!j["base"].is_object()) throw Error(path + ": base", "must be an object");
    for (const auto& [k, v] : j["base"].items()) set_param(s.base, k, v, path + ": base." + k);
  }
  if (!j.contains("grid") || !j["grid"].is_object() || j["grid"].empty())
    throw Error(path + ": grid", "must be an object of parameter lists, e.g. {\"n\": [8, 16]}");
  for (const auto& [k, v] : j["grid"].items()) {
    bool known = false;
    for (const auto& pn : kParams) known |= k == pn.key;
    if (!known)
      throw Error(path + ": grid." + k, "unknown hardware parameter (n, n1, coord_w, dir_frac, "
                                        "t_frac, unit_frac, edge_frac, inv_w, sqrt_w, metric, ip)");
    std::vector<json> values = v.is_array() ? v.get<std::vector<json>>() : std::vector<json>{v};
    if (values.empty()) throw Error(path + ": grid." + k, "must not be empty");
    for (size_t q = 0; q < values.size(); ++q) {
      ref::HwParams probe;
      set_param(probe, k, values[q], fmt::format("{}: grid.{}[{}]", path, k, q));
    }
    s.grid.emplace_back(k, values);
  }
  if (j.contains("rtl")) {
    const json& r = j["rtl"];
    if (r.is_boolean()) s.rtl = r.get<bool>();
    else if (r.is_object()) {
      s.rtl = r.value("enabled", true);
      s.rtl_build = r.value("build", false);
      if (r.contains("resolution"))
        std::tie(s.rtl_width, s.rtl_height) = read_size(r["resolution"], path + ": rtl.resolution");
    } else throw Error(path + ": rtl", "must be true, false or {enabled, resolution, build}");
  }
  if (j.contains("yosys")) {
    const json& y = j["yosys"];
    if (y.is_boolean()) s.yosys = y.get<bool>();
    else if (y.is_object()) {
      s.yosys = y.value("enabled", true);
      s.yosys_module = y.value("module", s.yosys_module);
      s.yosys_timeout = y.value("timeout", s.yosys_timeout);
      const std::string scale = y.value("scale", "");
      if (!scale.empty() && scale != "ip_candidates")
        throw Error(path + ": yosys.scale", "must be \"ip_candidates\" or absent");
      s.scale_ip_candidates = scale == "ip_candidates";
      if (s.scale_ip_candidates && s.yosys_module != "rpu_candidate")
        throw Error(path + ": yosys.scale", "ip_candidates needs module rpu_candidate");
      if (!std::regex_match(s.yosys_module, std::regex("rpu_[a-z0-9_]+")))
        throw Error(path + ": yosys.module", "must name an rtl/ module (rpu_...)");
    } else throw Error(path + ": yosys", "must be true, false or {enabled, module, timeout}");
  }
  return s;
}

// What a stored result must match to be reused: the scenes, resolutions and measurements.
std::string fingerprint(const Spec& s) {
  return hash_hex(json({{"scenes", s.scenes}, {"w", s.width}, {"h", s.height}, {"rtl", s.rtl},
                        {"rw", s.rtl_width}, {"rh", s.rtl_height}, {"yosys", s.yosys},
                        {"ym", s.yosys_module}, {"scale", s.scale_ip_candidates},
                        {"rb", s.rtl_build}}).dump());
}

struct Config {
  std::string id;
  ref::HwParams params;
  json params_json;
};

std::vector<Config> expand(const Spec& s) {
  std::vector<Config> out;
  std::vector<size_t> idx(s.grid.size(), 0);
  for (;;) {
    Config c;
    c.params = s.base;
    for (size_t k = 0; k < s.grid.size(); ++k)
      set_param(c.params, s.grid[k].first, s.grid[k].second[idx[k]], s.grid[k].first);
    c.params_json = hw_params_json(c.params);
    c.id = hash_hex(c.params_json.dump());
    out.push_back(c);
    size_t k = 0;
    while (k < idx.size() && ++idx[k] == s.grid[k].second.size()) idx[k++] = 0;
    if (k == idx.size()) break;
  }
  return out;
}

// ---- the per-scene float renders do not depend on the configuration (float) or only on n, n1
// (float-ip): shared between configurations ----
class FloatCache {
 public:
  const image::Frame& get(const scene::CompiledScene& sc, const std::string& key,
                          tracer::Method m, int n, int n1) {
    const std::string k = fmt::format("{}|{}|{}|{}", key, m == tracer::Method::kIdeal, n, n1);
    {
      std::lock_guard<std::mutex> lock(mu_);
      auto it = frames_.find(k);
      if (it != frames_.end()) return *it->second;
    }
    tracer::FloatOptions fo;
    fo.method = m;
    fo.n = m == tracer::Method::kIdeal ? 16 : n;
    fo.n1 = m == tracer::Method::kIdeal ? 2 : n1;
    fo.threads = 1;
    auto f = std::make_shared<image::Frame>(tracer::render_float(sc, fo));
    std::lock_guard<std::mutex> lock(mu_);
    auto [it, inserted] = frames_.emplace(k, f);
    return *it->second;
  }

 private:
  std::mutex mu_;
  std::map<std::string, std::shared_ptr<image::Frame>> frames_;
};

// ---- Yosys resources of one module at the configuration's parameters, cached by hash ----
std::vector<std::string> module_parameters(const std::string& module) {
  const fs::path file = fs::path(RPU_SOURCE_DIR) / "rtl" / (module + ".v");
  std::ifstream in(file);
  if (!in) throw Error(file.string(), "no such RTL module");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  std::vector<std::string> names;
  const std::regex re("parameter\\s+integer\\s+([A-Za-z0-9_]+)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator();
       ++it)
    names.push_back((*it)[1]);
  return names;
}

std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> f;
  std::string cur;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) {
      f.push_back(cur);
      cur.clear();
    } else cur += c;
  }
  f.push_back(cur);
  return f;
}

void yosys_resources(const Spec& s, const Config& c, const fs::path& cache, json& row) {
  row["yosys_module"] = s.yosys_module;
  const std::vector<std::string> declared = module_parameters(s.yosys_module);
  std::string gargs, key = s.yosys_module;
  for (const auto& pn : kParams) {
    if (std::find(declared.begin(), declared.end(), pn.verilog) == declared.end()) continue;
    const std::string value = verilog_value(pn, c.params_json);
    gargs += fmt::format(" -G {}:{}={}", s.yosys_module, pn.verilog, value);
    key += fmt::format(" {}={}", pn.verilog, value);
  }
  const fs::path dir = cache / (s.yosys_module + "-" + hash_hex(key));
  const fs::path csv = dir / "row.csv";
  // Configurations that share the module's parameters share one run: the first synthesises,
  // the others wait for it and read the cache.
  static std::mutex table_mu;
  static std::map<std::string, std::mutex> key_mu;
  std::mutex* mu;
  {
    std::lock_guard<std::mutex> lock(table_mu);
    mu = &key_mu[dir.string()];
  }
  std::lock_guard<std::mutex> key_lock(*mu);
  row["yosys_cache"] = fs::relative(dir, cache.parent_path()).string();
  if (!fs::exists(csv)) {
    fs::create_directories(dir);
    const std::string script = (fs::path(RPU_SOURCE_DIR) / "scripts" / "yosys_report.sh").string();
    const std::string cmd = fmt::format("'{}' -t {} -c '{}'{} {} > '{}' 2> '{}'", script,
                                        s.yosys_timeout, (dir / "row.tmp").string(), gargs,
                                        s.yosys_module, (dir / "table.md").string(),
                                        (dir / "log.txt").string());
    const int rc = std::system(cmd.c_str());
    if (rc != 0 && !fs::exists(dir / "row.tmp"))
      throw Error("yosys", fmt::format("{} failed (status {}), see {}", s.yosys_module, rc,
                                       (dir / "log.txt").string()));
    fs::rename(dir / "row.tmp", csv);
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
  const auto num = [&](const char* col) -> json {
    const std::string v = m.count(col) ? m[col] : "";
    if (v.empty() || !std::isdigit(static_cast<unsigned char>(v[0]))) return nullptr;
    return std::stol(v);
  };
  row["lut"] = num("LUT");
  row["ff"] = num("FF");
  row["dsp"] = num("DSP48E1");
  row["carry4"] = num("CARRY4");
  row["bram"] = m.count("BRAM36") && !m["BRAM36"].empty() && std::isdigit(m["BRAM36"][0])
                    ? json(std::stod(m["BRAM36"]))
                    : json(nullptr);
  row["longest_path_levels"] = num("Longest path (levels)");
  row["yosys_seconds"] = num("Yosys s");
  row["yosys_status"] = row["lut"].is_null() ? (m.count("LUT") ? m["LUT"] : "failed") : "ok";
  if (s.scale_ip_candidates && row["yosys_status"] == "ok") {
    const int J = 1 << c.params.n1, K = c.params.n / c.params.n1;
    const int count = c.params.unrolled ? K * (J - 1) + 2 : J + 1;
    for (const char* k : {"lut", "ff", "dsp", "carry4", "bram"}) {
      row[std::string("module_") + k] = row[k];
      if (!row[k].is_null()) row[k] = row[k].get<double>() * count;
    }
    row["yosys_basis"] = fmt::format("{} x {} candidate evaluators", s.yosys_module, count);
  } else {
    row["yosys_basis"] = s.yosys_module;
  }
}

#if RPU_HAVE_RTL
bool built_in(const ref::HwParams& p) {
  for (const auto& rc : sim::rtl_configs())
    if (!rc.fault && rc.params == p) return true;
  return false;
}
#endif

std::string cosim_name(const Config& c) { return "c" + c.id; }

// "N=16,N1=2,..." for RPU_COSIM_CONFIGS.
std::string verilog_params(const Config& c) {
  std::string out;
  for (const auto& pn : kParams) {
    const std::string value = verilog_value(pn, c.params_json);
    out += fmt::format("{}{}={}", out.empty() ? "" : ",", pn.verilog, value);
  }
  return out;
}

// Builds the co-simulation executables the sweep needs and this rpu does not contain; returns
// configuration id → executable for every one that exists afterwards.
std::map<std::string, std::string> build_cosim(const Spec& s, const std::vector<const Config*>& todo,
                                               const fs::path& out, int jobs) {
  std::map<std::string, std::string> exes;
#if RPU_HAVE_RTL
  const fs::path dir = out / "rtl_build";
  std::string list;
  size_t need = 0;
  for (const Config* c : todo) {
    try {
      c->params.validate();
    } catch (const Error&) {
      continue;
    }
    if (built_in(c->params)) continue;
    const fs::path exe = dir / ("cosim_" + cosim_name(*c));
    if (!fs::exists(exe)) ++need;
    list += (list.empty() ? "" : ";") + cosim_name(*c) + ":" + verilog_params(*c);
  }
  if (need > 0) {
    std::cerr << fmt::format("rpu sweep: Verilating {} configurations into {} (log: {})\n", need,
                             dir.string(), (dir / "build.log").string());
    fs::create_directories(dir);
    const std::string cmd = fmt::format(
        "cmake -S '{}' -B '{}' -G Ninja -DRPU_COSIM_ONLY=ON '-DRPU_COSIM_CONFIGS={}' > '{}' 2>&1 && "
        "ninja -C '{}' -k 0 -j {} >> '{}' 2>&1",
        RPU_SOURCE_DIR, dir.string(), list, (dir / "build.log").string(), dir.string(),
        std::max(1, jobs), (dir / "build.log").string());
    if (std::system(cmd.c_str()) != 0)
      std::cerr << "rpu sweep: some co-simulation builds failed; their rows say so (see the log)\n";
  }
  for (const Config* c : todo) {
    const fs::path exe = dir / ("cosim_" + cosim_name(*c));
    if (fs::exists(exe)) exes[c->id] = exe.string();
  }
#else
  (void)s;
  (void)todo;
  (void)out;
  (void)jobs;
#endif
  return exes;
}

// ---- one configuration ----
json run_config(const Spec& s, const Config& c, const fs::path& out, FloatCache& floats,
                const std::map<std::string, std::string>& external) {
  json row = c.params_json;
  row["config_id"] = c.id;
  row["fingerprint"] = s.fingerprint;
  row["K"] = c.params.n1 > 0 ? c.params.n / c.params.n1 : 0;
  try {
    c.params.validate();
  } catch (const Error& e) {
    row["status"] = "invalid";
    row["error"] = e.what();
    return row;
  }
  try {
    long pixels = 0, vs_ip = 0, vs_f = 0;
    json scenes = json::object();
    for (const std::string& arg : s.scenes) {
      scene::Scene scn = load_scene_argument(arg);
      scn.camera.width = s.width;
      scn.camera.height = s.height;
      const scene::CompiledScene sc = scene::compile_scene(scn);
      const ref::ModelScene model = ref::quantize_scene(sc, c.params);
      ref::RefOptions ro;
      ro.threads = 1;
      ref::RefStats rs;
      const image::Frame r = ref::render_ref(sc, model, ro, &rs);
      const std::string key = fmt::format("{}@{}x{}", arg, s.width, s.height);
      const image::Frame& fip = floats.get(sc, key, tracer::Method::kIterative, c.params.n, c.params.n1);
      const image::Frame& ff = floats.get(sc, key, tracer::Method::kIdeal, 0, 0);
      const long a = static_cast<long>(image::count_differing_pixels(r, fip));
      const long b = static_cast<long>(image::count_differing_pixels(r, ff));
      const std::string name = arg.starts_with("builtin:") ? arg.substr(8) : fs::path(arg).stem().string();
      scenes[name] = {{"pixels", s.width * s.height}, {"ref_vs_float_ip", a},
                      {"ref_vs_float", b}, {"hit_pixels", r.hit_pixels()},
                      {"overflow_pairs", rs.overflow_pairs}};
      pixels += s.width * s.height;
      vs_ip += a;
      vs_f += b;
    }
    row["scenes"] = scenes;
    row["pixels_total"] = pixels;
    row["ref_vs_float_ip_total"] = vs_ip;
    row["ref_vs_float_total"] = vs_f;

    row["rtl_status"] = "off";
    if (s.rtl) {
#if RPU_HAVE_RTL
      const bool built = built_in(c.params);
      const auto ext = external.find(c.id);
      if (!built && ext == external.end()) {
        row["rtl_status"] = s.rtl_build ? "build failed" : "no build";
      } else {
        scene::Scene scn = load_scene_argument(s.scenes.front());
        scn.camera.width = s.rtl_width;
        scn.camera.height = s.rtl_height;
        const scene::CompiledScene sc = scene::compile_scene(scn);
        const ref::ModelScene model = ref::quantize_scene(sc, c.params);
        sim::RtlOptions ro;
        ro.ref.threads = 1;
        if (!built) ro.external_exe = ext->second;
        const sim::RtlRender rr = sim::render_rtl(sc, model, ro);
        row["rtl_status"] = rr.ok ? "ok" : "failed";
        row["rtl_cycles"] = rr.stats.cycles;
        row["rtl_latency_cycles"] = rr.stats.latency_cycles;
        row["rtl_items"] = rr.stats.items;
        row["rtl_items_per_cycle"] = rr.stats.items_per_cycle();
        row["rtl_sample"] = fmt::format("{} at {}x{}", s.scenes.front(), s.rtl_width, s.rtl_height);
        if (!rr.ok) row["rtl_mismatches"] = rr.item_mismatches + rr.pixel_mismatches;
      }
#else
      row["rtl_status"] = "no build";
#endif
    }
    row["yosys_status"] = "off";
    if (s.yosys) yosys_resources(s, c, out / "yosys_cache", row);
    row["status"] = "ok";
  } catch (const std::exception& e) {
    row["status"] = "failed";
    row["error"] = e.what();
  }
  return row;
}

fs::path result_file(const fs::path& out, const std::string& id) {
  return out / "configs" / (id + ".json");
}

// A stored result that can be reused: same fingerprint, finished (ok or invalid).
bool reusable(const fs::path& f, const std::string& fingerprint) {
  std::ifstream in(f);
  if (!in) return false;
  try {
    const json j = json::parse(in);
    return j.value("fingerprint", "") == fingerprint &&
           (j.value("status", "") == "ok" || j.value("status", "") == "invalid");
  } catch (...) {
    return false;
  }
}


std::string csv_escape(const json& v) {
  if (v.is_null()) return "";
  std::string s = v.is_string() ? v.get<std::string>() : v.dump();
  if (s.find_first_of(",\"\n") != std::string::npos) {
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  }
  return s;
}

// Collects every configuration's stored result, writes results.csv, results.json and the plots.
int merge(const Spec& s, const std::vector<Config>& configs, const fs::path& out) {
  json rows = json::array();
  size_t missing = 0, failed = 0;
  std::vector<std::string> scene_names;
  for (const Config& c : configs) {
    std::ifstream in(result_file(out, c.id));
    json row;
    if (in) {
      try {
        row = json::parse(in);
      } catch (...) {
        row = nullptr;
      }
    }
    if (!row.is_object()) {
      row = c.params_json;
      row["config_id"] = c.id;
      row["status"] = "missing";
      row["error"] = "not run yet";
      ++missing;
    }
    if (row.value("status", "") == "failed") ++failed;
    if (row.contains("scenes"))
      for (const auto& [k, v] : row["scenes"].items())
        if (std::find(scene_names.begin(), scene_names.end(), k) == scene_names.end())
          scene_names.push_back(k);
    rows.push_back(row);
  }
  std::vector<std::string> cols = {"config_id", "status"};
  for (const auto& pn : kParams) cols.push_back(pn.key);
  for (const char* c : {"K", "pixels_total", "ref_vs_float_ip_total", "ref_vs_float_total",
                        "rtl_status", "rtl_cycles", "rtl_latency_cycles", "rtl_items",
                        "rtl_items_per_cycle", "yosys_status", "yosys_module", "yosys_basis", "lut", "ff",
                        "dsp", "bram", "carry4", "longest_path_levels"})
    cols.push_back(c);
  std::string csv;
  for (size_t k = 0; k < cols.size(); ++k) csv += (k ? "," : "") + cols[k];
  for (const auto& sc : scene_names)
    csv += fmt::format(",{0}_ref_vs_float_ip,{0}_ref_vs_float", sc);
  csv += ",error\n";
  for (const json& r : rows) {
    for (size_t k = 0; k < cols.size(); ++k)
      csv += (k ? "," : "") + csv_escape(r.contains(cols[k]) ? r[cols[k]] : json(nullptr));
    for (const auto& sc : scene_names) {
      const json e = r.contains("scenes") && r["scenes"].contains(sc) ? r["scenes"][sc] : json();
      csv += "," + csv_escape(e.is_object() ? e["ref_vs_float_ip"] : json(nullptr));
      csv += "," + csv_escape(e.is_object() ? e["ref_vs_float"] : json(nullptr));
    }
    csv += "," + csv_escape(r.contains("error") ? r["error"] : json(nullptr)) + "\n";
  }
  write_text_file(out / "results.csv", csv);
  write_text_file(out / "results.json", rows.dump(2) + "\n");
  const SweepPlots plots = write_sweep_report(rows, out.string(), "rpu sweep: " + s.path);
  std::cerr << fmt::format("rpu sweep: {} configurations, {} failed, {} not run; Pareto front: {}\n"
                           "rpu sweep: wrote {}\n", rows.size(), failed, missing,
                           plots.pareto_ids.size(), (out / "index.html").string());
  return failed || missing ? 2 : 0;
}

}  // namespace

int run_sweep(const SweepOptions& o) {
  const Spec spec = parse_spec(o.file);
  const std::vector<Config> configs = expand(spec);
  const fs::path out(o.out_dir);
  std::error_code ec;
  fs::create_directories(out / "configs", ec);
  if (ec) throw Error(o.out_dir, "cannot create the output directory: " + ec.message());

  if (o.emit_jobs) {
    std::string jobs;
    for (const Config& c : configs)
      jobs += fmt::format("'{}' sweep '{}' --out '{}' --config {}{}{}\n", o.self,
                          fs::absolute(o.file).string(), fs::absolute(out).string(), c.id,
                          o.no_rtl ? " --no-rtl" : "", o.no_yosys ? " --no-yosys" : "");
    write_text_file(out / "jobs.txt", jobs);
    write_text_file(out / "merge.sh",
               fmt::format("#!/bin/sh\n# Collects the per-configuration results of {} into "
                           "results.csv, results.json and index.html.\nexec '{}' sweep '{}' --out "
                           "'{}' --merge\n", o.file, o.self, fs::absolute(o.file).string(),
                           fs::absolute(out).string()));
    fs::permissions(out / "merge.sh", fs::perms::owner_exec | fs::perms::group_exec |
                                          fs::perms::others_exec, fs::perm_options::add);
    std::cerr << fmt::format("rpu sweep: {} jobs in {}, then {}\n", configs.size(),
                             (out / "jobs.txt").string(), (out / "merge.sh").string());
    return 0;
  }
  if (o.merge) return merge(spec, configs, out);

  Spec s = spec;
  if (o.no_rtl) s.rtl = false;
  if (o.no_yosys) s.yosys = false;
  s.fingerprint = fingerprint(s);  // a result made with other switches is not reused

  std::vector<const Config*> todo;
  for (const Config& c : configs) {
    if (!o.config.empty() && c.id != o.config) continue;
    if (reusable(result_file(out, c.id), s.fingerprint)) continue;
    todo.push_back(&c);
  }
  if (!o.config.empty() && todo.empty() &&
      std::none_of(configs.begin(), configs.end(), [&](const Config& c) { return c.id == o.config; }))
    throw Error("--config", "no configuration " + o.config + " in " + o.file);
  std::cerr << fmt::format("rpu sweep: {} configurations, {} done earlier, {} to run\n",
                           o.config.empty() ? configs.size() : 1,
                           (o.config.empty() ? configs.size() : 1) - todo.size(), todo.size());
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const unsigned n = o.jobs > 0 ? static_cast<unsigned>(o.jobs) : hw;
  const std::map<std::string, std::string> external =
      s.rtl && s.rtl_build ? build_cosim(s, todo, out, static_cast<int>(n))
                           : std::map<std::string, std::string>{};
  FloatCache floats;
  std::atomic<size_t> next{0}, done{0};
  std::mutex print_mu;
  const auto t0 = std::chrono::steady_clock::now();
  const auto worker = [&] {
    for (size_t k; (k = next.fetch_add(1)) < todo.size();) {
      const Config& c = *todo[k];
      const auto t1 = std::chrono::steady_clock::now();
      json row = run_config(s, c, out, floats, external);
      write_text_file(result_file(out, c.id), row.dump(2) + "\n");
      const double secs =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
      const double total =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const size_t d = ++done;
      std::lock_guard<std::mutex> lock(print_mu);
      std::cerr << fmt::format("[{}/{}] {} n {} n1 {} coord_w {} {}: {} in {:.1f} s{} (eta {:.0f} s)\n",
                               d, todo.size(), c.id, c.params.n, c.params.n1, c.params.coord_w,
                               c.params.unrolled ? "unrolled" : "iterative",
                               row.value("status", "?"), secs,
                               row.contains("error") ? " — " + row["error"].get<std::string>() : "",
                               total / d * (todo.size() - d));
    }
  };
  {
    std::vector<std::jthread> pool;
    for (unsigned t = 1; t < std::min<size_t>(n, todo.size()); ++t) pool.emplace_back(worker);
    worker();
  }
  if (!o.config.empty()) return 0;  // one job of an emitted set: the merge step collects
  return merge(spec, configs, out);
}

}  // namespace rpu::app
