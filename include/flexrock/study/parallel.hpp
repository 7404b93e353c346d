// SPDX-License-Identifier: BSD-3-Clause
// Running many independent simulations: an index-based pool of std::jthread workers. Work is
// handed out by an atomic counter and every result is stored at its index, so the output cannot
// depend on the thread count or on the order in which runs finish.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>

namespace flexrock::study {

/// How a study runs: threads, progress, cancellation, and (for several processes, e.g. MPI
/// ranks) which share of the run indices this process computes.
struct RunOptions {
  int threads = 0;                                // worker threads; 0: every core
  std::atomic<std::size_t>* completed = nullptr;  // if set: incremented after every finished run
  const std::atomic<bool>* cancel = nullptr;      // if set and true: no new runs are started
  int rank = 0;   // this process's share: runs with index % ranks == rank (static interleave)
  int ranks = 1;  // processes sharing the runs (1: this process runs them all)
};

/// Threads that `requested` means: itself if > 0, else std::thread::hardware_concurrency()
/// (at least 1).
int resolve_threads(int requested);

/// Calls task(i) for every i in [0, n) on `threads` workers (0: every core). Indices are taken
/// in increasing order from an atomic counter; `cancel` (may be null) stops handing out new
/// ones. The first exception a task throws is rethrown here after the workers stop; the other
/// workers stop taking new indices once one has thrown.
void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t)>& task,
                  const std::atomic<bool>* cancel = nullptr);

}  // namespace flexrock::study
