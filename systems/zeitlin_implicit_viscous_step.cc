// The implicit viscous step (systems/zeitlin_implicit_viscous_step.h), compiled once (its loops
// would otherwise be compiled in every file that includes the header).
#include <ddb/core/errors.h>
#include <ddb/systems/zeitlin_implicit_viscous_step.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <string>
#include <vector>

namespace ddb {

ZeitlinImplicitViscousStep::ZeitlinImplicitViscousStep(Eigen::Index n, double viscosity, int order,
                                                       double drag,
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

void ZeitlinImplicitViscousStep::setStep(double h) {
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
      const Complex a = ah * (viscosity_ * B[std::size_t(j) * std::size_t(p + 1) + std::size_t(d)]);
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

void ZeitlinImplicitViscousStep::applyToDiagonals(Eigen::Index m, Complex* first, Complex* second) {
  if (!kept(m)) throwInvalid("m", std::to_string(m), "is a block this step does not keep");
  solve(m, first);
  if (second != nullptr) solve(m, second);
}

void ZeitlinImplicitViscousStep::power(const Eigen::VectorXd& t, const Eigen::VectorXd& s,
                                       std::vector<double>& band, std::vector<double>& next) const {
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

void ZeitlinImplicitViscousStep::solve(Eigen::Index m, Complex* x) {
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

void ZeitlinImplicitViscousStep::subtract(const double* l, const double* other, double& ar,
                                          double& ai, double& br, double& bi) {
  const double lr = l[0], li = l[1];
  ar -= lr * other[0] - li * other[1];
  ai -= lr * other[1] + li * other[0];
  br -= lr * other[2] - li * other[3];
  bi -= lr * other[3] + li * other[2];
}

void ZeitlinImplicitViscousStep::substitute(Eigen::Index length, int p, const double* __restrict L,
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

}  // namespace ddb
