// SU(N), N chosen at run time: the algebra su(N) of complex skew-Hermitian traceless N×N
// matrices, its dual identified with it by the pairing Re tr(μᴴ ξ) (docs/reference/conventions.md
// §1). Casimirs: the spectrum of μ (the eigenvalues of the Hermitian −iμ, ascending).
// The Cayley family and the DDB Legendre unknown live in u(N) (see
// skew_hermitian_group.h); states are checked to be traceless by requireState.
#pragma once

#include <ddb/groups/skew_hermitian_group.h>

#include <complex>

namespace ddb {

namespace detail {
template <class T>
using ComplexScalar = std::complex<T>;
}  // namespace detail

struct SUN : SkewHermitianGroup<SUN, detail::ComplexScalar> {
  static constexpr const char* kName = "SU(N)";
  static constexpr const char* kAlgebraName = "skew-Hermitian";
};

/// SU(N) with its states in another backend's matrices X (docs/design/matrix-backend.md): SUN's
/// closed forms, with Algebra and Dual X, so that a system and a method are the library's own
/// classes instantiated off the dense matrices (on MPI ranks: SUNOn<DistributedMatrix>). Only
/// what is written against MatrixBackend<X> compiles for it: the system's in-place
/// evaluations, the methods of the method table's kBackendMatrixGroups family, integrate()
/// and Relaxation; the Casimirs, exp and log need dense matrices.
template <class X>
struct SUNOn : SkewHermitianGroup<SUNOn<X>, detail::ComplexScalar> {
  static constexpr const char* kName = "SU(N)";
  static constexpr const char* kAlgebraName = "skew-Hermitian";
  template <class T>
  using Algebra = X;
  template <class T>
  using Dual = X;
};

}  // namespace ddb
