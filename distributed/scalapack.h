// The BLACS and ScaLAPACK entry points the distributed layer calls, declared here because
// Debian's libscalapack-openmpi-dev ships no C header for them. The C BLACS take values;
// the Fortran routines (trailing underscore) take every argument by address, and the
// one-character options are passed without gfortran's hidden length (ScaLAPACK reads only
// their first character). Descriptors are the 9-integer array of ScaLAPACK's users' guide
// (DTYPE, CTXT, M, N, MB, NB, RSRC, CSRC, LLD).
#pragma once

#include <mpi.h>

#include <complex>

extern "C" {
int Csys2blacs_handle(MPI_Comm comm);
void Cfree_blacs_system_handle(int handle);
void Cblacs_gridinit(int* context, const char* order, int rows, int cols);
void Cblacs_gridinfo(int context, int* rows, int* cols, int* my_row, int* my_col);
void Cblacs_gridexit(int context);

int numroc_(const int* n, const int* block, const int* process, const int* source_process,
            const int* processes);
void descinit_(int* descriptor, const int* m, const int* n, const int* row_block,
               const int* col_block, const int* source_row, const int* source_col,
               const int* context, const int* leading_dimension, int* info);
void pzgemr2d_(const int* m, const int* n, const std::complex<double>* a, const int* ia,
               const int* ja, const int* desca, std::complex<double>* b, const int* ib,
               const int* jb, const int* descb, const int* context);
void pzgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
             const std::complex<double>* alpha, const std::complex<double>* a, const int* ia,
             const int* ja, const int* desca, const std::complex<double>* b, const int* ib,
             const int* jb, const int* descb, const std::complex<double>* beta,
             std::complex<double>* c, const int* ic, const int* jc, const int* descc);
void pzgetrf_(const int* m, const int* n, std::complex<double>* a, const int* ia, const int* ja,
              const int* desca, int* ipiv, int* info);
void pzgetrs_(const char* trans, const int* n, const int* nrhs, const std::complex<double>* a,
              const int* ia, const int* ja, const int* desca, const int* ipiv,
              std::complex<double>* b, const int* ib, const int* jb, const int* descb, int* info);
void pzheevd_(const char* jobz, const char* uplo, const int* n, std::complex<double>* a,
              const int* ia, const int* ja, const int* desca, double* w, std::complex<double>* z,
              const int* iz, const int* jz, const int* descz, std::complex<double>* work,
              const int* lwork, double* rwork, const int* lrwork, int* iwork, const int* liwork,
              int* info);
double pzlange_(const char* norm, const int* m, const int* n, const std::complex<double>* a,
                const int* ia, const int* ja, const int* desca, double* work);
}
