#include "pxpl5/worker_pool.h"

#include <utility>

namespace pxpl5 {

WorkerPool::WorkerPool(int workers) {
  for (int w = 1; w < workers; ++w) threads_.emplace_back([this, w] { work(w); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : threads_) t.join();
}

void WorkerPool::drain(int worker) {
  for (size_t task = next_.fetch_add(1); task < taskCount_; task = next_.fetch_add(1)) {
    try {
      (*job_)(task, worker);
    } catch (...) {
      // An exception must not leave a helper thread (that would terminate the program): keep
      // it for run() and let the others stop taking tasks.
      next_.store(taskCount_);
      std::lock_guard lock(mutex_);
      if (!failure_) failure_ = std::current_exception();
    }
  }
}

void WorkerPool::work(int worker) {
  uint64_t seen = 0;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
    }
    drain(worker);
    std::lock_guard lock(mutex_);
    if (--busy_ == 0) done_.notify_one();
  }
}

void WorkerPool::run(size_t taskCount, const std::function<void(size_t, int)>& job) {
  if (threads_.empty() || taskCount <= 1) {  // no one to share with: skip the wake-up
    for (size_t task = 0; task < taskCount; ++task) job(task, 0);
    return;
  }
  {
    std::lock_guard lock(mutex_);
    job_ = &job;
    taskCount_ = taskCount;
    next_.store(0);
    failure_ = nullptr;
    busy_ = static_cast<int>(threads_.size());
    ++generation_;
  }
  wake_.notify_all();
  drain(0);
  std::unique_lock lock(mutex_);
  done_.wait(lock, [&] { return busy_ == 0; });
  if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
}

}  // namespace pxpl5
