// The small implicit solver (core/detail/tiny_solver.h, docs/reference/conventions.md §4) on
// square equations whose roots are known in closed form, one for each of its three solvers of
// the normal equations (closed-form inverse n ≤ 4, Schur complement n = 6, Cholesky n = 9):
// Levenberg–Marquardt from a far guess, the chord iterations from a near one, Jet Jacobians
// against the derivatives written out, and the failures it reports.
#include <ddb/core/detail/tiny_solver.h>
#include <gtest/gtest.h>

#include <cmath>

namespace ddb::test {
namespace tiny_solver_tests {

// r_i(x) = x_i³ + (A x)_i − b_i with b = x*³ + A x* for a chosen root x*; A = I + 0.1 S (S a
// fixed matrix with entries in [−1, 1]) keeps the Jacobian 3 diag(x²) + A nonsingular near x*.
template <int N>
struct CubicEquations {
  Eigen::Matrix<double, N, N> A;
  Eigen::Matrix<double, N, 1> root, b;

  CubicEquations() {
    for (int i = 0; i < N; ++i) {
      root(i) = 0.5 + 0.25 * i;
      for (int j = 0; j < N; ++j) A(i, j) = (i == j ? 1.0 : 0.0) + 0.1 * std::sin(1.0 + 3 * i + j);
    }
    b = root.array().cube().matrix() + A * root;
  }
  template <class T>
  bool operator()(const T* x, T* r) const {
    for (int i = 0; i < N; ++i) {
      T sum = x[i] * x[i] * x[i] - T(b(i));
      for (int j = 0; j < N; ++j) sum += T(A(i, j)) * x[j];
      r[i] = sum;
    }
    return true;
  }
  // ∂r/∂x = 3 diag(x²) + A, written out.
  Eigen::Matrix<double, N, N> jacobian(const Eigen::Matrix<double, N, 1>& x) const {
    Eigen::Matrix<double, N, N> J = A;
    for (int i = 0; i < N; ++i) J(i, i) += 3 * x(i) * x(i);
    return J;
  }
};

template <class Size>
class TinySolverTest : public ::testing::Test {};
template <int N>
struct Size {
  static constexpr int value = N;
};
using Sizes = ::testing::Types<Size<3>, Size<6>, Size<9>>;
TYPED_TEST_SUITE(TinySolverTest, Sizes);

TYPED_TEST(TinySolverTest, JetJacobiansAreTheDerivativesWrittenOut) {
  constexpr int N = TypeParam::value;
  const CubicEquations<N> equations;
  const AutoDiffEquation<CubicEquations<N>, N> function(equations);
  Eigen::Matrix<double, N, 1> x = equations.root * 1.3;
  Eigen::Matrix<double, N, 1> r, r_plain;
  Eigen::Matrix<double, N, N> J;
  function(x.data(), r.data(), J.data());
  function(x.data(), r_plain.data(), nullptr);
  EXPECT_EQ((r - r_plain).norm(), 0.0);  // the same arithmetic on the Jets' scalar parts
  EXPECT_LE((J - equations.jacobian(x)).norm(), 1e-15 * equations.jacobian(x).norm());
}

TYPED_TEST(TinySolverTest, LevenbergMarquardtFindsTheRootFromAFarGuess) {
  constexpr int N = TypeParam::value;
  const CubicEquations<N> equations;
  Eigen::Matrix<double, N, 1> x = Eigen::Matrix<double, N, 1>::Constant(2.0);  // far off
  SolverOptions options;
  const TinySolveStats stats =
      solveTiny<N>(equations, x, equations.b.norm(), options, "cubic equations", 0.0, 0.1);
  EXPECT_TRUE(stats.converged);
  EXPECT_LE(stats.residual, options.relative_tolerance * equations.b.norm());
  EXPECT_LE((x - equations.root).norm(), 1e-14 * equations.root.norm());
  EXPECT_LT(stats.iterations, options.max_iterations);
}

// Newton's convergence is quadratic: from x₀ within δ of the root one iteration leaves O(δ²).
TYPED_TEST(TinySolverTest, OneIterationSquaresTheError) {
  constexpr int N = TypeParam::value;
  const CubicEquations<N> equations;
  const AutoDiffEquation<CubicEquations<N>, N> function(equations);
  for (double delta : {1e-2, 1e-3, 1e-4}) {
    Eigen::Matrix<double, N, 1> x = equations.root;
    x(0) += delta;
    runTinySolver(function, x, 0.0, 2);  // iterations 1 .. max − 1: one step
    const double error = (x - equations.root).norm();
    EXPECT_LE(error, 10.0 * delta * delta) << "delta " << delta;
    EXPECT_GT(error, 0.0) << "delta " << delta;  // a step, not the root by chance
  }
}

TYPED_TEST(TinySolverTest, ChordIterationsConvergeFromANearGuessToTheSameRoot) {
  constexpr int N = TypeParam::value;
  const CubicEquations<N> equations;
  const AutoDiffEquation<CubicEquations<N>, N> function(equations);
  Eigen::Matrix<double, N, 1> x = equations.root * (1.0 + 1e-4);
  const double target = 1e-14 * equations.b.norm();
  const TinySolveStats stats = runChordIterations(function, x, target, 10);
  EXPECT_TRUE(stats.converged);
  EXPECT_LE(stats.residual, target);
  EXPECT_LE((x - equations.root).norm(), 1e-14 * equations.root.norm());
  // The Jacobian of the first point only: the error contracts linearly, by about δ each time, so
  // more than one iteration and fewer than ten.
  EXPECT_GE(stats.iterations, 2);
  EXPECT_LE(stats.iterations, 9);
}

// x² + 1 = 0 has no real root: the solver ends at the least-squares point x = 0, ‖r‖ = 1.
struct NoRealRoot {
  template <class T>
  bool operator()(const T* x, T* r) const {
    r[0] = x[0] * x[0] + T(1.0);
    return true;
  }
};
TEST(TinySolver, AnEquationWithoutRootIsASolveFailureWithItsResidual) {
  Eigen::Matrix<double, 1, 1> x(0.7);
  try {
    solveTiny<1>(NoRealRoot(), x, 1.0, SolverOptions{}, "x^2 + 1 = 0", 2.5, 0.125);
    FAIL() << "no SolveFailure";
  } catch (const NonFiniteState&) {
    FAIL() << "a finite residual reported as non-finite";
  } catch (const SolveFailure& e) {
    EXPECT_EQ(e.whatFailed(), "x^2 + 1 = 0");
    EXPECT_EQ(e.time(), 2.5);
    EXPECT_EQ(e.h(), 0.125);
    // |x² + 1| ≥ 1 for every real x, with equality at the minimiser x = 0 of ½‖r‖²; and the
    // solver took no step that raised the cost from the guess's (|0.7² + 1| = 1.49).
    EXPECT_GE(e.residual(), 1.0);
    EXPECT_LE(e.residual(), 1.49);
    EXPECT_EQ(e.tolerance(), SolverOptions{}.relative_tolerance);
  }
}

// e^{1000 x} − 1 = 0 from x = 1: the residual overflows, which the solver reports as such.
struct Overflowing {
  template <class T>
  bool operator()(const T* x, T* r) const {
    using std::exp;
    r[0] = exp(T(1000.0) * x[0]) - T(1.0);
    return true;
  }
};
TEST(TinySolver, AnOverflowingResidualIsANonFiniteStateNamingTheResidual) {
  Eigen::Matrix<double, 1, 1> x(1.0);
  try {
    solveTiny<1>(Overflowing(), x, 1.0, SolverOptions{}, "overflowing equation", 0.0, 0.1);
    FAIL() << "no NonFiniteState";
  } catch (const NonFiniteState& e) {
    EXPECT_NE(std::string(e.what()).find("residual"), std::string::npos) << e.what();
  }
}

}  // namespace tiny_solver_tests
}  // namespace ddb::test
