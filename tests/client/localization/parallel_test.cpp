// parallel_for (client/localization/parallel.h): every item in exactly one chunk, and a
// call from inside a chunk runs on that chunk's thread rather than starting more.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <thread>
#include <vector>

#include "client/localization/parallel.h"

namespace fleetmap::localization {
namespace {

TEST(ParallelFor, EveryItemInExactlyOneChunk) {
  std::vector<std::atomic<int>> seen(101);
  parallel_for(3, seen.size(), [&](int, size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) ++seen[i];
  });
  for (const auto& s : seen) EXPECT_EQ(s.load(), 1);
}

TEST(ParallelFor, ANestedCallRunsAsOneChunkOnTheCallingThread) {
  std::mutex m;
  std::vector<std::thread::id> outer_threads;
  int inner_calls = 0;
  bool inner_on_own_thread = true, inner_whole_range = true;
  parallel_for(2, 2, [&](int, size_t, size_t) {
    const std::thread::id me = std::this_thread::get_id();
    parallel_for(4, 8, [&](int k, size_t begin, size_t end) {
      const std::lock_guard<std::mutex> lock(m);
      ++inner_calls;
      inner_on_own_thread = inner_on_own_thread && std::this_thread::get_id() == me;
      inner_whole_range = inner_whole_range && k == 0 && begin == 0 && end == 8;
    });
    const std::lock_guard<std::mutex> lock(m);
    outer_threads.push_back(me);
  });
  ASSERT_EQ(outer_threads.size(), 2u);
  EXPECT_NE(outer_threads[0], outer_threads[1]);  // the outer call did use two threads
  EXPECT_EQ(inner_calls, 2);                      // one chunk per inner call
  EXPECT_TRUE(inner_on_own_thread);
  EXPECT_TRUE(inner_whole_range);
  // After the outer call, a call from this thread starts its threads again.
  std::vector<std::thread::id> ids(4);
  parallel_for(4, 4, [&](int k, size_t, size_t) { ids[k] = std::this_thread::get_id(); });
  EXPECT_NE(ids[0], ids[1]);
}

}  // namespace
}  // namespace fleetmap::localization
