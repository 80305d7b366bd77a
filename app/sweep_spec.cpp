#include "sweep_spec.h"

#include <algorithm>
#include <climits>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <vector>

#include <fmt/format.h>

#include "backends.h"
#include "builtin_scenes.h"
#include "common/error.h"
#include "common/json_input.h"
#include "common/input_file.h"
#include "common/limits.h"
#include "scene/scene_json.h"

namespace rpu::app {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// "<file>: <json path>" for messages.
std::string at(const std::string& file, const std::string& json_path) {
  return json_path.empty() ? file : file + ": " + json_path;
}

using json_input::describe;

// The sweep file's document: linear-time, duplicate keys and syntax errors named (json_input).
json parse_json(const std::string& text, const std::string& file) {
  return json_input::parse(text, file, "the file is empty; expected a JSON object with 'scenes'");
}

// Refuses keys of `object` (at json_path in file) outside `allowed`.
void allow_keys(const json& object, const std::string& file, const std::string& json_path,
                const std::vector<std::string_view>& allowed) {
  for (const auto& [k, v] : object.items()) {
    if (std::find(allowed.begin(), allowed.end(), k) != allowed.end()) continue;
    std::string list;
    for (std::string_view a : allowed) list += fmt::format("{}{}", list.empty() ? "" : ", ", a);
    throw Error(at(file, json_path.empty() ? k : json_path + "." + k),
                fmt::format("unknown key (allowed: {})", list));
  }
}

bool read_bool(const json& v, const std::string& where) {
  if (!v.is_boolean()) throw Error(where, "must be true or false, got " + describe(v));
  return v.get<bool>();
}

// An integer in [lo, hi]; numbers past 64 bits (4294967312, 1e30) are refused, never wrapped.
long long read_int(const json& v, const std::string& where, long long lo, long long hi) {
  if (!v.is_number_integer())
    throw Error(where, "must be an integer, got " + describe(v));
  const bool fits = v.is_number_unsigned()
                        ? v.get<std::uint64_t>() <= static_cast<std::uint64_t>(LLONG_MAX) &&
                              v.get<std::int64_t>() >= lo && v.get<std::int64_t>() <= hi
                        : v.get<std::int64_t>() >= lo && v.get<std::int64_t>() <= hi;
  if (!fits) throw Error(where, fmt::format("{} is out of range [{}, {}]", v.dump(), lo, hi));
  return v.get<std::int64_t>();
}

// [width, height] within the project's image limits.
std::pair<int, int> read_size(const json& v, const std::string& where) {
  if (!v.is_array() || v.size() != 2 || !v[0].is_number_integer() || !v[1].is_number_integer())
    throw Error(where, "must be [width, height], two integers");
  // Past 64 bits the sides are out of range whatever they are; within, the limit says so.
  if ((v[0].is_number_unsigned() && v[0].get<std::uint64_t>() > LLONG_MAX) ||
      (v[1].is_number_unsigned() && v[1].get<std::uint64_t>() > LLONG_MAX))
    throw Error(where, fmt::format("image size {}x{} is out of range: each side must be in [1, {}]",
                                   v[0].dump(), v[1].dump(), limits::kMaxImageSide));
  const long long w = v[0].get<std::int64_t>(), h = v[1].get<std::int64_t>();
  limits::check_image_size(where, w, h);
  return {static_cast<int>(w), static_cast<int>(h)};
}

// Sets one parameter from a JSON value; `where` names it for errors. Values outside int are
// refused here; HwParams::validate judges the rest per configuration.
void set_param(ref::HwParams& p, const std::string& key, const json& v, const std::string& where) {
  const ref::HwParamInfo* d = ref::find_hw_param_key(key);
  if (!d) throw Error(where, "unknown hardware parameter (" + ref::hw_param_keys() + ")");
  if (d->kind == ref::HwParamKind::kChoice ||
      (d->kind == ref::HwParamKind::kRangeOrOff && v.is_string())) {  // a named value
    if (!v.is_string()) throw Error(where, "must be a string, got " + describe(v));
    const ref::HwChoice* c = d->choice(v.get<std::string>());
    if (!c) throw Error(where, "must be " + d->choice_list());
    d->set(p, c->value);
    return;
  }
  d->set(p, static_cast<int>(read_int(v, where, INT_MIN, INT_MAX)));
}

std::vector<SweepScene> read_scenes(const json& j, const std::string& file) {
  const std::string where = at(file, "scenes");
  if (!j.is_array() || j.empty())
    throw Error(where, "must be a non-empty array of scene files or builtin:NAME");
  // Relative scene files are relative to the sweep file's directory, never the current one.
  const fs::path base = fs::path(file).parent_path();
  std::vector<SweepScene> scenes;
  std::map<std::string, size_t> seen;  // normalised path → index
  for (size_t k = 0; k < j.size(); ++k) {
    const std::string w = fmt::format("{}[{}]", where, k);
    if (!j[k].is_string()) throw Error(w, "must be a string, got " + describe(j[k]));
    SweepScene sc;
    sc.argument = j[k].get<std::string>();
    if (sc.argument.empty()) throw Error(w, "must name a scene file or builtin:NAME");
    const bool builtin = sc.argument.starts_with("builtin:");
    sc.path = builtin || fs::path(sc.argument).is_absolute() ? sc.argument
                                                             : (base / sc.argument).string();
    sc.label = builtin ? sc.argument.substr(8) : fs::path(sc.argument).stem().string();
    const std::string normal = builtin ? sc.path : fs::path(sc.path).lexically_normal().string();
    const auto [it, fresh] = seen.emplace(normal, k);
    if (!fresh)
      throw Error(w, fmt::format("the same scene as scenes[{}]; list each scene once", it->second));
    scenes.push_back(sc);
  }
  // Two scenes with one stem (a/scene.json, b/scene.json) are told apart by their arguments.
  std::map<std::string, int> count;
  for (const SweepScene& sc : scenes) ++count[sc.label];
  for (SweepScene& sc : scenes)
    if (count[sc.label] > 1) sc.label = sc.argument;
  std::set<std::string> labels;
  for (size_t k = 0; k < scenes.size(); ++k)
    if (!labels.insert(scenes[k].label).second) {
      scenes[k].label += fmt::format("#{}", k);
      labels.insert(scenes[k].label);
    }
  return scenes;
}

// Number of configurations of a grid whose lists have these lengths, or -1 past the limit
// (checked before every multiplication, so it never overflows).
long long grid_size(const std::vector<size_t>& lengths) {
  long long product = 1;
  for (size_t n : lengths) {
    if (n != 0 && product > limits::kMaxSweepConfigurations / static_cast<long long>(n)) return -1;
    product *= static_cast<long long>(n);
  }
  return product;
}

void read_grid(const json& g, const std::string& file, SweepSpec& s) {
  const std::string where = at(file, "grid");
  if (!g.is_object() || g.empty())
    throw Error(where, "must be an object of parameter lists, e.g. {\"n\": [8, 16]}");
  std::vector<size_t> lengths;
  std::string shape;
  for (const auto& [k, v] : g.items()) {
    lengths.push_back(v.is_array() ? v.size() : 1);
    shape += fmt::format("{}{} {}", shape.empty() ? "" : " x ", lengths.back(), k);
  }
  const long long size = grid_size(lengths);
  if (size < 0 || size > limits::kMaxSweepConfigurations) {
    double product = 1;  // for the message only; the check above is exact
    for (size_t n : lengths) product *= static_cast<double>(n);
    throw Error(where, fmt::format("too many configurations: {} ({}); at most {} allowed",
                                   product < 1e15 ? fmt::format("{:.0f}", product)
                                                  : fmt::format("{:.3g}", product),
                                   shape, limits::kMaxSweepConfigurations));
  }
  for (const auto& [k, v] : g.items()) {
    const std::string wk = where + "." + k;
    if (!ref::find_hw_param_key(k))
      throw Error(wk, "unknown hardware parameter (" + ref::hw_param_keys() + ")");
    std::vector<json> values = v.is_array() ? v.get<std::vector<json>>() : std::vector<json>{v};
    if (values.empty()) throw Error(wk, "must not be empty");
    std::map<std::string, size_t> seen;  // value text → first index
    for (size_t q = 0; q < values.size(); ++q) {
      const std::string wq = v.is_array() ? fmt::format("{}[{}]", wk, q) : wk;
      ref::HwParams probe;
      set_param(probe, k, values[q], wq);
      const auto [it, fresh] = seen.emplace(values[q].dump(), q);
      if (!fresh)
        throw Error(wq, fmt::format("repeats {} of grid.{}[{}]; list each value once",
                                    values[q].dump(), k, it->second));
    }
    s.grid.emplace_back(k, values);
  }
}

// An optional section that is either a boolean or an object with an optional "enabled" and the
// keys in `allowed` (rtl, yosys). Sets `enabled`; true when `j` is an object whose other keys the
// caller reads.
bool read_section(const json& j, const std::string& file, const std::string& key,
                  std::initializer_list<std::string_view> allowed, bool& enabled) {
  const std::string where = at(file, key);
  if (j.is_boolean()) {
    enabled = j.get<bool>();
    return false;
  }
  std::string keys = "\"enabled\"";
  for (std::string_view a : allowed) keys += fmt::format(", \"{}\"", a);
  if (!j.is_object()) throw Error(where, "must be true, false or {" + keys + "}");
  std::vector<std::string_view> all = {"enabled"};
  all.insert(all.end(), allowed.begin(), allowed.end());
  allow_keys(j, file, key, all);
  enabled = j.contains("enabled") ? read_bool(j["enabled"], where + ".enabled") : true;
  return true;
}

void read_rtl(const json& r, const std::string& file, SweepSpec& s) {
  const std::string where = at(file, "rtl");
  if (!read_section(r, file, "rtl", {"resolution", "build"}, s.rtl)) return;
  if (r.contains("build")) s.rtl_build = read_bool(r["build"], where + ".build");
  if (r.contains("resolution"))
    std::tie(s.rtl_width, s.rtl_height) = read_size(r["resolution"], where + ".resolution");
}

void read_yosys(const json& y, const std::string& file, SweepSpec& s) {
  const std::string where = at(file, "yosys");
  if (y.is_object() && y.contains("scale"))
    throw Error(where + ".scale", "retired: the resources are the whole module's, synthesised "
                                  "through scripts/synth_hier.py (docs/sweeps.md); remove the key");
  if (!read_section(y, file, "yosys", {"module", "timeout"}, s.yosys)) return;
  if (y.contains("module")) {
    if (!y["module"].is_string())
      throw Error(where + ".module", "must be a string, got " + describe(y["module"]));
    s.yosys_module = y["module"].get<std::string>();
  }
  if (!std::regex_match(s.yosys_module, std::regex("rpu_[a-z0-9_]+")))
    throw Error(where + ".module", "must name an rtl/ module (rpu_...)");
  if (y.contains("timeout"))
    s.yosys_timeout = static_cast<int>(read_int(y["timeout"], where + ".timeout", 1, 7 * 24 * 3600));
}

}  // namespace

std::string verilog_value(const ref::HwParamInfo& d, const ref::HwParams& p) {
  return std::to_string(d.get(p));
}

ref::HwParams hw_params_from_json(const json& object, const std::string& where) {
  if (!object.is_object()) throw Error(where, "must be an object");
  ref::HwParams p;
  for (const auto& [k, v] : object.items()) set_param(p, k, v, where.empty() ? k : where + "." + k);
  return p;
}

std::string hash_hex(const std::string& bytes) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a 64
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return fmt::format("{:016x}", h);
}

std::string dump_json(const json& j, int indent) {
  return j.dump(indent, ' ', false, json::error_handler_t::replace);
}

SweepSpec parse_sweep_file(const std::string& path) {
  return parse_sweep_text(read_input_file(path, "sweep file"), path);
}

SweepSpec parse_sweep_text(const std::string& text, const std::string& path) {
  const json j = parse_json(text, path);
  SweepSpec s;
  s.path = path;
  if (!j.is_object()) throw Error(path, "must be a JSON object");
  allow_keys(j, path, "", {"scenes", "resolution", "grid", "base", "rtl", "yosys", "description"});
  if (!j.contains("scenes"))
    throw Error(at(path, "scenes"), "must be a non-empty array of scene files or builtin:NAME");
  s.scenes = read_scenes(j["scenes"], path);
  if (j.contains("description") && !j["description"].is_string())
    throw Error(at(path, "description"), "must be a string");
  if (j.contains("resolution"))
    std::tie(s.width, s.height) = read_size(j["resolution"], at(path, "resolution"));
  if (j.contains("base")) s.base = hw_params_from_json(j["base"], at(path, "base"));
  if (!j.contains("grid"))
    throw Error(at(path, "grid"), "must be an object of parameter lists, e.g. {\"n\": [8, 16]}");
  read_grid(j["grid"], path, s);
  if (j.contains("rtl")) read_rtl(j["rtl"], path, s);
  if (j.contains("yosys")) read_yosys(j["yosys"], path, s);
  return s;
}

LoadedScenes load_sweep_scenes(const SweepSpec& s) {
  LoadedScenes out;
  std::string all;
  for (const SweepScene& sc : s.scenes) {
    std::string text;
    if (sc.path.starts_with("builtin:")) {
      const std::string name = sc.path.substr(8);
      const auto& known = builtin_scenes();
      const auto it = std::find_if(known.begin(), known.end(),
                                   [&](const BuiltinScene& b) { return name == b.name; });
      if (it == known.end()) {
        out.scenes.push_back(load_scene_argument(sc.path));  // throws, naming the known ones
        continue;
      }
      text = it->json;
    } else {
      text = read_input_file(sc.path, "scene file");
    }
    out.scenes.push_back(scene::parse_scene(text, sc.path));
    // The sweep measures the model (ref) against the float tracers; ref has no path for patches,
    // so a frame with patches would compare two images that both lack them.
    if (!out.scenes.back().patches.empty())
      throw Error(sc.path + ": patches",
                  "a sweep measures the ref model against float and float-ip, and ref has no "
                  "fixed-point path for parametric patches (docs/algorithms.md §4); remove the "
                  "scene from the sweep or its patches from the scene");
    all += sc.label + '\0' + hash_hex(text) + '\0';
  }
  out.fingerprint = hash_hex(all);
  return out;
}

std::string rtl_fingerprint(const std::filesystem::path& root) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(root / "rtl", ec), end; !ec && it != end;
       it.increment(ec))
    if (it->is_regular_file(ec)) files.push_back(it->path());
  if (ec) throw Error((root / "rtl").string(), "cannot list the RTL: " + ec.message());
  files.push_back(root / "scripts" / "synth_hier.py");
  std::sort(files.begin(), files.end());
  std::string all;
  for (const fs::path& f : files)
    all += fs::relative(f, root).generic_string() + '\0' +
           hash_hex(read_input_file(f.string(), "RTL source")) + '\0';
  return hash_hex(all);
}

std::string sweep_fingerprint(const SweepSpec& s, const LoadedScenes& scenes) {
  return hash_hex(dump_json(json({{"scenes", scenes.fingerprint}, {"w", s.width}, {"h", s.height},
                                  {"rtl", s.rtl}, {"rw", s.rtl_width}, {"rh", s.rtl_height},
                                  {"yosys", s.yosys}, {"ym", s.yosys_module},
                                  {"yb", "synth_hier"}, {"rb", s.rtl_build},
                                  {"src", s.yosys || s.rtl ? rtl_fingerprint(RPU_SOURCE_DIR) : ""}})));
}

std::vector<SweepConfig> expand_grid(const SweepSpec& s) {
  std::vector<SweepConfig> out;
  std::set<std::string> ids;
  std::vector<size_t> idx(s.grid.size(), 0);
  for (;;) {
    SweepConfig c;
    c.params = s.base;
    for (size_t k = 0; k < s.grid.size(); ++k)
      set_param(c.params, s.grid[k].first, s.grid[k].second[idx[k]], s.grid[k].first);
    c.params_json = hw_params_json(c.params);
    c.id = hash_hex(c.params_json.dump());
    if (ids.insert(c.id).second) out.push_back(std::move(c));  // each configuration once
    size_t k = 0;
    while (k < idx.size() && ++idx[k] == s.grid[k].second.size()) idx[k++] = 0;
    if (k == idx.size()) break;
  }
  return out;
}

}  // namespace rpu::app
