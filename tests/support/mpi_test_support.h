// Shared by the MPI tests: the process grid they run on, seeded random matrices, the same on
// every rank, the relative Frobenius distance, and the suites parameterised by N and the
// block size.
#pragma once

#include <ddb/distributed/process_grid.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <complex>
#include <random>
#include <string>
#include <tuple>

namespace ddb::test {

/// The grid rows the tests ask for: the test program's --grid-rows=R
/// (tests/support/mpi_test_main.cc; tests/mpi/tests.cmake passes it for the runs on the other shape
/// of P = 2 and 3 ranks), else 0, the default shape.
inline int& gridRowsAsked() {
  static int rows = 0;
  return rows;
}

/// The grid of all ranks the tests run on.
class TestGrid : public ProcessGrid {
 public:
  TestGrid() : ProcessGrid(MPI_COMM_WORLD, gridRowsAsked()) {}
};

inline Eigen::MatrixXcd randomComplexMatrix(int n, unsigned seed) {
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXcd a(n, n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) a(i, j) = {normal(generator), normal(generator)};
  }
  return a;
}

/// A seeded random vorticity: traceless skew-Hermitian, the same on every rank.
inline Eigen::MatrixXcd randomVorticity(int n, unsigned seed) {
  const Eigen::MatrixXcd a = randomComplexMatrix(n, seed);
  Eigen::MatrixXcd w = (a - a.adjoint()) / 2.0;
  w.diagonal().array() -= w.trace() / double(n);
  return w;
}

inline double relativeDistance(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& reference) {
  return (a - reference).norm() / reference.norm();
}

// A suite run at N = get<0> and block size get<1> on a grid of all ranks.
class SizeAndBlockTest : public testing::TestWithParam<std::tuple<int, int>> {
 protected:
  int n() const { return std::get<0>(GetParam()); }
  int block() const { return std::get<1>(GetParam()); }
  TestGrid grid_;
};

inline std::string sizeAndBlockName(const testing::TestParamInfo<std::tuple<int, int>>& info) {
  return "N" + std::to_string(std::get<0>(info.param)) + "_block" +
         std::to_string(std::get<1>(info.param));
}

}  // namespace ddb::test
