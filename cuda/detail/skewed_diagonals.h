// The layout in which the CUDA backend's Poisson solve (cuda/cuda_poisson_solver.h) sweeps the
// Hoppe–Yau Laplacian's diagonals (systems/hoppe_yau_laplacian.h): an N×N matrix sheared into
// a (2N − 1)-wide array, entry k of diagonal m = j − i (entry (k, k + m) for m ≥ 0, (k − m, k)
// for m < 0) at row k, column c = m + N − 1. One GPU thread sweeps one column c down its
// rows, and the threads of a warp, at the same row, read neighbouring addresses. These
// functions are the kernels' per-entry and per-diagonal work, compiled for the host too, so
// that the host tests check them (tests/cuda/test_cuda_poisson_layout.cc).
#pragma once

#include <ddb/core/detail/host_device.h>

namespace ddb::skewed {

/// The array's width, 2N − 1 columns.
DDB_HOST_DEVICE inline long width(long n) { return 2 * n - 1; }

/// Where entry (i, j) of an N×N matrix lies: row min(i, j), column j − i + N − 1.
DDB_HOST_DEVICE inline long indexOf(long n, long i, long j) {
  return (i < j ? i : j) * width(n) + (j - i + n - 1);
}

/// The entries of column c's diagonal, N − |m|.
DDB_HOST_DEVICE inline long lengthOf(long n, long c) {
  const long m = c - (n - 1);
  return n - (m < 0 ? -m : m);
}

/// Column c's solve in place (HoppeYauLaplacian::sweepDiagonal without the mean, which the
/// caller removes over the whole matrix as HoppeYauLaplacian::solve does), on complex entries
/// stored as (re, im) pairs at 2·index: the forward sweep y_k −= lower_k y_{k−1}, then
/// x_k = y_k/w_k − lower_{k+1} x_{k+1}, with the factors in the same layout; each real and
/// imaginary part by the dense solve's operations in its order. The entries and factors of
/// kChunk rows are read before the chunk's dependent updates: on a GPU a thread then waits
/// for memory once per chunk, not once per row (the loads do not depend on the recurrence).
/// Both sweeps go row by row in step across columns (forward from row 1, back from row N − 2),
/// so that a warp's loads of one row are neighbouring addresses.
DDB_HOST_DEVICE inline void sweepColumn(long n, long c, double* values, const double* lower,
                                        const double* inverse_pivot) {
  constexpr long kChunk = 8;
  const long length = lengthOf(n, c), stride = width(n);
  double re = values[2 * c], im = values[2 * c + 1];
  double chunk_re[kChunk] = {}, chunk_im[kChunk] = {}, factor[kChunk] = {}, weight[kChunk] = {};
  // Forward: rows 1 … length − 1.
  long k = 1;
  for (; k < length; k += kChunk) {
    const long count = length - k < kChunk ? length - k : kChunk;
    DDB_UNROLL
    for (long j = 0; j < kChunk; ++j) {
      if (j < count) {
        const long at = (k + j) * stride + c;
        chunk_re[j] = values[2 * at];
        chunk_im[j] = values[2 * at + 1];
        factor[j] = lower[at];
      }
    }
    DDB_UNROLL
    for (long j = 0; j < kChunk; ++j) {
      if (j < count) {
        re = chunk_re[j] - factor[j] * re;
        im = chunk_im[j] - factor[j] * im;
        const long at = (k + j) * stride + c;
        values[2 * at] = re;
        values[2 * at + 1] = im;
      }
    }
  }
  // The last row, then back: rows length − 2 … 0, row r with lower_{r+1}. The chunks count
  // down from row N − 2 in every column, so that the threads of a warp (neighbouring columns,
  // whose lengths differ) read the same rows at once; a column skips the rows past its end.
  const long last = (length - 1) * stride + c;
  re *= inverse_pivot[last];
  im *= inverse_pivot[last];
  values[2 * last] = re;
  values[2 * last + 1] = im;
  for (k = n - 2; k >= 0; k -= kChunk) {
    DDB_UNROLL
    for (long j = 0; j < kChunk; ++j) {
      const long r = k - j;
      if (r >= 0 && r <= length - 2) {
        const long at = r * stride + c;
        chunk_re[j] = values[2 * at];
        chunk_im[j] = values[2 * at + 1];
        weight[j] = inverse_pivot[at];
        factor[j] = lower[at + stride];
      }
    }
    DDB_UNROLL
    for (long j = 0; j < kChunk; ++j) {
      const long r = k - j;
      if (r >= 0 && r <= length - 2) {
        re = chunk_re[j] * weight[j] - factor[j] * re;
        im = chunk_im[j] * weight[j] - factor[j] * im;
        const long at = r * stride + c;
        values[2 * at] = re;
        values[2 * at + 1] = im;
      }
    }
  }
}

}  // namespace ddb::skewed
