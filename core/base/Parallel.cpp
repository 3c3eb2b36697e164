#include "base/Parallel.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "base/Blas.h"

namespace rollsim {

namespace {
/// One batch of work: indices handed out by an atomic counter; the first failure (lowest index) kept.
class Batch {
 public:
  Batch(size_t n, const std::function<void(size_t)>& fn) : n_(n), fn_(fn) {}
  void work() {
    for (size_t i = next_++; i < n_; i = next_++) try {
        fn_(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex_);
        if (!error_ || i < error_index_) error_ = std::current_exception(), error_index_ = i;
      }
  }
  void rethrow() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  size_t n_;
  const std::function<void(size_t)>& fn_;
  std::atomic<size_t> next_{0};
  std::mutex error_mutex_;
  std::exception_ptr error_;
  size_t error_index_ = 0;
};

/// Threads kept for the process; grown on demand, joined at exit.
class Pool {
 public:
  ~Pool() {
    {
      const std::lock_guard<std::mutex> lock(m_);
      stop_ = true;
    }
    wake_.notify_all();
    for (auto& t : threads_) t.join();
  }
  /// Runs `batch` on `helpers` pool threads plus the caller; false if another caller holds the pool.
  bool run(Batch& batch, size_t helpers) {
    std::unique_lock<std::mutex> busy(busy_, std::try_to_lock);
    if (!busy.owns_lock()) return false;
    {
      const std::lock_guard<std::mutex> lock(m_);
      while (threads_.size() < helpers) threads_.emplace_back([this, k = threads_.size()] { loop(k); });
      batch_ = &batch;
      active_ = helpers;
      running_ = helpers;
      ++generation_;
    }
    wake_.notify_all();
    batch.work();
    std::unique_lock<std::mutex> lock(m_);
    done_.wait(lock, [&] { return running_ == 0; });
    batch_ = nullptr;
    return true;
  }

 private:
  void loop(size_t k) {
    set_openmp_threads(1);
    size_t seen = 0;
    for (;;) {
      Batch* batch = nullptr;
      {
        std::unique_lock<std::mutex> lock(m_);
        wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
        if (stop_) return;
        seen = generation_;
        if (k >= active_) continue;  // not needed for this batch
        batch = batch_;
      }
      batch->work();
      {
        const std::lock_guard<std::mutex> lock(m_);
        --running_;
      }
      done_.notify_one();
    }
  }

  std::mutex busy_;  // one batch at a time
  std::mutex m_;
  std::condition_variable wake_, done_;
  std::vector<std::thread> threads_;
  Batch* batch_ = nullptr;
  size_t active_ = 0, running_ = 0, generation_ = 0;
  bool stop_ = false;
};

Pool& pool() {
  static Pool p;
  return p;
}
}  // namespace

void for_each_group(size_t n, int threads, const std::function<void(size_t)>& fn) {
  const size_t count = std::min<size_t>(static_cast<size_t>(std::max(1, threads)), n);
  if (count <= 1) {
    for (size_t i = 0; i < n; ++i) fn(i);
    return;
  }
  Batch batch(n, fn);
  if (!pool().run(batch, count - 1)) {  // the pool is busy with another caller's batch: threads of our own
    std::vector<std::thread> own;
    for (size_t t = 1; t < count; ++t)
      own.emplace_back([&] {
        set_openmp_threads(1);
        batch.work();
      });
    batch.work();
    for (auto& t : own) t.join();
  }
  batch.rethrow();
}

}  // namespace rollsim
