// The library's threads (core/thread_pool.h) and the work that uses them: every task runs
// once, a nested or concurrent run falls back to the caller, and the threaded passes,
// products and solves give Eigen's serial results and the same bits on 1, 2 and 3 threads.
// Most matrices are large enough to be split three ways (3·ThreadPool::kMinEntries entries,
// half of that for the triangle of makeSkewHermitian), with sizes that the 32-wide tiles
// divide and do not; a few are too small to be split at all.
#include <ddb/core/detail/blas_threads.h>
#include <ddb/core/detail/dense_lu.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/core/parallel_passes.h>
#include <ddb/core/thread_pool.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/hoppe_yau_laplacian.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <atomic>
#include <cstring>
#include <thread>
#include <vector>

#include "test_support.h"

namespace ddb::test {
namespace {

using Matrix = Eigen::MatrixXcd;
using B = MatrixBackend<Matrix>;

// Restores the pool's thread count when a test ends.
class ThreadCount {
 public:
  ThreadCount() : saved_(ThreadPool::instance().threadCount()) {}
  ~ThreadCount() { ThreadPool::instance().setThreadCount(saved_); }
  void set(int n) { ThreadPool::instance().setThreadCount(n); }

 private:
  int saved_;
};

TEST(ThreadPool, EveryTaskRunsOnceAndANestedRunRunsOnTheCaller) {
  ThreadCount count;
  for (const int threads : {1, 2, 3}) {
    count.set(threads);
    ThreadPool& pool = ThreadPool::instance();
    EXPECT_EQ(pool.threadCount(), threads);
    for (int repeat = 0; repeat < 2000; ++repeat) {
      std::vector<std::atomic<int>> calls(static_cast<std::size_t>(threads));
      std::vector<std::atomic<int>> nested(static_cast<std::size_t>(threads));
      pool.run(threads, [&](int task) {
        ++calls[static_cast<std::size_t>(task)];
        // The pool is busy: this run must complete on the calling thread.
        pool.run(threads, [&](int inner) { ++nested[static_cast<std::size_t>(inner)]; });
      });
      for (int task = 0; task < threads; ++task) {
        ASSERT_EQ(calls[static_cast<std::size_t>(task)], 1) << threads << " threads, task " << task;
        ASSERT_EQ(nested[static_cast<std::size_t>(task)], threads) << threads << " threads";
      }
    }
  }
}

TEST(ThreadPool, RunsFromTwoUserThreadsAtOnceBothComplete) {
  ThreadCount count;
  count.set(2);
  std::atomic<long> sum{0};
  const auto work = [&] {
    for (int repeat = 0; repeat < 2000; ++repeat) {
      ThreadPool::instance().run(2, [&](int task) { sum += task + 1; });
    }
  };
  std::thread other(work);
  work();
  other.join();
  EXPECT_EQ(sum, 2 * 2000 * 3);
}

TEST(ThreadPool, MoreTasksThanThreadsRunOnceEach) {
  ThreadCount count;
  count.set(2);
  std::vector<std::atomic<int>> calls(7);
  ThreadPool::instance().run(7, [&](int task) { ++calls[static_cast<std::size_t>(task)]; });
  for (const auto& c : calls) EXPECT_EQ(c, 1);
}

TEST(ThreadPool, ABadThreadCountOrAChangeDuringARunIsRefusedByName) {
  ThreadCount count;
  for (const int n : {0, ThreadPool::kMaxTasks + 1}) {
    try {
      ThreadPool::instance().setThreadCount(n);
      FAIL() << "no exception for " << n;
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find("thread count"), std::string::npos) << e.what();
    }
  }
  count.set(2);
  std::atomic<int> refused{0};
  ThreadPool::instance().run(2, [&](int task) {
    if (task != 0) return;
    try {
      ThreadPool::instance().setThreadCount(3);
    } catch (const InvalidArgument&) {
      ++refused;
    }
  });
  EXPECT_EQ(refused, 1);
  EXPECT_EQ(ThreadPool::instance().threadCount(), 2);
}

// Runs f with 1, 2 and 3 threads and expects the same result bit for bit.
template <class F>
Matrix sameOnEveryThreadCount(const F& f) {
  ThreadCount count;
  count.set(1);
  const Matrix serial = f();
  for (const int threads : {2, 3}) {
    count.set(threads);
    const Matrix threaded = f();
    // memcmp: the same bits, the signs of zeros included.
    const bool same_shape = threaded.rows() == serial.rows() && threaded.cols() == serial.cols();
    EXPECT_TRUE(same_shape) << threads << " threads";
    EXPECT_TRUE(same_shape && std::memcmp(threaded.data(), serial.data(),
                                          sizeof(Matrix::Scalar) * serial.size()) == 0)
        << threads << " threads";
  }
  return serial;
}

TEST(ParallelPasses, SkewHermitianPartIsEigensBitForBit) {
  std::srand(3);
  for (const Eigen::Index n : {1, 31, 256, 257}) {
    const Matrix x = Matrix::Random(n, n);
    const Matrix expected = 0.5 * (x - x.adjoint());
    const Matrix result = sameOnEveryThreadCount([&] {
      Matrix y = x;
      B::makeSkewHermitian(y);
      return y;
    });
    EXPECT_TRUE(result == expected) << "N = " << n;
  }
}

TEST(ParallelPasses, AddedAdjointIsEigensBitForBit) {
  std::srand(4);
  const Matrix x = Matrix::Random(161, 203), out0 = Matrix::Random(203, 161);
  for (const Eigen::Index n : {1, 31}) {  // too small to be split
    const Matrix small = Matrix::Random(n, n);
    Matrix out = small;
    B::addAdjoint(2.0, small, out);
    EXPECT_TRUE(out == Matrix(small + 2.0 * small.adjoint())) << "N = " << n;
  }
  const Matrix expected = out0 + (-0.75) * x.adjoint();
  const Matrix result = sameOnEveryThreadCount([&] {
    Matrix out = out0;
    B::addAdjoint(-0.75, x, out);
    return out;
  });
  EXPECT_TRUE(result == expected);
}

TEST(ParallelPasses, AssignmentsAreEigensBitForBit) {
  std::srand(5);
  const Matrix x = Matrix::Random(150, 171), y = Matrix::Random(150, 171);
  const Matrix expected = 0.3 * x - y;
  const Matrix result = sameOnEveryThreadCount([&] {
    Matrix out;  // assignInParallel gives it the expression's shape
    assignInParallel(out, 0.3 * x - y);
    return out;
  });
  EXPECT_TRUE(result == expected);
  const Matrix added = sameOnEveryThreadCount([&] {
    Matrix out = y;
    addInParallel(out, 0.3 * x);
    return out;
  });
  EXPECT_TRUE(added == Matrix(y + 0.3 * x));
}

TEST(ParallelPasses, TheBackendsElementwiseOperationsAreTheSameBitsOnEveryThreadCount) {
  std::srand(6);
  const Matrix x = Matrix::Random(150, 171), y = Matrix::Random(150, 171),
               z = Matrix::Random(150, 171);
  sameOnEveryThreadCount([&] {
    Matrix out;
    B::sum(0.3, x, -1.0, y, 2.5, z, out);
    return out;
  });
  sameOnEveryThreadCount([&] {
    Matrix out = z;
    const Eigen::Vector2d c(0.3, -0.7);
    B::addCombination(
        c, [&](int j) -> const Matrix& { return j == 0 ? x : y; }, 2, out);
    return out;
  });
}

// The reductions split by columns: the 1-norm against a loop with std::abs, the zero test.
TEST(ParallelPasses, OneNormAndZeroTestAgreeWithLoopsOnEveryThreadCount) {
  std::srand(8);
  Matrix x = Matrix::Random(140, 230);
  x.col(201) *= 3.0;  // the largest column in the last task's range
  const double expected = oneNormByLoops(x);
  ThreadCount count;
  for (const int threads : {1, 2, 3}) {
    count.set(threads);
    EXPECT_NEAR(B::oneNorm(x), expected, 1e-14 * expected) << threads << " threads";
    Matrix nan = x;
    nan(3, 7) = NAN;  // in the first task's range
    EXPECT_TRUE(std::isnan(B::oneNorm(nan))) << threads << " threads";
    Matrix zero = Matrix::Zero(140, 230);
    EXPECT_TRUE(B::isZero(zero)) << threads << " threads";
    zero(139, 229) = 1e-300;  // the last entry, in the last task's range
    EXPECT_FALSE(B::isZero(zero)) << threads << " threads";
  }
}

// Products and LU solves are split among the library's threads under a single-threaded
// BLAS (this test's environment sets OPENBLAS_NUM_THREADS=1): against Eigen's coefficient-wise
// product (no BLAS) and an inverse, and the same bits on every thread count.
TEST(ParallelPasses, ProductsAndSolvesSplitByColumnsAgreeWithEigen) {
  if (detail::blasThreadCount() == 0) GTEST_SKIP() << "a BLAS that does not report its threads";
  ASSERT_EQ(detail::blasThreadCount(), 1) << "run with OPENBLAS_NUM_THREADS=1";
  std::srand(9);
  const Matrix a = Matrix::Random(150, 120), b = Matrix::Random(120, 173);
  const Matrix product = sameOnEveryThreadCount([&] {
    Matrix out;
    B::multiply(a, b, out);
    return out;
  });
  Matrix expected = Matrix::Zero(150, 173);
  expected.noalias() += a.lazyProduct(b);  // Eigen's coefficient-wise product, no BLAS
  EXPECT_LT((product - expected).norm(), 1e-13 * expected.norm());

  const Matrix A = Matrix::Random(140, 140) + 20.0 * Matrix::Identity(140, 140);
  const Matrix X = Matrix::Random(140, 200);  // four chunks of 64 columns
  const Matrix solved = sameOnEveryThreadCount([&] {
    Matrix factors = A, Y = X;
    DenseLu<Matrix> lu;
    EXPECT_TRUE(lu.factor(factors));
    lu.solve(factors, Y);
    return Y;
  });
  const Matrix reference = A.inverse() * X;
  EXPECT_LT((solved - reference).norm(), 1e-12 * reference.norm());
}

// The banded Poisson solve against the Laplacian's own apply (which it does not use) and the
// same bits on every thread count.
TEST(ParallelPasses, PoissonSolveByBandsInvertsTheLaplacian) {
  std::srand(6);
  for (const Eigen::Index n : {128, 191}) {
    const HoppeYauLaplacian laplacian(n);
    const Matrix W = Matrix::Random(n, n);
    const Matrix P = sameOnEveryThreadCount([&] {
      Matrix out;
      laplacian.solve(W, out);
      return out;
    });
    Matrix back;
    laplacian.apply(P, back);
    Matrix traceless = W;
    traceless.diagonal().array() -= W.trace() / double(n);
    EXPECT_LT((back - traceless).norm(), 1e-12 * traceless.norm()) << "N = " << n;
    EXPECT_LT(std::abs(P.trace()), 1e-12 * P.norm()) << "N = " << n;
  }
}

// A whole DDB step of the fluid with dissipation (solver, predictor, Poisson solves, both
// conjugations) gives the same state on every thread count. N = 224: every pass splits three
// ways (makeSkewHermitian's triangle has 224²/2 ≥ 3·8192 entries).
TEST(ParallelPasses, AFluidStepIsTheSameOnEveryThreadCount) {
  const Eigen::Index n = 224;
  const auto system = makeZeitlinFluid(n, 0.5);
  const Matrix W0 = randomVorticity(n, 1);
  sameOnEveryThreadCount([&] {
    auto method = makeMethod<SUN>("ddb-cay", system);
    Matrix W = W0;
    for (int k = 0; k < 5; ++k) method->advance(W, 0.01 * k, 0.01);
    return W;
  });
}

}  // namespace
}  // namespace ddb::test
