// The Casimir drift of a matrix state (SO(N), SU(N); docs/reference/conventions.md §2): the
// relative change of its whole spectrum, ‖λ(μ) − λ(μ₀)‖₂ / ‖λ(μ₀)‖₂, spectra sorted (G::casimirs).
// Not eigenvalue by eigenvalue: for odd N one eigenvalue of a real skew matrix is zero
// up to round-off, and its own relative change would be noise of order 1.
#pragma once

#include <Eigen/Core>

namespace ddb::app {

template <class G>
class SpectrumDrift {
 public:
  using Matrix = typename G::template Dual<double>;

  explicit SpectrumDrift(const Matrix& mu0) : initial_(G::casimirs(mu0)) {}
  double operator()(const Matrix& mu) const {
    return (G::casimirs(mu) - initial_).norm() / initial_.norm();
  }

 private:
  Eigen::VectorXd initial_;
};

}  // namespace ddb::app
