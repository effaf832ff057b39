// SU(N), N chosen at run time: the algebra su(N) of complex skew-Hermitian traceless N×N
// matrices, its dual identified with it by the pairing Re tr(μᴴ ξ) (docs/conventions.md
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

}  // namespace ddb
