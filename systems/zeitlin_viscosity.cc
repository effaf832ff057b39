// The viscous flow of Zeitlin's fluid (systems/zeitlin_viscosity.h), compiled once.
#include <ddb/systems/zeitlin_viscosity.h>

#include <cmath>
#include <utility>

namespace ddb {

ZeitlinViscousFlow::ZeitlinViscousFlow(Eigen::Index n, const ZeitlinViscosity& viscosity,
                                       Eigen::MatrixXcd planetary)
    : basis_(HoppeYauLaplacian(n)),
      rates_(n),
      factors_(n),
      planetary_(std::move(planetary)),
      rotating_(planetary_.size() > 0 && !planetary_.isZero(0.0)),
      keeps_operator_(SphericalHarmonicDegreeOperator::bytes(n) <= kOperatorBytes),
      diagonals_(viscosity.scheme == ZeitlinViscousScheme::kImplicit ? n * (n + 1) / 2 : 0) {
  viscosity.validate();
  for (Eigen::Index l = 0; l < n; ++l) rates_(l) = viscosity.rate(l);
  if (viscosity.scheme == ZeitlinViscousScheme::kImplicit) {
    implicit_.emplace(n, viscosity.viscosity, viscosity.order, viscosity.drag,
                      SphericalHarmonicBasis::allBlocks(n));
  } else if (!keeps_operator_) {
    workspace_.emplace(n);
  }
}

void ZeitlinViscousFlow::advance(Eigen::MatrixXcd& Q, double h) {
  if (implicit_) {
    advanceImplicitly(Q, h);
    return;
  }
  if (h != h_) {
    factors_ = (-h * rates_.array()).exp().matrix();
    h_ = h;
    // Kept for this h (a fixed step, or Strang splitting's two equal halves): a changing h
    // rebuilds it, about as costly as a step without it.
    if (keeps_operator_) {
      if (operator_) {
        operator_->setFactors(basis_, factors_);
      } else {
        operator_.emplace(basis_, factors_);
      }
    }
  }
  if (rotating_) Q -= planetary_;
  if (operator_) {
    operator_->apply(Q);
  } else {
    basis_.applyDegreeFunction(factors_, Q, *workspace_);
  }
  if (rotating_) Q += planetary_;
}

void ZeitlinViscousFlow::advanceImplicitly(Eigen::MatrixXcd& Q, double h) {
  if (h != h_) {
    implicit_->setStep(h);
    h_ = h;
  }
  const Eigen::Index n = Q.rows();
  if (rotating_) Q -= planetary_;
  const auto start = [n](Eigen::Index a) { return a * n - a * (a - 1) / 2; };
  for (Eigen::Index j = 0; j < n; ++j) {
    for (Eigen::Index i = j; i < n; ++i) diagonals_(start(i - j) + j) = Q(i, j);
  }
  for (Eigen::Index a = 0; a < n; ++a) {
    implicit_->applyToDiagonals(a, diagonals_.data() + start(a));
  }
  for (Eigen::Index j = 0; j < n; ++j) {
    for (Eigen::Index i = j; i < n; ++i) Q(i, j) = diagonals_(start(i - j) + j);
  }
  Q.triangularView<Eigen::StrictlyUpper>() = -Q.adjoint();
  if (rotating_) Q += planetary_;
}

}  // namespace ddb
