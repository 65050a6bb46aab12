#include "engine/generator/parallel_for.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

namespace pcsg {
namespace {

// Every job runs exactly once, whatever the thread count (more threads than jobs included).
TEST(ParallelFor, RunsEachJobOnce) {
  for (int threads : {1, 2, 4, 64}) {
    std::vector<std::atomic<int>> runs(37);
    parallel_for(
        runs.size(), threads, [] { return false; }, [&](size_t j) { ++runs[j]; });
    for (size_t j = 0; j < runs.size(); ++j) EXPECT_EQ(runs[j].load(), 1) << threads << " " << j;
  }
  parallel_for(
      0, 4, [] { return false; }, [](size_t) { ADD_FAILURE() << "no job to run"; });
}

// Progress is reported from the calling thread only, after each job it ran, with counts that
// never go back. (The other threads may take every job, so the caller may report none.)
TEST(ParallelFor, ReportsProgressFromTheCallingThread) {
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<size_t> seen;
  std::atomic<int> by_caller{0};
  parallel_for(
      200, 3, [] { return false; },
      [&](size_t) {
        if (std::this_thread::get_id() == caller) ++by_caller;
      },
      [&](size_t finished) {
        EXPECT_EQ(std::this_thread::get_id(), caller);
        seen.push_back(finished);
      });
  EXPECT_EQ(static_cast<int>(seen.size()), by_caller.load());
  for (size_t k = 1; k < seen.size(); ++k) EXPECT_LT(seen[k - 1], seen[k]);
  for (size_t f : seen) EXPECT_LE(f, 200u);
  // One thread: every job reported, in order.
  seen.clear();
  parallel_for(
      5, 1, [] { return false; }, [](size_t) {}, [&](size_t f) { seen.push_back(f); });
  EXPECT_EQ(seen, (std::vector<size_t>{1, 2, 3, 4, 5}));
}

// A stop request leaves the remaining jobs unrun.
TEST(ParallelFor, StopsWhenAsked) {
  std::atomic<int> ran{0};
  parallel_for(
      1000, 1, [&] { return ran.load() >= 10; }, [&](size_t) { ++ran; });
  EXPECT_EQ(ran.load(), 10);
  ran = 0;
  parallel_for(
      1000, 2, [&] { return ran.load() >= 10; }, [&](size_t) { ++ran; });
  EXPECT_GE(ran.load(), 10);
  EXPECT_LE(ran.load(), 11);  // at most one job per other thread was under way
}

}  // namespace
}  // namespace pcsg
