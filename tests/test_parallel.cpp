// parallel_rows (ref/common/parallel.h, issue 24): a failure in a worker is reported in the
// calling thread, never std::terminate; no more workers than rows.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <new>
#include <set>
#include <stdexcept>
#include <thread>

#include "common/error.h"
#include "common/parallel.h"

namespace rpu {
namespace {

// std::bad_alloc thrown by a row (an allocation past `ulimit -v` in a worker) reaches the caller,
// and the other workers stop taking rows.
TEST(ParallelRows, WorkerExceptionIsRethrownInTheCaller) {
  // Every other row takes 1 ms, so the 20,000 rows would take seconds on any machine if the
  // workers did not stop: a loaded machine that delays the throwing thread cannot let them finish
  // (with rows that cost nothing, 100,000 of them were once done before the exception landed).
  std::atomic<int> done{0};
  EXPECT_THROW(parallel_rows(
                   20000, 4,
                   [&](int j) {
                     if (j == 50) throw std::bad_alloc();
                     std::this_thread::sleep_for(std::chrono::milliseconds(1));
                     ++done;
                   },
                   [](auto&) {}),
               std::bad_alloc);
  EXPECT_LT(done.load(), 20000 - 1);
  EXPECT_THROW(parallel_rows(
                   8, 2, [](int j) { if (j == 7) throw Error("row 7", "failed"); },
                   [](auto&) {}),
               Error);
  // A failure in `finish` is reported too.
  EXPECT_THROW(parallel_rows(4, 2, [](int) {}, [](auto&) { throw std::runtime_error("finish"); }),
               std::runtime_error);
}

TEST(ParallelRows, NoMoreWorkersThanRows) {
  std::mutex mu;
  std::set<std::thread::id> ids;
  int rows_done = 0;
  parallel_rows(
      3, 64,
      [&](int) {
        std::lock_guard<std::mutex> lock(mu);
        ids.insert(std::this_thread::get_id());
        ++rows_done;
      },
      [](auto&) {});
  EXPECT_EQ(rows_done, 3);
  EXPECT_LE(ids.size(), 3u);
  // Zero rows: nothing runs, nothing fails.
  parallel_rows(0, 8, [](int) { FAIL(); }, [](auto&) {});
}

}  // namespace
}  // namespace rpu
