// Frame-parallel co-simulation's cut (sim/harness/frame_share.h): shares are contiguous, cover
// every work item and pixel exactly once, end only after a pixel's last item, are about equal in
// items, and come back unchanged through a shard file; the digest tells frames apart.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <random>

#include <fmt/format.h>

#include "common/error.h"
#include "frame_share.h"
#include "stream_file.h"
#include "test_seed.h"

namespace rpu::sim {
namespace {

// A frame of `pixels` pixels with 1..max_items work items each (random), ids 0, 1, 2, ...
FrameSchedule frame(int pixels, int max_items, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  FrameSchedule f;
  f.width = 64;
  f.height = (pixels + 63) / 64;
  std::uint32_t id = 0;
  for (int p = 0; p < pixels; ++p) {
    const int n = 1 + static_cast<int>(rng() % static_cast<std::uint64_t>(max_items));
    for (int k = 0; k < n; ++k) {
      WorkItem it;
      it.id = id++;
      it.i = p % 64;
      it.j = p / 64;
      it.seg = static_cast<std::uint32_t>(rng() % 100);
      it.texture = rng() % 4 == 0;
      it.last = k + 1 == n;
      f.items.push_back(it);
      ItemResult e;
      e.id = it.id;
      e.i = it.i;
      e.j = it.j;
      e.last = it.last;
      f.expected.push_back(e);
    }
    f.expected_pixels.push_back({p % 64, p / 64, false, 0, 0});
  }
  return f;
}

TEST(FrameShare, SharesCoverTheFrameOnceAndEndAtPixels) {
  const std::uint64_t seed = test::seed(7);
  for (int pixels : {1, 2, 5, 97, 1000}) {
    for (int count : {1, 2, 3, 7, 64}) {
      SCOPED_TRACE(fmt::format("{} pixels, {} shares, seed {}", pixels, count, seed));
      const FrameSchedule f = frame(pixels, 9, seed + static_cast<std::uint64_t>(pixels));
      const std::vector<FrameShare> s = split_frame(f, count);
      ASSERT_EQ(s.size(), static_cast<size_t>(count));
      std::size_t item = 0, pixel = 0, items_left = f.items.size();
      for (const FrameShare& x : s) {
        EXPECT_EQ(x.count, count);
        EXPECT_EQ(x.first_item, item);
        EXPECT_EQ(x.first_pixel, pixel);
        ASSERT_LE(x.first_item, x.end_item);
        if (x.end_item > x.first_item) {
          EXPECT_TRUE(f.items[x.end_item - 1].last);
        }
        const FrameSchedule part = share_schedule(f, x);
        EXPECT_EQ(part.items.size(), x.end_item - x.first_item);
        EXPECT_EQ(part.expected.size(), part.items.size());
        EXPECT_EQ(part.expected_pixels.size(), x.end_pixel - x.first_pixel);
        std::size_t lasts = 0;
        for (const WorkItem& it : part.items) lasts += it.last;
        EXPECT_EQ(lasts, part.expected_pixels.size());
        EXPECT_EQ(part.curve_items + part.texture_items, part.items.size());
        // Balanced: a share is at most its even part plus one pixel's items (9 at most).
        EXPECT_LE(x.end_item - x.first_item, f.items.size() / count + 9);
        item = x.end_item;
        pixel = x.end_pixel;
        items_left -= part.items.size();
      }
      EXPECT_EQ(item, f.items.size());
      EXPECT_EQ(pixel, f.expected_pixels.size());
      EXPECT_EQ(items_left, 0u);
    }
  }
  EXPECT_THROW(split_frame(frame(3, 2, seed), 0), Error);
}

TEST(FrameShare, TheDigestTellsFramesApart) {
  const FrameSchedule f = frame(50, 4, 1);
  FrameSchedule g = f;
  EXPECT_EQ(schedule_digest(f), schedule_digest(g));
  g.items[10].seg ^= 1;
  EXPECT_NE(schedule_digest(f), schedule_digest(g));
  g = f;
  g.params.n = 12;
  EXPECT_NE(schedule_digest(f), schedule_digest(g));
  g = f;
  g.width = 65;
  EXPECT_NE(schedule_digest(f), schedule_digest(g));
}

TEST(FrameShare, AShardFileRoundTrips) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / fmt::format("rpu_test_frame_share_{}.shard", ::getpid());
  ShardRecord r;
  r.digest = 0x0123456789abcdefull;
  r.share = split_frame(frame(40, 3, 2), 4)[2];
  r.config = "n16_n1_2_unrolled";
  ItemResult a;
  a.id = 77;
  a.hit = true;
  a.depth = i128{1} << 90;
  r.streams.results.push_back(a);
  r.streams.pixels.push_back({3, 4, true, -5, 9});
  r.streams.stats.cycles = 1234;
  write_shard(file.string(), r);
  const ShardRecord b = read_shard(file.string());
  EXPECT_EQ(b.digest, r.digest);
  EXPECT_EQ(b.share.index, 2);
  EXPECT_EQ(b.share.count, 4);
  EXPECT_EQ(b.share.first_item, r.share.first_item);
  EXPECT_EQ(b.share.end_pixel, r.share.end_pixel);
  EXPECT_EQ(b.config, r.config);
  ASSERT_EQ(b.streams.results.size(), 1u);
  EXPECT_EQ(b.streams.results[0], a);
  EXPECT_EQ(b.streams.pixels[0].depth, -5);
  EXPECT_EQ(b.streams.stats.cycles, 1234u);
  // A job file is not a shard file.
  write_job(file.string(), frame(3, 2, 3));
  EXPECT_THROW(read_shard(file.string()), Error);
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace rpu::sim
