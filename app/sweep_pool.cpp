#include "sweep_pool.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rpu::app {

void run_pool(size_t count, unsigned threads, const std::function<void(size_t)>& task) {
  std::atomic<size_t> next{0};
  std::atomic<bool> stop{false};
  std::exception_ptr first;
  std::mutex error_mu;
  const auto worker = [&] {
    for (size_t k; !stop.load() && (k = next.fetch_add(1)) < count;) {
      try {
        task(k);
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mu);
        if (!first) first = std::current_exception();
        stop.store(true);
      }
    }
  };
  {
    std::vector<std::jthread> pool;
    const size_t workers = std::min<size_t>(std::max(1u, threads), count);
    for (size_t t = 1; t < workers; ++t) pool.emplace_back(worker);
    worker();
  }
  if (first) std::rethrow_exception(first);
}

}  // namespace rpu::app
