#include "compare_report.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "common/error.h"
#include "image/image_io.h"
#include "common/output_file.h"
#include "report_text.h"

// app/compare_report.html, the report page with its {{slots}}, embedded at build time
// (app/embed_text.cmake).
extern const char kCompareReportHtml[];

namespace rpu::app {
namespace {

namespace fs = std::filesystem;
namespace IBA = OIIO::ImageBufAlgo;
using OIIO::ImageBuf;
using OIIO::ImageSpec;
using OIIO::ROI;
using OIIO::TypeDesc;

// ---------------------------------------------------------------------------------------------
// Input checks

bool usable_name(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '-' || c == '_';
  });
}

// Every render has a file-safe, unique name, the size of the first render, and primitive ids
// the scene knows.
void check_input(const CompareInput& in) {
  if (in.renders.empty()) throw Error(in.scene, "compare: no backend render to report");
  const image::Frame& first = in.renders.front().frame;
  for (size_t r = 0; r < in.renders.size(); ++r) {
    const BackendRender& render = in.renders[r];
    if (!usable_name(render.name))
      throw Error("backend \"" + render.name + "\"",
                  "a backend name may hold only letters, digits, '-' and '_' (it names files)");
    for (size_t s = 0; s < r; ++s)
      if (in.renders[s].name == render.name)
        throw Error("backend " + render.name, "rendered twice in one comparison");
    const image::Frame& f = render.frame;
    if (f.width <= 0 || f.height <= 0 || f.primitive.size() != static_cast<size_t>(f.width) * f.height)
      throw Error("backend " + render.name,
                  fmt::format("malformed frame: {}×{} with {} pixels", f.width, f.height,
                              f.primitive.size()));
    if (f.width != first.width || f.height != first.height)
      throw Error("backend " + render.name,
                  fmt::format("frame is {}×{} but {} is {}×{}", f.width, f.height,
                              in.renders.front().name, first.width, first.height));
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i) {
        const auto id = f.primitive[f.index(i, j)];
        if (id != image::kBackground && (id < 0 || static_cast<size_t>(id) >= in.colors.size()))
          throw Error(fmt::format("backend {}: pixel ({}, {})", render.name, i, j),
                      fmt::format("primitive id {} but the scene has {} primitives", id, in.colors.size()));
      }
  }
}

// ---------------------------------------------------------------------------------------------
// OpenImageIO helpers

// ImageBufAlgo reports failures through the returned buffer.
ImageBuf checked(ImageBuf buf, std::string_view operation) {
  if (buf.has_error()) throw Error(std::string("ImageBufAlgo::") + std::string(operation), buf.geterror());
  return buf;
}

ImageBuf float_image(int width, int height, int channels, const std::vector<float>& values) {
  ImageBuf buf(ImageSpec(width, height, channels, TypeDesc::FLOAT));
  buf.set_pixels(ROI::All(), TypeDesc::FLOAT, values.data());
  return buf;
}

// The frame in its exact colours (README "Command line").
ImageBuf colour_image(const image::Frame& f, const CompareInput& in) {
  return float_image(f.width, f.height, 3, image::to_rgb(f, in.colors, in.background));
}

// The primitive ids as an image OpenImageIO can compare exactly: id + 1 (0 for background) split
// into its low and high 16 bits, one channel each, so every value is an exact float.
ImageBuf id_image(const image::Frame& f) {
  std::vector<float> v(f.primitive.size() * 2);
  for (size_t k = 0; k < f.primitive.size(); ++k) {
    const auto shifted = static_cast<std::uint32_t>(f.primitive[k] + 1);
    v[2 * k] = static_cast<float>(shifted & 0xffffu);
    v[2 * k + 1] = static_cast<float>(shifted >> 16);
  }
  return float_image(f.width, f.height, 2, v);
}

// 1 where the id image is non-zero in any channel, 0 elsewhere (the values are whole numbers).
ImageBuf nonzero_mask(const ImageBuf& ids) {
  return checked(IBA::clamp(checked(IBA::maxchan(ids), "maxchan"), 0.0f, 1.0f), "clamp");
}

// A one-channel mask repeated into three channels, to weight an RGB image.
ImageBuf rgb_mask(const ImageBuf& mask) {
  return checked(IBA::channels(mask, 3, {0, 0, 0}), "channels");
}

std::array<float, 3> as_float(const scene::Color& c) {
  return {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
}

// The integer enlargement factor for the report (1: shown as is); difference images are enlarged
// up to kDiffEnlargeUpTo.
int enlargement(int width, int height, bool difference = false) {
  const int side = std::max(width, height);
  if (side < kEnlargeBelow) return std::max(2, 2 * kEnlargeBelow / side);
  return difference && side <= kDiffEnlargeUpTo ? 2 : 1;
}

// An image written as <stem>.png, and the file the report shows (an enlarged copy when small).
struct WrittenImage {
  std::string file, shown;
  int shown_width = 0, shown_height = 0;
};

// 8-bit PNG (OpenImageIO converts round(255·v) of v clamped to [0, 1]), every write checked
// (image::write_image_file).
void write_png(const ImageBuf& buf, const fs::path& path) {
  const ImageSpec& spec = buf.spec();
  std::vector<float> values(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  if (!buf.get_pixels(ROI::All(), TypeDesc::FLOAT, values.data()))
    throw Error(path.string(), "cannot read back the image to write: " + buf.geterror());
  image::write_image_file(path.string(),
                          ImageSpec(spec.width, spec.height, spec.nchannels, TypeDesc::UINT8),
                          TypeDesc::FLOAT, values.data());
}

WrittenImage write_image(const ImageBuf& buf, const fs::path& dir, const std::string& stem,
                         bool difference = false) {
  const ImageSpec& spec = buf.spec();
  WrittenImage w{stem + ".png", stem + ".png", spec.width, spec.height};
  write_png(buf, dir / w.file);
  if (const int k = enlargement(spec.width, spec.height, difference); k > 1) {
    // Nearest neighbour at an integer factor: every source pixel becomes a crisp k×k block.
    const ROI big(0, spec.width * k, 0, spec.height * k, 0, 1, 0, spec.nchannels);
    w.shown = fmt::format("{}_x{}.png", stem, k);
    w.shown_width = spec.width * k;
    w.shown_height = spec.height * k;
    write_png(checked(IBA::resample(buf, /*interpolate=*/false, big), "resample"), dir / w.shown);
  }
  return w;
}

// The colour a PNG holds for a linear value v (as image::write_rgb and OIIO write it).
std::string css_colour(const std::array<float, 3>& c) {
  const auto byte = [](float v) { return static_cast<int>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  return fmt::format("#{:02x}{:02x}{:02x}", byte(c[0]), byte(c[1]), byte(c[2]));
}

// ---------------------------------------------------------------------------------------------
// Comparisons

std::string key_name(std::string_view backend) {
  std::string k(backend);
  std::replace(k.begin(), k.end(), '-', '_');
  return k;
}

struct PairResult {
  std::string a, b, key;  // key: "<a>_vs_<b>" with '-' as '_'
  size_t mismatched = 0, only_a = 0, only_b = 0, different_primitive = 0;
  ImageBuf differ;        // one channel, 1 where the primitive ids differ
  WrittenImage image;
};

// Compares two renders, writes diff_<a>_vs_<b>.png: a dimmed where they agree, kHitOnlyInA /
// kHitOnlyInB where only one has a hit, kDifferentPrimitive where both hit different primitives.
PairResult compare_pair(const BackendRender& ra, const BackendRender& rb, const CompareInput& in,
                        const fs::path& dir) {
  PairResult p;
  p.a = ra.name;
  p.b = rb.name;
  p.key = key_name(ra.name) + "_vs_" + key_name(rb.name);
  const image::Frame& fa = ra.frame;
  const image::Frame& fb = rb.frame;

  // The counts, from the frames themselves.
  p.mismatched = image::count_differing_pixels(fa, fb);
  for (size_t k = 0; k < fa.primitive.size(); ++k) {
    const bool ha = fa.primitive[k] != image::kBackground;
    const bool hb = fb.primitive[k] != image::kBackground;
    p.only_a += ha && !hb;
    p.only_b += hb && !ha;
    p.different_primitive += ha && hb && fa.primitive[k] != fb.primitive[k];
  }

  // The same through OpenImageIO, which also yields the masks the images are built from.
  const ImageBuf ids_a = id_image(fa), ids_b = id_image(fb);
  const IBA::CompareResults cmp = IBA::compare(ids_a, ids_b, 0.5f, 0.5f);
  if (cmp.nfail != p.mismatched)
    throw Error("compare " + p.a + " vs " + p.b,
                fmt::format("ImageBufAlgo::compare finds {} differing pixels, the frames {}",
                            cmp.nfail, p.mismatched));
  p.differ = nonzero_mask(checked(IBA::absdiff(ids_a, ids_b), "absdiff"));
  const ImageBuf hit_a = nonzero_mask(ids_a), hit_b = nonzero_mask(ids_b);
  const ImageBuf miss_a = checked(IBA::invert(hit_a), "invert");
  const ImageBuf miss_b = checked(IBA::invert(hit_b), "invert");
  const ImageBuf only_a = checked(IBA::mul(hit_a, miss_b), "mul");
  const ImageBuf only_b = checked(IBA::mul(hit_b, miss_a), "mul");
  const ImageBuf both_differ = checked(IBA::mul(p.differ, checked(IBA::mul(hit_a, hit_b), "mul")), "mul");
  const ImageBuf agree = checked(IBA::invert(p.differ), "invert");

  // Exactly one of the four masks is 1 at each pixel, so a weighted sum composes the image.
  const auto paint = [](const ImageBuf& image, const ImageBuf& mask, const scene::Color& colour) {
    const auto c = as_float(colour);
    const ImageBuf layer = checked(IBA::mul(rgb_mask(mask), OIIO::cspan<float>(c.data(), c.size())), "mul");
    return checked(IBA::add(image, layer), "add");
  };
  const ImageBuf dimmed = checked(IBA::mul(colour_image(fa, in), kAgreeBrightness), "mul");
  ImageBuf diff = checked(IBA::mul(dimmed, rgb_mask(agree)), "mul");
  diff = paint(diff, only_a, kHitOnlyInA);
  diff = paint(diff, only_b, kHitOnlyInB);
  diff = paint(diff, both_differ, kDifferentPrimitive);
  p.image = write_image(diff, dir, fmt::format("diff_{}_vs_{}", p.a, p.b), /*difference=*/true);
  return p;
}

// Per pixel, the number of compared pairs that disagree there.
struct HeatMap {
  int pairs = 0;                      // P, pairs compared
  std::vector<size_t> histogram;      // pixels with d = 0..P disagreeing pairs
  std::vector<std::string> legend;    // CSS colour of d = 0..P
  WrittenImage image;
};

// The colour map applied to the heat value. OpenImageIO's maps are linear; encoded to sRGB they
// give the published colours (inferno: #000004 at 0 to #fcffa4 at 1).
ImageBuf heat_colours(const ImageBuf& value) {
  const ImageBuf linear = checked(IBA::color_map(value, 0, kHeatColorMap), "color_map");
  return checked(IBA::colorconvert(linear, "linear", "sRGB"), "colorconvert");
}

HeatMap heat_map(const std::vector<PairResult>& pairs, int width, int height, const fs::path& dir) {
  HeatMap h;
  h.pairs = static_cast<int>(pairs.size());
  const ROI roi(0, width, 0, height, 0, 1, 0, 1);
  ImageBuf count = checked(IBA::zero(roi), "zero");
  for (const PairResult& p : pairs) count = checked(IBA::add(count, p.differ), "add");

  std::vector<float> d(static_cast<size_t>(width) * height);
  count.get_pixels(roi, TypeDesc::FLOAT, d.data());
  h.histogram.assign(static_cast<size_t>(h.pairs) + 1, 0);
  for (float v : d) ++h.histogram.at(static_cast<size_t>(std::lround(v)));

  // heat_value(d) = (d + [d > 0]) / (P + 1), as in the header.
  const float scale = 1.0f / static_cast<float>(h.pairs + 1);
  const ImageBuf value =
      checked(IBA::mul(checked(IBA::add(count, nonzero_mask(count)), "add"), scale), "mul");
  h.image = write_image(heat_colours(value), dir, "heatmap");

  // The legend goes through the same colour map.
  std::vector<float> steps;
  for (int k = 0; k <= h.pairs; ++k) steps.push_back(static_cast<float>(heat_value(k, h.pairs)));
  const ImageBuf swatches = heat_colours(float_image(h.pairs + 1, 1, 1, steps));
  for (int k = 0; k <= h.pairs; ++k) {
    std::array<float, 3> c{};
    swatches.getpixel(k, 0, c.data(), 3);
    h.legend.push_back(css_colour(c));
  }
  return h;
}

// ---------------------------------------------------------------------------------------------
// report.html


// A JSON value as table text: strings bare, null as "—", everything else as JSON.
std::string cell(const nlohmann::json& v) {
  if (v.is_null()) return "—";
  if (v.is_string()) return escape_html(v.get<std::string>());
  if (v.is_number_float()) return escape_html(fmt::format("{:.6g}", v.get<double>()));
  return escape_html(v.dump());
}

// Rows "a.b.c | value" for a nested JSON object (arrays stay whole).
void flatten(const nlohmann::json& v, const std::string& prefix,
             std::vector<std::pair<std::string, nlohmann::json>>& rows) {
  if (v.is_object() && !v.empty()) {
    for (const auto& [key, value] : v.items())
      flatten(value, prefix.empty() ? key : prefix + "." + key, rows);
  } else {
    rows.emplace_back(prefix, v);
  }
}

std::string key_value_table(const nlohmann::json& v, std::string_view when_empty) {
  if (v.is_null() || (v.is_object() && v.empty())) return fmt::format("<p>{}</p>\n", escape_html(when_empty));
  std::vector<std::pair<std::string, nlohmann::json>> rows;
  flatten(v, "", rows);
  std::string html = "<table>\n<tr><th>parameter</th><th>value</th></tr>\n";
  for (const auto& [key, value] : rows)
    html += fmt::format("<tr><td>{}</td><td class=\"num\">{}</td></tr>\n", escape_html(key), cell(value));
  return html + "</table>\n";
}

std::string figure(const WrittenImage& w, const std::string& caption_html) {
  return fmt::format(
      "<figure><a href=\"{0}\"><img src=\"{1}\" width=\"{2}\" height=\"{3}\" alt=\"{4}\"></a>"
      "<figcaption>{5}</figcaption></figure>\n",
      escape_html(w.file), escape_html(w.shown), w.shown_width, w.shown_height, escape_html(w.file), caption_html);
}

std::string swatch(const std::string& css) {
  return fmt::format("<span class=\"swatch\" style=\"background:{}\"></span>", css);
}

struct ReportParts {
  const CompareInput& in;
  const nlohmann::json& metrics;
  const std::vector<WrittenImage>& renders;  // parallel to in.renders
  const std::vector<PairResult>& pairs;
  const HeatMap& heat;
};

std::string banner(const CompareInput& in, const nlohmann::json& metrics) {
  const auto has = [&](std::string_view name) {
    return std::any_of(in.renders.begin(), in.renders.end(), [&](const auto& r) { return r.name == name; });
  };
  if (!has("rtl")) return "<div class=\"banner skip\">rtl not run</div>\n";
  if (!has("ref")) return "<div class=\"banner skip\">rtl not checked: ref not run</div>\n";
  const auto differ = metrics["rtl_vs_ref_mismatched_pixels"].get<size_t>();
  const auto pixels = metrics["pixels"].get<size_t>();
  const nlohmann::json& items = metrics["rtl_work_item_mismatches"];
  if (differ == 0 && items.is_number() && items.get<size_t>() > 0)
    return fmt::format("<div class=\"banner fail\">FAIL: rtl == ref on all {} pixels, but {} work "
                       "items differ from the model in some field (see the mismatch records)</div>\n",
                       pixels, items.get<size_t>());
  if (differ == 0)
    return fmt::format("<div class=\"banner pass\">PASS: rtl == ref on all {} pixels</div>\n",
                       pixels);
  return fmt::format("<div class=\"banner fail\">FAIL: rtl differs from ref on {} of {} pixels</div>\n",
                     differ, pixels);
}

// The ref vs float-ip banner: shown when the difference exceeds the documented bound.
std::string bound_banner(const nlohmann::json& metrics) {
  const std::string warning = ref_vs_float_ip_warning(metrics);
  if (warning.empty()) return "";
  return "<div class=\"banner warn\">WARNING: " + escape_html(warning) + "</div>\n";
}

// The page: app/compare_report.html (embedded, kCompareReportHtml) with each {{slot}} replaced by
// its HTML. A slot the template names that the report does not fill, or the reverse, is a bug.
std::string fill_template(std::string_view page, const std::map<std::string, std::string>& slots) {
  std::string out;
  std::set<std::string> used;
  size_t at = 0;
  for (size_t open = page.find("{{"); open != std::string_view::npos; open = page.find("{{", at)) {
    const size_t close = page.find("}}", open);
    if (close == std::string_view::npos)
      throw std::logic_error("app/compare_report.html: an unclosed {{");
    const std::string name(page.substr(open + 2, close - open - 2));
    const auto it = slots.find(name);
    if (it == slots.end())
      throw std::logic_error("app/compare_report.html: no value for {{" + name + "}}");
    out.append(page.substr(at, open - at)).append(it->second);
    used.insert(name);
    at = close + 2;
  }
  out.append(page.substr(at));
  for (const auto& [name, value] : slots)
    if (!used.count(name))
      throw std::logic_error("app/compare_report.html: no {{" + name + "}} for its value");
  return out;
}

std::string report_html(const ReportParts& r) {
  const CompareInput& in = r.in;
  const nlohmann::json& m = r.metrics;
  std::map<std::string, std::string> slot;
  slot["scene"] = escape_html(in.scene);
  slot["width"] = std::to_string(m["width"].get<int>());
  slot["height"] = std::to_string(m["height"].get<int>());
  slot["pixels"] = std::to_string(m["pixels"].get<size_t>());
  slot["banners"] = banner(in, m) + bound_banner(m);

  std::string& renders = slot["renders"];
  for (size_t k = 0; k < in.renders.size(); ++k) {
    const BackendRender& b = in.renders[k];
    renders += figure(r.renders[k], fmt::format("<b>{}</b>: {} hit pixels, {:.3f} s", escape_html(b.name),
                                                b.frame.hit_pixels(), b.seconds));
  }

  std::string& differences = slot["differences"];
  if (r.pairs.empty()) {
    differences = "<p>No pair of backends to compare.</p>\n";
  } else {
    differences = fmt::format(
        "<p>In the image of <i>a</i> vs <i>b</i>: pixels where both agree show <i>a</i> at {:.0f} % "
        "brightness; {}hit only in <i>a</i>; {}hit only in <i>b</i>; {}both hit, different "
        "primitive.</p>\n<div class=\"gallery\">\n",
        100.0f * kAgreeBrightness, swatch(css_colour(as_float(kHitOnlyInA))),
        swatch(css_colour(as_float(kHitOnlyInB))), swatch(css_colour(as_float(kDifferentPrimitive))));
    for (const PairResult& p : r.pairs)
      differences += figure(p.image, fmt::format("<b>{0}</b> vs <b>{1}</b>: {2} pixels differ<br>"
                                                 "only {0}: {3}, only {1}: {4}, different primitive: {5}",
                                                 escape_html(p.a), escape_html(p.b), p.mismatched, p.only_a,
                                                 p.only_b, p.different_primitive));
    differences += "</div>\n";
  }

  std::string& heat = slot["heat"];
  heat = fmt::format("<p>Per pixel, how many of the {} compared pairs disagree (colour map \"{}\"): ",
                     r.heat.pairs, escape_html(kHeatColorMap));
  for (int d = 0; d <= r.heat.pairs; ++d)
    heat += fmt::format("{}{} ({} px){}", swatch(r.heat.legend[static_cast<size_t>(d)]), d,
                        r.heat.histogram[static_cast<size_t>(d)], d < r.heat.pairs ? ", " : ".");
  std::string compared;
  for (const PairResult& p : r.pairs) compared += (compared.empty() ? "" : ", ") + p.a + " vs " + p.b;
  heat += "</p>\n<div class=\"gallery\">\n" +
          figure(r.heat.image, "pairs: " + escape_html(compared.empty() ? "none" : compared)) + "</div>\n";

  std::string& metrics = slot["metrics"];
  metrics = "<table>\n<tr><th>metric</th><th>value</th></tr>\n";
  for (const char* key : {"pixels", "rtl_vs_ref_mismatched_pixels", "ref_vs_float_ip_mismatched_pixels",
                          "ref_vs_float_mismatched_pixels", "float_ip_vs_float_mismatched_pixels",
                          "ref_vs_float_ip_beyond_bound", "cycles", "pairs", "latency_cycles",
                          "rtl_equals_ref"})
    metrics += fmt::format("<tr><td>{}</td><td class=\"num\">{}</td></tr>\n", key, cell(m[key]));
  metrics += "</table>\n<table>\n<tr><th>backend</th><th>hit pixels</th><th>seconds</th></tr>\n";
  for (const BackendRender& b : in.renders)
    metrics += fmt::format("<tr><td>{}</td><td class=\"num\">{}</td><td class=\"num\">{:.3f}</td></tr>\n",
                           escape_html(b.name), b.frame.hit_pixels(), b.seconds);
  metrics += "</table>\n";
  if (!r.pairs.empty()) {
    metrics += "<table>\n<tr><th>a vs b</th><th>differ</th><th>hit only in a</th><th>hit only in b</th>"
               "<th>different primitive</th></tr>\n";
    for (const PairResult& p : r.pairs)
      metrics += fmt::format(
          "<tr><td>{} vs {}</td><td class=\"num\">{}</td><td class=\"num\">{}</td>"
          "<td class=\"num\">{}</td><td class=\"num\">{}</td></tr>\n",
          escape_html(p.a), escape_html(p.b), p.mismatched, p.only_a, p.only_b, p.different_primitive);
    metrics += "</table>\n";
  }

  slot["record"] = key_value_table(in.record, "Not recorded.");
  slot["resources"] = key_value_table(m.contains("resources") ? m["resources"] : nlohmann::json(),
                                      "Not given.");

  std::string& differing = slot["differing"];
  differing = fmt::format("<p>{} pixels where two renders disagree on the primitive{}; depths in "
                          "world units along W.</p>\n",
                          m["differing_pixels_total"].get<size_t>(),
                          m["differing_pixels_total"].get<size_t>() > kMaxPixelRecords
                              ? fmt::format(" (the first {} listed)", kMaxPixelRecords)
                              : std::string());
  if (!m["differing_pixels"].empty()) {
    differing += "<table>\n<tr><th>pixel</th>";
    for (const BackendRender& b : in.renders)
      differing += fmt::format("<th>{0} primitive</th><th>{0} depth</th>", escape_html(b.name));
    differing += "</tr>\n";
    for (const auto& rec : m["differing_pixels"]) {
      differing += fmt::format("<tr><td>({}, {})</td>", rec["x"].get<int>(), rec["y"].get<int>());
      for (const BackendRender& b : in.renders) {
        const auto& v = rec[b.name];
        differing += fmt::format("<td class=\"num\">{}</td><td class=\"num\">{}</td>",
                                 v["primitive"].is_null() ? "—" : v["primitive"].dump(),
                                 v["depth"].is_null() ? "—" : fmt::format("{:.6g}", v["depth"].get<double>()));
      }
      differing += "</tr>\n";
    }
    differing += "</table>\n";
  }

  std::string& depth = slot["depth"];
  if (m["depth_ref_vs_float"].is_object()) {
    const auto& d = m["depth_ref_vs_float"];
    depth += fmt::format("<p>ref vs float, on the {} pixels both hit with the same primitive: "
                         "relative depth difference mean {:.3g}, max {:.3g}; {} pixels beyond "
                         "{:g}.</p>\n",
                         d["pixels"].get<size_t>(), d["mean_relative"].get<double>(),
                         d["max_relative"].get<double>(), d["beyond_1e-3"].get<size_t>(),
                         kDepthAgreement);
  }
  if (m["curve_gaps_vs_float"].is_object()) {
    std::string gaps;
    for (const auto& [name, v] : m["curve_gaps_vs_float"].items())
      gaps += fmt::format("{}{}: {}", gaps.empty() ? "" : ", ", escape_html(name), v.get<long>());
    depth += "<p>Gaps along curves where float is connected and the backend is not (extra "
             "8-connected pieces per curve, summed): " + gaps + ".</p>\n";
  }

  slot["config"] = key_value_table(in.config, "No configuration given.");
  slot["rtl"] = key_value_table(in.rtl, "The RTL was not simulated.");
  std::string& mismatches = slot["mismatches"];
  if (in.mismatch_lines.empty()) {
    mismatches = "<p>None recorded.</p>\n";
  } else {
    mismatches = "<pre>";
    for (const std::string& line : in.mismatch_lines) mismatches += escape_html(line) + "\n";
    mismatches += "</pre>\n";
  }
  return fill_template(kCompareReportHtml, slot);
}


// ---------------------------------------------------------------------------------------------
// The engineering record: differing pixels, depth agreement, curve connectivity

namespace {

double depth_world(const BackendRender& r, size_t k) { return r.frame.depth[k] * r.depth_unit; }

// Pixels where two renders (every pair present, and rtl against its reference) disagree on the
// primitive, in scan order, at most kMaxPixelRecords, with every render's primitive and depth.
nlohmann::json pixel_records(const CompareInput& in, size_t& total) {
  std::vector<const BackendRender*> all;
  for (const auto& r : in.renders) all.push_back(&r);
  const image::Frame& f0 = in.renders.front().frame;
  nlohmann::json list = nlohmann::json::array();
  total = 0;
  for (int j = 0; j < f0.height; ++j)
    for (int i = 0; i < f0.width; ++i) {
      const size_t k = f0.index(i, j);
      bool differ = false;
      for (size_t a = 0; a < all.size() && !differ; ++a)
        for (size_t b = a + 1; b < all.size() && !differ; ++b)
          differ = all[a]->frame.primitive[k] != all[b]->frame.primitive[k];
      if (!differ) continue;
      ++total;
      if (list.size() >= kMaxPixelRecords) continue;
      nlohmann::json rec = {{"x", i}, {"y", j}};
      for (const auto* r : all) {
        const std::int32_t p = r->frame.primitive[k];
        rec[r->name] = p == image::kBackground
                           ? nlohmann::json{{"primitive", nullptr}, {"depth", nullptr}}
                           : nlohmann::json{{"primitive", p}, {"depth", depth_world(*r, k)}};
      }
      list.push_back(rec);
    }
  return list;
}

// ref against float where both hit the same primitive: how many, and the relative depth
// difference |c_ref − c_float| / c_float (mean, max, how many beyond kDepthAgreement).
nlohmann::json depth_statistics(const BackendRender& a, const BackendRender& b) {
  size_t n = 0, beyond = 0;
  double sum = 0.0, max = 0.0;
  for (size_t k = 0; k < a.frame.primitive.size(); ++k) {
    if (a.frame.primitive[k] == image::kBackground || a.frame.primitive[k] != b.frame.primitive[k]) continue;
    const double da = depth_world(a, k), db = depth_world(b, k);
    const double rel = std::fabs(da - db) / std::max(std::fabs(db), 1e-300);
    ++n;
    sum += rel;
    max = std::max(max, rel);
    beyond += rel > kDepthAgreement;
  }
  return {{"pixels", n}, {"mean_relative", n ? sum / static_cast<double>(n) : 0.0},
          {"max_relative", max}, {"beyond_1e-3", beyond}};
}

// 8-connected pieces of one primitive's pixels.
int pieces(const image::Frame& f, std::int32_t id) {
  std::vector<char> seen(f.primitive.size(), 0);
  std::vector<std::pair<int, int>> stack;
  int count = 0;
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) {
      const size_t k = f.index(i, j);
      if (seen[k] || f.primitive[k] != id) continue;
      ++count;
      seen[k] = 1;
      stack.push_back({i, j});
      while (!stack.empty()) {
        const auto [x, y] = stack.back();
        stack.pop_back();
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int u = x + dx, v = y + dy;
            if (u < 0 || v < 0 || u >= f.width || v >= f.height) continue;
            const size_t q = f.index(u, v);
            if (seen[q] || f.primitive[q] != id) continue;
            seen[q] = 1;
            stack.push_back({u, v});
          }
      }
    }
  return count;
}

// Per backend: the gaps along curves where float is connected and the backend is not, counted as
// the extra 8-connected pieces of each curve's pixels, summed over the curves.
nlohmann::json curve_connectivity(const CompareInput& in, const BackendRender& ideal) {
  nlohmann::json out = nlohmann::json::object();
  for (const BackendRender& r : in.renders) {
    if (&r == &ideal) continue;
    long gaps = 0;
    for (size_t id = 0; id < in.curve_primitive.size(); ++id) {
      if (!in.curve_primitive[id]) continue;
      const int want = pieces(ideal.frame, static_cast<std::int32_t>(id));
      const int have = pieces(r.frame, static_cast<std::int32_t>(id));
      gaps += std::max(0, have - want);
    }
    out[r.name] = gaps;
  }
  return out;
}

}  // namespace

// Writes every file of the report into `dir` (an existing, empty staging directory).
CompareSummary write_report_files(const CompareInput& in, const fs::path& dir) {
  const image::Frame& first = in.renders.front().frame;
  const auto find = [&](std::string_view name) -> const BackendRender* {
    for (const auto& r : in.renders)
      if (r.name == name) return &r;
    return nullptr;
  };

  nlohmann::json metrics = {{"scene", in.scene},
                            {"width", first.width},
                            {"height", first.height},
                            {"pixels", first.primitive.size()},
                            {"config", in.config},
                            {"rtl", in.rtl},
                            {"mismatch_records", in.mismatch_lines}};
  if (in.extra_metrics.is_object())
    for (const auto& [key, value] : in.extra_metrics.items()) metrics[key] = value;

  std::vector<WrittenImage> render_images;
  for (const BackendRender& b : in.renders) {
    render_images.push_back(write_image(colour_image(b.frame, in), dir, b.name));
    metrics["backends"][b.name] = {{"hit_pixels", b.frame.hit_pixels()},
                                   {"seconds", b.seconds},
                                   {"image", render_images.back().file}};
  }

  std::vector<PairResult> pairs;
  for (const auto& [a, b] : kComparedPairs) {
    const std::string key = key_name(a) + "_vs_" + key_name(b);
    const BackendRender* ra = find(a);
    const BackendRender* rb = find(b);
    if (!ra || !rb) {
      metrics[key + "_mismatched_pixels"] = nullptr;
      metrics["comparisons"][key] = nullptr;
      continue;
    }
    PairResult p = compare_pair(*ra, *rb, in, dir);
    metrics[key + "_mismatched_pixels"] = p.mismatched;
    metrics["comparisons"][key] = {{"mismatched_pixels", p.mismatched},
                                   {"hit_only_in_" + key_name(a), p.only_a},
                                   {"hit_only_in_" + key_name(b), p.only_b},
                                   {"different_primitive", p.different_primitive},
                                   {"image", p.image.file}};
    pairs.push_back(std::move(p));
  }

  for (const char* stat : {"cycles", "pairs", "latency_cycles"})
    metrics[stat] = in.rtl.is_object() && in.rtl.contains(stat) ? in.rtl[stat] : nlohmann::json();
  // The co-simulation's own checker: work items (every result field) and the pixel stream.
  metrics["rtl_work_item_mismatches"] =
      in.rtl.is_object() && in.rtl.contains("item_mismatches") ? in.rtl["item_mismatches"]
                                                               : nlohmann::json();

  const bool checked_rtl = find("rtl") && find("ref");
  const bool rtl_equals_ref = checked_rtl && metrics["rtl_vs_ref_mismatched_pixels"].get<size_t>() == 0;
  metrics["rtl_equals_ref"] = checked_rtl ? nlohmann::json(rtl_equals_ref) : nlohmann::json();
  // The engineering record.
  metrics["record"] = in.record;
  size_t differing = 0;
  metrics["differing_pixels"] = pixel_records(in, differing);
  metrics["differing_pixels_total"] = differing;
  if (const BackendRender* ref = find("ref"), *fl = find("float"); ref && fl)
    metrics["depth_ref_vs_float"] = depth_statistics(*ref, *fl);
  else
    metrics["depth_ref_vs_float"] = nullptr;
  const bool any_curve = std::find(in.curve_primitive.begin(), in.curve_primitive.end(), true) !=
                         in.curve_primitive.end();
  if (const BackendRender* fl = find("float"); fl && any_curve)
    metrics["curve_gaps_vs_float"] = curve_connectivity(in, *fl);
  else
    metrics["curve_gaps_vs_float"] = nullptr;
  // How much slower the cycle-accurate co-simulation is than the model on the same frame (each
  // backend's wall time).
  {
    const BackendRender* rtl = find("rtl");
    const BackendRender* model = find("ref");
    metrics["rtl_to_model_time"] = rtl && model && model->seconds > 0
                                       ? nlohmann::json(rtl->seconds / model->seconds)
                                       : nlohmann::json();
  }

  // ref vs float-ip against the documented bound (README; docs/fixed-point.md).
  if (const BackendRender* ref = find("ref"), *ip = find("float-ip"); ref && ip) {
    const RefVsFloatIp r = ref_vs_float_ip(ref->frame, ip->frame);
    metrics["ref_vs_float_ip_hit_pixels"] = r.hit_pixels;
    metrics["ref_vs_float_ip_fraction"] = r.fraction;
    metrics["ref_vs_float_ip_beyond_bound"] = r.beyond_bound;
  } else {
    metrics["ref_vs_float_ip_hit_pixels"] = nullptr;
    metrics["ref_vs_float_ip_fraction"] = nullptr;
    metrics["ref_vs_float_ip_beyond_bound"] = nullptr;
  }
  metrics["ref_vs_float_ip_bound"] = kRefVsFloatIpBound;

  const HeatMap heat = heat_map(pairs, first.width, first.height, dir);
  nlohmann::json compared = nlohmann::json::array();
  for (const PairResult& p : pairs) compared.push_back(p.key);
  metrics["heatmap"] = {{"image", heat.image.file},
                        {"color_map", kHeatColorMap},
                        {"pairs_compared", compared},
                        {"pixels_by_disagreeing_pairs", heat.histogram}};

  // Scene names and mismatch records may hold any bytes: invalid UTF-8 is replaced, not fatal.
  write_text_file(dir / "metrics.json",
                  metrics.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  write_text_file(dir / "report.html", report_html({in, metrics, render_images, pairs, heat}));
  return {metrics, rtl_equals_ref, ref_vs_float_ip_warning(metrics)};
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// The output directory

namespace {

// The file stems compare writes: every backend of kComparedPairs and of `renders`, every
// diff_<a>_vs_<b>, the heat map.
std::set<std::string> owned_stems(const std::vector<BackendRender>& renders) {
  std::set<std::string> stems = {"heatmap"};
  for (const auto& [a, b] : kComparedPairs) {
    stems.insert(std::string(a));
    stems.insert(std::string(b));
    stems.insert(fmt::format("diff_{}_vs_{}", a, b));
  }
  for (const BackendRender& r : renders) stems.insert(r.name);
  return stems;
}

// True for the names compare owns in its directory: metrics.json, report.html, and <stem>.png
// or <stem>_x<k>.png for an owned stem.
bool owned_file(const std::string& name, const std::set<std::string>& stems) {
  if (name == "metrics.json" || name == "report.html") return true;
  if (!name.ends_with(".png")) return false;
  std::string stem = name.substr(0, name.size() - 4);
  if (stems.count(stem)) return true;
  const size_t x = stem.rfind("_x");
  if (x == std::string::npos || x + 2 == stem.size()) return false;
  for (size_t k = x + 2; k < stem.size(); ++k)
    if (!std::isdigit(static_cast<unsigned char>(stem[k]))) return false;
  return stems.count(stem.substr(0, x)) > 0;
}

bool is_directory_entry(const fs::path& p) {
  struct stat st {};
  return ::lstat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

// The staging directories of compare runs that no longer exist (killed before cleaning up).
constexpr std::string_view kStagingPrefix = ".rpu-compare-staging-";

void remove_abandoned_staging(const fs::path& dir) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (!name.starts_with(kStagingPrefix)) continue;
    const std::string pid_text = name.substr(kStagingPrefix.size(), name.find('_') - kStagingPrefix.size());
    char* end = nullptr;
    const long pid = std::strtol(pid_text.c_str(), &end, 10);
    if (pid <= 0 || *end != '\0') continue;
    if (pid != ::getpid() && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH &&
        is_directory_entry(e.path()))
      fs::remove_all(e.path(), ec);
  }
}

}  // namespace

void check_compare_output(const std::string& out_dir, const std::string& input_file) {
  if (out_dir.empty())
    throw Error("--out", "the output directory is empty; name a directory (e.g. --out out/cmp)");
  const fs::path dir(out_dir);
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw Error(out_dir, "exists and is not a directory");
  if (input_file.empty() || !fs::is_directory(dir, ec)) return;
  const std::set<std::string> stems = owned_stems({});
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (owned_file(name, stems) && same_file(e.path().string(), input_file))
      throw Error(e.path().string(), "is the scene file being compared; rpu compare would "
                                     "overwrite it (choose another --out)");
  }
}

RefVsFloatIp ref_vs_float_ip(const image::Frame& ref, const image::Frame& float_ip) {
  RefVsFloatIp r;
  r.differing = image::count_differing_pixels(ref, float_ip);
  r.hit_pixels = std::max(ref.hit_pixels(), float_ip.hit_pixels());
  r.fraction = r.hit_pixels == 0 ? 0.0
                                 : static_cast<double>(r.differing) / static_cast<double>(r.hit_pixels);
  r.beyond_bound =
      static_cast<double>(r.differing) > kRefVsFloatIpBound * static_cast<double>(r.hit_pixels) &&
      r.differing > kRefVsFloatIpSlackPixels;
  return r;
}

std::string ref_vs_float_ip_warning(const nlohmann::json& metrics) {
  const nlohmann::json beyond = metrics.value("ref_vs_float_ip_beyond_bound", nlohmann::json());
  if (!beyond.is_boolean() || !beyond.get<bool>()) return "";
  const auto differ = metrics["ref_vs_float_ip_mismatched_pixels"].get<size_t>();
  const auto hits = metrics["ref_vs_float_ip_hit_pixels"].get<size_t>();
  return fmt::format("ref differs from float-ip on {} of {} hit pixels ({:.2f} %), beyond the "
                     "documented bound of {:g} % (and {} pixels)",
                     differ, hits, 100.0 * static_cast<double>(differ) / static_cast<double>(hits),
                     100.0 * kRefVsFloatIpBound, kRefVsFloatIpSlackPixels);
}

CompareSummary write_compare_report(const CompareInput& in, const std::string& out_dir) {
  check_input(in);
  check_compare_output(out_dir, in.input_file);
  const fs::path dir(out_dir);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw Error(dir.string(), "cannot create the output directory: " + ec.message());
  if (!fs::is_directory(dir)) throw Error(dir.string(), "exists and is not a directory");
  remove_abandoned_staging(dir);

  // Everything is written into a staging directory inside `dir` first and moved into place only
  // when every file was written, so a failure leaves the previous outputs and no partial ones.
  static std::atomic<unsigned> runs{0};
  const fs::path staging =
      dir / fmt::format("{}{}_{}", kStagingPrefix, ::getpid(), runs.fetch_add(1));
  fs::remove_all(staging, ec);
  if (!fs::create_directory(staging, ec) || ec)
    throw Error(dir.string(), "cannot create a staging directory in the output directory: " +
                                  (ec ? ec.message() : std::string("it exists")));
  try {
    CompareSummary summary = write_report_files(in, staging);
    // Move into place: images first, the report last.
    std::vector<std::string> written;
    for (const auto& e : fs::directory_iterator(staging)) written.push_back(e.path().filename().string());
    std::sort(written.begin(), written.end(), [](const std::string& a, const std::string& b) {
      const auto rank = [](const std::string& n) { return n == "report.html" ? 2 : n == "metrics.json" ? 1 : 0; };
      return std::pair(rank(a), a) < std::pair(rank(b), b);
    });
    check_compare_output(out_dir, in.input_file);
    for (const std::string& name : written)
      commit_temporary((staging / name).string(), (dir / name).string());
    // Outputs of an earlier run that this one did not write (e.g. rtl*.png after --no-rtl).
    const std::set<std::string> stems = owned_stems(in.renders);
    const std::set<std::string> now(written.begin(), written.end());
    for (const auto& e : fs::directory_iterator(dir, ec)) {
      const std::string name = e.path().filename().string();
      if (owned_file(name, stems) && !now.count(name) && !is_directory_entry(e.path()))
        fs::remove(e.path(), ec);
    }
    fs::remove_all(staging, ec);
    return summary;
  } catch (const Error& e) {
    fs::remove_all(staging, ec);
    // Name the output the user asked for, not its place in the staging directory.
    std::string where = e.where();
    if (const std::string prefix = staging.string(); where.starts_with(prefix))
      where = (dir / fs::path(where.substr(prefix.size() + 1))).string();
    throw Error(where, e.problem());
  } catch (...) {
    fs::remove_all(staging, ec);
    throw;
  }
}

}  // namespace rpu::app
