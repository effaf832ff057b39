// The entry weights that DualEigenbasis (core/dual_eigenbasis.h) applies to matrices in its
// 1-part's eigenbasis coordinates, m̂_ab ← w_ab m̂_ab, with x₀ = V diag(iθ) Vᴴ and m̂ = Vᴴ m V
// (docs/reference/conventions.md §1, "SU(N) over the dual numbers"). They are named types, as
// the phase functions are (core/phase_function.h), because a callable cannot cross onto a
// device: an eigenbasis with coordinates (kEigenbasisCoordinates, docs/design/matrix-backend.md)
// applies these three through weigh(weights, m̂), the host ones by core/detail/weigh_on_host.h,
// the CUDA backend's in its kernels (cuda/detail/cuda_kernels.cu, which includes this header, so
// it includes no Eigen). The formulas of the weights are written once, here, for both.
#pragma once

#include <ddb/core/detail/host_device.h>
#include <ddb/core/phase_function.h>

#include <cmath>

namespace ddb {

/// w_ab = f(scale·(θ_a − θ_b)): the part's own apply(f, scale, ·) in its coordinates.
struct PhaseFunctionWeights {
  PhaseFunction f;
  double scale;
};

/// w_ac = Γ(τ)_ac = τ e^{iτ(θ_a + θ_c)/2} sinc(τ(θ_a − θ_c)/2): the Daleckii–Krein weights of
/// the derivative of e^{τx} at x₀, (D e^{τ·}(x₀)[x₁])^ = Γ(τ) ∘ x̂₁.
struct ConjugationDerivativeWeights {
  double tau;
};

/// w_ab = e^{−iτθ_a} (row a of D̄ m̂, D = diag(e^{iτθ})).
struct RowPhaseWeights {
  double tau;
};

/// e^{iτθ/2} as (real, imaginary) parts: the half phase both weights above are formed from.
DDB_HOST_DEVICE inline void halfPhaseParts(double tau, double theta, double& real, double& imag) {
  const double angle = 0.5 * tau * theta;
  real = cos(angle);
  imag = sin(angle);
}

/// Γ(τ)_ac from θ_a, θ_c and their half phases h_a, h_c: (h_a h_c)·(τ sinc u),
/// u = τ(θ_a − θ_c)/2, sinc 0 = 1 (stable at equal and close phases).
DDB_HOST_DEVICE inline void conjugationDerivativeWeightParts(double tau, double theta_a,
                                                             double theta_c, double half_a_real,
                                                             double half_a_imag, double half_c_real,
                                                             double half_c_imag, double& real,
                                                             double& imag) {
  const double u = 0.5 * tau * (theta_a - theta_c);
  const double sinc = u == 0.0 ? 1.0 : sin(u) / u;
  const double factor = tau * sinc;
  real = (half_a_real * half_c_real - half_a_imag * half_c_imag) * factor;
  imag = (half_a_real * half_c_imag + half_a_imag * half_c_real) * factor;
}

/// e^{−iτθ_a} = conj(h_a²) from the half phase h_a.
DDB_HOST_DEVICE inline void rowPhaseWeightParts(double half_real, double half_imag, double& real,
                                                double& imag) {
  real = half_real * half_real - half_imag * half_imag;
  imag = -(half_real * half_imag + half_imag * half_real);
}

}  // namespace ddb
