// Zeitlin's SU(N) fluid (docs/reference/conventions.md §2), each property against something the
// library did not use to compute it: central differences along the flow, the isospectral
// midpoint rule written here from its own formula, the adaptive reference solver. Its parts have
// their own tests: test_hoppe_yau_laplacian, test_spherical_harmonic_basis,
// test_matrix_legendre_solver, test_correction_predictor, test_matrix_cayley_transport.

#include <ddb/integrators/methods/ddb.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/hoppe_yau_laplacian.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

#include "order_fit.h"
#include "zeitlin_step_fraction.h"

namespace ddb::test {
namespace zeitlin_tests {

using Matrix = Eigen::MatrixXcd;

// dE/dt = −α‖[P, W]‖²/(ħN) against the central difference of E along the vector field;
// Z constant along it.
TEST(ZeitlinFluid, EnergyRateMatchesCentralDifferencesAndEnstrophyIsConstant) {
  const int n = 12;
  for (double alpha : {0.0, 0.5, -0.5}) {
    const auto fluid = makeZeitlinFluid(n, alpha);
    const auto& hamiltonian = static_cast<const ZeitlinHamiltonian&>(fluid->hamiltonian());
    const ZeitlinDiagnostics diagnostics(hamiltonian);
    const Matrix W = randomVorticity(n, 11);
    const Matrix F = fluid->vectorField(W);
    const double eps = 1e-5;
    const Matrix plus = W + eps * F, minus = W - eps * F;
    const double dE = (diagnostics.energy(plus) - diagnostics.energy(minus)) / (2 * eps);
    const double expected =
        -alpha * std::pow(diagnostics.commutatorNorm(W), 2) / (hamiltonian.hbar() * n);
    EXPECT_NEAR(dE, expected, 1e-8 * std::max(1.0, std::abs(expected))) << alpha;
    const double dZ = (diagnostics.enstrophy(plus) - diagnostics.enstrophy(minus)) / (2 * eps);
    EXPECT_NEAR(dZ, 0.0, 1e-9) << alpha;
    // The library's energy H is N·E/ħ.
    EXPECT_NEAR(fluid->energy(W), n * diagnostics.energy(W) / hamiltonian.hbar(), 1e-12);
  }
}

TEST(ZeitlinFluid, DdbKeepsTheSpectrumAndMovesTheEnergyOneWay) {
  const int n = 32;
  for (double alpha : {0.5, -0.5}) {
    const auto fluid = makeZeitlinFluid(n, alpha);
    const ZeitlinDiagnostics diagnostics(
        static_cast<const ZeitlinHamiltonian&>(fluid->hamiltonian()));
    const Matrix W0 = randomVorticity(n, 1);
    const Eigen::VectorXd spectrum0 = SUN::casimirs(W0);
    auto method = makeMethod<SUN>("ddb-cay", fluid);
    // h = 0.02 ħ/‖P₀‖₂ (the benchmark's step). With α < 0 the energy grows 50-fold and
    // ‖[P, W]‖ 18-fold from this state; at 0.1 ħ/‖P₀‖₂ the step then no longer resolves
    // the flow and the energy reverses by up to 7.5% (docs/design/architecture.md, "Measured").
    const double h = zeitlinStepFraction(W0, 0.02);
    double drift = 0.0, previous = diagnostics.energy(W0);
    int wrong_way = 0;
    integrate(*method, W0, 0.0, h, 1000, [&](long, double, const Matrix& W) {
      drift = std::max(drift, (SUN::casimirs(W) - spectrum0).norm() / spectrum0.norm());
      const double energy = diagnostics.energy(W);
      if (alpha * (energy - previous) > 1e-15 * std::abs(previous)) ++wrong_way;
      previous = energy;
    });
    std::cout << "alpha=" << alpha << " spectrum drift " << drift << " E0 "
              << diagnostics.energy(W0) << " E " << previous << "\n";
    EXPECT_LE(drift, 1e-12) << alpha;
    EXPECT_EQ(wrong_way, 0) << alpha;
    EXPECT_NE(previous, diagnostics.energy(W0));
  }
}

// The exact flow loses energy (dE/dt = −α‖[P, W]‖_F²/(ħN) ≤ 0 for α > 0), and so does
// DDB Cayley within the stability bound of its dissipative factor, which is explicit in
// the state: the stiffness s = h|α|‖W‖₂²/ħ (‖W‖₂ a Casimir) must stay below about 6. At
// s = 4 the energy falls at every step, at s = 10 a period-2 mode of the large scales
// grows and the energy rises (docs/design/architecture.md, "Large N: the step's stability bound";
// the benchmark's h = 0.02 ħ/‖P₀‖₂ reaches s = 8.5 at N = 512).
TEST(ZeitlinFluid, DdbCayleysEnergyFallsWithinTheDissipationsStabilityBound) {
  const double alpha = 0.5;
  for (int n : {32, 64}) {
    const auto fluid = makeZeitlinFluid(n, alpha);
    const ZeitlinDiagnostics diagnostics(
        static_cast<const ZeitlinHamiltonian&>(fluid->hamiltonian()));
    const Matrix W0 = randomVorticity(n, 1);
    const double norm = SUN::casimirs(W0).cwiseAbs().maxCoeff();  // ‖W₀‖₂
    for (double stiffness : {4.0, 10.0}) {
      auto method = makeMethod<SUN>("ddb-cay", fluid);
      const double h = stiffness * zeitlinHbar(n) / (alpha * norm * norm);
      double previous = diagnostics.energy(W0), largest = previous;
      int rises = 0;
      // The unstable runs reach their largest energy within 40 steps (and take many sweeps).
      const long steps = stiffness < 6.0 ? 200 : 40;
      integrate(*method, W0, 0.0, h, steps, [&](long, double, const Matrix& W) {
        const double energy = diagnostics.energy(W);
        if (energy - previous > 1e-15 * previous) ++rises;
        largest = std::max(largest, energy);
        previous = energy;
      });
      if (stiffness < 6.0) {
        EXPECT_EQ(rises, 0) << "N = " << n << ", s = " << stiffness;
      } else {
        EXPECT_GT(largest, 1.5 * diagnostics.energy(W0)) << "N = " << n << ", s = " << stiffness;
      }
    }
  }
}

// The isospectral midpoint rule for Ẇ = [B(W), W], B = P/ħ, from its own formula:
//   W_k = (I − hB/2) W̃ (I + hB/2),  W_{k+1} = (I + hB/2) W̃ (I − hB/2),  B = B(W̃).
Matrix isospectralMidpoint(const ZeitlinHamiltonian& hamiltonian, const Matrix& W, double h) {
  const Eigen::Index n = W.rows();
  const Matrix I = Matrix::Identity(n, n);
  Matrix tilde = W;
  for (int k = 0; k < 500; ++k) {
    const Matrix B = hamiltonian.streamMatrix(tilde) / hamiltonian.hbar();
    // W̃ = (I − hB/2)⁻¹ W (I + hB/2)⁻¹
    const Matrix next = (I - 0.5 * h * B).inverse() * W * (I + 0.5 * h * B).inverse();
    const double change = (next - tilde).norm();
    tilde = next;
    if (change < 1e-16 * W.norm()) break;
  }
  const Matrix B = hamiltonian.streamMatrix(tilde) / hamiltonian.hbar();
  return (I + 0.5 * h * B) * tilde * (I - 0.5 * h * B);
}

TEST(ZeitlinFluid, AtAlphaZeroDdbCayleyIsTheIsospectralMidpoint) {
  const int n = 16;
  const auto fluid = makeZeitlinFluid(n, 0.0);
  const ZeitlinHamiltonian hamiltonian(n);
  const Matrix W0 = randomVorticity(n, 5);
  // The DDB step conjugates W_k, the midpoint rule reads out from W̃: they agree to
  // rounding per step, and this flow amplifies a 1e-16 perturbation 26-fold over 100
  // steps at h = 0.05 ħ/‖P₀‖₂ (1141-fold at 0.2, where rounding alone reaches 4e-13).
  const double h = zeitlinStepFraction(W0, 0.05);
  auto method = makeMethod<SUN>("ddb-cay", fluid);
  Matrix ddb = W0, midpoint = W0;
  for (int k = 0; k < 100; ++k) {
    ddb = method->step(ddb, k * h, h);
    midpoint = isospectralMidpoint(hamiltonian, midpoint, h);
  }
  std::cout << "DDB Cayley vs isospectral midpoint after 100 steps: "
            << (ddb - midpoint).norm() / W0.norm() << " relative\n";
  EXPECT_LT((ddb - midpoint).norm(), 1e-13 * W0.norm());
}

TEST(ZeitlinInitialConditions, LowModesHaveOnlyTheirDegreesAndTheOthersScale) {
  // Degree ≤ L ⟺ Π_{l=1..L} (Δ + l(l + 1)) W = 0 (Δ T_lm = −l(l + 1) T_lm), with Δ applied as the
  // matrix Laplacian, not through the basis the field is made of.
  const Eigen::Index n = 12;
  const HoppeYauLaplacian laplacian(n);
  for (Eigen::Index l_max : {1, 3, 5}) {
    const Matrix W = lowModeVorticity(n, l_max, 7);
    EXPECT_LT((W + W.adjoint()).norm(), 1e-15 * W.norm());
    EXPECT_LT(std::abs(W.trace()), 1e-14);
    EXPECT_NEAR(W.norm(), std::sqrt(double(n)), 1e-13);
    // Rounding grows with the factors' norms, at most L(L + 1) + l(l + 1) each; a degree above L
    // would leave Π |l(l + 1) − l'(l' + 1)| ≥ 10⁷ times its coefficient at L = 5.
    Matrix rest = W, next(n, n);
    double bound = W.norm();
    for (Eigen::Index l = 1; l <= l_max; ++l) {
      laplacian.apply(rest, next);
      rest = next + double(l * (l + 1)) * rest;
      bound *= double(l_max * (l_max + 1) + l * (l + 1));
      if (l < l_max) {
        EXPECT_GT(rest.norm(), 1e-3 * W.norm()) << "degree " << l + 1 << " is there";
      }
    }
    EXPECT_LT(rest.norm(), 1e-13 * bound) << "l_max " << l_max;
  }
  EXPECT_THROW(lowModeVorticity(n, 0, 1), InvalidArgument);
  EXPECT_THROW(lowModeVorticity(n, n, 1), InvalidArgument);
  EXPECT_EQ(lowModeVorticity(n, 3, 7), lowModeVorticity(n, 3, 7));
}

TEST(ZeitlinFluid, ZonalAndL1StatesAreFixedByOneStep) {
  const int n = 12;
  const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
  const Matrix l1 = 0.3 * basis.element(1, -1) - 0.7 * basis.element(1, 0) +
                    0.5 * basis.element(1, 1);  // a pure l = 1 element
  for (double alpha : {0.0, 0.5, -0.5}) {
    const auto fluid = makeZeitlinFluid(n, alpha);
    for (const Matrix& W : {zonalVorticity(n, 2), l1}) {
      auto method = makeMethod<SUN>("ddb-cay", fluid);
      const Matrix next = method->step(W, 0.0, zeitlinStepFraction(W, 0.5));
      EXPECT_LT((next - W).norm(), 1e-14 * W.norm()) << alpha;
    }
  }
}

TEST(ZeitlinFluid, EnergyAscentOnTheL1OrbitReachesHalfTheEnstrophy) {
  // W = U X₃ Uᴴ (random U) lies on the isospectral orbit of the l = 1 element X₃ but is
  // not itself l = 1; with α < 0 the energy rises to the orbit's maximum E/Z = ½.
  const int n = 12;
  const auto fluid = makeZeitlinFluid(n, -0.5);
  const ZeitlinDiagnostics diagnostics(
      static_cast<const ZeitlinHamiltonian&>(fluid->hamiltonian()));
  Matrix W = l1Vorticity(n, 4);
  const double ratio0 = diagnostics.energy(W) / diagnostics.enstrophy(W);
  auto method = makeMethod<SUN>("ddb-cay", fluid);
  integrate(*method, W, 0.0, 0.05, 4000, [&](long, double, const Matrix& state) { W = state; });
  const double ratio = diagnostics.energy(W) / diagnostics.enstrophy(W);
  std::cout << "E/Z: " << ratio0 << " -> " << ratio << "\n";
  EXPECT_LT(ratio0, 0.49);
  EXPECT_NEAR(ratio, 0.5, 1e-6);
}

// Orders against the adaptive reference, N = 8, t in [0, 1] (docs/reference/conventions.md §2).
struct FluidOrderCase {
  const char* method;
  double alpha;
  double expected;
};

class FluidOrder : public ::testing::TestWithParam<FluidOrderCase> {};

TEST_P(FluidOrder, FittedSlopeAgainstTheReference) {
  const auto& c = GetParam();
  const int n = 8;
  const auto fluid = makeZeitlinFluid(n, c.alpha);
  const Matrix W0 = randomVorticity(n, 1);
  const double t_end = 1.0;
  auto finalState = [&](const std::string& name, int steps) {
    auto method = makeMethod<SUN>(name, fluid);
    Matrix last;
    integrate(*method, W0, 0.0, t_end / steps, steps,
              [&](long, double, const Matrix& W) { last = W; });
    return last;
  };
  const Matrix reference = finalState("reference", 1);
  std::vector<double> hs, errors;
  for (int steps : {20, 40, 80, 160, 320}) {
    hs.push_back(t_end / steps);
    errors.push_back((finalState(c.method, steps) - reference).norm());
  }
  const OrderFit fit = fitOrder(hs, errors, 1e-11);
  std::cout << c.method << " alpha=" << c.alpha << " slope=" << fit.slope << "\n";
  ASSERT_GE(fit.points, 4);
  EXPECT_NEAR(fit.slope, c.expected, 0.15);
}
INSTANTIATE_TEST_SUITE_P(Zeitlin, FluidOrder,
                         ::testing::Values(FluidOrderCase{"ddb-cay", 0.0, 2},
                                           FluidOrderCase{"ddb-cay", 0.5, 1},
                                           FluidOrderCase{"ddb-cay", -0.5, 1},
                                           FluidOrderCase{"sddb-cay", 0.5, 2}),
                         [](const auto& info) {
                           const double a = info.param.alpha;
                           std::string name = std::string(info.param.method) +
                                              (a < 0 ? "_alpha_minus" : "_alpha_") +
                                              std::to_string(int(std::abs(a) * 10));
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(ZeitlinFluid, Rk4LeavesTheOrbitWhereDdbStaysOnIt) {
  const int n = 16;
  const auto fluid = makeZeitlinFluid(n, 0.5);
  const Matrix W0 = randomVorticity(n, 2);
  const Eigen::VectorXd spectrum0 = SUN::casimirs(W0);
  const double h = zeitlinStepFraction(W0, 0.2);
  for (const char* name : {"rk4", "ddb-cay"}) {
    auto method = makeMethod<SUN>(name, fluid);
    Matrix last;
    integrate(*method, W0, 0.0, h, 200, [&](long, double, const Matrix& W) { last = W; });
    const double drift = (SUN::casimirs(last) - spectrum0).norm() / spectrum0.norm();
    std::cout << name << " spectrum drift " << drift << "\n";
    if (std::string(name) == "rk4") {
      EXPECT_GT(drift, 1e-10);
    } else {
      EXPECT_LT(drift, 1e-13);
    }
  }
}

TEST(ZeitlinFluid, BadStatesAreRejectedWithTheirSizeAndWorstEntry) {
  const int n = 40;
  Matrix W = randomVorticity(n, 3);
  EXPECT_NO_THROW(SUN::requireState("W", W));
  Matrix hermitian = W;
  hermitian(3, 5) += 1.0;
  try {
    SUN::requireState("W", hermitian);
    FAIL() << "not skew-Hermitian accepted";
  } catch (const InvalidArgument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("40x40"), std::string::npos) << what;
    EXPECT_LT(what.size(), 300u) << what;
  }
  Matrix traced = W;
  traced.diagonal().array() += std::complex<double>(0, 0.1);
  EXPECT_THROW(SUN::requireState("W", traced), InvalidArgument);
  Matrix nan = W;
  nan(1, 1) = std::complex<double>(NAN, 0);
  EXPECT_THROW(SUN::requireState("W", nan), InvalidArgument);
  EXPECT_THROW(SUN::requireState("W", Matrix::Zero(1, 1)), InvalidArgument);
  EXPECT_THROW(makeZeitlinFluid(1, 0.5), InvalidArgument);
  EXPECT_THROW(makeZeitlinFluid(8, NAN), InvalidArgument);
}

}  // namespace zeitlin_tests
}  // namespace ddb::test
