// The report of `rpu sweep` (README "Command line"): from the sweep's results.json rows, three
// plots written as SVG text and an index.html that shows them with the Pareto configurations and
// the full results table. Running the configurations and writing results.csv / results.json are
// the caller's business; this module only plots and writes.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace rpu::app {

// The rows of a sweep's results.json: an array of objects, one per configuration. Keys:
//   "config_id" (string), "status" ("ok" | "failed" | "invalid"), "error" (string, when not ok),
//   "n","n1","K","coord_w","dir_frac","t_frac","unit_frac","edge_frac","inv_w","sqrt_w" (numbers),
//   "metric" ("abs"|"squared"), "ip" ("unrolled"|"iterative"),
//   "pixels_total", "ref_vs_float_ip_total", "ref_vs_float_total" (mismatched pixels summed over
//   scenes), "scenes": object scene-name -> {"pixels", "ref_vs_float_ip", "ref_vs_float"},
//   "rtl_status" ("ok" | "off" | "no build" | "failed"), "rtl_cycles", "rtl_latency_cycles",
//   "rtl_items_per_cycle", "rtl_items", "yosys_status" ("ok" | "off" | "failed" | "timeout"),
//   "yosys_module", "lut","ff","dsp","bram","carry4", "longest_path_levels".
// Any numeric field may be null or missing (not measured); a row whose status is not "ok" has only
// its parameters and error. Only "ok" rows are plotted; non-finite numbers count as missing.

// The hardware parameters of a row: the keys of the parameter table (ref/model/hw_params.def) in
// its order, with the derived K after n1. A plot's line is the set of ok rows that agree on every
// parameter except the plot's x parameter, among the parameters that vary in the sweep.
const std::vector<std::string_view>& sweep_parameters();

// The files write_sweep_report writes into out_dir.
inline constexpr std::string_view kAccuracyVsLutsSvg = "accuracy_vs_luts.svg";
inline constexpr std::string_view kLutsLatencyVsN1Svg = "luts_latency_vs_n1.svg";
inline constexpr std::string_view kMismatchesVsCoordWSvg = "mismatches_vs_coord_w.svg";
inline constexpr std::string_view kSweepIndexHtml = "index.html";
inline constexpr std::string_view kSweepPlotsJson = "plots.json";  // what the plots show

struct SweepPlots {
  std::vector<std::string> files;       // the paths written (out_dir/<name>), SVGs then index.html
  std::vector<std::string> pareto_ids;  // pareto_front(rows)
};

// Writes into out_dir (created if missing) plots.json, the data of every plot (its series, styles
// and points with their labels and tooltips), and the plots drawn from it by matplotlib
// (scripts/sweep_plots.py): linear axes, one SVG element per plotted point with a <title>
// tooltip naming its configuration:
//   accuracy_vs_luts.svg: x LUTs ("lut"), y ref_vs_float_total; a point per ok row with both,
//     labelled "n/n1" (+ " iterative"); the Pareto front (pareto_front) drawn as a highlighted
//     line through its points in LUT order.
//   luts_latency_vs_n1.svg: two panels over a shared n1 axis, LUTs and rtl_latency_cycles; one
//     line per n (split further when other parameters vary too, see sweep_parameters).
//   mismatches_vs_coord_w.svg: two panels over a shared coord_w axis and a shared y axis,
//     ref_vs_float_total and ref_vs_float_ip_total; one line per (n, n1) (split likewise).
//   index.html: the plots written, the Pareto configurations, and the full results table
//     including failed and invalid rows with their error, every text HTML-escaped; links to
//     results.csv and results.json, which the caller writes next to it. Its title is
//     "rpu sweep: <title>".
// A panel without data is left out of its plot, and a plot without any is not written (its file
// from an earlier run in out_dir is removed): a sweep without Yosys has no LUT plots. Throws
// rpu::Error naming the path on I/O failure, naming the script when it cannot draw (no
// matplotlib), and naming "sweep results" when rows is neither an array nor null (null: no rows).
SweepPlots write_sweep_report(const nlohmann::json& rows, const std::string& out_dir,
                              const std::string& title);

// The Pareto front in (fewer LUTs, fewer ref_vs_float_total mismatched pixels): the config_ids of
// the ok rows with both numbers that no other such row dominates (<= in both, < in at least one;
// so rows with equal numbers are all kept), sorted by LUTs, then mismatches, then config_id.
// Throws rpu::Error like write_sweep_report when rows is not an array.
std::vector<std::string> pareto_front(const nlohmann::json& rows);

}  // namespace rpu::app
