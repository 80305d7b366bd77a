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
// Axes

// A linear axis from lo to hi (lo < hi) with ticks at multiples of a nice step.
struct Axis {
  double lo = 0, hi = 1;
  std::vector<double> ticks;
  int decimals = 0;  // for the tick labels

  // Halved first, so that ends near ±1e308 do not overflow to inf - inf.
  double fraction(double v) const { return (0.5 * v - 0.5 * lo) / (0.5 * hi - 0.5 * lo); }
  std::string label(double v) const {
    if (std::abs(v) < 1e-9 * (hi - lo)) v = 0;  // no "-0"
    return fmt::format("{:.{}f}", v, decimals);
  }
};

// 1, 2, 2.5 or 5 × 10^k, so that span holds about `target` steps.
double nice_step(double span, int target) {
  const double raw = span / target;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / magnitude;
  const double m = f <= 1 ? 1 : f <= 2 ? 2 : f <= 2.5 ? 2.5 : f <= 5 ? 5 : 10;
  return m * magnitude;
}

// The decimals a tick label needs to show multiples of step exactly.
int decimals_of(double step) {
  for (int d = 0; d < 12; ++d) {
    const double scaled = step * std::pow(10.0, d);
    if (std::abs(scaled - std::round(scaled)) < 1e-6 * std::max(1.0, scaled)) return d;
  }
  return 12;
}

// The axis over values: rounded out to whole steps, through zero when from_zero, with whole-number
// steps when integral. An empty set gives [0, 1]; equal values a range around them that does not
// go below zero when they do not.
Axis make_axis(const std::vector<double>& values, bool from_zero, bool integral) {
  double lo = values.empty() ? 0.0 : *std::min_element(values.begin(), values.end());
  double hi = values.empty() ? 1.0 : *std::max_element(values.begin(), values.end());
  if (from_zero) {
    lo = std::min(lo, 0.0);
    hi = std::max(hi, 0.0);
  }
  const double scale = std::max(std::abs(lo), std::abs(hi));
  if (hi - lo <= scale * 1e-9) {
    double pad = scale == 0 ? 1.0 : 0.1 * scale;
    if (integral) pad = std::max(pad, 1.0);
    const bool non_negative = lo >= 0;
    lo -= pad;
    hi += pad;
    if (non_negative) lo = std::max(lo, 0.0);  // LUTs, cycles, widths: never below zero
  }
  Axis axis;
  double step = nice_step(hi - lo, 5);
  if (integral && step != std::floor(step)) step = step < 1 ? 1.0 : 2 * step;  // 2.5 → 5
  const double first = std::floor(lo / step) * step;
  const double last = std::ceil(hi / step) * step;
  const double count = std::round((last - first) / step);
  if (!std::isfinite(step) || !std::isfinite(first) || !std::isfinite(last) || !(count >= 1) ||
      count > 100) {
    // Beyond double's reach (values near ±1e308): the data's own ends, unrounded.
    axis.lo = std::isfinite(lo) ? lo : -1.0;
    axis.hi = std::isfinite(hi) && hi > axis.lo ? hi : axis.lo + 1.0;
    axis.ticks = {axis.lo, axis.hi};
    axis.decimals = 0;
    return axis;
  }
  axis.lo = first;
  axis.hi = last;
  for (int i = 0; i <= static_cast<int>(count); ++i) axis.ticks.push_back(first + i * step);
  axis.decimals = decimals_of(step);
  return axis;
}

// ---------------------------------------------------------------------------------------------
// Figures and their SVG


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
  std::string no_data;  // why a panel without points is empty
  bool share_y = false;
  std::vector<Panel> panels;
};

// Tableau 10, then the same colours dashed.
constexpr std::string_view kPalette[] = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f",
                                         "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"};
constexpr std::string_view kDashes[] = {"", "6 3", "2 2", "8 3 2 3"};
constexpr std::string_view kParetoColour = "#d62728";
constexpr std::string_view kPointColour = "#4e79a7";

// The layout, in SVG user units (pixels).
constexpr double kWidth = 900;
constexpr double kPlotLeft = 90;     // room for the y tick labels and the y label
constexpr double kPlotWidth = 540;
constexpr double kLegendLeft = kPlotLeft + kPlotWidth + 30;
constexpr double kTop = 44;          // the figure title
constexpr double kPanelTitle = 24;
constexpr double kPlotHeight = 260;
constexpr double kPanelBelow = 56;   // x tick labels and the x label
constexpr double kPanelHeight = kPanelTitle + kPlotHeight + kPanelBelow;
constexpr double kLegendRow = 18;

std::string coord(double v) { return fmt::format("{:.2f}", v); }

void append_values(const Panel& p, bool x, std::vector<double>& out) {
  for (const Series& s : p.series)
    for (const Point& q : s.points) out.push_back(x ? q.x : q.y);
}

// One panel whose plot area's top left corner is (left, top).
std::string svg_panel(const Panel& panel, const Axis& x_axis, const Axis* shared_y,
                      const Figure& figure, double top) {
  std::string svg = fmt::format("<g class=\"panel\">\n<text x=\"{}\" y=\"{}\" font-size=\"14\" "
                                "font-weight=\"bold\">{}</text>\n",
                                coord(kPlotLeft), coord(top - 8), escape_html(panel.title));
  const double left = kPlotLeft, bottom = top + kPlotHeight, right = kPlotLeft + kPlotWidth;
  size_t point_count = 0;
  for (const Series& s : panel.series) point_count += s.points.size();
  if (point_count == 0) {
    svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#f6f6f6\" "
                       "stroke=\"#999\"/>\n<text class=\"no-data\" x=\"{}\" y=\"{}\" "
                       "text-anchor=\"middle\" fill=\"#666\">no data: {}</text>\n</g>\n",
                       coord(left), coord(top), coord(kPlotWidth), coord(kPlotHeight),
                       coord(left + kPlotWidth / 2), coord(top + kPlotHeight / 2),
                       escape_html(figure.no_data));
    return svg;
  }

  std::vector<double> ys;
  append_values(panel, false, ys);
  const Axis y_axis = shared_y ? *shared_y : make_axis(ys, panel.y_from_zero, /*integral=*/true);
  const auto px = [&](double x) { return left + x_axis.fraction(x) * kPlotWidth; };
  const auto py = [&](double y) { return bottom - y_axis.fraction(y) * kPlotHeight; };

  // Grid, ticks and their labels.
  svg += "<g class=\"grid\" stroke=\"#e3e3e3\">\n";
  for (double t : x_axis.ticks)
    svg += fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\"/>\n", coord(px(t)),
                       coord(top), coord(bottom));
  for (double t : y_axis.ticks)
    svg += fmt::format("<line x1=\"{1}\" y1=\"{0}\" x2=\"{2}\" y2=\"{0}\"/>\n", coord(py(t)),
                       coord(left), coord(right));
  svg += "</g>\n";
  svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" "
                     "stroke=\"#444\"/>\n",
                     coord(left), coord(top), coord(kPlotWidth), coord(kPlotHeight));
  for (double t : x_axis.ticks)
    svg += fmt::format("<text class=\"x-tick\" x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n",
                       coord(px(t)), coord(bottom + 16), escape_html(x_axis.label(t)));
  for (double t : y_axis.ticks)
    svg += fmt::format("<text class=\"y-tick\" x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>\n",
                       coord(left - 6), coord(py(t) + 4), escape_html(y_axis.label(t)));
  svg += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n",
                     coord(left + kPlotWidth / 2), coord(bottom + 40), escape_html(figure.x_label));
  svg += fmt::format("<text x=\"{0}\" y=\"{1}\" text-anchor=\"middle\" "
                     "transform=\"rotate(-90 {0} {1})\">{2}</text>\n",
                     coord(left - 70), coord(top + kPlotHeight / 2), escape_html(panel.y_label));

  // Lines under the points, labels on top.
  for (const Series& s : panel.series) {
    if (!s.line || s.points.size() < 2) continue;
    std::vector<Point> sorted = s.points;
    std::stable_sort(sorted.begin(), sorted.end(), [](const Point& a, const Point& b) {
      return a.x != b.x ? a.x < b.x : a.y < b.y;
    });
    std::string points;
    for (const Point& q : sorted)
      points += fmt::format("{}{},{}", points.empty() ? "" : " ", coord(px(q.x)), coord(py(q.y)));
    svg += fmt::format("<polyline class=\"{}\" points=\"{}\" fill=\"none\" stroke=\"{}\" "
                       "stroke-width=\"{}\"{}/>\n",
                       s.highlighted ? "pareto" : "series", points, s.colour,
                       s.highlighted ? "2.5" : "1.5",
                       s.dash.empty() ? "" : fmt::format(" stroke-dasharray=\"{}\"", s.dash));
  }
  for (const Series& s : panel.series)
    for (const Point& q : s.points)
      svg += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\" stroke=\"#222\" "
                         "stroke-width=\"0.5\"><title>{}</title></circle>\n",
                         coord(px(q.x)), coord(py(q.y)), s.radius, s.colour, escape_html(q.tooltip));
  for (const Series& s : panel.series)
    for (const Point& q : s.points)
      if (!q.label.empty())
        svg += fmt::format("<text class=\"point-label\" x=\"{}\" y=\"{}\" font-size=\"10\" "
                           "fill=\"#333\">{}</text>\n",
                           coord(px(q.x) + 5), coord(py(q.y) - 5), escape_html(q.label));
  return svg + "</g>\n";
}

// The legend: one row per distinct series name, a line (when the series has one) and a square
// marker, so that <circle> stays one per plotted point.
std::string svg_legend(const Figure& figure, size_t& rows) {
  std::vector<const Series*> entries;
  for (const Panel& p : figure.panels)
    for (const Series& s : p.series)
      if (std::none_of(entries.begin(), entries.end(), [&](const Series* e) { return e->name == s.name; }))
        entries.push_back(&s);
  rows = entries.size();
  std::string svg = "<g class=\"legend\">\n";
  double y = kTop + kPanelTitle;
  for (const Series* s : entries) {
    if (s->line)
      svg += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" "
                         "stroke-width=\"2\"{}/>\n",
                         coord(kLegendLeft), coord(y), coord(kLegendLeft + 24), coord(y), s->colour,
                         s->dash.empty() ? "" : fmt::format(" stroke-dasharray=\"{}\"", s->dash));
    svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"8\" height=\"8\" fill=\"{}\" stroke=\"#222\" "
                       "stroke-width=\"0.5\"/>\n<text x=\"{}\" y=\"{}\">{}</text>\n",
                       coord(kLegendLeft + 8), coord(y - 4), s->colour, coord(kLegendLeft + 32),
                       coord(y + 4), escape_html(s->name));
    y += kLegendRow;
  }
  return svg + "</g>\n";
}

std::string svg_figure(const Figure& figure) {
  std::vector<double> xs, ys;
  for (const Panel& p : figure.panels) {
    append_values(p, true, xs);
    append_values(p, false, ys);
  }
  const Axis x_axis = make_axis(xs, /*from_zero=*/false, /*integral=*/true);
  const bool from_zero = std::any_of(figure.panels.begin(), figure.panels.end(),
                                     [](const Panel& p) { return p.y_from_zero; });
  const Axis shared_y = make_axis(ys, from_zero, /*integral=*/true);

  size_t legend_rows = 0;
  const std::string legend = svg_legend(figure, legend_rows);
  const double height = std::max(kTop + figure.panels.size() * kPanelHeight + 8,
                                 kTop + kPanelTitle + legend_rows * kLegendRow + 16);
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
      "viewBox=\"0 0 {0} {1}\" font-family=\"sans-serif\" font-size=\"12\">\n"
      "<title>{2}</title>\n<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n"
      "<text x=\"{3}\" y=\"24\" font-size=\"16\" font-weight=\"bold\">{2}</text>\n",
      kWidth, height, escape_html(figure.title), coord(kPlotLeft));
  for (size_t k = 0; k < figure.panels.size(); ++k)
    svg += svg_panel(figure.panels[k], x_axis, figure.share_y ? &shared_y : nullptr, figure,
                     kTop + k * kPanelHeight + kPanelTitle);
  return svg + legend + "</svg>\n";
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
  Figure figure{title + ": accuracy vs LUT sites", "LUT sites",
                "no ok configuration has both LUT sites and ref_vs_float_total", false, {}};
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
                     {title + ": LUT sites and latency vs n1", "n1",
                      "no ok configuration has this measurement", false, {}},
                     /*y_from_zero=*/false);
}

Figure mismatches_vs_coord_w(const std::vector<const json*>& rows, const std::string& title) {
  return line_figure(rows, "coord_w", {"n", "n1"},
                     {{"ref_vs_float_total", "ref vs float (double precision, ideal semantics)", "mismatched pixels"},
                      {"ref_vs_float_ip_total", "ref vs float-ip (double precision, the iterative process)",
                       "mismatched pixels"}},
                     {title + ": mismatched pixels vs coord_w", "coord_w",
                      "no ok configuration has this measurement", true, {}},
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
  // A figure is written only with data: its empty panels are dropped, and a figure left with no
  // panel is not written (a sweep without Yosys has no LUTs), and its file from an earlier run
  // into this directory is removed, so index.html never shows an empty or stale plot.
  std::vector<std::string_view> plotted;
  const auto plot = [&](std::string_view name, Figure figure) {
    std::erase_if(figure.panels, [](const Panel& p) {
      return std::all_of(p.series.begin(), p.series.end(),
                         [](const Series& s) { return s.points.empty(); });
    });
    if (figure.panels.empty()) {
      fs::remove(dir / name, ec);
      return;
    }
    write(name, svg_figure(figure));
    plotted.push_back(name);
  };
  plot(kAccuracyVsLutsSvg, accuracy_vs_luts(list, front, title));
  plot(kLutsLatencyVsN1Svg, luts_latency_vs_n1(list, title));
  plot(kMismatchesVsCoordWSvg, mismatches_vs_coord_w(list, title));
  write(kSweepIndexHtml, index_html(list, front, plotted, title));
  return plots;
}

}  // namespace rpu::app
