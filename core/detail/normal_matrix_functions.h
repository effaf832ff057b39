// Two decompositions of dense complex normal matrices that the matrix groups' Casimirs,
// logarithms and SO(N)'s adRadius rest on (groups/skew_hermitian_group.h,
// groups/special_orthogonal.h), compiled once in the library
// (core/detail/normal_matrix_functions.cc): at the dynamic size, and for adRadius, which a step
// calls, at a fixed capacity. Eigen's SelfAdjointEigenSolver and ComplexSchur instantiated in a
// header cost every translation unit that names a group's casimirs or log several seconds, again
// for each fixed size (docs/results/compile-costs.md, "Dense decompositions compiled once").
#pragma once

#include <Eigen/Core>

namespace ddb::detail {

/// The eigenvalues of the Hermitian A, ascending (its lower triangle is read).
Eigen::VectorXd hermitianEigenvalues(const Eigen::MatrixXcd& A);

/// log U = V diag(i arg λ) Vᴴ of a unitary U, from its complex Schur form U = V T Vᴴ (U is
/// normal, so T is diagonal, T = diag(λ)): the branch with the eigenvalues of −i log U in
/// (−π, π].
Eigen::MatrixXcd unitaryLogarithm(const Eigen::MatrixXcd& U);

/// SpecialOrthogonal<N>::adRadius of the real skew-symmetric n×n X (n ≥ 2): the sum of the two
/// largest eigenvalues of −iX, at least 0. The injectivity guard calls it before and after each
/// Legendre solve of the exponential methods, so up to n = 16 it works in fixed-capacity storage
/// and allocates nothing (tests/unit/test_allocations.cc); above, it allocates.
double skewSymmetricAdRadius(const Eigen::Ref<const Eigen::MatrixXd>& X);

}  // namespace ddb::detail
