// Running a per-row job on all cores: rows are handed out one at a time from an atomic counter
// (rendering cost varies a lot between rows), each worker keeps its own tallies.
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "common/error.h"

namespace rpu {

// Calls make_worker() once per thread; the returned callable is invoked for each row it takes,
// then destroyed (so it can flush its tallies in its destructor or via `finish`). `threads` = 0
// means all hardware threads; never more workers than rows.
//
// Failures are reported, never fatal: an exception thrown by a row or by `finish` in any worker
// (std::bad_alloc past a memory limit included) stops the other workers at their next row and is
// rethrown here, in the calling thread, once every worker has ended. A worker thread that cannot
// be started (the thread limit, or the address space for its stack under `ulimit -v`) is an
// rpu::Error naming --threads, thrown once the workers already started have ended.
template <class RowFn, class FinishFn>
void parallel_rows(int rows, int threads, RowFn row_fn, FinishFn finish_fn) {
  std::atomic<int> next{0};
  std::atomic<bool> stop{false};
  std::exception_ptr first;
  std::mutex error_mu;
  const auto fail = [&](std::exception_ptr e) {
    std::lock_guard<std::mutex> lock(error_mu);
    if (!first) first = std::move(e);
    stop.store(true);
  };
  const auto worker = [&] {
    try {
      auto local = row_fn;  // per-thread copy holding per-thread tallies
      for (int j; !stop.load(std::memory_order_relaxed) && (j = next.fetch_add(1)) < rows;) local(j);
      finish_fn(local);
    } catch (...) {
      fail(std::current_exception());
    }
  };
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const unsigned wanted = threads > 0 ? static_cast<unsigned>(threads) : hw;
  const unsigned n = std::max(1u, std::min(wanted, static_cast<unsigned>(std::max(rows, 1))));
  {
    std::vector<std::jthread> pool;
    try {
      pool.reserve(n);
      for (unsigned t = 1; t < n; ++t) pool.emplace_back(worker);
    } catch (const std::system_error& e) {
      fail(std::make_exception_ptr(Error(
          "--threads", "cannot start worker thread " + std::to_string(pool.size() + 2) + " of " +
                           std::to_string(n) + " (" + e.code().message() + "; " +
                           (threads > 0 ? std::to_string(threads) + " asked"
                                        : std::string("one per core")) +
                           ", at most one per row); lower --threads (README, \"Limits\")")));
    } catch (const std::bad_alloc&) {
      fail(std::current_exception());
    }
    if (!stop.load()) worker();
  }  // joins the started workers
  if (first) std::rethrow_exception(first);
}

}  // namespace rpu
