// The engineering record of a report (app/run_record.h): the command line quoted so that it can
// be run again, and the resources of the configuration read from docs/throughput.md, where they
// have their one home.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "run_record.h"

namespace rpu::app {
namespace {

TEST(RunRecord, CommandLineIsQuotedToRunAgain) {
  const char* args[] = {"build/rpu", "compare", "my scene.json", "--out", "it's", "--n", "8"};
  char* argv[7];
  for (int k = 0; k < 7; ++k) argv[k] = const_cast<char*>(args[k]);
  EXPECT_EQ(command_line(7, argv), R"(build/rpu compare 'my scene.json' --out 'it'\''s' --n 8)");
}

TEST(RunRecord, RecordNamesTheCommitAndTools) {
  const nlohmann::json r = run_record("rpu compare x");
  EXPECT_EQ(r["command"], "rpu compare x");
  for (const char* key : {"git_commit", "verilator", "yosys"}) {
    ASSERT_TRUE(r[key].is_string()) << key;
    EXPECT_FALSE(r[key].get<std::string>().empty()) << key;
  }
}

// The figures are the page's own: the test reads the same table row and compares.
TEST(RunRecord, ResourcesComeFromTheThroughputPage) {
  std::ifstream f(std::string(RPU_SOURCE_DIR) + "/docs/throughput.md");
  std::stringstream page;
  page << f.rdbuf();
  const nlohmann::json u = docs_resources(true, true, "builtin:curve12");
  ASSERT_TRUE(u.contains("lut_sites")) << u.dump();
  EXPECT_NE(page.str().find("| unrolled | " + u["source"].get<std::string>() + " | " +
                            u["lut_sites"].get<std::string>() + " | " + u["ff"].get<std::string>()),
            std::string::npos);
  ASSERT_TRUE(u["fps_1080p"].is_object());
  EXPECT_TRUE(u["fps_1080p"].contains("XC7VX690T"));
  EXPECT_EQ(docs_resources(true, false, "builtin:curve12")["form"], "iterative");
  EXPECT_TRUE(docs_resources(false, true, "builtin:curve12").contains("note"));
  EXPECT_TRUE(docs_resources(true, true, "builtin:surf_spiral")["fps_1080p"].is_string());
}

}  // namespace
}  // namespace rpu::app
