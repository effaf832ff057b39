// The matrix of a linear map on R^N, column by column: LieGroupBase's deduced dτ^{-1}* matrices
// (core/lie_group.h) and the truncated exponential's.
#pragma once

#include <Eigen/Core>

namespace ddb {

/// The N × N matrix of a linear map on R^N, column j = map(e_j).
template <int N, class Map>
Eigen::Matrix<double, N, N> linearMapMatrix(const Map& map) {
  using V = Eigen::Matrix<double, N, 1>;
  Eigen::Matrix<double, N, N> matrix;
  for (int j = 0; j < N; ++j) matrix.col(j) = map(V(V::Unit(j)));
  return matrix;
}

}  // namespace ddb
