// The worker pool of `rpu sweep`: configurations run concurrently, one per worker.
#pragma once

#include <cstddef>
#include <functional>

namespace rpu::app {

// Runs task(0) … task(count − 1), each once, on `threads` workers (this thread is one of them;
// at most count are started). When a task throws, no further task starts, the running ones
// finish, and the first exception is rethrown here.
void run_pool(size_t count, unsigned threads, const std::function<void(size_t)>& task);

}  // namespace rpu::app
