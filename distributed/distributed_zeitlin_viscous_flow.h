// The viscous flow of Zeitlin's fluid (ZeitlinViscousFlow, systems/zeitlin_viscosity.h) on a
// block-cyclic state (docs/design/distributed.md, "Viscosity and forcing"), exact or by the
// implicit step (ZeitlinViscousScheme): either maps each diagonal of W to itself, so the state's
// diagonals go to their owners as for the Poisson solve (DiagonalRedistribution), each rank steps
// its own, and they come back. Each rank keeps the operator (SphericalHarmonicDegreeOperator), or
// the implicit step's factors (ZeitlinImplicitViscousStep), of its diagonals' blocks only: about
// 2/P of the serial flow's.
#pragma once

#include <ddb/core/exact_flow.h>
#include <ddb/distributed/diagonal_redistribution.h>
#include <ddb/distributed/distributed_zeitlin_fluid.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/spherical_harmonic_degree_operator.h>
#include <ddb/systems/zeitlin_hamiltonian.h>
#include <ddb/systems/zeitlin_implicit_viscous_step.h>
#include <ddb/systems/zeitlin_viscosity.h>

#include <Eigen/Core>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

namespace ddb {

class DistributedZeitlinViscousFlow final : public ExactFlow<DistributedSUN> {
 public:
  /// The flow of `viscosity` on states of `layout`, absolute vorticities Q = W + F of a sphere
  /// rotating at `rotation` (ZeitlinPhysics::rotation); the same arguments on every rank.
  /// Throws InvalidArgument naming the parameter for bad ν, p or γ, on every rank alike.
  DistributedZeitlinViscousFlow(const BlockCyclicLayout& layout, const ZeitlinViscosity& viscosity,
                                double rotation = 0.0)
      : n_(layout.size()),
        redistribution_(layout),
        basis_(HoppeYauLaplacian(n_)),
        rates_(n_),
        factors_(n_) {
    viscosity.validate();
    for (Eigen::Index l = 0; l < n_; ++l) rates_(l) = viscosity.rate(l);
    // The blocks |m| of this rank's diagonals, each once, with where diagonals m and −m start.
    const auto& owned = redistribution_.diagonals();
    for (std::size_t d = 0; d < owned.size(); ++d) {
      const int m = owned[d];
      if (m == 0 && rotation != 0.0) {
        planetary_ = zeitlinPlanetaryVorticity(n_, rotation).diagonal();
        main_diagonal_ = redistribution_.offsets()[d];
      }
      Block* block = nullptr;
      for (Block& b : blocks_) {
        if (b.m == std::abs(m)) block = &b;
      }
      if (block == nullptr) block = &blocks_.emplace_back(Block{std::abs(m), -1, -1});
      (m >= 0 ? block->plus : block->minus) = redistribution_.offsets()[d];
    }
    for (const Block& b : blocks_) kept_.push_back(b.m);
    if (viscosity.scheme == ZeitlinViscousScheme::kImplicit) {
      implicit_.emplace(n_, viscosity.viscosity, viscosity.order, viscosity.drag, kept_);
      return;
    }
    double bytes = 0;
    for (const Block& b : blocks_) bytes += SphericalHarmonicDegreeOperator::blockBytes(n_, b.m);
    keeps_operator_ = bytes <= ZeitlinViscousFlow::kOperatorBytes;
    if (!keeps_operator_) workspace_.emplace(n_);
  }

  std::string name() const override { return "viscosity"; }

  /// Q ← F + exp(h L)(Q − F), L = ν (−1)^{p+1} Δ^p − γ; collective.
  void advance(DistributedMatrix& Q, double h) override {
    if (h != h_) {
      factors_ = (-h * rates_.array()).exp().matrix();
      h_ = h;
      if (implicit_) implicit_->setStep(h);
      if (keeps_operator_) {
        if (operator_) {
          operator_->setFactors(basis_, factors_);
        } else {
          operator_.emplace(basis_, factors_, kept_);
        }
      }
    }
    redistribution_.toDiagonals(Q.local(), diagonals_);
    const bool rotating = planetary_.size() > 0;
    if (rotating) diagonals_.segment(main_diagonal_, n_) -= planetary_;
    for (const Block& b : blocks_) {
      std::complex<double>* first = diagonals_.data() + (b.plus >= 0 ? b.plus : b.minus);
      std::complex<double>* second =
          b.plus >= 0 && b.minus >= 0 ? diagonals_.data() + b.minus : nullptr;
      if (implicit_) {
        implicit_->applyToDiagonals(b.m, first, second);
      } else if (operator_) {
        operator_->applyToDiagonals(b.m, first, second);
      } else {
        basis_.applyDegreeFunctionToDiagonals(factors_, b.m, first, second, *workspace_);
      }
    }
    if (rotating) diagonals_.segment(main_diagonal_, n_) += planetary_;
    redistribution_.toBlockCyclic(diagonals_, Q.local());
  }

 private:
  /// Block m of this rank's diagonals: where its diagonals m and −m start in diagonals_ (−1: not
  /// this rank's).
  struct Block {
    Eigen::Index m, plus, minus;
  };
  Eigen::Index n_;
  DiagonalRedistribution redistribution_;
  SphericalHarmonicBasis basis_;
  // The transform's workspace, where neither the operator nor the implicit step is kept (3 N²
  // numbers): the flow allocates nothing once built.
  std::optional<SphericalHarmonicBasis::Workspace> workspace_;
  std::vector<Block> blocks_;
  std::vector<Eigen::Index> kept_;  // blocks_' m, in order
  bool keeps_operator_ = false;     // whether its blocks' operator fits in kOperatorBytes
  std::optional<SphericalHarmonicDegreeOperator> operator_;  // exp(h_ L) on blocks_
  std::optional<ZeitlinImplicitViscousStep> implicit_;       // the implicit scheme's, on blocks_
  Eigen::VectorXd rates_, factors_;  // per degree l: the decay rate, exp(−rate h) for h_
  double h_ = std::nan("");
  Eigen::VectorXcd planetary_;      // F's main diagonal, where this rank owns it and Ω ≠ 0
  Eigen::Index main_diagonal_ = 0;  // where diagonal 0 starts in diagonals_
  Eigen::VectorXcd diagonals_;      // this rank's diagonals, packed (DiagonalRedistribution)
};

}  // namespace ddb
