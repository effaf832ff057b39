// SpecialOrthogonal<N>: SO(N) with N fixed at compile time, a fixed-size group whose algebra and
// dual are N(N−1)/2-vectors (docs/reference/conventions.md §1, "SO(N) and SE(N) of a fixed
// size"), so that it composes: SemidirectProduct<SpecialOrthogonal<N>> is SE(N)
// (groups/special_euclidean.h), the group of the N-dimensional heavy top. (SON is SO(N) with N
// chosen at run time and matrix states, the group of the Manakov body and the real fluid.)
//
// Coordinates: x_p = X_ji for the p-th pair i < j in the order (0,1), (0,2), …, (0,N−1), (1,2), …,
// so hat(x) has X_ji = x_p and X_ij = −x_p. The pairing is the dot product,
//   <μ, x> = μ·x = ½ tr(hat(μ)ᵀ hat(x)),  dualHat(μ) = hat(μ)/2,  dualVee(Y)_p = Y_ji − Y_ij,
// as SO3's, whose coordinates are these up to order and sign (at N = 3: (x_12, −x_02, x_01)).
// The bracket, ad*, Ad*, the Cayley map and its tangents are LieGroupBase's, through hat and vee.
#pragma once

#include <ddb/core/detail/normal_matrix_functions.h>
#include <ddb/core/detail/scalar.h>
#include <ddb/core/lie_group.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <functional>

namespace ddb {

namespace detail {
/// "SO(N)" or "SE(N)" with N's digits, at compile time: other names than SO3's and SE3's, whose
/// coordinates are others.
template <int N>
struct MatrixGroupName {
  static constexpr int kDigits = N < 10 ? 1 : N < 100 ? 2 : 3;
  static constexpr int kLength = kDigits + 5;  // with the terminating zero
  static constexpr std::array<char, kLength> make(char first, char second) {
    std::array<char, kLength> name{};
    name[0] = first;
    name[1] = second;
    name[2] = '(';
    int n = N;
    for (int d = kDigits - 1; d >= 0; --d, n /= 10) name[3 + d] = char('0' + n % 10);
    name[3 + kDigits] = ')';
    return name;
  }
};
}  // namespace detail

template <int N>
struct SpecialOrthogonal : LieGroupBase<SpecialOrthogonal<N>> {
  static_assert(N >= 2 && N < 1000, "SpecialOrthogonal<N> needs 2 <= N < 1000");
  static constexpr std::array<char, detail::MatrixGroupName<N>::kLength> kNameStorage =
      detail::MatrixGroupName<N>::make('S', 'O');
  static constexpr const char* kName = kNameStorage.data();
  static constexpr int kDim = N * (N - 1) / 2;
  /// Σ_a λ_a^{2k} for k = 1 … ⌊N/2⌋, λ the eigenvalues of −i hat(μ).
  static constexpr int kNumCasimirs = N / 2;

  template <class T>
  using Algebra = Eigen::Matrix<T, kDim, 1>;
  template <class T>
  using Dual = Eigen::Matrix<T, kDim, 1>;
  template <class T>
  using Matrix = Eigen::Matrix<T, N, N>;
  template <class T>
  using Casimirs = Eigen::Matrix<T, kNumCasimirs, 1>;

  /// The pair (i, j), i < j, of coordinate p.
  static constexpr std::array<std::array<int, 2>, kDim> kPairs = [] {
    std::array<std::array<int, 2>, kDim> pairs{};
    int p = 0;
    for (int i = 0; i < N; ++i) {
      for (int j = i + 1; j < N; ++j) pairs[p++] = {i, j};
    }
    return pairs;
  }();

  template <class T>
  static Matrix<T> hat(const Algebra<T>& x) {
    Matrix<T> X = Matrix<T>::Constant(constant<T>(0.0));
    for (int p = 0; p < kDim; ++p) {
      X(kPairs[p][1], kPairs[p][0]) = x(p);
      X(kPairs[p][0], kPairs[p][1]) = -x(p);
    }
    return X;
  }
  template <class T>
  static Algebra<T> vee(const Matrix<T>& X) {
    Algebra<T> x;
    for (int p = 0; p < kDim; ++p) x(p) = X(kPairs[p][1], kPairs[p][0]);
    return x;
  }
  template <class T>
  static Matrix<T> dualHat(const Dual<T>& mu) {
    return hat<T>(mu) * constant<T>(0.5);
  }
  template <class T>
  static Dual<T> dualVee(const Matrix<T>& Y) {
    Dual<T> y;
    for (int p = 0; p < kDim; ++p) {
      y(p) = Y(kPairs[p][1], kPairs[p][0]) - Y(kPairs[p][0], kPairs[p][1]);
    }
    return y;
  }
  template <class T>
  static T pairing(const Dual<T>& mu, const Algebra<T>& x) {
    return mu.dot(x);
  }
  template <class T>
  static Matrix<T> inverse(const Matrix<T>& R) {
    return R.transpose();
  }

  /// exp(X) by scaling and squaring: X/2^s has 1-norm at most 1/2, where the Taylor polynomial of
  /// degree 18 leaves under 2^−19/19! < 1e−22 relative; scalar-generic (Jets differentiate it).
  template <class T>
  static Matrix<T> exp(const Algebra<T>& x) {
    const Matrix<T> X = hat(x);
    double norm = 0.0;  // the 1-norm of X's value, for the branch
    for (int c = 0; c < N; ++c) {
      double column = 0.0;
      for (int r = 0; r < N; ++r) column += std::abs(scalarPart(X(r, c)));
      norm = std::max(norm, column);
    }
    int squarings = 0;
    while (norm > 0.5) {
      norm *= 0.5;
      ++squarings;
    }
    const Matrix<T> scaled = X * constant<T>(std::ldexp(1.0, -squarings));
    Matrix<T> sum = Matrix<T>::Identity(), term = Matrix<T>::Identity();
    for (int k = 1; k <= 18; ++k) {
      term = Matrix<T>(term * scaled) * constant<T>(1.0 / k);
      sum += term;
    }
    for (int s = 0; s < squarings; ++s) sum = Matrix<T>(sum * sum);
    return sum;
  }

  /// log(R) = U diag(i arg λ) Uᴴ from the complex Schur form of R (orthogonal, so normal: the form
  /// is diagonal), the branch with the eigenvalues of −i log R in (−π, π].
  static Algebra<double> log(const Matrix<double>& R) {
    const Matrix<double> X =
        detail::unitaryLogarithm(R.template cast<std::complex<double>>()).real();
    return vee<double>(Matrix<double>((X - X.transpose()) * 0.5));
  }

  /// c_k = Σ_a λ_a^{2k} = (−1)^k tr(hat(μ)^{2k}), k = 1 … ⌊N/2⌋ (λ the eigenvalues of −i hat(μ)):
  /// invariant under μ ↦ Ad*_R μ = dualVee-conjugation hat(μ) ↦ Rᵀ hat(μ) R.
  template <class T>
  static Casimirs<T> casimirs(const Dual<T>& mu) {
    return evenPowerTraces<kNumCasimirs, T>(hat(mu));
  }

  /// (−1)^k tr(X^{2k}) = Σ_a λ_a^{2k} for k = 1 … K, λ the eigenvalues of −iX, X skew: the spectral
  /// invariants of so(N)'s Casimirs and of se(N)'s (groups/special_euclidean.h).
  template <int K, class T>
  static Eigen::Matrix<T, K, 1> evenPowerTraces(const Matrix<T>& X) {
    const Matrix<T> X2 = X * X;
    Matrix<T> power = X2;
    Eigen::Matrix<T, K, 1> c;
    for (int k = 1; k <= K; ++k) {
      c(k - 1) = power.trace() * constant<T>(k % 2 == 0 ? 1.0 : -1.0);
      if (k < K) power = Matrix<T>(power * X2);
    }
    return c;
  }

  /// The spectral radius of ad_x on so(N) ≅ Λ²Rᴺ: its eigenvalues are i(λ_a + λ_b), a < b, for the
  /// eigenvalues λ of −iX, so the radius is the sum of the two largest λ (they come in ± pairs).
  /// exp is one-to-one below π and dexp⁻¹ has its poles at 2π, as for SO3 (|x| at N = 3).
  static double adRadius(const Algebra<double>& x) {
    return detail::skewSymmetricAdRadius(hat<double>(x));
  }
};

}  // namespace ddb
