// Forcing of Zeitlin's fluid (systems/zeitlin_forcing.h) against what the code did not use: the
// fluid's own energy (ZeitlinDiagnostics: traces of Q − F and its stream matrix, not the
// spectra's formula) for the mean injection rate ε over many draws, within three standard errors;
// the coefficients of the kicks (SphericalHarmonicBasis::coefficients) for the band and the
// variance σ² h of each mode; σ against its closed form; the moments of the generator's normals;
// and a stream saved and loaded mid-run against the uninterrupted one, to the bit.

#include <ddb/core/binary_record.h>
#include <ddb/core/errors.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/strang_splitting.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_forcing.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace ddb::test {
namespace zeitlin_forcing_tests {

using Matrix = Eigen::MatrixXcd;

/// Mean and standard error of samples.
struct Sample {
  double mean = 0, standard_error = 0;
};
Sample sampleOf(const std::vector<double>& x) {
  double sum = 0, squares = 0;
  for (double v : x) sum += v;
  const double mean = sum / double(x.size());
  for (double v : x) squares += (v - mean) * (v - mean);
  return {mean, std::sqrt(squares / double(x.size() - 1) / double(x.size()))};
}

ZeitlinStochasticForcing band(int centre, int half_width, double rate, std::uint64_t seed) {
  ZeitlinStochasticForcing f;
  f.band_centre = centre;
  f.band_half_width = half_width;
  f.rate = rate;
  f.seed = seed;
  return f;
}

TEST(ZeitlinForcing, TheGeneratorsNormalsHaveTheirMoments) {
  // Mean 0, variance 1, fourth moment 3 (Var g² = 2, Var g⁴ = 96), and no correlation between
  // neighbouring draws or indices: each within three standard errors over 200 000 numbers.
  const int count = 200000;
  std::vector<double> g(count), g2(count), g4(count), by_draw(count), by_index(count);
  for (int j = 0; j < count; ++j) {
    const auto k = static_cast<std::uint64_t>(j);
    g[j] = counterNormal(11, k / 100, k % 100);
    g2[j] = g[j] * g[j];
    g4[j] = g2[j] * g2[j];
    by_draw[j] = g[j] * counterNormal(11, k / 100 + 1, k % 100);
    by_index[j] = g[j] * counterNormal(11, k / 100, k % 100 + 1);
  }
  const auto within = [](const std::vector<double>& x, double expected, const char* what) {
    const Sample s = sampleOf(x);
    EXPECT_LT(std::abs(s.mean - expected), 3 * s.standard_error)
        << what << ": " << s.mean << " +- " << s.standard_error;
  };
  within(g, 0.0, "mean");
  within(g2, 1.0, "variance");
  within(g4, 3.0, "fourth moment");
  within(by_draw, 0.0, "correlation of draws k and k + 1");
  within(by_index, 0.0, "correlation of modes j and j + 1");
}

TEST(ZeitlinForcing, TheAmplitudeIsItsClosedForm) {
  // σ² Σ_band (2l + 1) · ½/(l(l + 1) + κ²) = ε, the sum written here.
  const Eigen::Index n = 10;
  for (const double kappa_squared : {0.0, 2.5}) {
    const ZeitlinStochasticForcingFlow flow(n, band(4, 2, 0.3, 1), kappa_squared);
    double unit = 0;
    for (int l = 2; l <= 6; ++l) unit += (2 * l + 1) * 0.5 / (l * (l + 1) + kappa_squared);
    EXPECT_NEAR(flow.amplitude(), std::sqrt(0.3 / unit), 1e-15) << "kappa^2 " << kappa_squared;
  }
}

TEST(ZeitlinForcing, OnlyTheBandIsForcedEachModeWithVarianceSigmaSquaredH) {
  const Eigen::Index n = 9;
  const double h = 0.04;
  const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
  ZeitlinStochasticForcingFlow flow(n, band(5, 1, 0.7, 3));
  const double sigma = flow.amplitude();
  std::vector<double> squares, products;
  for (int k = 0; k < 400; ++k) {
    Matrix W = Matrix::Zero(n, n);
    flow.advance(W, h);
    ASSERT_LT((W + W.adjoint()).norm(), 1e-14) << "a kick is skew-Hermitian";
    ASSERT_LT(std::abs(W.trace()), 1e-14) << "and traceless";
    const Eigen::VectorXd omega = basis.coefficients(W) / (sigma * std::sqrt(h));
    for (int l = 0; l < n; ++l) {
      for (int m = -l; m <= l; ++m) {
        const double c = omega(SphericalHarmonicBasis::index(l, m));
        if (l < 4 || l > 6) {
          ASSERT_LT(std::abs(c), 1e-12) << "(l, m) = (" << l << ", " << m << ") is not forced";
        } else {
          squares.push_back(c * c);
        }
      }
    }
    products.push_back(omega(SphericalHarmonicBasis::index(4, 1)) *
                       omega(SphericalHarmonicBasis::index(6, -3)));
  }
  const Sample variance = sampleOf(squares), covariance = sampleOf(products);
  EXPECT_LT(std::abs(variance.mean - 1.0), 3 * variance.standard_error) << variance.mean;
  EXPECT_LT(std::abs(covariance.mean), 3 * covariance.standard_error) << covariance.mean;
}

TEST(ZeitlinForcing, TheMeanInjectionRateIsEpsilonOnEveryKindOfSphere) {
  // One kick from a fixed Q at a time: ΔE/h over 4000 kicks, E the fluid's own energy
  // (ZeitlinDiagnostics) of Q − F, on a resting, a rotating and a quasi-geostrophic sphere.
  const Eigen::Index n = 12;
  const double h = 0.01, rate = 0.25;
  for (int kind = 0; kind < 3; ++kind) {
    ZeitlinPhysics physics;
    if (kind >= 1) physics.rotation = 1.5;
    if (kind == 2) physics.deformation_radius = 0.6;
    const ZeitlinHamiltonian hamiltonian(n, physics);
    const ZeitlinDiagnostics diagnostics(hamiltonian);
    const Matrix Q0 = randomVorticity(n, 5) + hamiltonian.planetaryVorticity();
    const double E0 = diagnostics.energy(Q0);
    ZeitlinStochasticForcingFlow flow(n, band(4, 1, rate, 17 + kind), physics.kappaSquared());
    std::vector<double> rates;
    for (int k = 0; k < 4000; ++k) {
      Matrix Q = Q0;
      flow.advance(Q, h);
      rates.push_back((diagnostics.energy(Q) - E0) / h);
    }
    const Sample s = sampleOf(rates);
    EXPECT_LT(std::abs(s.mean - rate), 3 * s.standard_error)
        << "sphere " << kind << ": " << s.mean << " +- " << s.standard_error;
  }
}

TEST(ZeitlinForcing, AForcedRunInjectsEpsilonOnAverageOverSeeds) {
  // rk4 Strang-split with the forcing, T = 1 in 40 steps, 300 seeds: (E(T) − E(0))/T, averaged,
  // is ε within three standard errors (rk4 keeps E to about 1e-9 here; the noise's standard
  // error is about 1e-2 ε).
  const Eigen::Index n = 8;
  const double h = 0.025, rate = 0.4;
  const auto fluid = makeZeitlinFluid(n, 0.0);
  const ZeitlinDiagnostics diagnostics(
      dynamic_cast<const ZeitlinHamiltonian&>(fluid->hamiltonian()));
  const Matrix Q0 = randomVorticity(n, 2);
  std::vector<double> rates;
  for (std::uint64_t seed = 0; seed < 300; ++seed) {
    StrangSplitting<SUN> method(
        makeMethod<SUN>("rk4", fluid),
        std::make_unique<ZeitlinStochasticForcingFlow>(n, band(3, 1, rate, seed)));
    Matrix Q = Q0;
    for (int k = 0; k < 40; ++k) method.advance(Q, k * h, h);
    rates.push_back(diagnostics.energy(Q) - diagnostics.energy(Q0));
  }
  const Sample s = sampleOf(rates);
  EXPECT_LT(std::abs(s.mean - rate), 3 * s.standard_error) << s.mean << " +- " << s.standard_error;
}

TEST(ZeitlinForcing, AStreamSavedAndLoadedMidRunGivesTheSameBits) {
  // 30 steps at once against 12, the method's record (warm start and the stream's count)
  // written and read into a new method, then 18; the same seed twice gives the same bits, another
  // seed other ones.
  const Eigen::Index n = 8;
  const double h = 0.02;
  const auto fluid = makeZeitlinFluid(n, 0.1);
  const auto method = [&](std::uint64_t seed) {
    return StrangSplitting<SUN>(
        makeMethod<SUN>("ddb-cay", fluid),
        std::make_unique<ZeitlinStochasticForcingFlow>(n, band(2, 1, 0.5, seed)));
  };
  const Matrix Q0 = randomVorticity(n, 9);
  Matrix whole = Q0, again = Q0, other = Q0;
  auto a = method(7), b = method(7), c = method(8);
  for (int k = 0; k < 30; ++k) {
    a.advance(whole, k * h, h);
    b.advance(again, k * h, h);
    c.advance(other, k * h, h);
  }
  EXPECT_EQ(whole, again);
  EXPECT_GT((whole - other).norm(), 1e-3);

  Matrix resumed = Q0;
  auto first = method(7);
  for (int k = 0; k < 12; ++k) first.advance(resumed, k * h, h);
  BinaryRecordWriter out;
  first.saveWarmStart(out);
  auto second = method(7);
  BinaryRecordReader in(out.bytes());
  second.loadWarmStart(in, resumed);
  for (int k = 12; k < 30; ++k) second.advance(resumed, k * h, h);
  EXPECT_EQ(resumed, whole) << "max difference " << (resumed - whole).cwiseAbs().maxCoeff();
}

TEST(ZeitlinForcing, BadBandsAndRatesAreRefusedNamingTheParameter) {
  const auto refused = [](const ZeitlinStochasticForcing& f, const char* parameter) {
    try {
      ZeitlinStochasticForcingFlow(8, f);
      ADD_FAILURE() << parameter << " was accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find(parameter), std::string::npos) << e.what();
    }
  };
  refused(band(0, 0, 1.0, 0), "band_centre");  // l = 0 is the trace
  refused(band(2, 2, 1.0, 0), "band_centre");  // 0 .. 4
  refused(band(6, 2, 1.0, 0), "band_centre");  // 4 .. 8 > N − 1
  refused(band(3, -1, 1.0, 0), "band_half_width");
  refused(band(3, 1, -1.0, 0), "rate");
  refused(band(3, 1, std::nan(""), 0), "rate");
  refused(band(3, 1, INFINITY, 0), "rate");
}

TEST(ZeitlinForcing, AFixedForcingAddsHPhiAndRefusesAMatrixOutsideSuN) {
  const Eigen::Index n = 6;
  const Matrix phi = randomVorticity(n, 4);
  ZeitlinFixedForcingFlow flow(n, phi);
  Matrix W = randomVorticity(n, 1);
  const Matrix expected = W + 0.3 * phi;
  flow.advance(W, 0.3);
  EXPECT_LT((W - expected).norm(), 1e-15 * expected.norm());
  const auto refused = [&](const Matrix& m) {
    EXPECT_THROW(ZeitlinFixedForcingFlow(n, m), InvalidArgument);
  };
  refused(Matrix::Zero(n + 1, n + 1));
  refused(phi + Matrix::Identity(n, n));                               // Hermitian part
  refused(phi + std::complex<double>(0, 1) * Matrix::Identity(n, n));  // a trace
  Matrix nan = phi;
  nan(1, 2) = std::nan("");
  refused(nan);
}

}  // namespace zeitlin_forcing_tests
}  // namespace ddb::test
