// LAPACK through LAPACKE (Debian liblapacke-dev), when the build found both next to the BLAS
// (DDB_USE_LAPACK): the five calls the library makes, declared here with std::complex and
// compiled in core/detail/lapack.cc, the one file that includes <lapacke.h> (its prototypes are
// 25 k lines, which every matrix group's header would otherwise pay). The calls are the _work
// variants on column-major storage: ?getrf/?getrs and ?heevd directly, no copy, no NaN scan.
#pragma once

#ifdef DDB_USE_LAPACK
#include <complex>

namespace ddb::lapack {

/// LAPACKE's lapack_int for the LAPACK the library is built against (Debian's: 32 bits;
/// lapack.cc refuses to compile if it is another).
using Int = int;

/// LU with partial pivoting of the n×n column-major a, in place; LAPACK's info (0: factored,
/// > 0: an exactly zero pivot).
Int getrf(Int n, double* a, Int* pivots);
Int getrf(Int n, std::complex<double>* a, Int* pivots);
/// B ← A⁻¹B for the factors of getrf, B n × columns.
Int getrs(Int n, Int columns, const double* a, const Int* pivots, double* b);
Int getrs(Int n, Int columns, const std::complex<double>* a, const Int* pivots,
          std::complex<double>* b);
/// ?heevd ('V', lower triangle) of the n×n Hermitian a: eigenvectors in a, eigenvalues
/// ascending in values. With lwork = lrwork = liwork = −1 a workspace query.
Int heevd(Int n, std::complex<double>* a, double* values, std::complex<double>* work, Int lwork,
          double* rwork, Int lrwork, Int* iwork, Int liwork);

}  // namespace ddb::lapack
#endif
