// Zeitlin's SU(N) fluid on the sphere with double-bracket dissipation
// (docs/reference/conventions.md §2): vorticity W ∈ su(N), ħ = 2/√(N² − 1), stream matrix
// P = Δ_N⁻¹ W, and
//   Ẇ = (1/ħ)([P, W] + α [W, [P, W]]),  dE/dt = −α ‖[P, W]‖_F²/(ħN),
// with energy E = Re tr(WP)/(2N) >= 0, enstrophy Z = ‖W‖_F²/(2N) (constant), and the
// spectrum of W as Casimirs. As a Lie–Poisson system with the pairing Re tr(AᴴB):
// μ = W, H(W) = Re tr(WP)/(2ħ) = N·E/ħ, ξ = ∂H/∂μ = −P/ħ, ad*_ξ μ = [μ, ξ] and
// k♯ = α·Id (ScaledIdentityMetric), so φ = α[p, ξ] = (α/ħ)[P(p), p].
#pragma once

#include <ddb/core/dissipation_metric.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/groups/sun.h>
#include <ddb/systems/hoppe_yau_laplacian.h>

#include <cmath>
#include <memory>

namespace ddb {

/// ħ = 2/√(N² − 1).
inline double zeitlinHbar(Eigen::Index n) { return 2.0 / std::sqrt(double(n * n - 1)); }

/// ξ = ∂H/∂W = −Δ⁻¹W/ħ given a Poisson solver of W's layout (dense: HoppeYauLaplacian,
/// distributed: DistributedPoissonSolver); the Hessian applies the same map.
template <class Laplacian, class X>
void zeitlinVelocityInto(Laplacian& laplacian, double hbar, const X& W, X& out) {
  laplacian.solve(W, out);
  MatrixBackend<X>::scale(-1.0 / hbar, out, out);
}

/// H(W) = Re tr(W Δ⁻¹W)/(2ħ); its gradient and Hessian are Poisson solves (O(N²)).
class ZeitlinHamiltonian final : public Hamiltonian<SUN> {
 public:
  using Matrix = Eigen::MatrixXcd;

  explicit ZeitlinHamiltonian(Eigen::Index n) : laplacian_(n), hbar_(zeitlinHbar(n)) {}

  const HoppeYauLaplacian& laplacian() const { return laplacian_; }
  double hbar() const { return hbar_; }

  /// P = Δ⁻¹ of the traceless part of W.
  Matrix streamMatrix(const Matrix& W) const {
    Matrix P(W.rows(), W.cols());
    laplacian_.solve(W, P);
    return P;
  }

  double value(const Matrix& W) const override {
    // The stream matrix in a per-thread workspace: the line searches of OrbitNewton evaluate
    // H inside a step, and a step does not allocate (tests/unit/test_allocations.cc).
    thread_local Matrix P;
    P.resize(W.rows(), W.cols());
    laplacian_.solve(W, P);
    return (W.cwiseProduct(P.transpose())).sum().real() / (2.0 * hbar_);
  }
  /// ξ = −P/ħ; P uses the traceless part of W (the Legendre unknown lives in u(N)).
  Matrix gradient(const Matrix& W) const override {
    Matrix out(W.rows(), W.cols());
    gradientInto(W, out);
    return out;
  }
  Matrix hessianTimes(const Matrix& W, const Matrix& V) const override {
    Matrix out(W.rows(), W.cols());
    hessianTimesInto(W, V, out);
    return out;
  }
  void gradientInto(const Matrix& W, Matrix& out) const override {
    zeitlinVelocityInto(laplacian_, hbar_, W, out);
  }
  void hessianTimesInto(const Matrix&, const Matrix& V, Matrix& out) const override {
    zeitlinVelocityInto(laplacian_, hbar_, V, out);
  }

 private:
  HoppeYauLaplacian laplacian_;
  double hbar_;
};

/// The fluid's diagnostics, in its own units (E, Z as in the header comment).
class ZeitlinDiagnostics {
 public:
  using Matrix = Eigen::MatrixXcd;
  explicit ZeitlinDiagnostics(const ZeitlinHamiltonian& hamiltonian) : h_(hamiltonian) {}

  /// E = ħ H / N (H = Re tr(WP)/(2ħ), the system's Hamiltonian).
  double energy(const Matrix& W) const { return h_.value(W) * h_.hbar() / double(W.rows()); }
  double enstrophy(const Matrix& W) const { return W.squaredNorm() / (2.0 * W.rows()); }
  /// ‖[P, W]‖_F: zero exactly at steady states of the Euler flow.
  double commutatorNorm(const Matrix& W) const {
    const Matrix P = h_.streamMatrix(W);
    return (P * W - W * P).norm();
  }

 private:
  const ZeitlinHamiltonian& h_;
};

/// Zeitlin's fluid at resolution N with double-bracket coefficient α (any finite sign).
std::shared_ptr<const LiePoissonSystem<SUN>> makeZeitlinFluid(Eigen::Index n, double alpha);

}  // namespace ddb
