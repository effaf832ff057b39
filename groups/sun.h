// SU(N), N chosen at run time: the algebra su(N) of complex skew-Hermitian traceless N×N
// matrices, its dual identified with it by the pairing Re tr(μᴴ ξ) (docs/reference/conventions.md
// §1). Casimirs: the spectrum of μ (the eigenvalues of the Hermitian −iμ, ascending).
// The Cayley family and the DDB Legendre unknown live in u(N) (see
// skew_hermitian_group.h); states are checked to be traceless by requireState.
#pragma once

#include <ddb/groups/skew_hermitian_group.h>

#include <Eigen/Core>
#include <complex>

namespace ddb {

namespace detail {
template <class T>
using ComplexScalar = std::complex<T>;
}  // namespace detail

/// SU(N) with its states in a backend's matrices X (docs/design/matrix-backend.md): the closed
/// forms of SkewHermitianGroup, with Algebra and Dual X, so that a system and a method are the
/// library's own classes for any backend (on MPI ranks: SUNOn<DistributedMatrix>; on one GPU:
/// SUNOn<CudaMatrix>). Only what is written against MatrixBackend<X> compiles for another X
/// than the dense matrices: the system's in-place evaluations, the methods of the method table's
/// kBackendMatrixGroups family, integrate() and Relaxation; the Casimirs, exp and log need dense
/// matrices.
template <class X>
struct SUNOn : SkewHermitianGroup<SUNOn<X>, detail::ComplexScalar> {
  static constexpr const char* kName = "SU(N)";
  static constexpr const char* kAlgebraName = "skew-Hermitian";
  template <class T>
  using Algebra = X;
  template <class T>
  using Dual = X;
};

/// On the dense matrices the states are SkewHermitianGroup's complex matrices of T (so that the
/// formulas run on Jets too, and T deduces from a state's type).
template <>
struct SUNOn<Eigen::MatrixXcd>
    : SkewHermitianGroup<SUNOn<Eigen::MatrixXcd>, detail::ComplexScalar> {
  static constexpr const char* kName = "SU(N)";
  static constexpr const char* kAlgebraName = "skew-Hermitian";
};

/// SU(N) on the dense matrices: one type with every backend's SU(N).
using SUN = SUNOn<Eigen::MatrixXcd>;

}  // namespace ddb
