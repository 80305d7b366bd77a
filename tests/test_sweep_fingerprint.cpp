// The RTL part of a sweep's resume fingerprint (app/sweep_spec.h, rtl_fingerprint): a result of
// the design before an RTL edit must not be reused for the design after it (docs/sweeps.md,
// "Resuming").
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "sweep_spec.h"

namespace {

namespace fs = std::filesystem;

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
}

class RtlFingerprint : public ::testing::Test {
 protected:
  void SetUp() override {
    // One directory per process: CTest runs each test of this fixture as its own process, in
    // parallel, so a name shared between them (gtest's random seed is one per second) races.
    root_ = fs::temp_directory_path() /
            ("rpu_test_rtl_fingerprint_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    write(root_ / "rtl" / "rpu.f", "common/a.v\n");
    write(root_ / "rtl" / "common" / "a.v", "module a; endmodule\n");
    write(root_ / "rtl" / "common" / "w.vh", "`define W 8\n");
    write(root_ / "scripts" / "synth_hier.py", "# flow\n");
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path root_;
};

TEST_F(RtlFingerprint, SameContentSameHash) {
  const std::string a = rpu::app::rtl_fingerprint(root_);
  write(root_ / "rtl" / "common" / "a.v", "module a; endmodule\n");  // rewritten, same bytes
  EXPECT_EQ(rpu::app::rtl_fingerprint(root_), a);
  EXPECT_EQ(a.size(), 16u);
}

TEST_F(RtlFingerprint, EveryKindOfChangeChangesIt) {
  const std::string a = rpu::app::rtl_fingerprint(root_);
  write(root_ / "rtl" / "common" / "a.v", "module a; // edited\nendmodule\n");
  const std::string b = rpu::app::rtl_fingerprint(root_);
  EXPECT_NE(b, a) << "a source edit";
  write(root_ / "rtl" / "common" / "w.vh", "`define W 9\n");
  const std::string c = rpu::app::rtl_fingerprint(root_);
  EXPECT_NE(c, b) << "a header edit";
  write(root_ / "rtl" / "common" / "b.v", "module b; endmodule\n");
  const std::string d = rpu::app::rtl_fingerprint(root_);
  EXPECT_NE(d, c) << "a new file";
  write(root_ / "scripts" / "synth_hier.py", "# flow, changed\n");
  const std::string e = rpu::app::rtl_fingerprint(root_);
  EXPECT_NE(e, d) << "a flow edit";
  fs::rename(root_ / "rtl" / "common" / "b.v", root_ / "rtl" / "common" / "c.v");
  EXPECT_NE(rpu::app::rtl_fingerprint(root_), e) << "a renamed file";
}

TEST(RtlFingerprintErrors, MissingFlowIsAnErrorNamingIt) {
  const fs::path root =
      fs::temp_directory_path() / ("rpu_test_rtl_fingerprint_noflow_" + std::to_string(::getpid()));
  fs::remove_all(root);
  write(root / "rtl" / "a.v", "module a; endmodule\n");
  try {
    rpu::app::rtl_fingerprint(root);
    ADD_FAILURE() << "no error without scripts/synth_hier.py";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("synth_hier.py"), std::string::npos) << e.what();
  }
  fs::remove_all(root);
}

}  // namespace
