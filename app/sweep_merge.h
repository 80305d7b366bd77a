// The stored results of `rpu sweep` and what collects them: one configs/<id>.json per
// configuration (written atomically when it finishes, reused on resume when its fingerprint
// matches), results.csv / results.json and the report (sweep_report.h) merged from them, and
// the commands for other machines (jobs.txt, merge.sh).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep_spec.h"

namespace rpu::app {

std::filesystem::path result_file(const std::filesystem::path& out_dir, const std::string& id);

// Writes a configuration's result atomically (report_text.h, write_text_file).
void store_result(const std::filesystem::path& out_dir, const std::string& id,
                  const nlohmann::json& row);

// Whether a stored result can be reused: it parses, has this fingerprint, and finished (ok or
// invalid).
bool reusable(const std::filesystem::path& file, const std::string& fingerprint);

// A CSV field (RFC 4180): quoted, with " doubled, when it holds a comma, quote, CR or LF; null
// is the empty field.
std::string csv_field(const nlohmann::json& value);

// Collects every configuration's stored result and writes results.csv, results.json and the
// report into out_dir. Returns 0 when every configuration finished (ok or invalid), 2 when some
// failed or have no result yet.
int merge_results(const SweepSpec& s, const std::vector<SweepConfig>& configs,
                  const std::filesystem::path& out_dir);

// What the jobs run on other machines: `self sweep FILE --out DIR --config ID [switches]`.
struct JobCommand {
  std::string self;       // this executable
  std::string sweep_file; // absolute
  std::string out_dir;    // absolute
  std::vector<std::string> switches;  // --no-rtl, --no-yosys
};

// Writes out_dir/jobs.txt, one POSIX sh command per line and configuration, and
// out_dir/merge.sh; every word quoted by shell_word (sweep_process.h).
void emit_jobs(const JobCommand& job, const std::vector<SweepConfig>& configs,
               const std::filesystem::path& out_dir);

}  // namespace rpu::app
