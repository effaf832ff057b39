// SkewHermitianEigenbasis: the spectral calculus of a skew-Hermitian (real: skew-symmetric)
// dense matrix x, on which the exponential retraction of SO(N) and SU(N) rests, and the dense
// backend's Eigenbasis (MatrixBackend<X>::Eigenbasis, docs/design/matrix-backend.md)
// (docs/reference/conventions.md §1, "Matrix algebras"). x = V diag(iθ) Vᴴ, θ real ascending, from
// the Hermitian −ix; in x's eigenbasis (Â = Vᴴ A V) ad_x multiplies entry (a, b) by
// i(θ_a − θ_b). So every function of ad_x with real Taylor coefficients (dexp, dexp⁻¹, their
// duals under the trace pairing, where ad_x is skew-adjoint, and Ad*_{exp x}) acts as
//   A ↦ V [F ∘ Â] Vᴴ,  F_ab = f(θ_a − θ_b),
// one decomposition and then four products per application, instead of a series in ad_x.
// Such F has F_ba = conj(F_ab), so skew-Hermitian A map to skew-Hermitian results, to which
// apply() projects its rounding (a Hermitian part would never be corrected: the eigensolver
// reads one triangle). Workspaces are allocated when a size first appears, then reused.
#pragma once

#include <ddb/core/detail/hermitian_eigensolver.h>
#include <ddb/core/detail/weigh_on_host.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/core/phase_function.h>

#include <Eigen/Core>
#include <cmath>
#include <complex>
#include <stdexcept>

namespace ddb {

template <class Matrix>
class SkewHermitianEigenbasis {
 public:
  using Complex = Eigen::MatrixXcd;
  static constexpr bool kReal = !Eigen::NumTraits<typename Matrix::Scalar>::IsComplex;

  /// Decomposes x (skew-Hermitian). Returns false when x is not finite (the eigensolver did
  /// not converge).
  bool compute(const Matrix& x) {
    allocate(x.rows());
    weighted_ = false;  // a new basis takes new weights
    hermitian_ = x.template cast<std::complex<double>>() * std::complex<double>(0.0, -1.0);
    return solver_.compute(hermitian_);
  }

  /// θ, ascending.
  const Eigen::VectorXd& phases() const { return solver_.eigenvalues(); }
  const Complex& vectors() const { return solver_.eigenvectors(); }
  /// max_ab |θ_a − θ_b|: the spectral radius of ad_x.
  double adRadius() const { return phases()(phases().size() - 1) - phases()(0); }

  /// out = V [F ∘ (Vᴴ in V)] Vᴴ with F_ab = factor(scale (θ_a − θ_b)), i.e. f(scale ad_x) for
  /// factor(η) = f(iη); `in` skew-Hermitian and factor(−η) = conj(factor(η)). out may be in.
  template <class Factor>
  void apply(const Factor& factor, double scale, const Matrix& in, Matrix& out) {
    const Eigen::VectorXd& theta = phases();
    applyEntrywise(
        [&](Eigen::Index a, Eigen::Index b) { return factor(scale * (theta(a) - theta(b))); }, in,
        out);
  }

  /// apply() of a named function (core/phase_function.h): the backend's contract.
  void apply(PhaseFunction f, double scale, const Matrix& in, Matrix& out) {
    // One loop per function, the function inlined in it.
    if (f == PhaseFunction::kCoadjointIncrement) {
      apply([](double eta) { return expm1OfI(-eta); }, scale, in, out);
    } else {
      apply([](double eta) { return expm1OfIOverI(-eta); }, scale, in, out);
    }
  }

  /// out = V [F ∘ (Vᴴ in V)] Vᴴ with F_ab = weight(a, b) and weight(b, a) = conj(weight(a, b)),
  /// so that skew-Hermitian `in` maps to skew-Hermitian out. out may be in.
  template <class Weight>
  void applyEntrywise(const Weight& weight, const Matrix& in, Matrix& out) {
    toBasis(in, hat_);
    for (Eigen::Index b = 0; b < hat_.cols(); ++b) {
      for (Eigen::Index a = 0; a < hat_.rows(); ++a) hat_(a, b) *= weight(a, b);
    }
    fromBasis(hat_, out);
  }

  /// hat = Vᴴ in V: `in` in the eigenbasis (two products).
  void toBasis(const Matrix& in, Complex& hat) {
    productWithVectors(in);
    hat.noalias() = vectors().adjoint() * product_;
  }

  /// m_ab ← f(a, b, m_ab) for every entry of a matrix in the eigenbasis' coordinates.
  template <class F>
  static void mapEntries(Complex& m, const F& f) {
    for (Eigen::Index b = 0; b < m.cols(); ++b) {
      for (Eigen::Index a = 0; a < m.rows(); ++a) m(a, b) = f(a, b, m(a, b));
    }
  }

  /// m ← w ∘ m for the named weights of a matrix in the eigenbasis' coordinates
  /// (core/eigenbasis_weights.h).
  template <class Weights>
  void weigh(const Weights& w, Complex& m) {
    detail::weighOnHost(w, phases(), half_, [&](const auto& f) { mapEntries(m, f); });
  }

  /// out = V hat Vᴴ projected onto the skew-Hermitian matrices (two products); hat is
  /// overwritten. The inverse of toBasis on skew-Hermitian matrices.
  void fromBasis(Complex& hat, Matrix& out) {
    const Complex& V = vectors();
    product_.noalias() = V * hat;
    hat.noalias() = product_ * V.adjoint();
    if constexpr (kReal) {
      out = hat.real();
    } else {
      out = hat;
    }
    MatrixBackend<Matrix>::makeSkewHermitian(out);
  }

  /// The weights of applyWeights after compute(): W_ab = weight(a, b), real and symmetric.
  template <class Weight>
  void setWeights(const Weight& weight) {
    const Eigen::Index n = phases().size();
    weights_.resize(n, n);
    for (Eigen::Index b = 0; b < n; ++b) {
      for (Eigen::Index a = 0; a < n; ++a) weights_(a, b) = weight(a, b);
    }
    weighted_ = true;
  }
  /// out = V [W ∘ (Vᴴ in V)] Vᴴ, projected onto the skew-Hermitian matrices; `in`
  /// skew-Hermitian. out may be in. Throws std::logic_error if no weights were set since
  /// compute().
  void applyWeights(const Matrix& in, Matrix& out) {
    if (!weighted_ || in.rows() != phases().size()) {
      throw std::logic_error("SkewHermitianEigenbasis::applyWeights: no weights for this basis");
    }
    applyEntrywise([this](Eigen::Index a, Eigen::Index b) { return weights_(a, b); }, in, out);
  }

  /// The phases of a skew-Hermitian y on x's eigenvectors: π_a = Im (Vᴴ y V)_aa (y's
  /// eigenvalues iπ_a when y commutes with x). One product.
  void diagonalPhasesOf(const Matrix& y, Eigen::VectorXd& out) {
    const Complex& V = vectors();
    productWithVectors(y);
    out.resize(V.cols());
    for (Eigen::Index a = 0; a < V.cols(); ++a) out(a) = V.col(a).dot(product_.col(a)).imag();
  }

  /// out = exp(scale·x) = I + V diag(e^{i scale θ} − 1) Vᴴ: formed as V diag(e^{iθ}) Vᴴ it is
  /// unitary only to a few ulps more (docs/reference/conventions.md §2).
  void exponential(double scale, Matrix& out) {
    const Complex& V = vectors();
    for (Eigen::Index a = 0; a < V.cols(); ++a) {
      product_.col(a) = V.col(a) * expm1OfI(scale * phases()(a));
    }
    hat_.noalias() = product_ * V.adjoint();
    hat_.diagonal().array() += 1.0;
    if constexpr (kReal) {
      out = hat_.real();
    } else {
      out = hat_;
    }
  }

 private:
  // product_ = m V (m real or complex).
  void productWithVectors(const Matrix& m) {
    if constexpr (kReal) {
      hermitian_ = m.template cast<std::complex<double>>();
      product_.noalias() = hermitian_ * vectors();
    } else {
      product_.noalias() = m * vectors();
    }
  }

  void allocate(Eigen::Index n) {
    if (hat_.rows() == n) return;
    for (Complex* m : {&hermitian_, &product_, &hat_}) m->setZero(n, n);
  }

  HermitianEigensolver solver_;
  Complex hermitian_, product_, hat_;
  Eigen::MatrixXd weights_;  // of applyWeights, kept between bases of one size
  Eigen::VectorXcd half_;    // weigh()'s half phases
  bool weighted_ = false;    // weights_ are this basis's
};

}  // namespace ddb
