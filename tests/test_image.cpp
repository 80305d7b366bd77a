// Images carry exact colours (README "Command line"): the background where nothing is hit, the
// primitive's colour otherwise, in every format.
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "common/error.h"
#include "image/frame.h"
#include "image/image_io.h"

namespace rpu::image {
namespace {

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "rpu_test_image_io" / name;
  std::filesystem::remove_all(dir);
  return dir;
}

void write_text(const std::filesystem::path& p, const std::string& text) { std::ofstream(p) << text; }

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(ImageIo, ExactColoursInEveryFormat) {
  Frame f(5, 3);
  f.primitive[f.index(1, 0)] = 0;
  f.primitive[f.index(4, 2)] = 1;
  const std::vector<scene::Color> colors = {{1.0, 0.8, 0.2}, {0.5, 0.5, 0.5}};
  const scene::Color background = {0.05, 0.15, 0.05};
  const auto rgb = to_rgb(f, colors, background);
  const auto dir = std::filesystem::temp_directory_path() / "rpu_test_image";
  std::filesystem::create_directories(dir);
  for (const char* ext : {".png", ".ppm", ".exr", ".tif"}) {
    const std::string path = (dir / (std::string("frame") + ext)).string();
    write_rgb(path, f.width, f.height, rgb);
    int w = 0, h = 0;
    const auto back = read_rgb(path, w, h);
    ASSERT_EQ(w, 5);
    ASSERT_EQ(h, 3);
    const bool is_float = std::string(ext) == ".exr";
    for (size_t k = 0; k < rgb.size(); ++k) {
      // 8-bit formats hold round(255·c) exactly; float formats hold c itself.
      const float expected = is_float ? rgb[k] : std::round(rgb[k] * 255.0f) / 255.0f;
      EXPECT_FLOAT_EQ(back[k], expected) << ext << " value " << k;
    }
  }
}

TEST(ImageIo, BadPathsAreReported) {
  EXPECT_THROW(check_writable("image.nosuchformat"), rpu::Error);
  EXPECT_THROW(check_writable("/no/such/directory/image.png"), rpu::Error);
  EXPECT_NO_THROW(check_writable("image.png"));
  // Outputs are regular files: a directory or a device (also behind a symlink) is refused.
  const auto dir = fresh_dir("bad_paths");
  std::filesystem::create_directories(dir / "d.png");
  std::filesystem::create_symlink("/dev/full", dir / "full.png");
  for (const char* name : {"d.png", "full.png"}) {
    try {
      check_writable((dir / name).string());
      ADD_FAILURE() << "accepted " << name;
    } catch (const rpu::Error& e) {
      EXPECT_EQ(e.where(), (dir / name).string());
    }
  }
}

// In a death-test child: writes each path under a 1 KiB file-size limit; exits 0 when every
// write threw naming its file.
[[noreturn]] void write_under_file_size_limit(const std::vector<std::string>& paths, int side,
                                              const std::vector<float>& rgb) {
  const rlimit limit{1024, 1024};
  ::setrlimit(RLIMIT_FSIZE, &limit);
  std::signal(SIGXFSZ, SIG_IGN);
  for (const std::string& path : paths) {
    try {
      write_rgb(path, side, side, rgb);
      std::fprintf(stderr, "%s: written\n", path.c_str());
      std::exit(1);
    } catch (const rpu::Error& e) {
      std::fprintf(stderr, "%s\n", e.what());
      if (e.where() != path) std::exit(2);
    }
  }
  std::exit(0);
}

// A write that fails part-way (here a file-size limit, as `ulimit -f` sets) throws naming the
// file and leaves neither the file nor a temporary behind, in every format; a file already there
// keeps its content.
TEST(ImageIoDeathTest, FailedWritesLeaveNoPartialFile) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  constexpr int kSide = 128;  // noise: no format compresses it below the 1 KiB limit
  std::vector<float> rgb(kSide * kSide * 3);
  std::uint32_t state = 12345;
  for (float& v : rgb) v = static_cast<float>((state = state * 1664525u + 1013904223u) >> 8) / 16777216.0f;
  const auto dir = fresh_dir("partial");
  std::filesystem::create_directories(dir);
  write_text(dir / "old.png", "previous content");
  std::vector<std::string> paths;
  for (const char* name : {"x.png", "x.exr", "x.ppm", "x.tif", "old.png"})
    paths.push_back((dir / name).string());
  EXPECT_EXIT(write_under_file_size_limit(paths, kSide, rgb), ::testing::ExitedWithCode(0),
              "x.png: cannot write the file: File too large");
  std::vector<std::string> left;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    left.push_back(e.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"old.png"});
  EXPECT_EQ(read_text(dir / "old.png"), "previous content");
}

// The rename replaces a symlink at the output path; the file it pointed to is untouched.
TEST(ImageIo, SymlinkAtTheOutputIsReplacedNotFollowed) {
  const auto dir = fresh_dir("symlink");
  std::filesystem::create_directories(dir);
  write_text(dir / "target.png", "keep");
  std::filesystem::create_symlink(dir / "target.png", dir / "link.png");
  const Frame f(4, 4);
  write_rgb((dir / "link.png").string(), 4, 4, to_rgb(f, {}, {0, 0, 0}));
  EXPECT_FALSE(std::filesystem::is_symlink(dir / "link.png"));
  EXPECT_EQ(read_text(dir / "target.png"), "keep");
  int w = 0, h = 0;
  read_rgb((dir / "link.png").string(), w, h);
  EXPECT_EQ(w, 4);
}

}  // namespace
}  // namespace rpu::image
