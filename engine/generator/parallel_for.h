#pragma once
// The generator's one worker pool: independent jobs handed out in index order to a few
// threads, the calling thread among them. Callers write each job's result to its own slot
// and merge the slots in index order afterwards, so the outcome does not depend on the
// number of threads or on which thread ran which job.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace pcsg {

// Runs job(j) once for each j in [0, jobs) on min(threads, jobs) threads (at least one: the
// caller's), taking the next index until none is left or stop() returns true; a stopped run
// leaves the remaining jobs unrun. After each job the calling thread (and only it, so that
// listeners are called from one thread) calls progress(finished), where `finished` counts
// the jobs done so far on every thread.
template <typename Job, typename Stop, typename Progress>
void parallel_for(size_t jobs, int threads, Stop&& stop, Job&& job, Progress&& progress) {
  std::atomic<size_t> next{0}, done{0};
  auto worker = [&](bool caller) {
    for (size_t j; (j = next.fetch_add(1)) < jobs;) {
      if (stop()) break;
      job(j);
      const size_t finished = ++done;
      if (caller) progress(finished);
    }
  };
  const int n = std::max(1, static_cast<int>(std::min<size_t>(std::max(threads, 1), jobs)));
  std::vector<std::thread> pool;
  for (int t = 1; t < n; ++t) pool.emplace_back(worker, false);
  worker(true);
  for (std::thread& t : pool) t.join();
}

// The same without progress reports.
template <typename Job, typename Stop>
void parallel_for(size_t jobs, int threads, Stop&& stop, Job&& job) {
  parallel_for(jobs, threads, stop, job, [](size_t) {});
}

}  // namespace pcsg
