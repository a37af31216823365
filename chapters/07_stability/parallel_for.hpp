// Runs body(i) for i = 0..count-1 on `threads` threads, each taking the next index when it is done: the sweep's
// jobs differ in cost by a factor of a thousand, so a fixed split would leave one thread idle.
#pragma once

#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace ch07 {

template <class Body>
void parallel_for(std::size_t count, int threads, Body&& body) {
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t i; (i = next++) < count;) body(i);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();  // the calling thread is one of them
  for (std::thread& t : pool) t.join();
}

}  // namespace ch07
