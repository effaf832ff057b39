// The viscous flow's implicit step (ZeitlinViscousScheme::kImplicit, systems/zeitlin_viscosity.h):
// in place of exp(−hA), A = ν (−Δ)^p + γ, the rational function
//   R(hA) = (I + hA + (hA)²/2)⁻¹,
// second order (R(z) = e^{−z} + O(z³)) and L-stable (R(z) → 0 as z → ∞, 0 < R(z) < 1 for z > 0:
// every mode decays, none changes sign), so that a split step stays second order and a stiff
// hyperviscosity damps the small scales as the exact flow does. Each diagonal m of W is its own
// system, −Δ being the tridiagonal block T_m there (HoppeYauLaplacian::blockCoefficients), so A is
// banded (half-width p): a step costs O(N² p), about a quarter of a matrix product at N = 512
// where the exact flow costs 1.7 (docs/results/benchmarks.md, "The viscous flow's implicit step,
// and subnormal operators"), and holds (p + 1) N²/2 complex numbers (the factors) where the exact
// one holds N³/6 reals.
// A² is not formed: I + z + z²/2 = (1 + a z)(1 + ā z) with a = (1 + i)/2, and by partial
// fractions
//   R(z) = 2 Re(α / (1 + a z)),  α = (1 − i)/2,
// so a real vector u goes to 2 Re(α C⁻¹ u), C = I + a hA, one complex banded solve. C is complex
// symmetric with positive definite real part I + hA/2 and semidefinite imaginary part hA/2, so its
// LDLᵀ factorisation needs no pivoting (N. J. Higham, "Factorizing complex symmetric matrices with
// positive definite real and imaginary parts", Math. Comp. 67 (1998) 1591–1599: growth below 3).
// Rounding: forming T^p costs about ε ‖hA‖ on the slowest modes per step (ε ‖hA‖² had A² been
// formed).
#pragma once

#include <ddb/core/errors.h>
#include <ddb/systems/hoppe_yau_laplacian.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <string>
#include <vector>

namespace ddb {

class ZeitlinImplicitViscousStep {
 public:
  using Complex = std::complex<double>;

  /// The step of ν (−Δ)^p + γ (ν, γ >= 0, p >= 1, checked by the caller's ZeitlinViscosity) at
  /// resolution N on the blocks m in `blocks` (diagonals m and −m; all of them: every m < N).
  ZeitlinImplicitViscousStep(Eigen::Index n, double viscosity, int order, double drag,
                             const std::vector<Eigen::Index>& blocks)
      : n_(n),
        viscosity_(viscosity),
        drag_(drag),
        order_(order),
        kept_(static_cast<std::size_t>(n), false),
        offsets_(static_cast<std::size_t>(n) + 1, 0),
        solved_(4 * static_cast<std::size_t>(n)) {
    if (order < 1) throwInvalid("order", std::to_string(order), "must be >= 1");
    for (const Eigen::Index m : blocks) {
      if (!(m >= 0 && m < n_)) {
        throwInvalid("blocks", std::to_string(m), "must be 0 <= m < N = " + std::to_string(n_));
      }
      kept_[std::size_t(m)] = true;
    }
    for (Eigen::Index m = 0; m < n_; ++m) {
      offsets_[std::size_t(m) + 1] = offsets_[std::size_t(m)] + (kept(m) ? std::size_t(n_ - m) : 0);
    }
    const std::size_t entries = offsets_.back();
    lower_.resize(entries * std::size_t(order_));
    inverse_pivot_.resize(entries);
  }

  bool kept(Eigen::Index m) const { return m >= 0 && m < n_ && kept_[std::size_t(m)]; }

  /// Factors C = I + a h A of every kept block for the step h > 0: O(N² p²) in all, (−Δ)^p's
  /// band made again (it is not kept: as many numbers as the factors).
  void setStep(double h) {
    const Complex ah = Complex(0.5, 0.5) * h;
    const int p = order_;
    Eigen::VectorXd diagonal, off;
    std::vector<double> band, next;
    for (Eigen::Index m = 0; m < n_; ++m) {
      if (!kept(m)) continue;
      const Eigen::Index length = n_ - m;
      HoppeYauLaplacian::blockCoefficients(n_, m, diagonal, off);
      power(-diagonal, -off, band, next);
      const double* B = band.data();
      Complex* L = lower(m);
      Complex* inverse_pivot = inverse_pivot_.data() + offsets_[std::size_t(m)];
      // C(j + d, j) = [d = 0] + a h (ν B(j + d, j) + γ [d = 0]); LDLᵀ, column by column.
      const auto C = [&](Eigen::Index j, int d) {
        const Complex a =
            ah * (viscosity_ * B[std::size_t(j) * std::size_t(p + 1) + std::size_t(d)]);
        return d == 0 ? 1.0 + a + ah * drag_ : a;
      };
      for (Eigen::Index j = 0; j < length; ++j) {
        Complex pivot = C(j, 0);
        for (int d = 1; d <= p && j - d >= 0; ++d) {
          const Complex l = L[std::size_t(j - d) * std::size_t(p) + std::size_t(d - 1)];
          pivot -= l * l / inverse_pivot[j - d];
        }
        inverse_pivot[j] = 1.0 / pivot;
        for (int d = 1; d <= p && j + d < length; ++d) {
          // L(j + d, j) D_j = C(j + d, j) − Σ_k L(j + d, k) L(j, k) D_k over k < j.
          Complex value = C(j, d);
          for (int e = 1; e <= p - d && j - e >= 0; ++e) {
            value -= L[std::size_t(j - e) * std::size_t(p) + std::size_t(d + e - 1)] *
                     L[std::size_t(j - e) * std::size_t(p) + std::size_t(e - 1)] /
                     inverse_pivot[j - e];
          }
          L[std::size_t(j) * std::size_t(p) + std::size_t(d - 1)] = value;  // L(j + d, j) D_j
        }
        for (int d = 1; d <= p && j + d < length; ++d) {
          L[std::size_t(j) * std::size_t(p) + std::size_t(d - 1)] *= inverse_pivot[j];
        }
      }
    }
  }

  /// Diagonals of block m of a matrix W (W's diagonal m or −m, entries in the order
  /// k = min(i, j)), one (`second` null) or both, each replaced by R(hA) applied to it. Block m
  /// must be kept and setStep called. Allocates nothing.
  void applyToDiagonals(Eigen::Index m, Complex* first, Complex* second = nullptr) {
    if (!kept(m)) throwInvalid("m", std::to_string(m), "is a block this step does not keep");
    solve(m, first);
    if (second != nullptr) solve(m, second);
  }

 private:
  Complex* lower(Eigen::Index m) {
    return lower_.data() + offsets_[std::size_t(m)] * std::size_t(order_);
  }

  /// The lower band of T^p into `band`, T symmetric tridiagonal (diagonal t, couplings s(k) of
  /// k − 1 and k): (p + 1) numbers per row j, T^p(j + d, j) at j (p + 1) + d; p products by T,
  /// each widening the band by one (`next` their scratch).
  void power(const Eigen::VectorXd& t, const Eigen::VectorXd& s, std::vector<double>& band,
             std::vector<double>& next) const {
    const Eigen::Index length = t.size();
    const int p = order_;
    band.assign(std::size_t(length) * std::size_t(p + 1), 0.0);
    next.resize(band.size());
    for (Eigen::Index j = 0; j < length; ++j) band[std::size_t(j) * std::size_t(p + 1)] = 1.0;
    const auto at = [&](const std::vector<double>& b, int width, Eigen::Index i, Eigen::Index j) {
      const Eigen::Index d = std::abs(i - j);
      if (d > width || i < 0 || j < 0 || i >= length || j >= length) return 0.0;
      return b[std::size_t(std::min(i, j)) * std::size_t(p + 1) + std::size_t(d)];
    };
    const auto T = [&](Eigen::Index i, Eigen::Index j) {
      if (i == j) return t(i);
      if (std::abs(i - j) == 1) return s(std::max(i, j));
      return 0.0;
    };
    for (int width = 0; width < p; ++width) {
      std::fill(next.begin(), next.end(), 0.0);
      for (Eigen::Index j = 0; j < length; ++j) {
        for (int d = 0; d <= width + 1 && j + d < length; ++d) {
          const Eigen::Index i = j + d;
          double value = 0.0;
          for (Eigen::Index k = j - 1; k <= j + 1; ++k) {
            if (k >= 0 && k < length) value += at(band, width, i, k) * T(k, j);
          }
          next[std::size_t(j) * std::size_t(p + 1) + std::size_t(d)] = value;
        }
      }
      band.swap(next);
    }
  }

  // A diagonal x (complex entries: its real and imaginary parts two real vectors u, v) ←
  // 2 Re(α C⁻¹ u) + 2i Re(α C⁻¹ v), both solves in one pass.
  void solve(Eigen::Index m, Complex* x) {
    const Eigen::Index length = n_ - m;
    double* yr = solved_.data();
    for (Eigen::Index i = 0; i < length; ++i) {
      yr[4 * i] = x[i].real();
      yr[4 * i + 1] = 0.0;
      yr[4 * i + 2] = x[i].imag();
      yr[4 * i + 3] = 0.0;
    }
    const double* L = reinterpret_cast<const double*>(lower(m));
    const double* D =
        reinterpret_cast<const double*>(inverse_pivot_.data() + offsets_[std::size_t(m)]);
    substitute(length, order_, L, D, yr);
    // 2 Re(α y), α = (1 − i)/2: y's real part plus its imaginary part.
    for (Eigen::Index i = 0; i < length; ++i) {
      x[i] = {yr[4 * i] + yr[4 * i + 1], yr[4 * i + 2] + yr[4 * i + 3]};
    }
  }

  // (a, b) −= l · (the two unknowns at `other`), complex l = (l[0], l[1]).
  static void subtract(const double* l, const double* other, double& ar, double& ai, double& br,
                       double& bi) {
    const double lr = l[0], li = l[1];
    ar -= lr * other[0] - li * other[1];
    ai -= lr * other[1] + li * other[0];
    br -= lr * other[2] - li * other[3];
    bi -= lr * other[3] + li * other[2];
  }
  // C⁻¹ of two right-hand sides at once, interleaved in y (entry i: Re, Im of the first, Re, Im
  // of the second, at 4i..4i + 3): L z = y, z ← D⁻¹ z, Lᵀ y = z. L's p subdiagonals by column
  // (L(j + d, j) at 2 (j p + d − 1), real then imaginary), D⁻¹ likewise (2 j). Restrict-qualified
  // real arrays: std::complex's products check for infinities through a library call (C99
  // Annex G), and pointers that might alias make every unknown a reload.
  static void substitute(Eigen::Index length, int p, const double* __restrict L,
                         const double* __restrict D, double* __restrict y) {
    for (Eigen::Index i = 0; i < length; ++i) {
      double ar = y[4 * i], ai = y[4 * i + 1], br = y[4 * i + 2], bi = y[4 * i + 3];
      for (int d = 1; d <= p && i - d >= 0; ++d) {
        subtract(L + 2 * ((i - d) * p + d - 1), y + 4 * (i - d), ar, ai, br, bi);
      }
      y[4 * i] = ar;
      y[4 * i + 1] = ai;
      y[4 * i + 2] = br;
      y[4 * i + 3] = bi;
    }
    for (Eigen::Index i = 0; i < length; ++i) {
      const double dr = D[2 * i], di = D[2 * i + 1];
      const double ar = y[4 * i], ai = y[4 * i + 1], br = y[4 * i + 2], bi = y[4 * i + 3];
      y[4 * i] = dr * ar - di * ai;
      y[4 * i + 1] = dr * ai + di * ar;
      y[4 * i + 2] = dr * br - di * bi;
      y[4 * i + 3] = dr * bi + di * br;
    }
    for (Eigen::Index i = length - 1; i >= 0; --i) {
      double ar = y[4 * i], ai = y[4 * i + 1], br = y[4 * i + 2], bi = y[4 * i + 3];
      for (int d = 1; d <= p && i + d < length; ++d) {
        subtract(L + 2 * (i * p + d - 1), y + 4 * (i + d), ar, ai, br, bi);
      }
      y[4 * i] = ar;
      y[4 * i + 1] = ai;
      y[4 * i + 2] = br;
      y[4 * i + 3] = bi;
    }
  }

  Eigen::Index n_;
  double viscosity_, drag_;
  int order_;
  std::vector<bool> kept_;
  std::vector<std::size_t> offsets_;  // where block m's rows start (n_ − m rows if kept)
  std::vector<Complex> lower_;        // L's p subdiagonals per row, by column: L(j + d, j)
  std::vector<Complex> inverse_pivot_;
  std::vector<double> solved_;  // the two solves' unknowns, real and imaginary parts (4 N)
};

}  // namespace ddb
