// The LAPACK calls of core/detail/lapack.h, through LAPACKE's own prototypes, so that the
// integer type is the one the LAPACK is built with and the complex type's cast is the only one.
#include <ddb/core/detail/lapack.h>

#ifdef DDB_USE_LAPACK
#include <lapacke.h>

#include <type_traits>

namespace ddb::lapack {

static_assert(std::is_same_v<Int, lapack_int>,
              "ddb::lapack::Int must be LAPACKE's lapack_int (core/detail/lapack.h)");

namespace {
lapack_complex_double* complexData(std::complex<double>* z) {
  return reinterpret_cast<lapack_complex_double*>(z);
}
const lapack_complex_double* complexData(const std::complex<double>* z) {
  return reinterpret_cast<const lapack_complex_double*>(z);
}
}  // namespace

Int getrf(Int n, double* a, Int* pivots) {
  return LAPACKE_dgetrf_work(LAPACK_COL_MAJOR, n, n, a, n, pivots);
}
Int getrf(Int n, std::complex<double>* a, Int* pivots) {
  return LAPACKE_zgetrf_work(LAPACK_COL_MAJOR, n, n, complexData(a), n, pivots);
}
Int getrs(Int n, Int columns, const double* a, const Int* pivots, double* b) {
  return LAPACKE_dgetrs_work(LAPACK_COL_MAJOR, 'N', n, columns, a, n, pivots, b, n);
}
Int getrs(Int n, Int columns, const std::complex<double>* a, const Int* pivots,
          std::complex<double>* b) {
  return LAPACKE_zgetrs_work(LAPACK_COL_MAJOR, 'N', n, columns, complexData(a), n, pivots,
                             complexData(b), n);
}
Int heevd(Int n, std::complex<double>* a, double* values, std::complex<double>* work, Int lwork,
          double* rwork, Int lrwork, Int* iwork, Int liwork) {
  return LAPACKE_zheevd_work(LAPACK_COL_MAJOR, 'V', 'L', n, complexData(a), n, values,
                             complexData(work), lwork, rwork, lrwork, iwork, liwork);
}

}  // namespace ddb::lapack
#endif
