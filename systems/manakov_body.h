// The SO(N) generalised rigid body (Manakov; docs/reference/conventions.md §2) with double-bracket
// dissipation K = α·Id: Ω real skew-symmetric, l(Ω) = ½<Ω, 𝕁Ω> with the inertia operator
// 𝕁Ω = ΩJ + JΩ, J = diag(J_1..J_N) > 0; M = 𝕁Ω, so Ω_ij = M_ij/(J_i + J_j), and
// Ṁ = [M, Ω] plus the double bracket. For N = 3 it is the rigid body with
// 𝕀 = (J₂ + J₃, J₁ + J₃, J₁ + J₂) under so(3) ≅ R³ (the matrix pairing is twice the
// dot product, and so is H: ξ is the same).
#pragma once

#include <ddb/core/dissipation_metric.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/groups/son.h>

#include <memory>

namespace ddb {

class ManakovHamiltonian final : public Hamiltonian<SON> {
 public:
  using Matrix = Eigen::MatrixXd;

  explicit ManakovHamiltonian(const Eigen::VectorXd& J) : J_(requirePositive("J", J)) {
    if (J_.size() < 2) throwInvalid("J", formatValue(J_), "needs N >= 2 entries");
    inverse_inertia_ =
        (J_.replicate(1, J_.size()) + J_.transpose().replicate(J_.size(), 1)).cwiseInverse();
  }

  /// H(M) = ½ <M, 𝕁⁻¹M>.
  double value(const Matrix& M) const override {
    return 0.5 * M.cwiseProduct(M.cwiseProduct(inverse_inertia_)).sum();
  }
  Matrix gradient(const Matrix& M) const override { return M.cwiseProduct(inverse_inertia_); }
  Matrix hessianTimes(const Matrix&, const Matrix& V) const override {
    return V.cwiseProduct(inverse_inertia_);
  }
  void gradientInto(const Matrix& M, Matrix& out) const override {
    out = M.cwiseProduct(inverse_inertia_);
  }
  void hessianTimesInto(const Matrix&, const Matrix& V, Matrix& out) const override {
    out = V.cwiseProduct(inverse_inertia_);
  }

 private:
  Eigen::VectorXd J_;
  Matrix inverse_inertia_;  // 1/(J_i + J_j)
};

/// The Manakov body with principal values J (all > 0) and damping α.
std::shared_ptr<const LiePoissonSystem<SON>> makeManakovBody(const Eigen::VectorXd& J,
                                                             double alpha);

}  // namespace ddb

// The generic system of SO(N) compiled once (instantiations/lie_poisson_systems.cc).
DDB_LIE_POISSON_SYSTEM_INSTANCE(extern, ::ddb::SON);
