#include "engine/generator/parallel_for.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <numeric>
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

// A model of the generator's joins: each job "joins" two of 12 nodes (union-find); the order
// tries a job only if its nodes are apart after the commits before it, and ends when nodes 0
// and 1 are together. Jobs take uneven times, so threads finish out of order. Whatever the
// thread count and window, the commits (and so the answer) are those of running the jobs one
// by one; with one thread not even a skipped job runs.
TEST(OrderedPipeline, CommitsWhatRunningInOrderWould) {
  struct Edge {
    int i, j;
    bool joins;
  };
  std::vector<Edge> edges;
  for (int k = 0; k < 60; ++k) edges.push_back({(k * 7 + 3) % 12, (k * 5 + 1) % 12, k % 3 != 0});
  auto run = [&](int threads, size_t window, std::vector<size_t>& committed, size_t& ran) {
    std::vector<int> parent(12);
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](int x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    std::vector<char> result(edges.size(), 0);
    std::atomic<size_t> runs{0};
    ordered_pipeline(
        edges.size(), threads, window, [] { return false; },
        [&](size_t e) { return root(edges[e].i) == root(edges[e].j); },
        [&](size_t e) {
          ++runs;
          std::this_thread::sleep_for(std::chrono::microseconds(50 * ((e * 37) % 11)));
          result[e] = edges[e].joins;
        },
        [&](size_t e) {
          if (root(edges[e].i) == root(edges[e].j)) return true;  // made moot: dropped
          committed.push_back(e);
          if (result[e]) parent[root(edges[e].i)] = root(edges[e].j);
          return root(0) != root(1);
        });
    ran = runs;
  };
  std::vector<size_t> reference;
  size_t ran_one = 0;
  run(1, 1, reference, ran_one);
  ASSERT_FALSE(reference.empty());
  EXPECT_LT(reference.back(), edges.size() - 1) << "the model ends early (0 and 1 joined)";
  EXPECT_EQ(ran_one, reference.size()) << "one thread runs only the jobs it commits";
  for (int threads : {2, 3, 8})
    for (size_t window : {size_t{1}, size_t{2}, size_t{8}, size_t{100}}) {
      std::vector<size_t> committed;
      size_t ran = 0;
      run(threads, window, committed, ran);
      EXPECT_EQ(committed, reference) << threads << " threads, window " << window;
      EXPECT_GE(ran, reference.size());
    }
}

// Without skips or an early end every job runs and is committed once, in index order, and
// no job starts `window` or more places past the first not yet committed.
TEST(OrderedPipeline, CommitsEveryJobInOrder) {
  constexpr size_t kWindow = 3;
  for (int threads : {1, 2, 4}) {
    std::vector<std::atomic<int>> runs(41);
    std::vector<size_t> order;
    std::atomic<size_t> committed{0};
    ordered_pipeline(
        runs.size(), threads, kWindow, [] { return false; }, [](size_t) { return false; },
        [&](size_t j) {
          EXPECT_LT(j, committed.load() + kWindow) << "started beyond the window";
          std::this_thread::sleep_for(std::chrono::microseconds(30 * (j % 4)));
          ++runs[j];
        },
        [&](size_t j) {
          EXPECT_EQ(runs[j].load(), 1);
          order.push_back(j);
          ++committed;
          return true;
        });
    ASSERT_EQ(order.size(), runs.size()) << threads;
    for (size_t j = 0; j < order.size(); ++j) EXPECT_EQ(order[j], j);
  }
  ordered_pipeline(
      0, 2, 4, [] { return false; }, [](size_t) { return false; },
      [](size_t) { ADD_FAILURE() << "no job to run"; },
      [](size_t) {
        ADD_FAILURE() << "no job to commit";
        return true;
      });
}

// A stop request ends the run: no job starts once the calling thread has seen it; only those
// started before (at most the window) may still run.
TEST(OrderedPipeline, StopsWhenAsked) {
  constexpr size_t kWindow = 4;
  for (int threads : {1, 2}) {
    std::atomic<int> ran{0};
    ordered_pipeline(
        1000, threads, kWindow, [&] { return ran.load() >= 10; }, [](size_t) { return false; },
        [&](size_t) { ++ran; }, [](size_t) { return true; });
    EXPECT_GE(ran.load(), 10) << threads;
    if (threads == 1) {
      EXPECT_EQ(ran.load(), 10);
    }
    EXPECT_LE(ran.load(), 10 + static_cast<int>(kWindow)) << threads;
  }
}

}  // namespace
}  // namespace pcsg
