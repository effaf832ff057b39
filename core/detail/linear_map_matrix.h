// The matrix of a linear map on R^N, column by column: LieGroupBase's deduced dτ^{-1}* matrices
// (core/lie_group.h), the truncated exponential's and the adjoint and coadjoint representations
// (groups/representation.h), whose entries may be Jets.
#pragma once

#include <Eigen/Core>

namespace ddb {

/// The N × N matrix of a linear map on R^N (entries of type T), column j = map(e_j).
template <int N, class T = double, class Map>
Eigen::Matrix<T, N, N> linearMapMatrix(const Map& map) {
  using V = Eigen::Matrix<T, N, 1>;
  Eigen::Matrix<T, N, N> matrix;
  for (int j = 0; j < N; ++j) matrix.col(j) = map(V(V::Unit(j)));
  return matrix;
}

}  // namespace ddb
