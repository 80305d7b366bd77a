// The report of `rpu compare` (README "Command line"): on small synthetic frames with known
// differences, the counts, the files, the difference colours and the heat map are what they
// should be, and failures name the path.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.h"
#include "compare_report.h"
#include "image/frame.h"
#include "image/image_io.h"

namespace rpu::app {
namespace {

namespace fs = std::filesystem;

constexpr int kW = 8, kH = 6;
// Colours chosen so that c·255 and c·255/4 are never halfway between two bytes.
const std::vector<scene::Color> kColors = {{0.9, 0.3, 0.1}, {0.2, 0.8, 0.4}, {0.6, 0.6, 0.0}};
constexpr scene::Color kBackgroundColor = {0.05, 0.15, 0.3};

// A PNG byte read back as float, within half a step.
constexpr float kByteTolerance = 0.5f / 255.0f;
float png_value(double c) { return std::round(static_cast<float>(c) * 255.0f) / 255.0f; }

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "rpu_test_compare_report" / name;
  fs::remove_all(dir);
  return dir;
}

// The four renders, with the disagreements the tests know (x, y):
//   ref:      primitive 0 on [1,4)×[1,4), primitive 1 on [5,7)×[2,5)
//   rtl:      ref, plus (0,0)=2 and (2,5)=2, minus (1,1), and (5,2)=2 instead of 1
//   float-ip: ref, plus (7,5)=0, (3,5)=2, (2,5)=0
//   float:    float-ip, plus (6,0)=1, and (3,5)=1, (2,5)=1
// Pixels and how many of the four compared pairs disagree there:
//   (0,0) (1,1) (5,2): 1 (rtl/ref);  (7,5): 2;  (6,0): 2;  (3,5): 3;  (2,5): 4;  41 others: 0.
image::Frame ref_frame() {
  image::Frame f(kW, kH);
  for (int j = 1; j < 4; ++j)
    for (int i = 1; i < 4; ++i) f.primitive[f.index(i, j)] = 0;
  for (int j = 2; j < 5; ++j)
    for (int i = 5; i < 7; ++i) f.primitive[f.index(i, j)] = 1;
  return f;
}

CompareInput full_input() {
  const image::Frame ref = ref_frame();
  image::Frame rtl = ref;
  rtl.primitive[rtl.index(0, 0)] = 2;
  rtl.primitive[rtl.index(2, 5)] = 2;
  rtl.primitive[rtl.index(1, 1)] = image::kBackground;
  rtl.primitive[rtl.index(5, 2)] = 2;
  image::Frame float_ip = ref;
  float_ip.primitive[float_ip.index(7, 5)] = 0;
  float_ip.primitive[float_ip.index(3, 5)] = 2;
  float_ip.primitive[float_ip.index(2, 5)] = 0;
  image::Frame float_ideal = float_ip;
  float_ideal.primitive[float_ideal.index(6, 0)] = 1;
  float_ideal.primitive[float_ideal.index(3, 5)] = 1;
  float_ideal.primitive[float_ideal.index(2, 5)] = 1;

  CompareInput in;
  in.scene = "builtin:synthetic";
  in.colors = kColors;
  in.background = kBackgroundColor;
  in.renders = {{"float", float_ideal, 0.5}, {"float-ip", float_ip, 0.25},
                {"ref", ref, 1.5},           {"rtl", rtl, 12.0}};
  in.config = {{"n", 24}, {"n1", 8}, {"coord_w", 16}, {"metric", "abs"}};
  in.rtl = {{"cycles", 1234}, {"pairs", 567}, {"latency_cycles", 19}, {"stall_cycles", 3},
            {"harness", "c++"}};
  in.mismatch_lines = {"FAILURE pixel (0, 0): expected background, got primitive 2"};
  return in;
}

std::string read_text(const fs::path& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// The RGB of pixel (x, y) of an image read back through OpenImageIO.
std::array<float, 3> pixel(const std::vector<float>& rgb, int width, int x, int y) {
  const size_t k = 3 * (static_cast<size_t>(y) * width + x);
  return {rgb[k], rgb[k + 1], rgb[k + 2]};
}

void expect_colour(const std::array<float, 3>& got, const scene::Color& want, double scale,
                   const std::string& what) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[c], png_value(want[c] * scale), kByteTolerance) << what << " channel " << c;
}

TEST(CompareReport, CountsMatchKnownDifferences) {
  const fs::path dir = fresh_dir("counts");
  const CompareSummary s = write_compare_report(full_input(), dir.string());
  const nlohmann::json& m = s.metrics;
  EXPECT_FALSE(s.rtl_equals_ref);
  EXPECT_EQ(m["rtl_equals_ref"], false);
  EXPECT_EQ(m["pixels"], kW * kH);
  EXPECT_EQ(m["width"], kW);
  EXPECT_EQ(m["height"], kH);
  EXPECT_EQ(m["scene"], "builtin:synthetic");
  EXPECT_EQ(m["rtl_vs_ref_mismatched_pixels"], 4);
  EXPECT_EQ(m["ref_vs_float_ip_mismatched_pixels"], 3);
  EXPECT_EQ(m["ref_vs_float_mismatched_pixels"], 4);
  EXPECT_EQ(m["float_ip_vs_float_mismatched_pixels"], 3);

  const nlohmann::json& c = m["comparisons"];
  EXPECT_EQ(c["rtl_vs_ref"]["hit_only_in_rtl"], 2);
  EXPECT_EQ(c["rtl_vs_ref"]["hit_only_in_ref"], 1);
  EXPECT_EQ(c["rtl_vs_ref"]["different_primitive"], 1);
  EXPECT_EQ(c["ref_vs_float_ip"]["hit_only_in_ref"], 0);
  EXPECT_EQ(c["ref_vs_float_ip"]["hit_only_in_float_ip"], 3);
  EXPECT_EQ(c["ref_vs_float"]["hit_only_in_float"], 4);
  EXPECT_EQ(c["float_ip_vs_float"]["hit_only_in_float_ip"], 0);
  EXPECT_EQ(c["float_ip_vs_float"]["hit_only_in_float"], 1);
  EXPECT_EQ(c["float_ip_vs_float"]["different_primitive"], 2);

  // Per backend: hits (ref has 9 + 6) and the wall times as given.
  EXPECT_EQ(m["backends"]["ref"]["hit_pixels"], 15);
  EXPECT_EQ(m["backends"]["rtl"]["hit_pixels"], 16);
  EXPECT_EQ(m["backends"]["float-ip"]["hit_pixels"], 18);
  EXPECT_EQ(m["backends"]["float"]["hit_pixels"], 19);
  EXPECT_DOUBLE_EQ(m["backends"]["rtl"]["seconds"].get<double>(), 12.0);
  // The co-simulation against the model on the same frame: 12 s / 1.5 s.
  EXPECT_DOUBLE_EQ(m["rtl_to_model_time"].get<double>(), 8.0);

  // The co-simulation statistics are copied, and the whole object kept.
  EXPECT_EQ(m["cycles"], 1234);
  EXPECT_EQ(m["pairs"], 567);
  EXPECT_EQ(m["latency_cycles"], 19);
  EXPECT_EQ(m["rtl"]["stall_cycles"], 3);
  EXPECT_EQ(m["rtl"]["harness"], "c++");
  EXPECT_EQ(m["config"]["n"], 24);

  EXPECT_EQ(m["heatmap"]["pixels_by_disagreeing_pairs"], nlohmann::json({41, 3, 2, 1, 1}));
  EXPECT_EQ(m["heatmap"]["pairs_compared"].size(), 4u);

  // metrics.json holds the same.
  EXPECT_EQ(nlohmann::json::parse(read_text(dir / "metrics.json")), m);
}

// The engineering record: the run's record as given, the differing pixels with every render's
// primitive and depth (world units: ref's depth is scaled by its unit), ref vs float depth
// statistics, and the gaps along curves.
TEST(CompareReport, EngineeringRecord) {
  CompareInput in = full_input();
  for (auto& r : in.renders)
    for (size_t k = 0; k < r.frame.primitive.size(); ++k)
      if (r.frame.primitive[k] != image::kBackground) r.frame.depth[k] = r.name == "ref" ? 20.0 : 10.0;
  image::Frame& ref = in.renders[2].frame;
  ref.depth[ref.index(2, 2)] = 20.4;  // 2 % deeper than float there
  in.renders[2].depth_unit = 0.5;
  in.curve_primitive = {true, false, false};
  in.record = {{"command", "rpu compare builtin:synthetic --out x"}, {"git_commit", "abc123"}};
  const fs::path dir = fresh_dir("record");
  const nlohmann::json m = write_compare_report(in, dir.string()).metrics;
  EXPECT_EQ(m["record"]["git_commit"], "abc123");
  // (0,0) (1,1) (5,2) rtl/ref; (7,5) (6,0) (3,5) (2,5) among the others.
  EXPECT_EQ(m["differing_pixels_total"], 7);
  const nlohmann::json& first = m["differing_pixels"][0];
  EXPECT_EQ(first["x"], 0);
  EXPECT_EQ(first["y"], 0);
  EXPECT_EQ(first["rtl"]["primitive"], 2);
  EXPECT_EQ(first["rtl"]["depth"], 10.0);
  EXPECT_TRUE(first["ref"]["primitive"].is_null());
  const nlohmann::json& d = m["depth_ref_vs_float"];
  EXPECT_EQ(d["pixels"], 15);  // every ref hit is float's primitive too
  EXPECT_NEAR(d["max_relative"].get<double>(), 0.02, 1e-12);
  EXPECT_EQ(d["beyond_1e-3"], 1);
  // Curve 0: float has the block and (7,5); float-ip adds the lone (2,5): one gap.
  EXPECT_EQ(m["curve_gaps_vs_float"]["float-ip"], 1);
  EXPECT_EQ(m["curve_gaps_vs_float"]["ref"], 0);
  EXPECT_EQ(m["curve_gaps_vs_float"]["rtl"], 0);
  const std::string html = read_text(dir / "report.html");
  EXPECT_NE(html.find("rpu compare builtin:synthetic --out x"), std::string::npos);
  EXPECT_NE(html.find("<td>(3, 5)</td>"), std::string::npos);
  EXPECT_NE(html.find("Gaps along curves"), std::string::npos);
}

TEST(CompareReport, EqualRtlAndRefPass) {
  CompareInput in = full_input();
  for (auto& r : in.renders)
    if (r.name == "rtl") r.frame = ref_frame();
  const fs::path dir = fresh_dir("pass");
  const CompareSummary s = write_compare_report(in, dir.string());
  EXPECT_TRUE(s.rtl_equals_ref);
  EXPECT_EQ(s.metrics["rtl_vs_ref_mismatched_pixels"], 0);
  EXPECT_EQ(s.metrics["rtl_equals_ref"], true);
  const std::string html = read_text(dir / "report.html");
  EXPECT_NE(html.find("<div class=\"banner pass\">PASS: rtl == ref on all 48 pixels"), std::string::npos);
  EXPECT_EQ(html.find("banner fail"), std::string::npos);
}

TEST(CompareReport, WritesEveryFileReadableAtTheRightSize) {
  const fs::path dir = fresh_dir("files");
  write_compare_report(full_input(), dir.string());
  // 8×6 is small: every image is also written 64 times larger (512×384) for the report.
  for (const char* stem : {"float", "float-ip", "ref", "rtl", "diff_rtl_vs_ref", "diff_ref_vs_float-ip",
                           "diff_ref_vs_float", "diff_float-ip_vs_float", "heatmap"}) {
    int w = 0, h = 0;
    image::read_rgb((dir / (std::string(stem) + ".png")).string(), w, h);
    EXPECT_EQ(w, kW) << stem;
    EXPECT_EQ(h, kH) << stem;
    image::read_rgb((dir / (std::string(stem) + "_x64.png")).string(), w, h);
    EXPECT_EQ(w, kW * 64) << stem;
    EXPECT_EQ(h, kH * 64) << stem;
  }
  const std::string html = read_text(dir / "report.html");
  EXPECT_NE(html.find("<div class=\"banner fail\">FAIL: rtl differs from ref on 4 of 48 pixels"),
            std::string::npos);
  EXPECT_NE(html.find("src=\"diff_rtl_vs_ref_x64.png\""), std::string::npos);
  EXPECT_NE(html.find("stall_cycles"), std::string::npos);
  EXPECT_NE(html.find("coord_w"), std::string::npos);
  EXPECT_NE(html.find("FAILURE pixel (0, 0)"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);

  // The render images carry the exact colours.
  int w = 0, h = 0;
  const auto ref = image::read_rgb((dir / "ref.png").string(), w, h);
  expect_colour(pixel(ref, w, 2, 2), kColors[0], 1.0, "ref (2,2)");
  expect_colour(pixel(ref, w, 0, 0), kBackgroundColor, 1.0, "ref (0,0)");
}

TEST(CompareReport, LargeImagesAreNotEnlarged) {
  CompareInput in = full_input();
  in.renders = {{"ref", image::Frame(300, 2), 0.0}};
  const fs::path dir = fresh_dir("large");
  write_compare_report(in, dir.string());
  EXPECT_TRUE(fs::exists(dir / "ref.png"));
  EXPECT_TRUE(fs::exists(dir / "heatmap.png"));
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find("_x"), std::string::npos) << entry.path();
}

// Difference images stay enlarged ×2 up to kDiffEnlargeUpTo, so that one differing pixel of a
// 256×256 demo image is a 2×2 block; the renders are not.
TEST(CompareReport, DifferenceImagesAreEnlargedUpToTheirLimit) {
  for (const int side : {300, kDiffEnlargeUpTo + 1}) {
    CompareInput in = full_input();
    image::Frame a(side, 2), b(side, 2);
    b.primitive[b.index(5, 1)] = 0;
    in.renders = {{"ref", a, 0.0}, {"float-ip", b, 0.0}};
    const fs::path dir = fresh_dir("diff_large_" + std::to_string(side));
    write_compare_report(in, dir.string());
    EXPECT_EQ(fs::exists(dir / "diff_ref_vs_float-ip_x2.png"), side <= kDiffEnlargeUpTo) << side;
    EXPECT_FALSE(fs::exists(dir / "ref_x2.png")) << side;
    if (side <= kDiffEnlargeUpTo) {
      EXPECT_NE(read_text(dir / "report.html").find("diff_ref_vs_float-ip_x2.png"), std::string::npos);
    }
  }
}

TEST(CompareReport, DiffImageColours) {
  const fs::path dir = fresh_dir("diff");
  write_compare_report(full_input(), dir.string());
  int w = 0, h = 0;
  const auto diff = image::read_rgb((dir / "diff_rtl_vs_ref.png").string(), w, h);
  ASSERT_EQ(w, kW);
  expect_colour(pixel(diff, w, 0, 0), kHitOnlyInA, 1.0, "hit only in rtl");
  expect_colour(pixel(diff, w, 1, 1), kHitOnlyInB, 1.0, "hit only in ref");
  expect_colour(pixel(diff, w, 5, 2), kDifferentPrimitive, 1.0, "different primitive");
  expect_colour(pixel(diff, w, 2, 2), kColors[0], kAgreeBrightness, "agreeing hit");
  expect_colour(pixel(diff, w, 0, 5), kBackgroundColor, kAgreeBrightness, "agreeing background");
  // The three marker colours are distinct.
  EXPECT_NE(pixel(diff, w, 0, 0), pixel(diff, w, 1, 1));
  EXPECT_NE(pixel(diff, w, 0, 0), pixel(diff, w, 5, 2));
  EXPECT_NE(pixel(diff, w, 1, 1), pixel(diff, w, 5, 2));

  // The enlarged copy is nearest neighbour: a whole 64×64 block per source pixel, crisp edges.
  const auto big = image::read_rgb((dir / "diff_rtl_vs_ref_x64.png").string(), w, h);
  ASSERT_EQ(w, kW * 64);
  for (const auto& [x, y] : std::array<std::pair<int, int>, 3>{{{0, 0}, {63, 63}, {0, 63}}})
    expect_colour(pixel(big, w, x, y), kHitOnlyInA, 1.0, "enlarged only-rtl block");
  expect_colour(pixel(big, w, 64, 0), kBackgroundColor, kAgreeBrightness, "next block");

  // In float-ip vs float, a is float-ip: (6,0) is hit only in float.
  const auto fip = image::read_rgb((dir / "diff_float-ip_vs_float.png").string(), w, h);
  expect_colour(pixel(fip, w, 6, 0), kHitOnlyInB, 1.0, "hit only in float");
  expect_colour(pixel(fip, w, 3, 5), kDifferentPrimitive, 1.0, "float-ip 2 vs float 1");
}

TEST(CompareReport, HeatMapIsHotterWhereMorePairsDisagree) {
  const fs::path dir = fresh_dir("heat");
  write_compare_report(full_input(), dir.string());
  int w = 0, h = 0;
  const auto heat = image::read_rgb((dir / "heatmap.png").string(), w, h);
  ASSERT_EQ(w, kW);
  // One pixel each with 0, 1, 2, 3, 4 disagreeing pairs (see full_input).
  const std::array<std::pair<int, int>, 5> by_count = {{{0, 5}, {0, 0}, {7, 5}, {3, 5}, {2, 5}}};

  // Through the same colour map: 0 where all agree, then (d + 1) / 5 for d of the four pairs.
  OIIO::ImageBuf steps(OIIO::ImageSpec(5, 1, 1, OIIO::TypeDesc::FLOAT));
  const float fractions[5] = {0.0f, 0.4f, 0.6f, 0.8f, 1.0f};
  for (int d = 0; d < 5; ++d) EXPECT_FLOAT_EQ(static_cast<float>(heat_value(d, 4)), fractions[d]);
  steps.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, fractions);
  const OIIO::ImageBuf expected = OIIO::ImageBufAlgo::colorconvert(
      OIIO::ImageBufAlgo::color_map(steps, 0, kHeatColorMap), "linear", "sRGB");
  ASSERT_FALSE(expected.has_error()) << expected.geterror();
  // The ends of inferno as published: #000004 and #fcffa4.
  expect_colour(pixel(heat, w, 0, 5), {0x00 / 255.0, 0x00 / 255.0, 0x04 / 255.0}, 1.0, "no pair");
  expect_colour(pixel(heat, w, 2, 5), {0xfc / 255.0, 0xff / 255.0, 0xa4 / 255.0}, 1.0, "all pairs");

  float previous_luminance = -1.0f;
  for (int d = 0; d < 5; ++d) {
    const auto [x, y] = by_count[d];
    const auto got = pixel(heat, w, x, y);
    float want[3];
    expected.getpixel(d, 0, want, 3);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(got[c], png_value(want[c]), kByteTolerance) << d << " pairs, channel " << c;
    // Inferno rises in luminance: more disagreement is brighter.
    const float luminance = 0.2126f * got[0] + 0.7152f * got[1] + 0.0722f * got[2];
    EXPECT_GT(luminance, previous_luminance) << d << " disagreeing pairs";
    previous_luminance = luminance;
  }
  // Pixels with the same count have the same colour.
  EXPECT_EQ(pixel(heat, w, 0, 0), pixel(heat, w, 1, 1));
  EXPECT_EQ(pixel(heat, w, 7, 5), pixel(heat, w, 6, 0));
}

TEST(CompareReport, MissingRendersGiveNullCounts) {
  CompareInput in = full_input();
  std::erase_if(in.renders, [](const BackendRender& r) { return r.name == "rtl" || r.name == "float-ip"; });
  in.rtl = nullptr;
  const fs::path dir = fresh_dir("missing");
  const CompareSummary s = write_compare_report(in, dir.string());
  const nlohmann::json& m = s.metrics;
  EXPECT_FALSE(s.rtl_equals_ref);
  EXPECT_TRUE(m["rtl_equals_ref"].is_null());
  EXPECT_TRUE(m["rtl_vs_ref_mismatched_pixels"].is_null());
  EXPECT_TRUE(m["ref_vs_float_ip_mismatched_pixels"].is_null());
  EXPECT_TRUE(m["float_ip_vs_float_mismatched_pixels"].is_null());
  EXPECT_EQ(m["ref_vs_float_mismatched_pixels"], 4);
  for (const char* key : {"cycles", "pairs", "latency_cycles", "rtl"}) {
    ASSERT_TRUE(m.contains(key)) << key;
    EXPECT_TRUE(m[key].is_null()) << key;
  }
  EXPECT_EQ(m["heatmap"]["pixels_by_disagreeing_pairs"], nlohmann::json({44, 4}));
  EXPECT_TRUE(fs::exists(dir / "diff_ref_vs_float.png"));
  EXPECT_FALSE(fs::exists(dir / "diff_rtl_vs_ref.png"));
  EXPECT_FALSE(fs::exists(dir / "rtl.png"));
  EXPECT_TRUE(fs::exists(dir / "heatmap.png"));
  const std::string html = read_text(dir / "report.html");
  EXPECT_NE(html.find("rtl not run"), std::string::npos);
  EXPECT_EQ(html.find("banner pass"), std::string::npos);
  EXPECT_EQ(html.find("banner fail"), std::string::npos);
}

TEST(CompareReport, TextIsEscapedInHtml) {
  CompareInput in = full_input();
  in.scene = "<b>scene</b> & \"co\"";
  in.mismatch_lines = {"<script>alert(1)</script>"};
  in.config["label"] = "a<b";
  const fs::path dir = fresh_dir("escape");
  write_compare_report(in, dir.string());
  const std::string html = read_text(dir / "report.html");
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  EXPECT_EQ(html.find("<b>scene"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  EXPECT_NE(html.find("&lt;b&gt;scene&lt;/b&gt; &amp; &quot;co&quot;"), std::string::npos);
  EXPECT_NE(html.find("a&lt;b"), std::string::npos);
}

TEST(CompareReport, UnwritableOutDirThrowsNamingThePath) {
  const fs::path dir = fresh_dir("unwritable");
  fs::create_directories(dir);
  const fs::path file = dir / "a_file";
  std::ofstream(file) << "not a directory\n";
  for (const fs::path& out : {file / "report", file}) {
    try {
      write_compare_report(full_input(), out.string());
      ADD_FAILURE() << "no error for " << out;
    } catch (const rpu::Error& e) {
      EXPECT_NE(std::string(e.what()).find(out.string()), std::string::npos) << e.what();
    }
  }
}

TEST(CompareReport, InconsistentInputNamesTheBackend) {
  CompareInput in = full_input();
  in.renders[1].frame = image::Frame(kW + 1, kH);
  try {
    write_compare_report(in, fresh_dir("size").string());
    ADD_FAILURE() << "no error for frames of different sizes";
  } catch (const rpu::Error& e) {
    EXPECT_NE(std::string(e.what()).find("float-ip"), std::string::npos) << e.what();
  }
  in = full_input();
  in.renders[2].frame.primitive[in.renders[2].frame.index(4, 3)] = 7;
  try {
    write_compare_report(in, fresh_dir("id").string());
    ADD_FAILURE() << "no error for an unknown primitive id";
  } catch (const rpu::Error& e) {
    EXPECT_NE(std::string(e.what()).find("ref: pixel (4, 3)"), std::string::npos) << e.what();
  }
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A rerun without the RTL removes the rtl outputs of the previous run (and nothing else).
TEST(CompareReport, RerunRemovesStaleOutputsItOwns) {
  const fs::path dir = fresh_dir("stale");
  write_compare_report(full_input(), dir.string());
  ASSERT_TRUE(fs::exists(dir / "rtl.png"));
  std::ofstream(dir / "notes.txt") << "mine\n";
  std::ofstream(dir / "rtl_backup.png") << "mine too\n";
  CompareInput no_rtl = full_input();
  no_rtl.renders.pop_back();
  no_rtl.rtl = nullptr;
  write_compare_report(no_rtl, dir.string());
  for (const std::string& name : names_in(dir)) {
    EXPECT_FALSE(name.starts_with("rtl.") || name.starts_with("rtl_x") ||
                 name.starts_with("diff_rtl")) << name;
    EXPECT_FALSE(name.starts_with(".rpu-compare-staging")) << name;
  }
  EXPECT_TRUE(fs::exists(dir / "notes.txt"));
  EXPECT_TRUE(fs::exists(dir / "rtl_backup.png"));
  EXPECT_TRUE(fs::exists(dir / "ref.png"));
}

// A symlink named like an output is replaced; the file it points to (outside) is untouched.
TEST(CompareReport, SymlinkedOutputsAreReplacedNotFollowed) {
  const fs::path dir = fresh_dir("symlink");
  const fs::path outside = fresh_dir("symlink_outside");
  fs::create_directories(dir);
  fs::create_directories(outside);
  std::ofstream(outside / "precious.png") << "precious\n";
  fs::create_symlink(outside / "precious.png", dir / "ref.png");
  fs::create_symlink(outside / "precious.png", dir / "metrics.json");
  write_compare_report(full_input(), dir.string());
  EXPECT_EQ(read_text(outside / "precious.png"), "precious\n");
  EXPECT_FALSE(fs::is_symlink(dir / "ref.png"));
  EXPECT_FALSE(fs::is_symlink(dir / "metrics.json"));
}

// The scene file sitting in the output directory under an output's name is never overwritten.
TEST(CompareReport, RefusesToOverwriteTheInput) {
  const fs::path dir = fresh_dir("input");
  fs::create_directories(dir);
  std::ofstream(dir / "metrics.json") << "{\"camera\": {}}\n";
  CompareInput in = full_input();
  in.input_file = (dir / "metrics.json").string();
  try {
    write_compare_report(in, dir.string());
    ADD_FAILURE() << "overwrote the input";
  } catch (const rpu::Error& e) {
    EXPECT_EQ(e.where(), (dir / "metrics.json").string());
    EXPECT_NE(e.problem().find("scene file"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_text(dir / "metrics.json"), "{\"camera\": {}}\n");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"metrics.json"});
  // Also through a hard link under another owned name.
  fs::remove(dir / "metrics.json");
  std::ofstream(dir / "scene.json") << "{}\n";
  fs::create_hard_link(dir / "scene.json", dir / "ref_x64.png");
  in.input_file = (dir / "scene.json").string();
  EXPECT_THROW(write_compare_report(in, dir.string()), rpu::Error);
  EXPECT_THROW(check_compare_output("", ""), rpu::Error);
}

// In a death-test child: the report under a small file-size limit; exits 0 when it threw.
[[noreturn]] void report_under_file_size_limit(const fs::path& dir) {
  const rlimit limit{2048, 2048};
  ::setrlimit(RLIMIT_FSIZE, &limit);
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    write_compare_report(full_input(), dir.string());
  } catch (const rpu::Error& e) {
    std::fprintf(stderr, "%s\n", e.what());
    std::exit(0);
  }
  std::exit(1);
}

// A failed write (full disk, file-size limit) leaves the previous report as it was and nothing
// of the failed run: no partial images, no metrics.json.tmp, no staging directory.
TEST(CompareReportDeathTest, FailureLeavesNoPartialOutputs) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const fs::path dir = fresh_dir("failure");
  CompareInput small = full_input();
  write_compare_report(small, dir.string());
  const std::vector<std::string> before = names_in(dir);
  const std::string metrics_before = read_text(dir / "metrics.json");
  EXPECT_EXIT(report_under_file_size_limit(dir), ::testing::ExitedWithCode(0),
              "cannot write the file: File too large");
  EXPECT_EQ(names_in(dir), before);
  EXPECT_EQ(read_text(dir / "metrics.json"), metrics_before);
  const fs::path fresh = fresh_dir("failure_fresh");
  EXPECT_EXIT(report_under_file_size_limit(fresh), ::testing::ExitedWithCode(0), "File too large");
  EXPECT_TRUE(names_in(fresh).empty());
}

// ref vs float-ip beyond the documented bound: a field in metrics.json, the warning text, the
// banner; within it, none of them.
TEST(CompareReport, RefVsFloatIpBeyondTheBoundIsFlagged) {
  const fs::path dir = fresh_dir("bound");
  const CompareSummary s = write_compare_report(full_input(), dir.string());
  // ref hits 15 pixels, float-ip 18; they differ on 3.
  EXPECT_EQ(s.metrics["ref_vs_float_ip_hit_pixels"], 18);
  EXPECT_EQ(s.metrics["ref_vs_float_ip_beyond_bound"], true);
  EXPECT_EQ(s.metrics["ref_vs_float_ip_bound"], 0.001);
  EXPECT_EQ(s.warning, "ref differs from float-ip on 3 of 18 hit pixels (16.67 %), beyond the "
                       "documented bound of 0.1 % (and 2 pixels)");
  EXPECT_NE(read_text(dir / "report.html").find("banner warn\">WARNING: ref differs from float-ip"),
            std::string::npos);
  EXPECT_NE(read_text(dir / "metrics.json").find("\"ref_vs_float_ip_beyond_bound\": true"),
            std::string::npos);

  CompareInput agree = full_input();
  agree.renders[1].frame = agree.renders[2].frame;  // float-ip = ref
  const fs::path dir2 = fresh_dir("bound_ok");
  const CompareSummary ok = write_compare_report(agree, dir2.string());
  EXPECT_EQ(ok.metrics["ref_vs_float_ip_beyond_bound"], false);
  EXPECT_TRUE(ok.warning.empty());
  EXPECT_EQ(read_text(dir2 / "report.html").find("banner warn"), std::string::npos);
}

// The measure itself (compare and fuzz/fuzz_render share it): the larger hit count, the
// fraction, the bound exclusive at exactly 0.1 %, and the slack of 2 pixels.
TEST(CompareReport, RefVsFloatIpMeasure) {
  const CompareInput in = full_input();  // renders: float, float-ip, ref, rtl
  const RefVsFloatIp r = ref_vs_float_ip(in.renders[2].frame, in.renders[1].frame);
  EXPECT_EQ(r.differing, 3u);
  EXPECT_EQ(r.hit_pixels, 18u);
  EXPECT_DOUBLE_EQ(r.fraction, 3.0 / 18.0);
  EXPECT_TRUE(r.beyond_bound);

  image::Frame a(50, 40), b(50, 40);  // 2000 hits each
  std::fill(a.primitive.begin(), a.primitive.end(), 0);
  b.primitive = a.primitive;
  EXPECT_FALSE(ref_vs_float_ip(a, b).beyond_bound);
  b.primitive[7] = 1;
  b.primitive[9] = 1;  // 2 of 2000: exactly the bound, not beyond it
  EXPECT_FALSE(ref_vs_float_ip(a, b).beyond_bound);
  b.primitive[11] = image::kBackground;  // 3 of 2000
  EXPECT_TRUE(ref_vs_float_ip(a, b).beyond_bound);
  EXPECT_EQ(ref_vs_float_ip(a, b).hit_pixels, 2000u);

  // Never beyond it on kRefVsFloatIpSlackPixels = 2 pixels or fewer: 1 or 2 of 295 hits is not a
  // finding, 3 of 295 is.
  image::Frame c(59, 5), e(59, 5);  // 295 hits each
  std::fill(c.primitive.begin(), c.primitive.end(), 0);
  e.primitive = c.primitive;
  e.primitive[0] = image::kBackground;
  EXPECT_FALSE(ref_vs_float_ip(c, e).beyond_bound);
  e.primitive[1] = 1;
  EXPECT_FALSE(ref_vs_float_ip(c, e).beyond_bound);
  e.primitive[2] = 1;
  EXPECT_TRUE(ref_vs_float_ip(c, e).beyond_bound);

  const image::Frame empty(4, 4);
  const RefVsFloatIp none = ref_vs_float_ip(empty, empty);
  EXPECT_EQ(none.hit_pixels, 0u);
  EXPECT_EQ(none.fraction, 0.0);
  EXPECT_FALSE(none.beyond_bound);
}

// Scene names are any bytes (file names need not be UTF-8): written, not an exception.
TEST(CompareReport, NonUtf8SceneNameIsWritten) {
  CompareInput in = full_input();
  in.scene = "sc\xff\xfe.json";
  const fs::path dir = fresh_dir("utf8");
  EXPECT_NO_THROW(write_compare_report(in, dir.string()));
  EXPECT_NE(read_text(dir / "metrics.json").find("\"scene\": \"sc"), std::string::npos);
}

}  // namespace
}  // namespace rpu::app
