// The CUDA backend's kernels (cuda/detail/cuda_kernels.cu), on device addresses: what
// cuda/cuda_backend.cc and cuda/cuda_poisson_solver.cc launch. A complex matrix is passed as
// its 2·size real parts (std::complex's layout, C++17 [complex.numbers]/4) where the operation
// treats real and imaginary parts alike. Everything runs in the given context's stream, in order
// (cuda/cuda_context.h); the reductions use its scratch.
#pragma once

#include <ddb/core/eigenbasis_weights.h>
#include <ddb/core/phase_function.h>
#include <ddb/cuda/cuda_context.h>

namespace ddb::cuda_kernels {

// ---- Element-wise, over `count` reals, evaluated as written (no fused multiply-add). ----
void scale(CudaContext::State& ctx, long count, double a, const double* x,
           double* out);                                                // out = a·x
void divide(CudaContext::State& ctx, long count, double* x, double a);  // x = x / a
void axpy(CudaContext::State& ctx, long count, double a, const double* x,
          double* y);  // y = y + a·x
void sum(CudaContext::State& ctx, long count, double a, const double* x, double b, const double* y,
         double* out);  // out = a·x + b·y
void sum(CudaContext::State& ctx, long count, double a, const double* x, double b, const double* y,
         double c, const double* z, double* out);  // out = (a·x + b·y) + c·z
void addSum(CudaContext::State& ctx, long count, double a, const double* x, double b,
            const double* y,
            double* out);  // out = out + (a·x + b·y)
void flushSubnormals(CudaContext::State& ctx, long count, double* x);

// ---- Complex n×m column-major matrices (re, im interleaved). ----
/// out(i, j) += s·conj(x(j, i)), out n×m, x m×n.
void addAdjoint(CudaContext::State& ctx, long n, long m, double s, const double* x, double* out);
/// x ← (x − xᴴ)/2, x n×n, each pair (i, j), (j, i) from one value.
void makeSkewHermitian(CudaContext::State& ctx, long n, double* x);
/// x(i, i) += c for i < count = min(rows, cols), x with `rows` rows.
void addToDiagonal(CudaContext::State& ctx, long rows, long count, double* x, double c_real,
                   double c_imag);
/// x(a, b) ← f(scale (θ_a − θ_b))·x(a, b) for the n×n x and the n phases θ (a device array):
/// an eigenbasis's weights (core/phase_function.h, cuda/cuda_eigenbasis.h).
void weighByPhases(CudaContext::State& ctx, long n, const double* phases, double scale,
                   PhaseFunction f, double* x);
/// x(a, c) ← Γ(τ)_ac·x(a, c) and x(a, b) ← e^{−iτθ_a}·x(a, b) for the n×n x and the n phases θ
/// (a device array): the dual numbers' eigenbasis weights (core/eigenbasis_weights.h).
void weighByConjugationDerivative(CudaContext::State& ctx, long n, const double* phases, double tau,
                                  double* x);
void weighRowsByPhase(CudaContext::State& ctx, long n, const double* phases, double tau, double* x);
/// x(a, b) ← w(a, b)·x(a, b) for the `count` entries of x and the reals w (device arrays).
void weighEntrywise(CudaContext::State& ctx, long count, const double* weights, double* x);
/// out(i) = Im x(i, i) for the n×n x (device arrays).
void imaginaryDiagonal(CudaContext::State& ctx, long n, const double* x, double* out);
/// values(s) = x at linear index indices(s) (device arrays of `count`).
void gather(CudaContext::State& ctx, long count, const double* x, const long* indices,
            double* values);

// ---- Reductions, in a fixed tree (the same bits every run on one device); the result is
// copied back to the host. ----
/// Σ x_k y_k over `count` reals.
double dot(CudaContext::State& ctx, long count, const double* x, const double* y);
/// Σ (x_k − y_k)² over `count` reals.
double squaredDistance(CudaContext::State& ctx, long count, const double* x, const double* y);
/// Σ_i x(i, i), i < count = min(rows, cols), of a complex matrix with `rows` rows (real and
/// imaginary parts).
void traceOf(CudaContext::State& ctx, long rows, long count, const double* x, double* real,
             double* imag);
/// The largest column sum of |x_ij| over the m columns of an n×m complex matrix, |z| as
/// √(Re² + Im²) or (exact) hypot(Re, Im); NaN if any sum is NaN.
double largestColumnSum(CudaContext::State& ctx, long n, long m, const double* x, bool exact);
/// How many of `count` reals are not finite, and how many are not zero.
long countNotFinite(CudaContext::State& ctx, long count, const double* x);
long countNotZero(CudaContext::State& ctx, long count, const double* x);

}  // namespace ddb::cuda_kernels
