// The functions of ad_x that the matrix groups' exponential steps apply in x's eigenbasis
// (docs/reference/conventions.md §1, "Matrix algebras"): with x = V diag(iθ) Vᴴ, f(ad_x)
// multiplies entry (a, b) of Vᴴ A V by f(i(θ_a − θ_b)). A backend's eigenbasis
// (MatrixBackend<X>::Eigenbasis, docs/design/matrix-backend.md) applies these few, named,
// rather than any callable: a callable cannot cross into a compiled library or onto a
// device, a name can.
#pragma once

#include <ddb/core/detail/host_device.h>

#include <cmath>
#include <complex>

// The formulas below compile for a CUDA device too (cuda/detail/cuda_kernels.cu applies them
// there), on real and imaginary parts: std::complex has no device functions.
namespace ddb {

/// e^{iη} − 1 as (real, imaginary) parts, without the cancellation of cos η − 1 at small η.
DDB_HOST_DEVICE inline void expm1OfIParts(double eta, double& real, double& imag) {
  const double s = sin(0.5 * eta);
  real = -2.0 * s * s;
  imag = sin(eta);
}

/// (e^{iη} − 1)/(iη) as (real, imaginary) parts, 1 at η = 0: the factor of dexp_x (z = iη),
/// an entire function.
DDB_HOST_DEVICE inline void expm1OfIOverIParts(double eta, double& real, double& imag) {
  if (eta == 0.0) {
    real = 1.0;
    imag = 0.0;
    return;
  }
  const double s = sin(0.5 * eta);
  real = sin(eta) / eta;
  imag = 2.0 * s * s / eta;
}

/// e^{iη} − 1.
inline std::complex<double> expm1OfI(double eta) {
  double real, imag;
  expm1OfIParts(eta, real, imag);
  return {real, imag};
}

/// (e^{iη} − 1)/(iη).
inline std::complex<double> expm1OfIOverI(double eta) {
  double real, imag;
  expm1OfIOverIParts(eta, real, imag);
  return {real, imag};
}

/// The functions f(η), η = scale·(θ_a − θ_b), a step applies in an eigenbasis. Each has
/// f(−η) = conj(f(η)), so skew-Hermitian matrices map to skew-Hermitian ones.
enum class PhaseFunction {
  /// e^{−iη} − 1: Ad*_{exp(scale·x)} − id, the exponential's conjugation as an increment
  /// (integrators/matrix_kernels/matrix_conjugation.h).
  kCoadjointIncrement,
  /// (e^{−iη} − 1)/(−iη): ((dexp⁻¹_{scale·x})*)⁻¹, the exponential's Legendre sweep
  /// (integrators/solvers/matrix_legendre.h).
  kInverseDexpInverseDual,
};

/// f(η) for the named f, as (real, imaginary) parts.
DDB_HOST_DEVICE inline void phaseFunctionParts(PhaseFunction f, double eta, double& real,
                                               double& imag) {
  if (f == PhaseFunction::kCoadjointIncrement) {
    expm1OfIParts(-eta, real, imag);
  } else {
    expm1OfIOverIParts(-eta, real, imag);
  }
}

}  // namespace ddb
