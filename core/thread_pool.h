// ThreadPool: the library's own threads for the O(N²) work of a matrix step (element-wise
// passes, the Poisson solve), which the BLAS's threads do not touch (docs/design.md,
// "Threads"). One pool per process, of threadCount() threads counting the caller.
//
// Why not OpenMP: libgomp's idle threads spin at full speed after each parallel region
// while the BLAS's threads need the cores for the next product, and its spin is read from
// the environment when it loads, out of a header library's reach. These threads spin
// briefly, yielding the core, and then sleep (docs/design.md, "Threads").
//
// How many threads: DDB_NUM_THREADS if set (a positive integer, else InvalidArgument naming
// it); else what OpenBLAS reads, OPENBLAS_NUM_THREADS and then OMP_NUM_THREADS, so that one
// variable sets both pools; else the machine's cores. setThreadCount() overrides all.
// Nothing is parallel below kMinEntries entries per task: a wake-up costs more there.
//
// run(tasks, f) calls f(task) once for each task in [0, tasks) and returns when all have
// returned; f must not throw (it is called on threads that cannot pass an exception on). A call
// made while the pool is busy (from inside a task, or from another thread of the user's) runs its
// tasks on the calling thread: the results are the same, since callers partition their work by its
// size, never by the thread count.
#pragma once

#include <ddb/core/errors.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace ddb {

class ThreadPool {
 public:
  /// Entries (matrix elements) a task must have for the work to be split at all.
  static constexpr long kMinEntries = 8192;

  /// The process's pool, started on first use.
  static ThreadPool& instance() {
    static ThreadPool pool(defaultThreadCount());
    return pool;
  }

  /// The threads a run() uses, the caller's included.
  int threadCount() const { return static_cast<int>(workers_.size()) + 1; }

  /// Restarts the pool with n threads, the caller's included (1: everything on the caller).
  /// Not to be called while another thread runs work on it.
  void setThreadCount(int n) {
    if (n < 1) throwInvalid("thread count", std::to_string(n), "must be >= 1");
    stop();
    start(n);
  }

  /// The most tasks a run is split into (callers may keep one result per task).
  static constexpr int kMaxTasks = 64;

  /// How many tasks `entries` entries of work should be split into.
  int tasksFor(long entries) const {
    return static_cast<int>(
        std::clamp<long>(entries / kMinEntries, 1, std::min(threadCount(), kMaxTasks)));
  }

  /// f(task) for every task in [0, tasks), task 0 on the caller's thread and task i on the
  /// pool's thread i; at most threadCount() tasks.
  template <class F>
  void run(int tasks, const F& f) {
    if (tasks <= 1 || workers_.empty() || ::getpid() != owner_ ||
        busy_.exchange(true, std::memory_order_acquire)) {
      for (int task = 0; task < tasks; ++task) f(task);
      return;
    }
    invoke_ = [](const void* context, int task) { (*static_cast<const F*>(context))(task); };
    context_ = &f;
    tasks_ = tasks;
    done_.store(0, std::memory_order_relaxed);
    // Every worker answers every generation (done_), so none can still read this run's
    // work when the next one writes it.
    generation_.fetch_add(1, std::memory_order_seq_cst);
    if (sleepers_.load(std::memory_order_seq_cst) > 0) {
      // Taking the lock orders the wake-up after any sleeper's last check of generation_.
      { std::lock_guard<std::mutex> lock(mutex_); }
      wake_.notify_all();
    }
    f(0);
    const int workers = static_cast<int>(workers_.size());
    while (done_.load(std::memory_order_acquire) < workers) std::this_thread::yield();
    busy_.store(false, std::memory_order_release);
  }

  /// f(first, count) over consecutive column ranges covering [0, cols) of a matrix with
  /// `rows` rows, split among the threads when the matrix is large enough.
  template <class F>
  void forColumnRanges(long rows, long cols, const F& f) {
    const int tasks = static_cast<int>(std::min<long>(tasksFor(rows * cols), cols));
    run(tasks, [&](int task) {
      const long first = cols * task / tasks, end = cols * (task + 1) / tasks;
      f(first, end - first);
    });
  }

  /// f(first, count) for each chunk of `width` consecutive columns of [0, cols) (the last
  /// one narrower), the chunks shared among the threads. For work whose rounding depends on
  /// how its columns are grouped (a BLAS product): the chunks do not depend on the threads.
  template <class F>
  void forColumnChunks(long cols, long width, const F& f) {
    const long chunks = (cols + width - 1) / width;
    const int tasks = static_cast<int>(std::min<long>(chunks, std::min(threadCount(), kMaxTasks)));
    run(tasks, [&](int task) {
      for (long chunk = chunks * task / tasks; chunk < chunks * (task + 1) / tasks; ++chunk) {
        f(chunk * width, std::min(width, cols - chunk * width));
      }
    });
  }

  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;
  ~ThreadPool() { stop(); }

 private:
  /// Yields an idle worker makes before it sleeps. Short, so that a worker waiting beside a
  /// threaded BLAS gives the core up soon; 200 to 20000 timed alike under a single-threaded
  /// BLAS, where the products run on these threads too (docs/design.md, "Threads").
  static constexpr int kSpinYields = 2000;

  explicit ThreadPool(int n) { start(n); }

  static int defaultThreadCount() {
    if (const char* value = std::getenv("DDB_NUM_THREADS")) {
      const int n = parseCount(value);
      if (n < 1) throwInvalid("DDB_NUM_THREADS", value, "must be a positive integer");
      return n;
    }
    for (const char* name : {"OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"}) {
      if (const char* value = std::getenv(name)) {
        if (const int n = parseCount(value); n >= 1) return n;
      }
    }
    return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  }
  // A positive integer of at most 4096, else 0.
  static int parseCount(const char* text) {
    char* end = nullptr;
    const long n = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || n < 1 || n > 4096) return 0;
    return static_cast<int>(n);
  }

  void start(int n) {
    stopping_ = false;
    owner_ = ::getpid();
    // A worker answers the generations after this one, whenever its thread starts.
    const unsigned long now = generation_.load(std::memory_order_seq_cst);
    for (int i = 1; i < n; ++i) workers_.emplace_back([this, i, now] { serve(i, now); });
  }
  void stop() {
    if (::getpid() != owner_) {
      // A forked child has none of these threads: nothing to join (its runs are serial).
      for (std::thread& worker : workers_) worker.detach();
      workers_.clear();
      return;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_.store(true, std::memory_order_release);
    }
    generation_.fetch_add(1, std::memory_order_seq_cst);
    wake_.notify_all();
    for (std::thread& worker : workers_) worker.join();
    workers_.clear();
  }

  void serve(int index, unsigned long seen) {
    for (;;) {
      for (int spins = 0;
           generation_.load(std::memory_order_acquire) == seen && spins < kSpinYields; ++spins) {
        std::this_thread::yield();
      }
      if (generation_.load(std::memory_order_acquire) == seen) {
        sleepers_.fetch_add(1, std::memory_order_seq_cst);
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(
            lock, [&] { return stopping_ || generation_.load(std::memory_order_seq_cst) != seen; });
        sleepers_.fetch_sub(1, std::memory_order_relaxed);
        if (stopping_) return;
      }
      seen = generation_.load(std::memory_order_acquire);
      if (stopping_.load(std::memory_order_acquire)) return;
      if (index < tasks_) invoke_(context_, index);
      done_.fetch_add(1, std::memory_order_release);
    }
  }

  std::vector<std::thread> workers_;
  pid_t owner_ = 0;  // the process that started the workers
  std::mutex mutex_;
  std::condition_variable wake_;
  std::atomic<bool> stopping_{false};
  std::atomic<unsigned long> generation_{0};
  std::atomic<int> sleepers_{0};
  std::atomic<bool> busy_{false};
  // The current run's work: written by the caller before generation_ moves.
  void (*invoke_)(const void*, int) = nullptr;
  const void* context_ = nullptr;
  int tasks_ = 0;
  std::atomic<int> done_{0};  // workers that have answered the current generation
};

}  // namespace ddb
