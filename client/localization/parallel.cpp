#include "client/localization/parallel.h"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace fleetmap::localization {

namespace {

thread_local int inside = 0;  // chunks of a parallel_for running on this thread

// Marks the running chunk, so that a parallel_for called from it runs on its thread.
struct InsideChunk {
  InsideChunk() { ++inside; }
  ~InsideChunk() { --inside; }
};

}  // namespace

void parallel_for(int threads, size_t n, const std::function<void(int, size_t, size_t)>& fn) {
  const int t = inside > 0 ? 1 : std::max(1, threads);
  const auto begin = [&](int k) { return n * static_cast<size_t>(k) / static_cast<size_t>(t); };
  if (t == 1) {
    fn(0, 0, n);
    return;
  }
  std::vector<std::exception_ptr> errors(t);
  std::vector<std::thread> pool;
  pool.reserve(t - 1);
  for (int k = 1; k < t; ++k)
    pool.emplace_back([&, k] {
      try {
        const InsideChunk mark;
        fn(k, begin(k), begin(k + 1));
      } catch (...) {
        errors[k] = std::current_exception();
      }
    });
  try {
    const InsideChunk mark;
    fn(0, begin(0), begin(1));
  } catch (...) {
    errors[0] = std::current_exception();
  }
  for (std::thread& th : pool) th.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace fleetmap::localization
