// SO(N), N chosen at run time: the algebra so(N) of real skew-symmetric N×N matrices,
// its dual identified with it by the pairing Re tr(μᵀ ξ) (docs/reference/conventions.md §1).
// Casimirs: the spectrum of μ (the eigenvalues ±iλ of a real skew matrix, as the real
// eigenvalues of −iμ, ascending).
#pragma once

#include <ddb/groups/skew_hermitian_group.h>

namespace ddb {

namespace detail {
template <class T>
using RealScalar = T;
}  // namespace detail

struct SON : SkewHermitianGroup<SON, detail::RealScalar> {
  static constexpr const char* kName = "SO(N)";
  static constexpr const char* kAlgebraName = "skew-symmetric";
};

}  // namespace ddb
