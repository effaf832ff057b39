// Ceres as the solver of a DDB Cayley step's discrete Legendre equation on a matrix group,
// an independent check of the matrix-free iterations (MatrixLegendreSolver's fixed point
// and Newton–Krylov, matrix_legendre.h): ceres::Problem with dense QR on
//   r(p) = (I + a(p)) p (I − a(p)) − W = 0
// in real coordinates of u(N) (so(N)), the imaginary diagonal and the upper triangle, the
// Jacobian assembled column by column from the solver's exact Jacobian–vector products.
// For small N only (at most kMaxCeresUnknowns). Kept apart so that the methods' headers do
// not include <ceres/ceres.h>: the one header of the library that needs Ceres's library, which
// ddb does not link; a program that includes it links Ceres::ceres itself.
#pragma once

#include <ceres/ceres.h>
#include <ddb/core/errors.h>
#include <ddb/integrators/solvers/matrix_legendre.h>

#include <Eigen/Core>
#include <complex>
#include <string>
#include <vector>

namespace ddb {

/// The most real unknowns Ceres is asked to take (u(8)).
inline constexpr Eigen::Index kMaxCeresUnknowns = 64;

namespace detail {

// Real coordinates of u(N) (so(N)) and back.
template <class Dual>
struct AlgebraCoordinates {
  static constexpr bool kComplex = Eigen::NumTraits<typename Dual::Scalar>::IsComplex;
  static Eigen::Index count(Eigen::Index n) { return kComplex ? n * n : n * (n - 1) / 2; }
  static void to(const Dual& x, double* v) {
    for (Eigen::Index j = 0; j < x.cols(); ++j) {
      for (Eigen::Index i = 0; i <= j; ++i) {
        if constexpr (kComplex) {
          if (i == j) {
            *v++ = x(i, i).imag();
          } else {
            *v++ = x(i, j).real();
            *v++ = x(i, j).imag();
          }
        } else if (i < j) {
          *v++ = x(i, j);
        }
      }
    }
  }
  static void from(const double* v, Dual& x) {
    for (Eigen::Index j = 0; j < x.cols(); ++j) {
      for (Eigen::Index i = 0; i <= j; ++i) {
        if constexpr (kComplex) {
          if (i == j) {
            x(i, i) = typename Dual::Scalar(0.0, *v++);
          } else {
            const double re = *v++;
            x(i, j) = typename Dual::Scalar(re, *v++);
            x(j, i) = -std::conj(x(i, j));
          }
        } else if (i < j) {
          x(i, j) = *v++;
          x(j, i) = -x(i, j);
        } else {
          x(i, i) = 0.0;
        }
      }
    }
  }
};

// r(p) in coordinates, with the Jacobian column by column.
template <class Solver>
class CeresLegendreResidual : public ceres::CostFunction {
  using Dual = typename Solver::Dual;
  using Coordinates = AlgebraCoordinates<Dual>;

 public:
  CeresLegendreResidual(Solver& solver, const Dual& W, double h, int n)
      : solver_(solver), W_(W), h_(h), value_(W), direction_(W), column_(W) {
    set_num_residuals(n);
    mutable_parameter_block_sizes()->push_back(n);
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const int n = num_residuals();
    Coordinates::from(parameters[0], solver_.iterate());
    solver_.residualInto(W_, h_, value_);
    Coordinates::to(value_, residuals);
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      std::vector<double> unit(static_cast<std::size_t>(n), 0.0), column(unit);
      for (int k = 0; k < n; ++k) {
        unit[static_cast<std::size_t>(k)] = 1.0;
        Coordinates::from(unit.data(), direction_);
        unit[static_cast<std::size_t>(k)] = 0.0;
        solver_.jacobianTimes(direction_, h_, column_);
        Coordinates::to(column_, column.data());
        for (int i = 0; i < n; ++i) jacobians[0][i * n + k] = column[static_cast<std::size_t>(i)];
      }
    }
    return true;
  }

 private:
  Solver& solver_;
  const Dual& W_;
  double h_;
  mutable Dual value_, direction_, column_;
};

}  // namespace detail

/// Makes `solver` solve DDB's Cayley equation by Ceres (dense QR) from the predicted
/// iterate: at most kMaxCeresUnknowns real unknowns, else InvalidArgument at the solve.
template <class R, class System>
void useCeres(MatrixLegendreSolver<R, System>& solver) {
  using Solver = MatrixLegendreSolver<R, System>;
  using Dual = typename Solver::Dual;
  static_assert(Solver::kDense && Solver::kProductForm,
                "Ceres solves the Cayley equation on dense matrices");
  solver.setExternalSolver([](Solver& s, const Dual& W, double h) {
    using Coordinates = detail::AlgebraCoordinates<Dual>;
    const Eigen::Index n = Coordinates::count(W.rows());
    if (n > kMaxCeresUnknowns) {
      throwInvalid("strategy", "ceres",
                   "solves at most " + std::to_string(kMaxCeresUnknowns) + " unknowns, not " +
                       std::to_string(n));
    }
    std::vector<double> x(static_cast<std::size_t>(n));
    Coordinates::to(s.iterate(), x.data());
    ceres::Problem::Options problem_options;
    problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(problem_options);
    detail::CeresLegendreResidual<Solver> residual(s, W, h, static_cast<int>(n));
    problem.AddResidualBlock(&residual, nullptr, x.data());
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::DENSE_QR;
    options.max_num_iterations = 50;
    options.function_tolerance = 0.0;
    options.gradient_tolerance = 0.0;
    options.parameter_tolerance = 1e-16;
    options.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    Coordinates::from(x.data(), s.iterate());
    return static_cast<int>(summary.iterations.size());
  });
}

}  // namespace ddb
