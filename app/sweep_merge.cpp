#include "sweep_merge.h"

#include <algorithm>
#include <iostream>

#include <fmt/format.h>

#include "common/error.h"
#include "common/input_file.h"
#include "report_text.h"
#include "sweep_process.h"
#include "sweep_report.h"

namespace rpu::app {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A stored result, or null when it is missing or unreadable.
json read_result(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return nullptr;
  try {
    return json::parse(read_input_file(file.string(), "stored result"));
  } catch (const std::exception&) {
    return nullptr;
  }
}

}  // namespace

fs::path result_file(const fs::path& out_dir, const std::string& id) {
  return out_dir / "configs" / (id + ".json");
}

void store_result(const fs::path& out_dir, const std::string& id, const json& row) {
  write_text_file(result_file(out_dir, id), dump_json(row, 2) + "\n");
}

bool reusable(const fs::path& file, const std::string& fingerprint) {
  const json j = read_result(file);
  if (!j.is_object()) return false;
  const auto text = [&](const char* key) {
    return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : std::string();
  };
  return text("fingerprint") == fingerprint &&
         (text("status") == "ok" || text("status") == "invalid");
}

std::string csv_field(const json& value) {
  if (value.is_null()) return "";
  const std::string s = value.is_string() ? value.get<std::string>() : dump_json(value);
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

int merge_results(const SweepSpec& s, const std::vector<SweepConfig>& configs,
                  const fs::path& out_dir) {
  json rows = json::array();
  size_t missing = 0, failed = 0;
  // The sweep's scenes, in file order; then any other a stored row names.
  std::vector<std::string> scene_names;
  for (const SweepScene& sc : s.scenes) scene_names.push_back(sc.label);
  for (const SweepConfig& c : configs) {
    json row = read_result(result_file(out_dir, c.id));
    if (!row.is_object()) {
      row = c.params_json;
      row["config_id"] = c.id;
      row["status"] = "missing";
      row["error"] = "not run yet";
      ++missing;
    }
    if (row.value("status", json()) == "failed") ++failed;
    if (row.contains("scenes") && row["scenes"].is_object())
      for (const auto& [k, v] : row["scenes"].items())
        if (std::find(scene_names.begin(), scene_names.end(), k) == scene_names.end())
          scene_names.push_back(k);
    rows.push_back(row);
  }
  std::vector<std::string> cols = {"config_id", "status"};
  for (const ref::HwParamInfo& d : ref::hw_param_table()) cols.emplace_back(d.key);
  for (const char* c : {"K", "pixels_total", "ref_vs_float_ip_total", "ref_vs_float_total",
                        "rtl_status", "rtl_cycles", "rtl_latency_cycles", "rtl_items",
                        "rtl_items_per_cycle", "yosys_status", "yosys_module", "yosys_basis",
                        "lut_sites", "lut", "srl", "lutram", "ff", "dsp", "bram", "carry4",
                        "sta_ns"})
    cols.push_back(c);
  std::string csv;
  for (size_t k = 0; k < cols.size(); ++k) csv.append(k ? "," : "").append(cols[k]);
  for (const std::string& sc : scene_names) {
    csv.append(",").append(csv_field(sc + "_ref_vs_float_ip"));
    csv.append(",").append(csv_field(sc + "_ref_vs_float"));
  }
  csv += ",error\n";
  const auto get = [](const json& o, const std::string& key) {
    return o.is_object() && o.contains(key) ? o[key] : json(nullptr);
  };
  for (const json& r : rows) {
    for (size_t k = 0; k < cols.size(); ++k) csv.append(k ? "," : "").append(csv_field(get(r, cols[k])));
    for (const std::string& sc : scene_names) {
      const json e = get(get(r, "scenes"), sc);
      csv.append(",").append(csv_field(get(e, "ref_vs_float_ip")));
      csv.append(",").append(csv_field(get(e, "ref_vs_float")));
    }
    csv.append(",").append(csv_field(get(r, "error"))).append("\n");
  }
  write_text_file(out_dir / "results.csv", csv);
  write_text_file(out_dir / "results.json", dump_json(rows, 2) + "\n");
  const SweepPlots plots = write_sweep_report(rows, out_dir.string(), s.path);
  std::cerr << fmt::format("rpu sweep: {} configurations, {} failed, {} not run; Pareto front: {}\n"
                           "rpu sweep: wrote {}\n", rows.size(), failed, missing,
                           plots.pareto_ids.size(), (out_dir / "index.html").string());
  return failed || missing ? 2 : 0;
}

void emit_jobs(const JobCommand& job, const std::vector<SweepConfig>& configs,
               const fs::path& out_dir) {
  std::string jobs;
  for (const SweepConfig& c : configs) {
    std::vector<std::string> words = {job.self, "sweep", job.sweep_file, "--out", job.out_dir,
                                      "--config", c.id};
    words.insert(words.end(), job.switches.begin(), job.switches.end());
    jobs += shell_command(words) + "\n";
  }
  write_text_file(out_dir / "jobs.txt", jobs);
  const fs::path merge_sh = out_dir / "merge.sh";
  write_text_file(merge_sh,
                  "#!/bin/sh\n# Collects the per-configuration results of the sweep into "
                  "results.csv, results.json and index.html.\n" +
                      shell_command({job.self, "sweep", job.sweep_file, "--out", job.out_dir,
                                     "--merge"}, "exec ") + "\n");
  std::error_code ec;
  fs::permissions(merge_sh, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                  fs::perm_options::add, ec);
  if (ec) throw Error(merge_sh.string(), "cannot make it executable: " + ec.message());
  std::cerr << fmt::format("rpu sweep: {} jobs in {}, then {}\n", configs.size(),
                           (out_dir / "jobs.txt").string(), merge_sh.string());
}

}  // namespace rpu::app
