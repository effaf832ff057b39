// DissipationMetric: the symmetric semi-definite k: g* × g* → R through its
// musical map k♯: g* → g (paper, eq. (3.5)): φ(ξ) = k♯(ad*_ξ ∂l/∂ξ(ξ)).
// A negative scale (α < 0) is allowed: energy ascent on the orbit (docs/reference/conventions.md
// §4).
#pragma once

#include <ddb/core/errors.h>
#include <ddb/core/group_traits.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/core/matrix_traits.h>

#include <optional>
#include <string>

namespace ddb {

template <class G>
class DissipationMetric {
 public:
  using Algebra = typename G::template Algebra<double>;
  using Dual = typename G::template Dual<double>;

  virtual ~DissipationMetric() = default;
  /// k♯(mu); linear in mu.
  virtual Algebra sharp(const Dual& mu) const = 0;
  /// k♯(mu) into `out` (already of mu's size); override for large algebras.
  virtual void sharpInto(const Dual& mu, Algebra& out) const { out = sharp(mu); }
  /// α where k♯ = α·R, R the Riesz map of G's pairing onto its coordinates' inner product
  /// (rieszMapInPlace, core/group_traits.h: the identity but on SU(N) ⋉ su(N)*); nothing for any
  /// other metric. The linearly implicit DDB needs one: its dissipative factor is a Newton step
  /// in that inner product whose explicit Euler step is DDB's hk♯(ad*_ξ μ)
  /// (integrators/methods/linearly_implicit_ddb.h).
  virtual std::optional<double> scalarMultiple() const { return std::nullopt; }
};

/// k♯ = α · identity (coordinates of g* identified with those of g by the basis,
/// or by the trace pairing for matrix algebras). The rigid body of Section 5.
template <class G>
class ScaledIdentityMetric final : public DissipationMetric<G> {
 public:
  using typename DissipationMetric<G>::Algebra;
  using typename DissipationMetric<G>::Dual;

  explicit ScaledIdentityMetric(double alpha) : alpha_(requireFinite("alpha", alpha)) {}
  Algebra sharp(const Dual& mu) const override {
    if constexpr (isEigenMatrix<Dual>) {
      return alpha_ * mu;
    } else {  // a backend's matrix
      Algebra out = mu;
      MatrixBackend<Dual>::scale(alpha_, mu, out);
      return out;
    }
  }
  void sharpInto(const Dual& mu, Algebra& out) const override {
    if constexpr (hasFixedSize<Algebra>) {
      out = alpha_ * mu;
    } else {
      MatrixBackend<Dual>::scale(alpha_, mu, out);  // a matrix algebra: an O(N²) pass of the step
    }
  }
  double alpha() const { return alpha_; }
  /// α, unless G's pairing is not its coordinates' inner product: α·I is then no multiple of
  /// the Riesz map (SU(N) ⋉ su(N)*'s metric is SwappedPartsMetric).
  std::optional<double> scalarMultiple() const override {
    if constexpr (detail::HasIndefinitePairing<G>::value) {
      return std::nullopt;
    } else {
      return alpha_;
    }
  }

 private:
  double alpha_;
};

/// The metric as k♯ = α·I, or nullptr if it is not one.
template <class G>
const ScaledIdentityMetric<G>* asScalarMetric(const DissipationMetric<G>& metric) {
  return dynamic_cast<const ScaledIdentityMetric<G>*>(&metric);
}

/// k♯ = α · diag(k), k_i >= 0 (the heavy-top and Kirchhoff metrics of
/// docs/reference/command-lines-and-files.md).
template <class G>
class DiagonalMetric final : public DissipationMetric<G> {
 public:
  using typename DissipationMetric<G>::Algebra;
  using typename DissipationMetric<G>::Dual;

  DiagonalMetric(double alpha, const Algebra& k) : alpha_(requireFinite("alpha", alpha)), k_(k) {
    requireFinite("metric", k_);
    if ((k_.array() < 0).any()) throwInvalid("metric", formatValue(k_), "entries must be >= 0");
  }
  Algebra sharp(const Dual& mu) const override { return alpha_ * k_.cwiseProduct(mu); }

 private:
  double alpha_;
  Algebra k_;
};

}  // namespace ddb
