// Forcing of Zeitlin's fluid (docs/reference/conventions.md §2), as exact flows that a
// StrangSplitting takes apart from the Lie–Poisson part (as the viscosity's,
// systems/zeitlin_viscosity.h):
//   fixed:      Ẇ = Φ, Φ a traceless skew-Hermitian matrix:       W ← W + h Φ;
//   stochastic: dW = σ Σ_{l ∈ band, |m| ≤ l} T_lm dB_lm(t), the B_lm independent Brownian motions
//               (white in time, band-limited in degree, as GLIFS's forced QG solver):
//               W ← W + σ √h Σ g_lm T_lm, g_lm independent standard normals: the exact flow.
// Both leave the coadjoint orbit by design. The energy E = ½ Σ ω_lm² / (l(l + 1) + κ²)
// (systems/zeitlin_spectra.h) is quadratic and diagonal in the T_lm, so one stochastic kick
// adds on average σ² h Σ_band e_l, e_l = ½/(l(l + 1) + κ²) the energy of one unit coefficient:
// σ² = ε / Σ_band e_l injects energy at the mean rate ε, whatever the state (Itô; Novikov's
// formula).
// The normals come from a counter-based generator: g_lm of the k-th kick is a function of (seed,
// k, mode), so that the stream's whole state is the count k, which a checkpoint keeps (save, load)
// and every machine draws the same numbers (no std:: distribution, whose algorithm is the
// standard library's own).
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/errors.h>
#include <ddb/core/exact_flow.h>
#include <ddb/groups/sun.h>

#include <Eigen/Core>
#include <cmath>
#include <complex>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace ddb {

/// The band, rate and seed of band-limited white-in-time forcing.
struct ZeitlinStochasticForcing {
  int band_centre = 0;      ///< l_f: the forced degrees are l_f − δ .. l_f + δ
  int band_half_width = 0;  ///< δ >= 0
  double rate = 0.0;        ///< ε >= 0, the mean energy injection rate (energy per unit time)
  std::uint64_t seed = 0;   ///< the random stream's seed

  /// Whether anything is forced (ε > 0).
  bool forces() const { return rate > 0; }
  /// Whether the band's degrees l_f − δ .. l_f + δ lie in 1 .. N − 1 (l = 0 is the trace).
  bool bandFits(Eigen::Index n) const {
    return band_half_width >= 0 && long(band_centre) - band_half_width >= 1 &&
           long(band_centre) + band_half_width <= long(n) - 1;
  }
  /// Throws InvalidArgument naming the parameter unless 1 <= l_f − δ, l_f + δ <= N − 1 and ε is
  /// finite and >= 0.
  void validate(Eigen::Index n) const {
    if (band_half_width < 0) {
      throwInvalid("band_half_width", std::to_string(band_half_width), "must be >= 0");
    }
    if (!bandFits(n)) {
      throwInvalid("band_centre",
                   std::to_string(band_centre) + " +- " + std::to_string(band_half_width),
                   "must have its degrees in [1, N - 1], N = " + std::to_string(n));
    }
    if (!(rate >= 0 && std::isfinite(rate))) {
      throwInvalid("rate", formatValue(rate), "must be finite and >= 0");
    }
  }
};

/// A standard normal that is a function of (seed, draw, index) alone: SplitMix64's finaliser
/// (S. Vigna; the mixer of Java's SplittableRandom) keys two uniforms, Box–Muller's cosine branch
/// maps them. Statistically independent across all three arguments for the forcing's purposes.
inline double counterNormal(std::uint64_t seed, std::uint64_t draw, std::uint64_t index) {
  const auto mix = [](std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  const std::uint64_t key = mix(mix(mix(seed) ^ draw) ^ (2 * index));
  const std::uint64_t other = mix(key ^ 0x5851f42d4c957f2dULL);
  // 53-bit uniforms: u1 in (0, 1] (log finite), u2 in [0, 1).
  const double u1 = (double(key >> 11) + 1.0) * 0x1.0p-53;
  const double u2 = double(other >> 11) * 0x1.0p-53;
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * 3.14159265358979323846 * u2);
}

/// The band of a ZeitlinStochasticForcing at resolution N for a fluid of κ² (ZeitlinPhysics::
/// kappaSquared; 0: Euler): its modes T_lm, each held as its two nonzero diagonals (O(N) each),
/// and the amplitude σ. Kick k over a step h adds c_j T_j, c_j = σ √h counterNormal(seed, k, j),
/// for the modes j in order: one formula for every placement of the states
/// (ZeitlinStochasticForcingFlow here, DistributedZeitlinStochasticForcingFlow on MPI ranks).
class ZeitlinForcingBand {
 public:
  /// T_lm's diagonal `offset` = |m| (upper) and −|m| (lower; the same for m = 0), entries in the
  /// order k = min(i, j).
  struct Mode {
    Eigen::Index offset;
    Eigen::VectorXcd upper, lower;
  };

  /// Throws InvalidArgument naming the parameter for a band or rate N refuses
  /// (ZeitlinStochasticForcing::validate).
  ZeitlinForcingBand(Eigen::Index n, const ZeitlinStochasticForcing& forcing,
                     double kappa_squared = 0.0);

  const std::vector<Mode>& modes() const { return modes_; }
  /// σ, the noise amplitude that gives the mean injection rate ε.
  double amplitude() const { return sigma_; }
  /// c_j of kick `draw` over a step h into `c` (one per mode, sized by the caller: no allocation).
  void coefficients(double h, std::uint64_t draw, Eigen::VectorXd& c) const;

 private:
  ZeitlinStochasticForcing forcing_;
  std::vector<Mode> modes_;
  double sigma_ = 0.0;
};

/// What the stochastic forcing's flow is on every placement of the states: its band, the stream's
/// position (the count of kicks given, which a checkpoint keeps) and the next kick's
/// coefficients; each placement adds them to its own storage (advance).
template <class G>
class ZeitlinStochasticForcingStream : public ExactFlow<G> {
 public:
  ZeitlinStochasticForcingStream(Eigen::Index n, const ZeitlinStochasticForcing& forcing,
                                 double kappa_squared)
      : band_(n, forcing, kappa_squared), c_(Eigen::Index(band_.modes().size())) {}

  std::string name() const override { return "forcing"; }
  /// σ, the noise amplitude that gives the mean injection rate ε.
  double amplitude() const { return band_.amplitude(); }
  /// How many kicks the stream has given (the next kick's draw index).
  std::uint64_t draws() const { return draws_; }
  void save(BinaryRecordWriter& out) const override { out.put(draws_); }
  void load(BinaryRecordReader& in) override { in.get(draws_); }

 protected:
  const ZeitlinForcingBand& band() const { return band_; }
  /// The next kick's coefficients c_j over a step h (the stream moves on by one).
  const Eigen::VectorXd& nextKick(double h) {
    band_.coefficients(h, draws_, c_);
    ++draws_;
    return c_;
  }

 private:
  ZeitlinForcingBand band_;
  Eigen::VectorXd c_;  // the kick's coefficients
  std::uint64_t draws_ = 0;
};

/// The stochastic forcing's exact flow at resolution N for a fluid of κ²: a kick costs
/// O(N · modes) and allocates nothing.
class ZeitlinStochasticForcingFlow final : public ZeitlinStochasticForcingStream<SUN> {
 public:
  ZeitlinStochasticForcingFlow(Eigen::Index n, const ZeitlinStochasticForcing& forcing,
                               double kappa_squared = 0.0)
      : ZeitlinStochasticForcingStream<SUN>(n, forcing, kappa_squared) {}

  /// W ← W + σ √h Σ g_lm T_lm, the next kick of the stream.
  void advance(Eigen::MatrixXcd& W, double h) override;
};

/// The fixed forcing's exact flow: W ← W + h Φ.
class ZeitlinFixedForcingFlow final : public ExactFlow<SUN> {
 public:
  /// Throws InvalidArgument naming "forcing" unless Φ is N × N, finite, skew-Hermitian and
  /// traceless (to 1e-12 of its norm: a member of su(N)).
  ZeitlinFixedForcingFlow(Eigen::Index n, Eigen::MatrixXcd forcing);

  /// The constructor's checks of Φ (every placement's: DistributedZeitlinFixedForcingFlow).
  static void requireValid(Eigen::Index n, const Eigen::MatrixXcd& forcing);

  std::string name() const override { return "forcing"; }
  void advance(Eigen::MatrixXcd& W, double h) override { W += h * forcing_; }

 private:
  Eigen::MatrixXcd forcing_;
};

}  // namespace ddb
