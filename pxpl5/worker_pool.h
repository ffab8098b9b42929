// The graphics-processor and renderer threads of a Machine: created once with it, woken for each
// phase of a frame. The calling thread works as worker 0, so one worker means no extra thread.
#pragma once

#include <atomic>
#include <condition_variable>
#include <exception>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace pxpl5 {

class WorkerPool {
 public:
  explicit WorkerPool(int workers);  // workers >= 1
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int size() const { return static_cast<int>(threads_.size()) + 1; }

  // Calls job(task, worker) once for every task in [0, taskCount), tasks taken in increasing
  // order by whichever worker comes free first; returns when all are done. If a job throws, the
  // remaining tasks are skipped and the first exception is rethrown here. Not re-entrant.
  void run(size_t taskCount, const std::function<void(size_t task, int worker)>& job);

 private:
  void work(int worker);
  void drain(int worker);

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  uint64_t generation_ = 0;  // bumped per run; workers wait for a new one
  int busy_ = 0;             // helper threads still inside the current run
  bool stop_ = false;
  const std::function<void(size_t, int)>* job_ = nullptr;
  size_t taskCount_ = 0;
  std::atomic<size_t> next_{0};
  std::exception_ptr failure_;  // the first exception a job threw in this run (under mutex_)
};

}  // namespace pxpl5
