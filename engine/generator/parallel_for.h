#pragma once
// The generator's one worker pool: independent jobs handed out in index order to a few
// threads, the calling thread among them. Callers write each job's result to its own slot
// and merge the slots in index order afterwards, so the outcome does not depend on the
// number of threads or on which thread ran which job.
#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
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

// A window for ordered_pipeline: this many jobs per thread may start ahead of the first job
// not yet committed. The joins and motions it runs differ in length by 10x and more (a motion
// that fails at once, against a walk through waypoints), so one slow job at the head must not
// idle the other threads; a wider window only risks more work that an early answer makes
// useless.
constexpr size_t kJobsAheadPerThread = 4;
inline size_t jobs_ahead(int threads) {
  return kJobsAheadPerThread * static_cast<size_t>(std::max(1, threads));
}

// Jobs whose results are used in index order, as if run one by one, with up to `threads`
// of them running at once ahead of an in-order commit. The calling thread decides which jobs
// start, commits them, and runs started jobs itself while the next to commit is not done.
// - skip(j) is asked before job j would start (after every commit that the jobs done by then
//   allow): true leaves j unrun and uncommitted. It is asked again once every job before j
//   is committed: true then drops j's result unread. So a skip must stay true once true, and
//   commit(j) always follows a false skip(j).
// - commit(j) is called once for each job run and not dropped, in index order; false ends
//   the run (no job after it is committed, or started).
// - At most `window` jobs past the first not yet committed are started (work that an earlier
//   commit may make useless). stop() ends the run early.
// skip, commit and stop run on the calling thread only (so that listeners hear from one
// thread), never alongside each other, and jobs must not touch what they change. With one
// thread it is exactly: for j in order: if (!skip(j)) { job(j); if (!commit(j)) break; }.
// Unlike batches of `threads` jobs, no thread waits for the slowest job of a batch, nor (but
// the calling one) for a commit: a thread that finishes a job takes the next at once.
template <typename Stop, typename Skip, typename Job, typename Commit>
void ordered_pipeline(size_t jobs, int threads, size_t window, Stop&& stop, Skip&& skip, Job&& job,
                      Commit&& commit) {
  if (threads <= 1 || jobs <= 1) {
    for (size_t j = 0; j < jobs && !stop(); ++j) {
      if (skip(j)) continue;
      job(j);
      if (!commit(j)) break;
    }
    return;
  }
  enum : char { kWaiting, kQueued, kDone, kSkipped };
  std::vector<char> status(jobs, kWaiting);  // under the lock
  std::deque<size_t> queue;                  // started, not yet taken by a worker
  bool closing = false;
  std::mutex mutex;
  std::condition_variable work, finished;
  // Under the lock, with a job queued: runs the first outside it.
  auto run_first = [&](std::unique_lock<std::mutex>& lock) {
    const size_t j = queue.front();
    queue.pop_front();
    lock.unlock();
    job(j);
    lock.lock();
    if (status[j] == kQueued) status[j] = kDone;  // (not when skipped meanwhile)
  };
  auto worker = [&] {
    std::unique_lock<std::mutex> lock(mutex);
    for (;;) {
      work.wait(lock, [&] { return closing || !queue.empty(); });
      if (closing) return;
      run_first(lock);
      finished.notify_one();
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads && t < static_cast<int>(jobs); ++t) pool.emplace_back(worker);
  window = std::max<size_t>(window, 1);
  size_t next = 0, committed = 0;
  while (committed < jobs && !stop()) {
    // Start what the window allows.
    for (; next < jobs && next < committed + window; ++next) {
      const bool skipped = skip(next);
      std::lock_guard<std::mutex> lock(mutex);
      status[next] = skipped ? kSkipped : kQueued;
      if (!skipped) {
        queue.push_back(next);
        work.notify_one();
      }
    }
    // The first job not yet committed: skipped after all if the commits before it say so
    // now (its result, done or to come, is not read); else waited for, and committed
    // (outside the lock: the workers go on meanwhile).
    char head;
    {
      std::unique_lock<std::mutex> lock(mutex);
      head = status[committed];
    }
    if (head != kSkipped && skip(committed)) {
      std::lock_guard<std::mutex> lock(mutex);
      const auto queued = std::find(queue.begin(), queue.end(), committed);
      if (queued != queue.end()) queue.erase(queued);
      status[committed] = kSkipped;
      head = kSkipped;
    }
    if (head == kQueued) {
      // Until it is done, this thread runs started jobs too (the lowest first).
      std::unique_lock<std::mutex> lock(mutex);
      while (status[committed] == kQueued) {
        if (queue.empty())
          finished.wait(lock);
        else
          run_first(lock);
      }
      head = status[committed];
    }
    if (head == kDone && !commit(committed)) break;
    ++committed;
  }
  {
    std::lock_guard<std::mutex> lock(mutex);
    closing = true;
    queue.clear();
  }
  work.notify_all();
  for (std::thread& t : pool) t.join();
}

}  // namespace pcsg
