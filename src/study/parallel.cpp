// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/study/parallel.hpp"

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace flexrock::study {

int resolve_threads(int requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw > 0 ? static_cast<int>(hw) : 1;
}

void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t)>& task,
                  const std::atomic<bool>* cancel) {
  if (n == 0) return;
  const auto workers = static_cast<std::size_t>(
      std::min<std::size_t>(static_cast<std::size_t>(resolve_threads(threads)), n));
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_error;
  std::mutex error_mutex;
  auto work = [&] {
    for (;;) {
      if (failed.load(std::memory_order_relaxed)) return;
      if (cancel && cancel->load(std::memory_order_relaxed)) return;
      const std::size_t i = next.fetch_add(1, std::memory_order_relaxed);
      if (i >= n) return;
      try {
        task(i);
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!first_error) first_error = std::current_exception();
        failed.store(true);
        return;
      }
    }
  };
  if (workers == 1) {
    // no thread for a single worker: simpler stacks in a debugger, same order
    work();
  } else {
    std::vector<std::jthread> pool;
    pool.reserve(workers);
    for (std::size_t w = 0; w < workers; ++w) pool.emplace_back(work);
  }  // jthreads join here
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace flexrock::study
