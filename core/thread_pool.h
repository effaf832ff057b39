// ThreadPool: the library's own threads for a matrix step: its element-wise passes and
// Poisson solve, which no BLAS threads, and, under a single-threaded BLAS, its products and
// solves too (core/detail/blas_threads.h), so that one pool runs all of a step's work
// (docs/design/architecture.md, "Threads"). One pool per process, of threadCount() threads counting
// the caller.
//
// Why not OpenMP: libgomp's idle threads spin at full speed after each parallel region
// while the BLAS's threads need the cores for the next product, and its spin is read from
// the environment when it loads, out of a header library's reach. These threads spin
// briefly, yielding the core, and then sleep.
//
// How many threads: DDB_NUM_THREADS if set (a positive integer, else InvalidArgument naming
// it); else OPENBLAS_NUM_THREADS and then OMP_NUM_THREADS, as OpenBLAS reads them, so that
// one variable sets both pools; else the cores this process may run on. At most kMaxTasks.
// setThreadCount() overrides all.
//
// run(tasks, f) calls f(task) once for each task in [0, tasks) and returns when all have
// returned; f must not throw (a throw ends the process: it may run on a thread that cannot
// pass it on). A run made while the pool is busy (from inside a task, or from another thread
// of the user's), or in a forked child, which has none of the parent's threads, runs its tasks
// on the calling thread. Callers split work so that each entry is computed by the same
// operations whatever the split (element-wise passes, column sums, bands of the Poisson
// solve), or, where the rounding depends on the grouping (BLAS calls), by chunks set by the
// size alone: the results do not depend on the number of threads.
#pragma once

#include <ddb/core/errors.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdlib>
#include <mutex>
#include <string>
#include <system_error>
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
  int threadCount() const { return threads_; }

  /// Restarts the pool with n threads (at most kMaxTasks), the caller's included (1:
  /// everything on the caller). Refused while a run is under way.
  void setThreadCount(int n) {
    if (n < 1 || n > kMaxTasks) {
      throwInvalid("thread count", std::to_string(n),
                   "must be between 1 and " + std::to_string(kMaxTasks));
    }
    if (::getpid() != owner_) {
      stop();  // a forked child keeps to its own thread: the parent's locks may be held
      return;
    }
    if (busy_.exchange(true, std::memory_order_acquire)) {
      throwInvalid("thread count", std::to_string(n), "cannot change while the pool runs work");
    }
    stop();
    start(n);
    busy_.store(false, std::memory_order_release);
  }

  /// The most threads, and the most tasks a run is split into (callers may keep one result
  /// per task).
  static constexpr int kMaxTasks = 64;

  /// How many tasks `entries` entries of work should be split into: none below kMinEntries
  /// entries per task, where a wake-up costs more than the work.
  int tasksFor(long entries) const {
    return static_cast<int>(std::clamp<long>(entries / kMinEntries, 1, threadCount()));
  }

  /// f(task) for every task in [0, tasks): task t on the pool's thread t mod threadCount(),
  /// 0 on the caller's.
  template <class F>
  void run(int tasks, const F& f) {
    const auto call = [&f](int task) noexcept { f(task); };
    if (tasks <= 1 || workers_.empty() || ::getpid() != owner_ ||
        busy_.exchange(true, std::memory_order_acquire)) {
      for (int task = 0; task < tasks; ++task) call(task);
      return;
    }
    using Call = decltype(call);
    invoke_ = [](const void* context, int task) { (*static_cast<const Call*>(context))(task); };
    context_ = &call;
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
    for (int task = 0; task < tasks; task += threadCount()) call(task);
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
    const int tasks = static_cast<int>(std::min<long>(chunks, threadCount()));
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
  /// Yields an idle worker makes before it sleeps: few, so that a worker idle beside a
  /// threaded BLAS gives the core up soon (docs/design/architecture.md, "Threads").
  static constexpr int kSpinYields = 2000;

  explicit ThreadPool(int n) { start(n); }

  static int defaultThreadCount() {
    if (const char* value = std::getenv("DDB_NUM_THREADS")) {
      const int n = parseCount(value);
      if (n < 1) {
        throwInvalid("DDB_NUM_THREADS", value,
                     "must be an integer between 1 and " + std::to_string(kMaxTasks));
      }
      return n;
    }
    for (const char* name : {"OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"}) {
      if (const char* value = std::getenv(name)) {
        if (const int n = parseCount(value); n >= 1) return n;
      }
    }
    cpu_set_t allowed;
    const int cores = sched_getaffinity(0, sizeof(allowed), &allowed) == 0
                          ? CPU_COUNT(&allowed)
                          : static_cast<int>(std::thread::hardware_concurrency());
    return std::clamp(cores, 1, kMaxTasks);
  }
  // An integer between 1 and kMaxTasks, else 0.
  static int parseCount(const char* text) {
    char* end = nullptr;
    const long n = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || n < 1 || n > kMaxTasks) return 0;
    return static_cast<int>(n);
  }

  void start(int n) {
    stopping_ = false;
    owner_ = ::getpid();
    // A worker answers the generations after this one, whenever its thread starts.
    const unsigned long now = generation_.load(std::memory_order_seq_cst);
    // The workers read threads_ only in runs, which begin after it is set here.
    try {
      for (int i = 1; i < n; ++i) workers_.emplace_back([this, i, now] { serve(i, now); });
    } catch (const std::system_error&) {
      // No more threads to be had: run with those started.
    }
    threads_ = static_cast<int>(workers_.size()) + 1;
  }
  void stop() {
    if (::getpid() != owner_) {
      // A forked child has none of these threads: nothing to join (its runs are serial).
      for (std::thread& worker : workers_) worker.detach();
      workers_.clear();
      threads_ = 1;
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
    threads_ = 1;
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
      for (int task = index; task < tasks_; task += threadCount()) invoke_(context_, task);
      done_.fetch_add(1, std::memory_order_release);
    }
  }

  std::vector<std::thread> workers_;
  int threads_ = 1;  // workers_.size() + 1
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
