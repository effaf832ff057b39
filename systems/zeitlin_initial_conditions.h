// Seeded, reproducible initial vorticities for Zeitlin's fluid
// (docs/reference/command-lines-and-files.md, fluid-relax --init): every one is in su(N) and scaled
// to ‖W‖_F = √N, i.e. enstrophy ½.
//   random: i.i.d. standard normal real and imaginary parts, projected to su(N);
//   l1:     W = U X₃ Uᴴ, X₃ = ħ i diag(j − (N−1)/2), U a random unitary (QR of a normal
//           matrix with the phases of R's diagonal removed: Haar-distributed) — a point of
//           the isospectral orbit of the l = 1 element X₃; its energy maximum E/Z = ½ is
//           reached at the pure l = 1 states of that orbit (X₃'s rotations);
//   zonal:  i diag(d), d normal with its mean removed: a steady state ([P, W] = 0);
//   low modes (lowModeVorticity): Σ ω_lm T_lm over 1 ≤ l ≤ L with ω_lm normal of deviation 1/l, a
//           smooth large-scale field (mhd-relax's magnetic potential Θ₀; examples/python/mhd.py).
// std::mt19937_64 and a Box–Muller normal written here, so that the numbers do not depend
// on the standard library's distribution implementation.
#pragma once

#include <ddb/core/errors.h>
#include <ddb/groups/sun.h>
#include <ddb/systems/zeitlin_fluid.h>

#include <Eigen/Core>
#include <cmath>
#include <complex>
#include <cstdint>
#include <random>
#include <string>

namespace ddb {

namespace detail {
class NormalSource {
 public:
  explicit NormalSource(std::uint64_t seed) : rng_(seed) {}
  double next() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    // Box–Muller on (0, 1] uniforms built from 53 random bits.
    const double u1 = (double(rng_() >> 11) + 1.0) * 0x1.0p-53;
    const double u2 = double(rng_() >> 11) * 0x1.0p-53;
    const double r = std::sqrt(-2.0 * std::log(u1));
    spare_ = r * std::sin(2.0 * M_PI * u2);
    has_spare_ = true;
    return r * std::cos(2.0 * M_PI * u2);
  }
  Eigen::MatrixXcd complexMatrix(Eigen::Index n) {
    Eigen::MatrixXcd m(n, n);
    for (Eigen::Index j = 0; j < n; ++j) {
      for (Eigen::Index i = 0; i < n; ++i) {
        const double re = next();
        m(i, j) = std::complex<double>(re, next());
      }
    }
    return m;
  }

 private:
  std::mt19937_64 rng_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

Eigen::MatrixXcd normalised(Eigen::MatrixXcd W);

void requireResolution(Eigen::Index n);
}  // namespace detail

/// X₃ = ħ i diag(j − (N−1)/2): the l = 1, m = 0 element (T_10 = √3 X₃).
Eigen::MatrixXcd zeitlinX3(Eigen::Index n);

Eigen::MatrixXcd randomVorticity(Eigen::Index n, std::uint64_t seed);

/// A Haar-random unitary: Q of the QR of a normal matrix times the phases of R's diagonal.
Eigen::MatrixXcd randomUnitary(Eigen::Index n, std::uint64_t seed);

Eigen::MatrixXcd l1Vorticity(Eigen::Index n, std::uint64_t seed);

Eigen::MatrixXcd zonalVorticity(Eigen::Index n, std::uint64_t seed);

/// Σ ω_lm T_lm over 1 ≤ l ≤ l_max (the basis of systems/spherical_harmonic_basis.h), ω_lm
/// normal with deviation 1/l, scaled as the others. InvalidArgument naming N, or l_max outside
/// [1, N − 1].
Eigen::MatrixXcd lowModeVorticity(Eigen::Index n, Eigen::Index l_max, std::uint64_t seed);

}  // namespace ddb
