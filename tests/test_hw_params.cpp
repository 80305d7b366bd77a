// The one table of hardware parameters (ref/model/hw_params.def) and everything derived from it:
// every entry round-trips through the command line (HwFlags), a sweep file (parse_sweep_text →
// expand_grid), metrics.json's "config" (hw_params_json → hw_params_from_json), the Verilated
// registry's Verilog names (hw_params_from_verilog) and, where the co-simulation is built, the
// job file; an out-of-range value is refused naming the flag; rtl/top/rpu_top_params.vh declares
// the table's defaults.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "backends.h"
#include "common/error.h"
#include "hw_flags.h"
#include "model/hw_params.h"
#include "sweep_spec.h"
#if RPU_TEST_COSIM
#include "stream_file.h"
#endif

namespace rpu {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using ref::HwParamInfo;
using ref::HwParamKind;
using ref::HwParams;

// A legal value of the entry other than its default, with every other parameter at its default:
// the largest such integer (or the off value), or the other choice.
int non_default(const HwParamInfo& d) {
  std::vector<int> candidates;
  for (int v = d.max; v >= d.min; --v) candidates.push_back(v);
  for (const ref::HwChoice& c : d.choices) candidates.push_back(c.value);
  for (int v : candidates) {
    if (v == d.def) continue;
    HwParams p;
    d.set(p, v);
    try {
      p.validate();
      return v;
    } catch (const Error&) {
    }
  }
  ADD_FAILURE() << d.key << ": no legal value besides the default";
  return d.def;
}

HwParams with(const HwParamInfo& d, int v) {
  HwParams p;
  d.set(p, v);
  return p;
}

// The flags parsed as `rpu config` parses them; HwFlags::params() (throws rpu::Error).
HwParams from_cli(const std::vector<std::string>& args) {
  CLI::App app{"test"};
  app::HwFlags flags;
  flags.add_to(app);
  std::vector<std::string> argv = args;
  std::reverse(argv.begin(), argv.end());  // CLI11 takes them reversed
  app.parse(argv);
  return flags.params();
}

// The value as a sweep file or metrics.json writes it.
json json_value(const HwParamInfo& d, int v) {
  return d.kind == HwParamKind::kChoice ? json(d.text(v)) : json(v);
}

// A one-configuration sweep file setting the key in its grid or its base.
HwParams from_sweep(const std::string& section, const std::string& key, const json& value) {
  json spec = {{"scenes", json::array({"builtin:curve12"})}};
  if (section == "grid") {
    spec["grid"] = {{key, json::array({value})}};
  } else {
    spec["base"] = {{key, value}};
    spec["grid"] = {{key == "n" ? "n1" : "n", json::array({key == "n" ? 2 : 16})}};
  }
  const app::SweepSpec s = app::parse_sweep_text(spec.dump(), "params.json");
  const std::vector<app::SweepConfig> configs = app::expand_grid(s);
  EXPECT_EQ(configs.size(), 1u);
  return configs.at(0).params;
}

TEST(HwParamTable, EntriesAreDistinctAndMatchTheDefaults) {
  const auto& table = ref::hw_param_table();
  ASSERT_FALSE(table.empty());
  std::set<std::string_view> fields, keys, flags, verilog, symbols;
  const HwParams defaults;
  for (size_t k = 0; k < table.size(); ++k) {
    const HwParamInfo& d = table[k];
    SCOPED_TRACE(std::string(d.key));
    EXPECT_EQ(static_cast<size_t>(d.id), k);
    EXPECT_EQ(&ref::hw_param(d.id), &d);
    EXPECT_TRUE(fields.insert(d.field).second);
    EXPECT_TRUE(keys.insert(d.key).second);
    EXPECT_TRUE(flags.insert(d.flag).second);
    EXPECT_TRUE(symbols.insert(d.symbol).second);
    if (!d.verilog.empty()) {
      EXPECT_TRUE(verilog.insert(d.verilog).second);
      EXPECT_EQ(ref::find_hw_param_verilog(d.verilog), &d);
    }
    EXPECT_TRUE(d.flag.starts_with("--"));
    EXPECT_EQ(d.get(defaults), d.def);
    EXPECT_TRUE(d.legal(d.def));
    EXPECT_FALSE(d.meaning.empty());
    EXPECT_EQ(d.meaning.find('\n'), std::string_view::npos);
    EXPECT_EQ(ref::find_hw_param_key(d.key), &d);
    switch (d.kind) {
      case HwParamKind::kChoice: EXPECT_GE(d.choices.size(), 2u); break;
      case HwParamKind::kRangeOrOff: EXPECT_EQ(d.choices.size(), 1u); break;
      case HwParamKind::kRange: EXPECT_TRUE(d.choices.empty()); break;
    }
  }
  EXPECT_NO_THROW(defaults.validate());
  // surf_w and angle_w are entries like any other.
  EXPECT_TRUE(keys.count("surf_w") && keys.count("angle_w"));
  EXPECT_EQ(HwParams::kMaxCoordW, ref::hw_param(ref::HwParamId::coord_w).max);
  EXPECT_EQ(HwParams::kMaxSurfW, ref::hw_param(ref::HwParamId::surf_w).max);
}

// The round trip of every entry: one non-default legal value through each reader gives the same
// HwParams.
TEST(HwParamTable, EveryEntryRoundTrips) {
  for (const HwParamInfo& d : ref::hw_param_table()) {
    SCOPED_TRACE(std::string(d.key));
    const int v = non_default(d);
    ASSERT_NE(v, d.def);
    const HwParams want = with(d, v);
    ASSERT_NE(want, HwParams{});
    // The command line.
    EXPECT_EQ(from_cli({std::string(d.flag), d.text(v)}), want);
    EXPECT_EQ(from_cli({std::string(d.flag) + "=" + d.text(v)}), want);
    // A sweep file, as a grid value and as the base.
    EXPECT_EQ(from_sweep("grid", std::string(d.key), json_value(d, v)), want);
    EXPECT_EQ(from_sweep("base", std::string(d.key), json_value(d, v)), want);
    // metrics.json's "config": every key of the table, read back.
    const json config = app::hw_params_json(want);
    EXPECT_EQ(config.size(), ref::hw_param_table().size());
    EXPECT_EQ(config.at(std::string(d.key)), json_value(d, v));
    EXPECT_EQ(app::hw_params_from_json(config, "config"), want);
    EXPECT_EQ(app::hw_params_from_json(json::parse(config.dump()), "config"), want);
    // The Verilated registry's generated parameters, by Verilog name.
    if (!d.verilog.empty()) {
      EXPECT_EQ(ref::hw_params_from_verilog({{d.verilog, v}}), want);
      EXPECT_EQ(app::verilog_value(d, want), std::to_string(v));
    }
    // `rpu config` and the RTL descriptions show it.
    EXPECT_NE(want.describe().find(fmt::format("{:<10} = {}\n", d.key, d.describe(v))),
              std::string::npos);
    EXPECT_NE((" " + want.summary() + " ").find(fmt::format(" {} {} ", d.key, d.text(v))),
              std::string::npos);
  }
}

void expect_refused(const std::vector<std::string>& args, std::string_view flag) {
  try {
    (void)from_cli(args);
    ADD_FAILURE() << "accepted " << args[0] << " " << args[1];
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), flag) << e.what();
  }
}

TEST(HwParamTable, OutOfRangeValuesAreRefusedNamingTheFlag) {
  for (const HwParamInfo& d : ref::hw_param_table()) {
    SCOPED_TRACE(std::string(d.key));
    const std::string flag(d.flag);
    if (d.kind == HwParamKind::kChoice) {
      expect_refused({flag, "nonsense"}, flag);
      // A sweep file names the key; the choices are listed.
      try {
        (void)from_sweep("grid", std::string(d.key), "nonsense");
        ADD_FAILURE() << "sweep accepted " << d.key << " nonsense";
      } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("grid." + std::string(d.key) + "[0]: must be " +
                                             d.choice_list()),
                  std::string::npos)
            << e.what();
      }
      // An integer outside the choices (only a program can make one) is refused by validate.
      HwParams p;
      d.set(p, d.max + 1);
      if (d.get(p) == d.max + 1) {
        try {
          p.validate();
          ADD_FAILURE() << "validate accepted " << d.key << " = " << d.max + 1;
        } catch (const Error& e) {
          EXPECT_EQ(e.where(), flag);
        }
      }
      continue;
    }
    for (int v : {d.min - 1, d.max + 1}) {
      if (d.legal(v)) continue;  // sqrt_w: min - 1 might be the off value
      expect_refused({flag, std::to_string(v)}, flag);
      // A sweep accepts the file and records the configuration as invalid, naming the flag.
      const HwParams p = from_sweep("grid", std::string(d.key), v);
      try {
        p.validate();
        ADD_FAILURE() << "validate accepted " << d.key << " = " << v;
      } catch (const Error& e) {
        EXPECT_EQ(e.where(), flag);
        EXPECT_NE(e.problem().find(fmt::format("must be in [{}, {}], got {}", d.min, d.max, v)),
                  std::string::npos)
            << e.what();
      }
    }
  }
}

TEST(HwParamTable, CrossFieldChecksStayAfterTheRanges) {
  // n1 out of range is named before n % n1 is computed.
  expect_refused({"--n1", "0"}, "--n1");
  expect_refused({"--n1", "3"}, "--n");  // 16 % 3
  expect_refused({"--surf-w", "16", "--angle-w", "32"}, "--angle-w");
  HwParams p;
  p.coord_w = 40;
  p.t_frac = 48;
  try {
    p.validate();
    ADD_FAILURE() << "accepted a 131-bit product";
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), "--t-frac");
    EXPECT_NE(e.problem().find("limit 126"), std::string::npos);
  }
}

TEST(HwParamTable, UnknownKeysListEveryParameter) {
  try {
    (void)app::parse_sweep_text(R"({"scenes": ["builtin:curve12"], "grid": {"m1": [1]}})", "x.json");
    ADD_FAILURE() << "accepted grid.m1";
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), "x.json: grid.m1");
    EXPECT_EQ(e.problem(), "unknown hardware parameter (" + ref::hw_param_keys() + ")");
  }
  EXPECT_THROW(ref::hw_params_from_verilog({{"NoSuchParam", 1}}), Error);
}

TEST(HwParamTable, MarkdownHasOneRowPerEntry) {
  const std::string md = ref::hw_params_markdown();
  const std::string rows = ref::hw_params_readme_rows();
  for (const HwParamInfo& d : ref::hw_param_table()) {
    EXPECT_NE(md.find(fmt::format("| {} | `{}` | {} |", d.symbol, d.flag, d.default_text())),
              std::string::npos) << d.key;
    EXPECT_NE(rows.find(fmt::format("| {} | `{}` | {} |", d.key, d.flag, d.default_text())),
              std::string::npos) << d.key;
  }
  EXPECT_EQ(std::count(md.begin(), md.end(), '\n'), static_cast<long>(ref::hw_param_table().size() + 2));
  // A '|' in a meaning is escaped, so every row has the header's five cells.
  EXPECT_NE(md.find("md = \\|pr − s\\|"), std::string::npos);
}

// The RTL uses the table's Verilog names, and rpu_top declares the table's defaults: the
// registry's default configuration (no -G) is the default HwParams. rpu_top's parameter list is
// one file (rtl/top/rpu_top_params.vh), which rpu_top and the AXI shell both include.
TEST(HwParamTable, TheRtlDeclaresTheParametersWithTheirDefaults) {
  const std::regex decl(R"(parameter\s+integer\s+([A-Za-z0-9_]+)\s*=\s*(-?[0-9]+))");
  const auto read = [](const fs::path& p) {
    std::ifstream in(p);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  std::map<std::string, int> top;
  std::set<std::string> anywhere;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(RPU_SOURCE_DIR) / "rtl")) {
    if (e.path().extension() != ".v" && e.path().extension() != ".vh") continue;
    const std::string s = read(e.path());
    for (auto it = std::sregex_iterator(s.begin(), s.end(), decl); it != std::sregex_iterator(); ++it) {
      anywhere.insert((*it)[1]);
      if (e.path().filename() == "rpu_top_params.vh") top[(*it)[1]] = std::stoi((*it)[2]);
    }
  }
  ASSERT_FALSE(top.empty()) << "rpu_top_params.vh not found under rtl/";
  for (const HwParamInfo& d : ref::hw_param_table()) {
    if (d.verilog.empty()) continue;
    SCOPED_TRACE(std::string(d.key));
    EXPECT_TRUE(anywhere.count(std::string(d.verilog))) << d.verilog << " is in no rtl/ module";
    const auto it = top.find(std::string(d.verilog));
    if (it != top.end()) {
      EXPECT_EQ(it->second, d.def) << "rpu_top_params.vh's default of " << d.verilog;
    }
  }
  // rpu_top and the AXI shell (docs/axi.md) take the one list.
  for (const char* f : {"top/rpu_top.v", "axi/rpu_axi.v"}) {
    EXPECT_NE(read(fs::path(RPU_SOURCE_DIR) / "rtl" / f).find("`include \"rpu_top_params.vh\""),
              std::string::npos)
        << "rtl/" << f << " does not include rpu_top_params.vh";
  }
}

#if RPU_TEST_COSIM
// The co-simulation job file carries every parameter (by key, in the table's order).
TEST(HwParamTable, TheJobFileCarriesEveryEntry) {
  const fs::path file = fs::temp_directory_path() / fmt::format("rpu_test_hw_params_{}.job", ::getpid());
  for (const HwParamInfo& d : ref::hw_param_table()) {
    SCOPED_TRACE(std::string(d.key));
    sim::FrameSchedule f;
    f.params = with(d, non_default(d));
    sim::write_job(file.string(), f);
    EXPECT_EQ(sim::read_job(file.string()).params, f.params);
  }
  // A job file of another version is refused, naming the file.
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    const std::uint32_t words[] = {0x52505531, 1, 16};
    out.write(reinterpret_cast<const char*>(words), sizeof words);
  }
  try {
    (void)sim::read_job(file.string());
    ADD_FAILURE() << "read a version-1 job file";
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), file.string());
    EXPECT_NE(e.problem().find("format 1"), std::string::npos) << e.what();
  }
  fs::remove(file);
}
#endif

}  // namespace
}  // namespace rpu
