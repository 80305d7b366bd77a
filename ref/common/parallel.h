// Running a per-row job on all cores: rows are handed out one at a time from an atomic counter
// (rendering cost varies a lot between rows), each worker keeps its own tallies.
#pragma once

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace rpu {

// Calls make_worker() once per thread; the returned callable is invoked for each row it takes,
// then destroyed (so it can flush its tallies in its destructor or via `finish`). `threads` = 0
// means all hardware threads.
template <class RowFn, class FinishFn>
void parallel_rows(int rows, int threads, RowFn row_fn, FinishFn finish_fn) {
  std::atomic<int> next{0};
  const auto worker = [&] {
    auto local = row_fn;  // per-thread copy holding per-thread tallies
    for (int j; (j = next.fetch_add(1)) < rows;) local(j);
    finish_fn(local);
  };
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const unsigned n = threads > 0 ? static_cast<unsigned>(threads) : hw;
  std::vector<std::jthread> pool;
  for (unsigned t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
}

}  // namespace rpu
