#include "sweep_report.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "common/error.h"
#include "model/hw_params.h"
#include "report_text.h"
#include "sweep_process.h"

namespace rpu::app {

const std::vector<std::string_view>& sweep_parameters() {
  static const std::vector<std::string_view> keys = [] {
    std::vector<std::string_view> k;
    for (const ref::HwParamInfo& d : ref::hw_param_table()) {
      k.push_back(d.key);
      if (d.id == ref::HwParamId::n1) k.push_back("K");
    }
    return k;
  }();
  return keys;
}

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// ---------------------------------------------------------------------------------------------
// Rows

// The rows as a list; null is an empty sweep.
std::vector<const json*> row_list(const json& rows) {
  if (rows.is_null()) return {};
  if (!rows.is_array())
    throw Error("sweep results", std::string("expected an array of rows, got ") + rows.type_name());
  std::vector<const json*> list;
  for (const json& row : rows) list.push_back(&row);
  return list;
}

const json* field(const json& row, std::string_view key) {
  if (!row.is_object()) return nullptr;
  const auto it = row.find(std::string(key));
  return it == row.end() ? nullptr : &*it;
}

// A measured number: present, numeric and finite.
std::optional<double> number(const json& row, std::string_view key) {
  const json* v = field(row, key);
  if (!v || !v->is_number()) return std::nullopt;
  const double d = v->get<double>();
  if (!std::isfinite(d)) return std::nullopt;
  return d;
}

std::string text(const json& row, std::string_view key) {
  const json* v = field(row, key);
  return v && v->is_string() ? v->get<std::string>() : std::string();
}

bool is_ok(const json& row) { return text(row, "status") == "ok"; }

// The row's config_id, or "row <index>" when it has none.
std::string row_id(const json& row, size_t index) {
  std::string id = text(row, "config_id");
  return id.empty() ? fmt::format("row {}", index) : id;
}

// Whole numbers without a decimal point, others in six significant digits.
std::string number_text(double v) {
  if (std::abs(v) < 1e15 && v == std::floor(v)) return fmt::format("{}", static_cast<long long>(v));
  return fmt::format("{:.6g}", v);
}

// A parameter's value as a short text ("—" when missing).
std::string value_text(const json* v) {
  if (!v || v->is_null()) return "—";
  if (v->is_string()) return v->get<std::string>();
  if (v->is_number()) return number_text(v->get<double>());
  return v->dump();
}

// ---------------------------------------------------------------------------------------------
// Pareto front

struct Candidate {
  size_t row = 0;
  std::string id;
  double luts = 0, mismatches = 0;
};

// The undominated ok rows in (LUT sites, ref_vs_float_total), sorted. Quadratic, which is nothing for
// a sweep's few hundred configurations and keeps the definition visible.
std::vector<Candidate> pareto_candidates(const std::vector<const json*>& rows) {
  std::vector<Candidate> all;
  for (size_t k = 0; k < rows.size(); ++k) {
    const json& row = *rows[k];
    const auto luts = number(row, "lut_sites");
    const auto mismatches = number(row, "ref_vs_float_total");
    if (is_ok(row) && luts && mismatches) all.push_back({k, row_id(row, k), *luts, *mismatches});
  }
  const auto dominates = [](const Candidate& b, const Candidate& a) {
    return b.luts <= a.luts && b.mismatches <= a.mismatches &&
           (b.luts < a.luts || b.mismatches < a.mismatches);
  };
  std::vector<Candidate> front;
  for (const Candidate& a : all)
    if (std::none_of(all.begin(), all.end(), [&](const Candidate& b) { return dominates(b, a); }))
      front.push_back(a);
  std::sort(front.begin(), front.end(), [](const Candidate& a, const Candidate& b) {
    if (a.luts != b.luts) return a.luts < b.luts;
    if (a.mismatches != b.mismatches) return a.mismatches < b.mismatches;
    return a.id < b.id;
  });
  return front;
}

// ---------------------------------------------------------------------------------------------
// Figures: what is plotted (scripts/sweep_plots.py draws it with matplotlib)


struct Point {
  double x = 0, y = 0;
  std::string label;    // drawn next to the point ("" for none)
  std::string tooltip;  // the circle's <title>
};

struct Series {
  std::string name{};    // legend text
  std::string colour{};  // CSS colour
  std::string dash{};    // stroke-dasharray, "" for a solid line
  bool line = true;    // connect the points in x order
  bool highlighted = false;  // the Pareto front: a thicker line, class "pareto"
  double radius = 3.5;
  std::vector<Point> points{};
};

struct Panel {
  std::string title, y_label;
  bool y_from_zero = false;
  std::vector<Series> series;
};

struct Figure {
  std::string title, x_label;
  bool share_y = false;
  std::vector<Panel> panels;
};

// Tableau 10, then the same colours dashed.
constexpr std::string_view kPalette[] = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f",
                                         "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"};
constexpr std::string_view kDashes[] = {"", "6 3", "2 2", "8 3 2 3"};
constexpr std::string_view kParetoColour = "#d62728";
constexpr std::string_view kPointColour = "#4e79a7";

// A figure as the plot data scripts/sweep_plots.py draws (its file name, titles, panels, and every
// series with its style and points).
json figure_json(std::string_view file, const Figure& f) {
  json panels = json::array();
  for (const Panel& p : f.panels) {
    json series = json::array();
    for (const Series& s : p.series) {
      json points = json::array();
      for (const Point& q : s.points)
        points.push_back({{"x", q.x}, {"y", q.y}, {"label", q.label}, {"tooltip", q.tooltip}});
      series.push_back({{"name", s.name}, {"colour", s.colour}, {"dash", s.dash},
                        {"line", s.line}, {"highlighted", s.highlighted}, {"radius", s.radius},
                        {"points", std::move(points)}});
    }
    panels.push_back({{"title", p.title}, {"y_label", p.y_label}, {"y_from_zero", p.y_from_zero},
                      {"series", std::move(series)}});
  }
  return {{"file", file}, {"title", f.title}, {"x_label", f.x_label}, {"share_y", f.share_y},
          {"panels", std::move(panels)}};
}

// ---------------------------------------------------------------------------------------------
// The three plots

// The parameters whose values differ between ok rows (missing counts as a value).
std::vector<std::string_view> varying_parameters(const std::vector<const json*>& rows) {
  std::vector<std::string_view> varying;
  for (std::string_view p : sweep_parameters()) {
    std::optional<json> first;
    for (const json* row : rows) {
      if (!is_ok(*row)) continue;
      const json* v = field(*row, p);
      const json value = v ? *v : json();
      if (!first) {
        first = value;
      } else if (value != *first) {
        varying.push_back(p);
        break;
      }
    }
  }
  return varying;
}

std::string point_tooltip(const json& row, size_t index, std::string_view x_name, double x,
                          std::string_view y_name, double y) {
  return fmt::format("{}: {} {}, {} {}", row_id(row, index), x_name, number_text(x), y_name,
                     number_text(y));
}

// A line plot over x_key: one series per value of the key parameters (`by` and whatever else
// varies, except x_key), one panel per y key. The series have the same colour in every panel.
struct PanelSpec {
  std::string_view y_key, title, y_label;
};

Figure line_figure(const std::vector<const json*>& rows, std::string_view x_key,
                   const std::vector<std::string_view>& by, const std::vector<PanelSpec>& specs,
                   Figure figure, bool y_from_zero) {
  const std::vector<std::string_view> varying = varying_parameters(rows);
  std::vector<std::string_view> key_params;
  for (std::string_view p : sweep_parameters()) {
    const bool wanted = std::find(by.begin(), by.end(), p) != by.end() ||
                        std::find(varying.begin(), varying.end(), p) != varying.end();
    // K = n/n1 is derived: it varies along the n1 axis without making a series of its own.
    if (wanted && p != x_key && p != "K") key_params.push_back(p);
  }
  const auto series_key = [&](const json& row) {
    json key = json::array();
    for (std::string_view p : key_params) {
      const json* v = field(row, p);
      key.push_back(v ? *v : json());
    }
    return key;
  };
  // The series keys in order (json compares numbers numerically), then their styles.
  std::map<json, std::string> names;
  for (const json* row : rows) {
    if (!is_ok(*row) || !number(*row, x_key)) continue;
    std::string name;
    for (std::string_view p : key_params)
      name += fmt::format("{}{}={}", name.empty() ? "" : ", ", p, value_text(field(*row, p)));
    names.emplace(series_key(*row), std::move(name));
  }
  std::map<json, size_t> style;
  for (const auto& [key, name] : names) style.emplace(key, style.size());

  for (const PanelSpec& spec : specs) {
    Panel panel{std::string(spec.title), std::string(spec.y_label), y_from_zero, {}};
    for (const auto& [key, name] : names) {
      const size_t k = style.at(key);
      panel.series.push_back(
          {.name = name,
           .colour = std::string(kPalette[k % std::size(kPalette)]),
           .dash = std::string(kDashes[(k / std::size(kPalette)) % std::size(kDashes)])});
    }
    for (size_t r = 0; r < rows.size(); ++r) {
      const json& row = *rows[r];
      const auto x = number(row, x_key);
      const auto y = number(row, spec.y_key);
      if (!is_ok(row) || !x || !y) continue;
      panel.series[style.at(series_key(row))].points.push_back(
          {*x, *y, "", point_tooltip(row, r, x_key, *x, spec.y_key, *y)});
    }
    std::erase_if(panel.series, [](const Series& s) { return s.points.empty(); });
    figure.panels.push_back(std::move(panel));
  }
  return figure;
}

Figure accuracy_vs_luts(const std::vector<const json*>& rows, const std::vector<Candidate>& front,
                        const std::string& title) {
  Series others{.name = "configuration", .colour = std::string(kPointColour), .line = false};
  Series pareto{.name = "Pareto front", .colour = std::string(kParetoColour), .highlighted = true,
                .radius = 5};
  for (size_t r = 0; r < rows.size(); ++r) {
    const json& row = *rows[r];
    const auto luts = number(row, "lut_sites");
    const auto mismatches = number(row, "ref_vs_float_total");
    if (!is_ok(row) || !luts || !mismatches) continue;
    std::string label = value_text(field(row, "n")) + "/" + value_text(field(row, "n1"));
    if (text(row, "ip") == "iterative") label += " iterative";
    const bool on_front = std::any_of(front.begin(), front.end(),
                                      [&](const Candidate& c) { return c.row == r; });
    (on_front ? pareto : others)
        .points.push_back({*luts, *mismatches, label,
                           point_tooltip(row, r, "LUT sites", *luts, "mismatched pixels", *mismatches) +
                               (on_front ? " (Pareto front)" : "")});
  }
  Figure figure{title + ": accuracy vs LUT sites", "LUT sites", false, {}};
  Panel panel{"mismatched pixels (ref vs float, all scenes) against LUT sites",
              "mismatched pixels", true, {}};
  if (!others.points.empty()) panel.series.push_back(std::move(others));
  if (!pareto.points.empty()) panel.series.push_back(std::move(pareto));
  figure.panels.push_back(std::move(panel));
  return figure;
}

Figure luts_latency_vs_n1(const std::vector<const json*>& rows, const std::string& title) {
  return line_figure(rows, "n1", {"n"},
                     {{"lut_sites", "LUT sites against n1", "LUT sites"},
                      {"rtl_latency_cycles", "latency against n1", "latency (cycles)"}},
                     {title + ": LUT sites and latency vs n1", "n1", false, {}},
                     /*y_from_zero=*/false);
}

Figure mismatches_vs_coord_w(const std::vector<const json*>& rows, const std::string& title) {
  return line_figure(rows, "coord_w", {"n", "n1"},
                     {{"ref_vs_float_total", "ref vs float (double precision, ideal semantics)", "mismatched pixels"},
                      {"ref_vs_float_ip_total", "ref vs float-ip (double precision, the iterative process)",
                       "mismatched pixels"}},
                     {title + ": mismatched pixels vs coord_w", "coord_w", true, {}},
                     /*y_from_zero=*/true);
}

// ---------------------------------------------------------------------------------------------
// index.html

// A JSON value as table text: strings bare, null or missing as "—", numbers compact.
std::string cell(const json* v) {
  if (!v || v->is_null()) return "—";
  if (v->is_string()) return escape_html(v->get<std::string>());
  if (v->is_number_float()) return escape_html(fmt::format("{:.6g}", v->get<double>()));
  return escape_html(v->dump());
}

// "scene: ip / float of pixels" per scene.
std::string scenes_cell(const json* scenes) {
  if (!scenes || !scenes->is_object() || scenes->empty()) return "—";
  std::string html;
  for (const auto& [name, s] : scenes->items())
    html += fmt::format("{}{}: {} / {} of {}", html.empty() ? "" : "<br>", escape_html(name),
                        cell(field(s, "ref_vs_float_ip")), cell(field(s, "ref_vs_float")),
                        cell(field(s, "pixels")));
  return html;
}

// The class of a row's status (never the raw text, which goes into an attribute).
std::string_view status_class(const json& row) {
  const std::string status = text(row, "status");
  if (status == "ok") return "ok";
  if (status == "failed") return "failed";
  if (status == "invalid") return "invalid";
  return "other";
}

constexpr std::string_view kMeasurements[] = {
    "pixels_total", "ref_vs_float_ip_total", "ref_vs_float_total", "rtl_status", "rtl_cycles",
    "rtl_latency_cycles", "rtl_items_per_cycle", "rtl_items", "yosys_status", "yosys_module",
    "lut_sites", "lut", "srl", "lutram", "ff", "dsp", "bram", "carry4", "sta_ns"};

std::string results_table(const std::vector<const json*>& rows, const std::vector<Candidate>& front) {
  std::string html = "<div class=\"wide\"><table>\n<tr><th>config_id</th><th>status</th>";
  for (std::string_view p : sweep_parameters()) html += fmt::format("<th>{}</th>", p);
  for (std::string_view m : kMeasurements) html += fmt::format("<th>{}</th>", m);
  html += "<th>scenes (ref vs float-ip / ref vs float of pixels)</th><th>error</th></tr>\n";
  for (size_t r = 0; r < rows.size(); ++r) {
    const json& row = *rows[r];
    const bool on_front = std::any_of(front.begin(), front.end(),
                                      [&](const Candidate& c) { return c.row == r; });
    html += fmt::format("<tr class=\"{}{}\"><td>{}</td><td>{}</td>", status_class(row),
                        on_front ? " pareto" : "", escape_html(row_id(row, r)), cell(field(row, "status")));
    for (std::string_view p : sweep_parameters())
      html += fmt::format("<td class=\"num\">{}</td>", cell(field(row, p)));
    for (std::string_view m : kMeasurements)
      html += fmt::format("<td class=\"num\">{}</td>", cell(field(row, m)));
    const std::string error =
        row.is_object() ? (field(row, "error") ? cell(field(row, "error")) : std::string())
                        : escape_html("malformed row (not an object): " + row.dump());
    html += fmt::format("<td>{}</td><td class=\"error\">{}</td></tr>\n",
                        scenes_cell(field(row, "scenes")), error);
  }
  return html + "</table></div>\n";
}

std::string pareto_table(const std::vector<const json*>& rows, const std::vector<Candidate>& front) {
  if (front.empty())
    return "<p>No ok configuration has both LUT sites and ref_vs_float_total, so there is no front.</p>\n";
  std::string html = "<table>\n<tr><th>config_id</th>";
  for (std::string_view p : sweep_parameters()) html += fmt::format("<th>{}</th>", p);
  html += "<th>LUT sites</th><th>ref vs float mismatched pixels</th><th>ref vs float-ip mismatched "
          "pixels</th><th>latency (cycles)</th></tr>\n";
  for (const Candidate& c : front) {
    const json& row = *rows[c.row];
    html += fmt::format("<tr><td>{}</td>", escape_html(c.id));
    for (std::string_view p : sweep_parameters())
      html += fmt::format("<td class=\"num\">{}</td>", cell(field(row, p)));
    for (std::string_view m : {"lut_sites", "ref_vs_float_total", "ref_vs_float_ip_total", "rtl_latency_cycles"})
      html += fmt::format("<td class=\"num\">{}</td>", cell(field(row, m)));
    html += "</tr>\n";
  }
  return html + "</table>\n";
}

constexpr std::string_view kStyle = R"(
body { font-family: system-ui, sans-serif; margin: 1.5em; color: #222; }
.gallery { display: flex; flex-wrap: wrap; gap: 1.2em; align-items: flex-start; }
figure { margin: 0; max-width: 100%; }
figure img { display: block; max-width: 100%; height: auto; border: 1px solid #bbb; }
figcaption { font-size: .9em; margin-top: .3em; max-width: 900px; }
.wide { overflow-x: auto; }
table { border-collapse: collapse; margin: .5em 0 1em; font-size: .9em; }
th, td { border: 1px solid #ccc; padding: .2em .5em; text-align: left; vertical-align: top; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
tr.failed, tr.invalid, tr.other { background: #fdecea; }
tr.pareto { background: #fff4d6; }
td.error { font-family: monospace; white-space: pre-wrap; }
)";

std::string index_html(const std::vector<const json*>& rows, const std::vector<Candidate>& front,
                       const std::vector<std::string_view>& plotted, const std::string& title) {
  std::map<std::string, size_t> by_status;
  for (const json* row : rows) ++by_status[row->is_object() ? text(*row, "status") : "malformed"];
  std::string counts = fmt::format("{} ok, {} failed, {} invalid", by_status["ok"],
                                   by_status["failed"], by_status["invalid"]);
  for (const auto& [status, n] : by_status)
    if (n > 0 && status != "ok" && status != "failed" && status != "invalid")
      counts += fmt::format(", {} {}", n, status.empty() ? "without status" : status);

  std::string html = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<title>rpu sweep: {0}</title>\n<style>{1}</style>\n</head>\n<body>\n"
      "<h1>rpu sweep: {0}</h1>\n<p>{2} configurations: {3}. The results as "
      "<a href=\"results.csv\">results.csv</a> and <a href=\"results.json\">results.json</a>.</p>\n",
      escape_html(title), kStyle, rows.size(), escape_html(counts));

  html += "<h2>Plots</h2>\n";
  if (plotted.empty())
    html += "<p>Nothing to plot: no ok configuration has a measurement.</p>\n";
  html += "<div class=\"gallery\">\n";
  const std::pair<std::string_view, std::string_view> plots[] = {
      {kAccuracyVsLutsSvg,
       "Accuracy against area: mismatched pixels of ref vs float over all scenes against the "
       "LUT sites of the whole synthesised module (yosys_module), labelled n/n1; the Pareto "
       "front highlighted."},
      {kLutsLatencyVsN1Svg,
       "LUT sites and RTL latency against n1, one line per n (and per value of any other parameter "
       "the sweep varies)."},
      {kMismatchesVsCoordWSvg,
       "Mismatched pixels against coord_w, ref vs float and ref vs float-ip, one line per (n, n1) "
       "(and per value of any other parameter the sweep varies)."}};
  for (const auto& [file, caption] : plots) {
    if (std::find(plotted.begin(), plotted.end(), file) == plotted.end()) continue;
    html += fmt::format("<figure><a href=\"{0}\"><img src=\"{0}\" alt=\"{0}\"></a>"
                        "<figcaption>{1}</figcaption></figure>\n",
                        escape_html(file), escape_html(caption));
  }
  html += "</div>\n";
  if (!plotted.empty() && plotted.size() < std::size(plots))
    html += "<p>Plots without data are left out (resources need Yosys, latency a co-simulated "
            "sample).</p>\n";

  html += "<h2>Pareto front</h2>\n<p>The ok configurations no other dominates: none has at most "
          "as many LUT sites and at most as many mismatched pixels (ref vs float), and fewer of "
          "one. Sorted by LUT sites.</p>\n";
  html += pareto_table(rows, front);
  html += "<h2>All configurations</h2>\n" + results_table(rows, front);
  return html + "</body>\n</html>\n";
}


// The script that draws the plots with matplotlib, run by /usr/bin/python3 (Debian's, which has
// python3-matplotlib; scripts/setup.sh installs it), on the plot data.
constexpr std::string_view kSweepPlotsScript = RPU_SOURCE_DIR "/scripts/sweep_plots.py";

void draw_plots(const fs::path& data, const fs::path& dir) {
  const fs::path log = dir / "plots.log";
  const int status = run_child({"/usr/bin/python3", std::string(kSweepPlotsScript), data.string(),
                                dir.string()},
                               {"", log.string()});
  if (status != 0)
    throw Error(std::string(kSweepPlotsScript),
                fmt::format("drawing the sweep's plots failed (exit {}; {}); it needs "
                            "/usr/bin/python3 with python3-matplotlib (scripts/setup.sh)",
                            status, log.string()));
  fs::remove(log);
}

}  // namespace

std::vector<std::string> pareto_front(const nlohmann::json& rows) {
  std::vector<std::string> ids;
  for (const Candidate& c : pareto_candidates(row_list(rows))) ids.push_back(c.id);
  return ids;
}

SweepPlots write_sweep_report(const nlohmann::json& rows, const std::string& out_dir,
                              const std::string& title) {
  const std::vector<const json*> list = row_list(rows);
  const fs::path dir = out_dir.empty() ? fs::path(".") : fs::path(out_dir);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw Error(dir.string(), "cannot create the output directory: " + ec.message());
  if (!fs::is_directory(dir)) throw Error(dir.string(), "exists and is not a directory");

  const std::vector<Candidate> front = pareto_candidates(list);
  SweepPlots plots;
  for (const Candidate& c : front) plots.pareto_ids.push_back(c.id);
  const auto write = [&](std::string_view name, const std::string& text) {
    const fs::path path = dir / name;
    write_text_file(path, text);
    plots.files.push_back(path.string());
  };
  // A figure is drawn only with data: its empty panels are dropped, and a figure left with no
  // panel is not drawn (a sweep without Yosys has no LUTs), and its file from an earlier run
  // into this directory is removed, so index.html never shows an empty or stale plot.
  std::vector<std::string_view> plotted;
  json figures = json::array();
  const auto plot = [&](std::string_view name, Figure figure) {
    std::erase_if(figure.panels, [](const Panel& p) {
      return std::all_of(p.series.begin(), p.series.end(),
                         [](const Series& s) { return s.points.empty(); });
    });
    fs::remove(dir / name, ec);
    if (figure.panels.empty()) return;
    figures.push_back(figure_json(name, figure));
    plotted.push_back(name);
  };
  plot(kAccuracyVsLutsSvg, accuracy_vs_luts(list, front, title));
  plot(kLutsLatencyVsN1Svg, luts_latency_vs_n1(list, title));
  plot(kMismatchesVsCoordWSvg, mismatches_vs_coord_w(list, title));
  const fs::path data = dir / kSweepPlotsJson;
  // Texts come from the sweep's file and rows (a title, a config_id): bytes that are not UTF-8
  // become U+FFFD in the plot data, as a browser would show them.
  write_text_file(data, json{{"figures", figures}}.dump(1, ' ', false,
                                                        json::error_handler_t::replace) + "\n");
  if (!plotted.empty()) draw_plots(data, dir);
  for (std::string_view name : plotted) {
    if (!fs::is_regular_file(dir / name))
      throw Error((dir / name).string(), "was not drawn by " + std::string(kSweepPlotsScript));
    plots.files.push_back((dir / name).string());
  }
  write(kSweepIndexHtml, index_html(list, front, plotted, title));
  return plots;
}

}  // namespace rpu::app
