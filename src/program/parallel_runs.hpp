// Independent runs spread over a few threads, for the programs that run many (Chapters 5 and 7). Each job builds
// its own Scene, ForceField and Stepper, since those are not safe to share; the pool only hands out job numbers
// and carries the first exception back to the caller.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace cloth {

/// Calls job(0) .. job(count - 1), at most `threads` at a time, in order of job number as threads free up (put
/// the longest jobs first). Rethrows the first exception a job threw, after every thread has stopped. Returns the
/// wall-clock seconds it took.
inline double run_in_parallel(std::size_t count, int threads, const std::function<void(std::size_t)>& job) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto worker = [&] {
    for (std::size_t k = next++; k < count; k = next++) {
      try {
        job(k);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = count;  // the others finish their current job and stop
      }
    }
  };
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace cloth
