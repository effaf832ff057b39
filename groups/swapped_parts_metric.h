// SwappedPartsMetric: the double bracket's metric on SU(N) ⋉ su(N)* (groups/dual_number_sun.h),
// k♯(ν₀ + εν₁) = α(ν₁ + εν₀). The group's pairing, the ε-coefficient of Re tr(μᴴξ), is indefinite
// (it pairs the 1-part of one with the ε-part of the other), so α·Id is no metric there; with the
// parts swapped ⟨ν, k♯ν⟩ = α(‖ν₀‖²_F + ‖ν₁‖²_F), positive for α > 0, and the energy falls at
// dH/dt = −α(‖c₀‖² + ‖c₁‖²), c = ad*_ξ μ (docs/reference/conventions.md §1, "SU(N) over the dual
// numbers").
#pragma once

#include <ddb/core/dissipation_metric.h>
#include <ddb/core/dual_matrix.h>
#include <ddb/core/errors.h>
#include <ddb/groups/dual_number_sun.h>

#include <optional>

namespace ddb {

template <class X>
class SwappedPartsMetric final : public DissipationMetric<DualNumberSUNOn<X>> {
 public:
  using D = DualMatrix<X>;

  /// α, any finite sign (α < 0: energy ascent, as ScaledIdentityMetric's).
  explicit SwappedPartsMetric(double alpha) : alpha_(requireFinite("alpha", alpha)) {}
  D sharp(const D& mu) const override {
    D out;
    MatrixBackend<D>::zeroLike(out, mu);
    sharpInto(mu, out);
    return out;
  }
  /// α times the pairing's Riesz map (DualNumberSUNOn::rieszMap, no entry copied). out may be mu.
  void sharpInto(const D& mu, D& out) const override {
    MatrixBackend<D>::scale(alpha_, mu, out);
    DualNumberSUNOn<X>::rieszMap(out);
  }
  double alpha() const { return alpha_; }
  /// α: the swap is the pairing's Riesz map (DualNumberSUNOn::rieszMap).
  std::optional<double> scalarMultiple() const override { return alpha_; }

 private:
  double alpha_;
};

}  // namespace ddb
