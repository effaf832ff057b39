// LAPACK through LAPACKE (Debian liblapacke-dev), when the build found both next to the BLAS
// (DDB_USE_LAPACK): its own prototypes instead of hand-declared ones, so that the integer
// type is its lapack_int (set by LAPACK_ILP64, as the LAPACK it is built against needs), and
// the one cast the library's calls need: LAPACKE's complex type, whatever an includer
// chose, is layout-compatible with std::complex.
#pragma once

#ifdef DDB_USE_LAPACK
#include <lapacke.h>

#include <complex>

namespace ddb {

inline lapack_complex_double* lapackData(std::complex<double>* z) {
  return reinterpret_cast<lapack_complex_double*>(z);
}
inline const lapack_complex_double* lapackData(const std::complex<double>* z) {
  return reinterpret_cast<const lapack_complex_double*>(z);
}

}  // namespace ddb
#endif
