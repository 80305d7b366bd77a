// The report of `rpu sweep`: the Pareto front of hand-made rows; the plot data (plots.json: every
// point, series and line) and the SVGs matplotlib draws from it (scripts/sweep_plots.py: well-
// formed, one element per point with its tooltip, the labels and legend as text); no plots for
// an empty sweep; escaped text in index.html and the SVGs; failures that name the path.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <unistd.h>

#include "common/error.h"
#include "report_text.h"
#include "sweep_report.h"

namespace rpu::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Per process (two checkouts' suites may run at once on one machine), removed at exit.
fs::path scratch() {
  return fs::temp_directory_path() / ("rpu_test_sweep_report_" + std::to_string(::getpid()));
}
struct RemoveScratch {
  ~RemoveScratch() {
    std::error_code ec;
    fs::remove_all(scratch(), ec);
  }
} remove_scratch;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = scratch() / name;
  fs::remove_all(dir);
  return dir;
}

std::string read_text(const fs::path& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

size_t count_of(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// The problem with an SVG as the XML subset the report writes, or "" when there is none: an XML
// declaration, then one <svg> root element, tags that close in order, quoted attributes, no raw
// '<' or '>' in text, and every '&' starting an entity.
std::string svg_problem(std::string s) {
  if (s.rfind("<?xml", 0) == 0) s = s.substr(s.find("?>") + 2);
  s.erase(0, s.find_first_not_of(" \n"));
  if (s.rfind("<svg", 0) != 0) return "does not start with <svg";
  static const std::regex entity("^&(amp|lt|gt|quot|#[0-9]+);");
  for (size_t at = s.find('&'); at != std::string::npos; at = s.find('&', at + 1))
    if (!std::regex_search(s.substr(at, 8), entity)) return "bare '&' at " + std::to_string(at);
  std::vector<std::string> open;
  bool closed_root = false;
  for (size_t i = 0; i < s.size();) {
    if (s[i] == '>') return "'>' in text at " + std::to_string(i);
    if (s[i] != '<') {
      if (closed_root && !std::isspace(static_cast<unsigned char>(s[i])))
        return "text after the root element";
      ++i;
      continue;
    }
    if (closed_root) return "a second root element";
    const size_t end = s.find('>', i);
    if (end == std::string::npos) return "unterminated tag at " + std::to_string(i);
    const std::string tag = s.substr(i + 1, end - i - 1);
    if (tag.empty() || tag.find('<') != std::string::npos) return "malformed tag at " + std::to_string(i);
    if (std::count(tag.begin(), tag.end(), '"') % 2 != 0) return "unbalanced quotes in <" + tag + ">";
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1)) return "unexpected </" + tag.substr(1) + ">";
      open.pop_back();
      closed_root = open.empty();
    } else if (tag.back() != '/') {
      open.push_back(tag.substr(0, tag.find_first_of(" \n")));
    }
    i = end + 1;
  }
  return open.empty() ? "" : "unclosed <" + open.back() + ">";
}

// The plot data of a report (plots.json) and one figure of it by file name.
json plot_data(const fs::path& dir) { return json::parse(read_text(dir / "plots.json")); }
json figure(const fs::path& dir, const std::string& file) {
  const json data = plot_data(dir);
  for (const json& f : data.at("figures"))
    if (f.at("file") == file) return f;
  ADD_FAILURE() << "no figure " << file << " in plots.json";
  return json::object();
}
// Its points, and its series drawn as a line (of two points or more; the Pareto front aside).
size_t point_count(const json& f) {
  size_t n = 0;
  for (const json& p : f.value("panels", json::array()))
    for (const json& s : p.at("series")) n += s.at("points").size();
  return n;
}
size_t line_count(const json& f) {
  size_t n = 0;
  for (const json& p : f.value("panels", json::array()))
    for (const json& s : p.at("series"))
      n += s.at("line").get<bool>() && !s.at("highlighted").get<bool>() && s.at("points").size() > 1;
  return n;
}

// One ok row of the sweep; null measurements are written as JSON null.
json ok_row(const std::string& id, int n, int n1, int coord_w, json lut, json vs_float,
            json vs_float_ip, json latency) {
  return {{"config_id", id}, {"status", "ok"}, {"n", n}, {"n1", n1}, {"K", n / n1},
          {"coord_w", coord_w}, {"dir_frac", 12}, {"t_frac", 10}, {"unit_frac", 14},
          {"edge_frac", 10}, {"inv_w", 18}, {"sqrt_w", 16}, {"metric", "abs"},
          {"ip", "unrolled"}, {"pixels_total", 4096}, {"ref_vs_float_ip_total", vs_float_ip},
          {"ref_vs_float_total", vs_float},
          {"scenes", {{"spiral", {{"pixels", 4096}, {"ref_vs_float_ip", vs_float_ip},
                                   {"ref_vs_float", vs_float}}}}},
          {"rtl_status", latency.is_null() ? "off" : "ok"}, {"rtl_cycles", nullptr},
          {"rtl_latency_cycles", latency}, {"rtl_items_per_cycle", nullptr}, {"rtl_items", nullptr},
          {"yosys_status", lut.is_null() ? "timeout" : "ok"}, {"yosys_module", "rpu_top"},
          {"lut_sites", lut}, {"ff", 500}, {"dsp", 4}, {"bram", 0}, {"carry4", 60},
          {"longest_path_levels", 12}};
}

std::string config_id(int n, int n1) { return "n" + std::to_string(n) + "_n1_" + std::to_string(n1); }

json failed_row(const std::string& id, const std::string& status, int n, int n1,
                const std::string& error) {
  return {{"config_id", id}, {"status", status}, {"n", n}, {"n1", n1}, {"K", 4}, {"coord_w", 16},
          {"metric", "abs"}, {"ip", "unrolled"}, {"error", error}};
}

// n ∈ {16, 24} × n1 ∈ {4, 8} × coord_w ∈ {12, 16}, with a few measurements missing, plus a
// failed and an invalid configuration:
//   id  n  n1 coord_w  LUTs  vs float  vs float-ip  latency
//   c0  16  4  12      1000  900       880          20
//   c1  16  4  16      1200  400       390          20
//   c2  16  8  12      1500  700       650          24
//   c3  16  8  16      —     300       280          24
//   c4  24  4  12      1400  500       —            —
//   c5  24  4  16      1800  100        90          28
//   c6  24  8  12      2100  100        95          32
//   c7  24  8  16      2600    0         0          32
// Pareto front by LUTs: c0, c1, c5, c7 (c4 and c2 need more LUTs than c1 for more mismatches,
// c6 more LUTs than c5 for as many).
json sweep_rows() {
  return json::array({
      ok_row("c0", 16, 4, 12, 1000, 900, 880, 20),
      ok_row("c1", 16, 4, 16, 1200, 400, 390, 20),
      ok_row("c2", 16, 8, 12, 1500, 700, 650, 24),
      ok_row("c3", 16, 8, 16, nullptr, 300, 280, 24),
      ok_row("c4", 24, 4, 12, 1400, 500, nullptr, nullptr),
      ok_row("c5", 24, 4, 16, 1800, 100, 90, 28),
      ok_row("c6", 24, 8, 12, 2100, 100, 95, 32),
      ok_row("c7", 24, 8, 16, 2600, 0, 0, 32),
      failed_row("f1", "failed", 32, 8, "verilator: build failed"),
      failed_row("i1", "invalid", 8, 16, "n1 must not exceed n"),
  });
}

TEST(ParetoFront, KeepsOnlyUndominatedOkRows) {
  const json rows = json::array({
      ok_row("a", 16, 4, 16, 100, 50, 50, 10),
      ok_row("b", 16, 8, 16, 200, 20, 20, 10),
      ok_row("c", 24, 8, 16, 300, 20, 20, 10),        // as accurate as b, more LUTs
      ok_row("d", 24, 4, 16, 150, 60, 60, 10),        // worse than a in both
      ok_row("e", 16, 8, 12, 200, 20, 20, 10),        // ties b: both stay
      ok_row("f", 32, 8, 16, 400, 0, 0, 10),
      ok_row("g", 8, 4, 16, 120, 50, 50, 10),         // as accurate as a, more LUTs
      ok_row("h", 8, 2, 16, 50, nullptr, 0, 10),      // no accuracy: ignored
      ok_row("i", 8, 2, 12, nullptr, 0, 0, 10),       // no LUTs: ignored
      failed_row("j", "failed", 8, 2, "yosys crashed"),
      failed_row("k", "invalid", 8, 2, "bad"),
  });
  json with_failed_measurements = rows;
  // A failed row that would dominate everything if it counted.
  with_failed_measurements[9]["lut_sites"] = 1;
  with_failed_measurements[9]["ref_vs_float_total"] = 0;
  json no_lut_key = ok_row("m", 8, 2, 8, 1, 0, 0, 1);
  no_lut_key.erase("lut_sites");
  with_failed_measurements.push_back(no_lut_key);

  const std::vector<std::string> want = {"a", "b", "e", "f"};
  EXPECT_EQ(pareto_front(rows), want);
  EXPECT_EQ(pareto_front(with_failed_measurements), want);
}

TEST(ParetoFront, SmallAndDegenerateSets) {
  EXPECT_TRUE(pareto_front(json::array()).empty());
  EXPECT_TRUE(pareto_front(json()).empty());
  EXPECT_EQ(pareto_front(json::array({ok_row("only", 16, 4, 16, 10, 5, 5, 1)})),
            std::vector<std::string>{"only"});
  // All equal: every row is on the front, in config_id order.
  EXPECT_EQ(pareto_front(json::array({ok_row("z", 16, 4, 16, 10, 5, 5, 1),
                                      ok_row("y", 16, 8, 16, 10, 5, 5, 1)})),
            (std::vector<std::string>{"y", "z"}));
  EXPECT_EQ(pareto_front(sweep_rows()), (std::vector<std::string>{"c0", "c1", "c5", "c7"}));
  EXPECT_THROW(pareto_front(json{{"config_id", "not an array"}}), rpu::Error);
}

TEST(SweepReport, DrawsEveryPointWithItsTooltip) {
  const fs::path dir = fresh_dir("files");
  const SweepPlots plots = write_sweep_report(sweep_rows(), dir.string(), "widths");
  const std::vector<std::string> files = {
      (dir / "accuracy_vs_luts.svg").string(), (dir / "luts_latency_vs_n1.svg").string(),
      (dir / "mismatches_vs_coord_w.svg").string(), (dir / "index.html").string()};
  EXPECT_EQ(plots.files, files);
  EXPECT_EQ(plots.pareto_ids, (std::vector<std::string>{"c0", "c1", "c5", "c7"}));

  // Points: accuracy 7 (c3 has no LUTs); LUTs 7 + latency 7 (c4 has none); vs float 8 +
  // vs float-ip 7. Lines (series of at least two points): per n and coord_w in each panel of
  // luts_latency (c1 alone in LUTs, c6 alone in latency): 3 + 3; per (n, n1): 4 + 3 (c5 alone).
  const std::pair<const char*, std::pair<size_t, size_t>> expected[] = {
      {"accuracy_vs_luts.svg", {7, 0}},
      {"luts_latency_vs_n1.svg", {14, 6}},
      {"mismatches_vs_coord_w.svg", {15, 7}}};
  for (const auto& [file, counts] : expected) {
    const json f = figure(dir, file);
    EXPECT_EQ(point_count(f), counts.first) << file;
    EXPECT_EQ(line_count(f), counts.second) << file;
    ASSERT_TRUE(fs::exists(dir / file)) << file;
    const std::string svg = read_text(dir / file);
    EXPECT_EQ(svg_problem(svg), "") << file;
    EXPECT_EQ(count_of(svg, "id=\"point-"), counts.first) << file;  // one element per point
    EXPECT_EQ(count_of(svg, "<title>"), counts.first) << file;       // each with its tooltip
    EXPECT_EQ(count_of(svg, "id=\"series"), counts.second) << file;
    EXPECT_FALSE(std::regex_search(svg, std::regex("[\",= ]-?(nan|inf)[\" ,<]", std::regex::icase))) << file;
  }

  // The Pareto front is one highlighted line through its four points, in LUT order.
  const json accuracy_data = figure(dir, "accuracy_vs_luts.svg");
  const json& pareto = accuracy_data.at("panels").at(0).at("series").back();
  EXPECT_EQ(pareto.at("name"), "Pareto front");
  EXPECT_TRUE(pareto.at("highlighted").get<bool>());
  std::vector<double> xs;
  for (const json& q : pareto.at("points")) xs.push_back(q.at("x").get<double>());
  EXPECT_EQ(xs, (std::vector<double>{1000, 1200, 1800, 2600}));
  const std::string accuracy = read_text(dir / "accuracy_vs_luts.svg");
  EXPECT_EQ(count_of(accuracy, "id=\"pareto\""), 1u);
  EXPECT_NE(accuracy.find(">16/4</text>"), std::string::npos);
  EXPECT_NE(accuracy.find(">24/8</text>"), std::string::npos);
  EXPECT_NE(accuracy.find("<title>c5: LUT sites 1800, mismatched pixels 100 (Pareto front)</title>"),
            std::string::npos);

  // The line figures name their series by n and the other swept parameter (the legend).
  const std::string luts = read_text(dir / "luts_latency_vs_n1.svg");
  EXPECT_NE(luts.find(">n=16, coord_w=12</text>"), std::string::npos);
  EXPECT_NE(luts.find(">n=24, coord_w=16</text>"), std::string::npos);
  const std::string widths = read_text(dir / "mismatches_vs_coord_w.svg");
  EXPECT_NE(widths.find(">n=16, n1=8</text>"), std::string::npos);

  const std::string html = read_text(dir / "index.html");
  for (const char* needed : {"href=\"results.csv\"", "href=\"results.json\"",
                             "src=\"accuracy_vs_luts.svg\"", "src=\"luts_latency_vs_n1.svg\"",
                             "src=\"mismatches_vs_coord_w.svg\"", "verilator: build failed",
                             "n1 must not exceed n", "10 configurations: 8 ok, 1 failed, 1 invalid"})
    EXPECT_NE(html.find(needed), std::string::npos) << needed;
  EXPECT_EQ(count_of(html, "<tr class=\"ok pareto\">"), 4u);
  EXPECT_EQ(count_of(html, "<tr class=\"failed\">"), 1u);
  EXPECT_EQ(count_of(html, "<tr class=\"invalid\">"), 1u);
}

TEST(SweepReport, OneLinePerNWhenOnlyNAndN1Vary) {
  json rows = json::array();
  for (int n : {16, 24})
    for (int n1 : {4, 8, 12})
      rows.push_back(ok_row(config_id(n, n1), n, n1, 16, 100 * n + 10 * n1, 50 - n1, 40 - n1, n1 + 8));
  const fs::path dir = fresh_dir("per_n");
  write_sweep_report(rows, dir.string(), "n1");
  const json f = figure(dir, "luts_latency_vs_n1.svg");
  EXPECT_EQ(point_count(f), 12u);
  // Two lines per panel, three points each; legend rows n=16 and n=24 only.
  EXPECT_EQ(line_count(f), 4u);
  for (const json& p : f.at("panels"))
    for (const json& s : p.at("series")) EXPECT_EQ(s.at("points").size(), 3u) << s.at("name");
  const std::string svg = read_text(dir / "luts_latency_vs_n1.svg");
  EXPECT_EQ(svg_problem(svg), "");
  EXPECT_EQ(count_of(svg, "id=\"point-"), 12u);
  EXPECT_EQ(count_of(svg, "id=\"series"), 4u);
  EXPECT_NE(svg.find(">n=16</text>"), std::string::npos);
  EXPECT_NE(svg.find(">n=24</text>"), std::string::npos);
  EXPECT_EQ(svg.find("coord_w="), std::string::npos);
  // One coord_w only: one point per (n, n1), no lines.
  const json w = figure(dir, "mismatches_vs_coord_w.svg");
  EXPECT_EQ(point_count(w), 12u);
  EXPECT_EQ(line_count(w), 0u);
  const std::string widths = read_text(dir / "mismatches_vs_coord_w.svg");
  EXPECT_EQ(svg_problem(widths), "");
  EXPECT_EQ(count_of(widths, "id=\"point-"), 12u);
  EXPECT_EQ(count_of(widths, "id=\"series"), 0u);
}

TEST(SweepReport, EmptySweepWritesNoPlots) {
  for (const json& rows : {json::array(), json()}) {
    const fs::path dir = fresh_dir(rows.is_null() ? "null" : "empty");
    SweepPlots plots;
    ASSERT_NO_THROW(plots = write_sweep_report(rows, dir.string(), "nothing"));
    EXPECT_TRUE(plots.pareto_ids.empty());
    EXPECT_EQ(plots.files.size(), 1u);  // index.html only
    for (const char* file : {"accuracy_vs_luts.svg", "luts_latency_vs_n1.svg", "mismatches_vs_coord_w.svg"})
      EXPECT_FALSE(fs::exists(dir / file)) << file;
    const std::string html = read_text(dir / "index.html");
    EXPECT_NE(html.find("0 configurations"), std::string::npos);
    EXPECT_NE(html.find("no front"), std::string::npos);
    EXPECT_NE(html.find("Nothing to plot"), std::string::npos);
    EXPECT_EQ(html.find(".svg"), std::string::npos);
  }
  // Only failed rows: nothing to plot either.
  const fs::path dir = fresh_dir("failed_only");
  write_sweep_report(json::array({failed_row("f", "failed", 16, 4, "boom")}), dir.string(), "x");
  EXPECT_FALSE(fs::exists(dir / "accuracy_vs_luts.svg"));
}

// A sweep without Yosys (no "lut_sites" in any row): the LUT plot is left out, the LUT panel of the n1
// plot too, and a plot left from an earlier run with Yosys in the same directory is removed. The
// page title names the sweep once.
TEST(SweepReport, PlotsWithoutDataAreLeftOut) {
  json rows = json::array();
  for (int n1 : {1, 2, 4}) {
    json row = ok_row(config_id(16, n1), 16, n1, 16, 100 * n1, 10 - n1, 9 - n1, 20 + n1);
    row.erase("lut_sites");
    rows.push_back(row);
  }
  const fs::path dir = fresh_dir("no_yosys");
  fs::create_directories(dir);
  write_text_file(dir / "accuracy_vs_luts.svg", "<svg>stale</svg>\n");
  const SweepPlots plots = write_sweep_report(rows, dir.string(), "sweeps/no_yosys.json");
  EXPECT_EQ(plots.files.size(), 3u);
  EXPECT_FALSE(fs::exists(dir / "accuracy_vs_luts.svg"));
  const std::string n1 = read_text(dir / "luts_latency_vs_n1.svg");
  EXPECT_EQ(svg_problem(n1), "");
  EXPECT_EQ(n1.find("LUT sites against n1"), std::string::npos);
  EXPECT_NE(n1.find("latency against n1"), std::string::npos);
  EXPECT_EQ(figure(dir, "luts_latency_vs_n1.svg").at("panels").size(), 1u);
  const std::string html = read_text(dir / "index.html");
  EXPECT_EQ(html.find("accuracy_vs_luts.svg"), std::string::npos);
  EXPECT_NE(html.find("src=\"luts_latency_vs_n1.svg\""), std::string::npos);
  EXPECT_NE(html.find("<title>rpu sweep: sweeps/no_yosys.json</title>"), std::string::npos);
  EXPECT_EQ(html.find("rpu sweep: rpu sweep"), std::string::npos);
}

TEST(SweepReport, SinglePointAndEqualValuesHaveFiniteAxes) {
  const std::vector<json> sets = {
      json::array({ok_row("one", 16, 8, 16, 1234, 0, 0, 20)}),
      json::array({ok_row("p", 16, 8, 16, 500, 7, 7, 20), ok_row("q", 16, 8, 16, 500, 7, 7, 20),
                   ok_row("r", 16, 8, 16, 500, 7, 7, 20)}),
      json::array({ok_row("zero", 16, 8, 16, 0, 0, 0, 0)}),
      // Ends beyond what a nice step can span (hi - lo overflows).
      json::array({ok_row("low", 16, 8, 16, -1.5e308, 5, 5, -1.5e308),
                   ok_row("high", 16, 8, 16, 1.5e308, 0, 0, 1.5e308)})};
  for (size_t k = 0; k < sets.size(); ++k) {
    const fs::path dir = fresh_dir("degenerate" + std::to_string(k));
    const SweepPlots plots = write_sweep_report(sets[k], dir.string(), "one");
    EXPECT_EQ(plots.pareto_ids.size(), sets[k].size());
    for (const char* file : {"accuracy_vs_luts.svg", "luts_latency_vs_n1.svg", "mismatches_vs_coord_w.svg"}) {
      const std::string svg = read_text(dir / file);
      EXPECT_EQ(svg_problem(svg), "") << file;
      EXPECT_EQ(count_of(svg, "id=\"point-"), (file[0] == 'a' ? 1 : 2) * sets[k].size()) << file;
      EXPECT_FALSE(std::regex_search(svg, std::regex("[\",= ]-?(nan|inf)[\" ,<]", std::regex::icase)))
          << k << " " << file;
      // At least two ticks on each axis.
      EXPECT_GE(count_of(svg, "id=\"xtick_"), 2u) << file;
      EXPECT_GE(count_of(svg, "id=\"ytick_"), 2u) << file;
    }
  }
}

TEST(SweepReport, TextIsEscaped) {
  json rows = sweep_rows();
  rows[0]["config_id"] = "<img src=x onerror=alert(1)>";
  rows[8]["error"] = "<script>alert('x')</script> & \"quoted\"";
  rows[9]["ip"] = "<b>iterative</b>";
  rows.push_back("<i>not an object</i>");
  const fs::path dir = fresh_dir("escape");
  write_sweep_report(rows, dir.string(), "<title>&</title>");
  const std::string html = read_text(dir / "index.html");
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<img src=x"), std::string::npos);
  EXPECT_EQ(html.find("<b>iterative"), std::string::npos);
  EXPECT_EQ(html.find("<i>not"), std::string::npos);
  EXPECT_EQ(html.find("<title>&</title>"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; &quot;quoted&quot;"),
            std::string::npos);
  EXPECT_NE(html.find("&lt;img src=x onerror=alert(1)&gt;"), std::string::npos);
  EXPECT_NE(html.find("malformed row"), std::string::npos);
  EXPECT_NE(html.find("&lt;title&gt;&amp;&lt;/title&gt;"), std::string::npos);
  for (const char* file : {"accuracy_vs_luts.svg", "luts_latency_vs_n1.svg", "mismatches_vs_coord_w.svg"}) {
    const std::string svg = read_text(dir / file);
    EXPECT_EQ(svg_problem(svg), "") << file;
    EXPECT_EQ(svg.find("<img"), std::string::npos) << file;
    EXPECT_NE(svg.find("&lt;title&gt;&amp;&lt;/title&gt;"), std::string::npos) << file;
  }
  EXPECT_NE(read_text(dir / "accuracy_vs_luts.svg").find("&lt;img src=x onerror=alert(1)&gt;: LUT sites"),
            std::string::npos);
}

TEST(SweepReport, UnwritableOutDirThrowsNamingThePath) {
  const fs::path dir = fresh_dir("unwritable");
  fs::create_directories(dir);
  const fs::path file = dir / "a_file";
  std::ofstream(file) << "not a directory\n";
  for (const fs::path& out : {file / "report", file}) {
    try {
      write_sweep_report(sweep_rows(), out.string(), "x");
      ADD_FAILURE() << "no error for " << out;
    } catch (const rpu::Error& e) {
      EXPECT_NE(std::string(e.what()).find(out.string()), std::string::npos) << e.what();
    }
  }
  // A file in the way of one of the outputs.
  const fs::path blocked = fresh_dir("blocked");
  fs::create_directories(blocked / "index.html");
  try {
    write_sweep_report(sweep_rows(), blocked.string(), "x");
    ADD_FAILURE() << "no error for a directory named index.html";
  } catch (const rpu::Error& e) {
    EXPECT_NE(std::string(e.what()).find((blocked / "index.html").string()), std::string::npos) << e.what();
  }
}

TEST(SweepReport, RowsThatAreNotAnArrayThrow) {
  try {
    write_sweep_report(json{{"rows", 1}}, fresh_dir("object").string(), "x");
    ADD_FAILURE() << "no error for an object";
  } catch (const rpu::Error& e) {
    EXPECT_NE(std::string(e.what()).find("sweep results"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rpu::app
