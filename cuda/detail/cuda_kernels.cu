// The CUDA backend's kernels (declared in cuda/detail/cuda_kernels.h and
// cuda/detail/poisson_kernels.h). Compiled with --fmad=false (CMakeLists.txt): every
// product and sum is rounded once, as the dense backend's element-wise operations are
// (docs/design/matrix-backend.md, "Element-wise operations"). Reductions add in a fixed tree,
// so that a run repeats to the bit on one device (kill and resume: docs/reference/guarantees.md).
#include <ddb/cuda/detail/cuda_check.h>
#include <ddb/cuda/detail/cuda_context_state.h>
#include <ddb/cuda/detail/cuda_kernels.h>
#include <ddb/cuda/detail/laplacian_entries.h>
#include <ddb/cuda/detail/poisson_kernels.h>
#include <ddb/cuda/detail/skewed_diagonals.h>

#include <cmath>

namespace ddb::cuda_kernels {
namespace {

constexpr int kThreads = 256;
// The reductions' first pass: a fixed number of blocks whatever the size, so that the
// order of the additions depends on the size only.
constexpr int kReductionBlocks = 1024;

int blocksFor(long count) {
  const long blocks = (count + kThreads - 1) / kThreads;
  return static_cast<int>(blocks < 65535 ? (blocks > 0 ? blocks : 1) : 65535);
}

// f(k) for k < count, grid-stride.
template <class F>
__global__ void forEach(long count, F f) {
  for (long k = blockIdx.x * long(blockDim.x) + threadIdx.x; k < count;
       k += long(blockDim.x) * gridDim.x) {
    f(k);
  }
}

template <class F>
void launch(CudaContext::State& ctx, long count, F f) {
  if (count <= 0) return;
  forEach<<<blocksFor(count), kThreads, 0, ctx.stream>>>(count, f);
  checkCuda(cudaGetLastError(), "an element-wise kernel");
}

struct Add {
  __device__ double operator()(double a, double b) const { return a + b; }
};
// The larger, NaN if either is NaN (fmax would drop a NaN).
struct MaxWithNaN {
  __device__ double operator()(double a, double b) const {
    return (isnan(a) || isnan(b)) ? NAN : (a > b ? a : b);
  }
};

// shared[0] ← the tree combination of shared[0 … kThreads).
template <class Combine>
__device__ void reduceBlock(double* shared, Combine combine) {
  __syncthreads();
  for (int half = kThreads / 2; half > 0; half /= 2) {
    if (threadIdx.x < half)
      shared[threadIdx.x] = combine(shared[threadIdx.x], shared[threadIdx.x + half]);
    __syncthreads();
  }
}

// partials[block] ← the combination of term(k) over this block's share of k < count.
template <class Term, class Combine>
__global__ void reducePartials(long count, Term term, Combine combine, double identity,
                               double* partials) {
  __shared__ double shared[kThreads];
  double value = identity;
  for (long k = blockIdx.x * long(kThreads) + threadIdx.x; k < count;
       k += long(kThreads) * gridDim.x) {
    value = combine(value, term(k));
  }
  shared[threadIdx.x] = value;
  reduceBlock(shared, combine);
  if (threadIdx.x == 0) partials[blockIdx.x] = shared[0];
}

template <class Combine>
__global__ void reduceFinal(const double* partials, int count, Combine combine, double identity,
                            double* result) {
  __shared__ double shared[kThreads];
  double value = identity;
  for (int k = threadIdx.x; k < count; k += kThreads) value = combine(value, partials[k]);
  shared[threadIdx.x] = value;
  reduceBlock(shared, combine);
  if (threadIdx.x == 0) *result = shared[0];
}

template <class Term, class Combine>
double reduce(CudaContext::State& ctx, long count, Term term, Combine combine, double identity) {
  // The context's scratch: kReductionBlocks partials and the result.
  double* scratch = ctx.reduction.reserve<double>(kReductionBlocks + 1);
  reducePartials<<<kReductionBlocks, kThreads, 0, ctx.stream>>>(count, term, combine, identity,
                                                                scratch);
  checkCuda(cudaGetLastError(), "a reduction");
  reduceFinal<<<1, kThreads, 0, ctx.stream>>>(scratch, kReductionBlocks, combine, identity,
                                              scratch + kReductionBlocks);
  checkCuda(cudaGetLastError(), "a reduction");
  double result = 0.0;
  copyToHost(ctx, &result, scratch + kReductionBlocks, sizeof(double));
  return result;
}

// The adjoint passes go by 32×32 tiles through shared memory, so that both the tile and its
// mirror are read and written along columns (coalesced).
constexpr int kTile = 32, kTileRows = 8;

__global__ void addAdjointKernel(long n, long m, double s, const double2* x, double2* out) {
  __shared__ double2 tile[kTile][kTile + 1];
  const long i0 = blockIdx.x * long(kTile), j0 = blockIdx.y * long(kTile);
  // tile[b][a] = x(j0 + a, i0 + b), x m×n.
  for (int b = threadIdx.y; b < kTile; b += kTileRows) {
    const long j = j0 + threadIdx.x, i = i0 + b;
    if (j < m && i < n) tile[b][threadIdx.x] = x[j + i * m];
  }
  __syncthreads();
  for (int b = threadIdx.y; b < kTile; b += kTileRows) {
    const long i = i0 + threadIdx.x, j = j0 + b;
    if (i < n && j < m) {
      const double2 v = tile[threadIdx.x][b];  // x(j, i)
      double2& o = out[i + j * n];
      o.x = o.x + s * v.x;
      o.y = o.y + s * (-v.y);
    }
  }
}

// (u − conj(l))/2, MatrixBackend::skewPart's operations.
__device__ double2 skewPart(double2 u, double2 l) {
  return make_double2(0.5 * (u.x - l.x), 0.5 * (u.y - (-l.y)));
}

// x_k ← w·x_k for complex entry k of x (re, im interleaved), w = (wr, wi): the host's
// std::complex product, (ac − bd, ad + bc).
__device__ void multiplyEntry(double* x, long k, double wr, double wi) {
  const double xr = x[2 * k], xi = x[2 * k + 1];
  x[2 * k] = xr * wr - xi * wi;
  x[2 * k + 1] = xr * wi + xi * wr;
}

// Tile pair (I, J), I ≤ J: block (J, I) of the grid; the blocks below the diagonal exit.
__global__ void makeSkewHermitianKernel(long n, double2* x) {
  if (blockIdx.y > blockIdx.x) return;
  __shared__ double2 upper[kTile][kTile + 1], lower[kTile][kTile + 1];
  const long i0 = blockIdx.y * long(kTile), j0 = blockIdx.x * long(kTile);
  // upper[b][a] = x(i0 + a, j0 + b); lower[b][a] = x(j0 + a, i0 + b).
  for (int b = threadIdx.y; b < kTile; b += kTileRows) {
    const long a = threadIdx.x;
    if (i0 + a < n && j0 + b < n) upper[b][a] = x[(i0 + a) + (j0 + b) * n];
    if (j0 + a < n && i0 + b < n) lower[b][a] = x[(j0 + a) + (i0 + b) * n];
  }
  __syncthreads();
  for (int b = threadIdx.y; b < kTile; b += kTileRows) {
    const long a = threadIdx.x;
    // Entry (i0 + a, j0 + b) of the upper tile; its mirror (j0 + b, i0 + a) is lower[a][b]
    // (on a diagonal tile, lower is upper).
    if (i0 + a < n && j0 + b < n) {
      const long i = i0 + a, j = j0 + b;
      double2 v;
      if (i <= j) {
        v = skewPart(upper[b][a], lower[a][b]);
      } else {  // below the diagonal of a diagonal tile: its mirror's value, −conj
        const double2 w = skewPart(upper[a][b], upper[b][a]);
        v = make_double2(-w.x, w.y);
      }
      x[i + j * n] = v;
    }
    // Entry (j0 + a, i0 + b) of the lower tile, below the diagonal, off the diagonal tile.
    if (i0 != j0 && j0 + a < n && i0 + b < n) {
      const double2 w = skewPart(upper[a][b], lower[b][a]);  // entry (i0 + b, j0 + a)
      x[(j0 + a) + (i0 + b) * n] = make_double2(-w.x, w.y);
    }
  }
}

}  // namespace

void scale(CudaContext::State& ctx, long count, double a, const double* x, double* out) {
  launch(ctx, count, [=] __device__(long k) { out[k] = a * x[k]; });
}
void divide(CudaContext::State& ctx, long count, double* x, double a) {
  launch(ctx, count, [=] __device__(long k) { x[k] = x[k] / a; });
}
void axpy(CudaContext::State& ctx, long count, double a, const double* x, double* y) {
  launch(ctx, count, [=] __device__(long k) { y[k] = y[k] + a * x[k]; });
}
void sum(CudaContext::State& ctx, long count, double a, const double* x, double b, const double* y,
         double* out) {
  launch(ctx, count, [=] __device__(long k) { out[k] = a * x[k] + b * y[k]; });
}
void sum(CudaContext::State& ctx, long count, double a, const double* x, double b, const double* y,
         double c, const double* z, double* out) {
  launch(ctx, count, [=] __device__(long k) { out[k] = (a * x[k] + b * y[k]) + c * z[k]; });
}
void addSum(CudaContext::State& ctx, long count, double a, const double* x, double b,
            const double* y, double* out) {
  launch(ctx, count, [=] __device__(long k) { out[k] = out[k] + (a * x[k] + b * y[k]); });
}
void flushSubnormals(CudaContext::State& ctx, long count, double* x) {
  launch(ctx, count, [=] __device__(long k) {
    // Subnormal: 0 < |x| < 2^-1022, the smallest normal double (NaN compares false).
    const double magnitude = fabs(x[k]);
    if (magnitude != 0.0 && magnitude < 2.2250738585072014e-308) x[k] = copysign(0.0, x[k]);
  });
}

void addAdjoint(CudaContext::State& ctx, long n, long m, double s, const double* x, double* out) {
  if (n <= 0 || m <= 0) return;
  const dim3 grid((n + kTile - 1) / kTile, (m + kTile - 1) / kTile), block(kTile, kTileRows);
  addAdjointKernel<<<grid, block, 0, ctx.stream>>>(n, m, s, reinterpret_cast<const double2*>(x),
                                                   reinterpret_cast<double2*>(out));
  checkCuda(cudaGetLastError(), "the adjoint kernel");
}

void makeSkewHermitian(CudaContext::State& ctx, long n, double* x) {
  if (n <= 0) return;
  const long tiles = (n + kTile - 1) / kTile;
  const dim3 grid(tiles, tiles), block(kTile, kTileRows);
  makeSkewHermitianKernel<<<grid, block, 0, ctx.stream>>>(n, reinterpret_cast<double2*>(x));
  checkCuda(cudaGetLastError(), "the skew-Hermitian kernel");
}

void weighByPhases(CudaContext::State& ctx, long n, const double* phases, double scale,
                   PhaseFunction f, double* x) {
  launch(ctx, n * n, [=] __device__(long k) {
    const long a = k % n, b = k / n;
    double fr, fi;
    phaseFunctionParts(f, scale * (phases[a] - phases[b]), fr, fi);
    multiplyEntry(x, k, fr, fi);
  });
}

void weighByConjugationDerivative(CudaContext::State& ctx, long n, const double* phases, double tau,
                                  double* x) {
  launch(ctx, n * n, [=] __device__(long k) {
    const long a = k % n, c = k / n;
    double ar, ai, cr, ci, wr, wi;
    halfPhaseParts(tau, phases[a], ar, ai);
    halfPhaseParts(tau, phases[c], cr, ci);
    conjugationDerivativeWeightParts(tau, phases[a], phases[c], ar, ai, cr, ci, wr, wi);
    multiplyEntry(x, k, wr, wi);
  });
}

void weighRowsByPhase(CudaContext::State& ctx, long n, const double* phases, double tau,
                      double* x) {
  launch(ctx, n * n, [=] __device__(long k) {
    double hr, hi, wr, wi;
    halfPhaseParts(tau, phases[k % n], hr, hi);
    rowPhaseWeightParts(hr, hi, wr, wi);
    multiplyEntry(x, k, wr, wi);
  });
}

void weighEntrywise(CudaContext::State& ctx, long count, const double* weights, double* x) {
  launch(ctx, count, [=] __device__(long k) {
    x[2 * k] = x[2 * k] * weights[k];
    x[2 * k + 1] = x[2 * k + 1] * weights[k];
  });
}

void imaginaryDiagonal(CudaContext::State& ctx, long n, const double* x, double* out) {
  launch(ctx, n, [=] __device__(long i) { out[i] = x[2 * (i + i * n) + 1]; });
}

void addToDiagonal(CudaContext::State& ctx, long rows, long count, double* x, double c_real,
                   double c_imag) {
  launch(ctx, count, [=] __device__(long i) {
    const long at = 2 * (i + i * rows);
    x[at] = x[at] + c_real;
    x[at + 1] = x[at + 1] + c_imag;
  });
}

void gather(CudaContext::State& ctx, long count, const double* x, const long* indices,
            double* values) {
  launch(ctx, count, [=] __device__(long s) {
    values[2 * s] = x[2 * indices[s]];
    values[2 * s + 1] = x[2 * indices[s] + 1];
  });
}

double dot(CudaContext::State& ctx, long count, const double* x, const double* y) {
  return reduce(
      ctx, count, [=] __device__(long k) { return x[k] * y[k]; }, Add(), 0.0);
}
double squaredDistance(CudaContext::State& ctx, long count, const double* x, const double* y) {
  return reduce(
      ctx, count,
      [=] __device__(long k) {
        const double d = x[k] - y[k];
        return d * d;
      },
      Add(), 0.0);
}
void traceOf(CudaContext::State& ctx, long rows, long count, const double* x, double* real,
             double* imag) {
  *real = reduce(
      ctx, count, [=] __device__(long i) { return x[2 * (i + i * rows)]; }, Add(), 0.0);
  *imag = reduce(
      ctx, count, [=] __device__(long i) { return x[2 * (i + i * rows) + 1]; }, Add(), 0.0);
}

namespace {
// sums[j] ← Σ_i |x(i, j)|, one block per column, the rows in a fixed tree.
__global__ void columnSums(long n, const double2* x, bool exact, double* sums) {
  __shared__ double shared[kThreads];
  const long j = blockIdx.x;
  double value = 0.0;
  for (long i = threadIdx.x; i < n; i += kThreads) {
    const double2 z = x[i + j * n];
    value += exact ? hypot(z.x, z.y) : sqrt(z.x * z.x + z.y * z.y);
  }
  shared[threadIdx.x] = value;
  reduceBlock(shared, Add());
  if (threadIdx.x == 0) sums[j] = shared[0];
}
}  // namespace

double largestColumnSum(CudaContext::State& ctx, long n, long m, const double* x, bool exact) {
  if (m <= 0) return 0.0;
  double* sums = ctx.column_sums.reserve<double>(static_cast<std::size_t>(m));
  columnSums<<<m, kThreads, 0, ctx.stream>>>(n, reinterpret_cast<const double2*>(x), exact, sums);
  checkCuda(cudaGetLastError(), "the column sums");
  const double* s = sums;
  return reduce(
      ctx, m, [=] __device__(long j) { return s[j]; }, MaxWithNaN(), 0.0);
}

long countNotFinite(CudaContext::State& ctx, long count, const double* x) {
  return static_cast<long>(reduce(
      ctx, count, [=] __device__(long k) { return isfinite(x[k]) ? 0.0 : 1.0; }, Add(), 0.0));
}
long countNotZero(CudaContext::State& ctx, long count, const double* x) {
  return static_cast<long>(reduce(
      ctx, count, [=] __device__(long k) { return x[k] != 0.0 ? 1.0 : 0.0; }, Add(), 0.0));
}

// ---- The Poisson solve's and apply's passes (cuda/detail/poisson_kernels.h). ----

void toSkewed(CudaContext::State& ctx, long n, const double* w, double mean_real, double mean_imag,
              double* skewed) {
  launch(ctx, n * n, [=] __device__(long linear) {
    const long i = linear % n, j = linear / n, at = skewed::indexOf(n, i, j);
    if (i == j) {
      skewed[2 * at] = w[2 * linear] - mean_real;
      skewed[2 * at + 1] = w[2 * linear + 1] - mean_imag;
    } else {
      skewed[2 * at] = w[2 * linear];
      skewed[2 * at + 1] = w[2 * linear + 1];
    }
  });
}

namespace {
__global__ void sweepColumns(long n, double* values, const double* lower,
                             const double* inverse_pivot) {
  const long c = blockIdx.x * long(blockDim.x) + threadIdx.x;
  if (c < skewed::width(n)) skewed::sweepColumn(n, c, values, lower, inverse_pivot);
}
}  // namespace

void sweepDiagonals(CudaContext::State& ctx, long n, double* skewed, const double* lower,
                    const double* inverse_pivot) {
  // Small blocks: 2N − 1 threads in all, spread over as many multiprocessors as they fill.
  constexpr int kSweepThreads = 64;
  const long columns = skewed::width(n);
  sweepColumns<<<(columns + kSweepThreads - 1) / kSweepThreads, kSweepThreads, 0, ctx.stream>>>(
      n, skewed, lower, inverse_pivot);
  checkCuda(cudaGetLastError(), "the diagonal sweeps");
}

void fromSkewed(CudaContext::State& ctx, long n, const double* skewed, double* out) {
  launch(ctx, n * n, [=] __device__(long linear) {
    const long i = linear % n, j = linear / n, at = skewed::indexOf(n, i, j);
    out[2 * linear] = skewed[2 * at];
    out[2 * linear + 1] = skewed[2 * at + 1];
  });
}

void applyLaplacian(CudaContext::State& ctx, long n, double kappa_squared, const double* p,
                    double* out) {
  launch(ctx, n * n, [=] __device__(long linear) {
    laplacian_entries::applyAt(n, kappa_squared, linear % n, linear / n, p, out);
  });
}

}  // namespace ddb::cuda_kernels
