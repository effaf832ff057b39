// Zeitlin's fluid on a rotating sphere and in quasi-geostrophic flow
// (systems/zeitlin_hamiltonian.h, docs/reference/conventions.md §2), each property against
// something the library did not use to compute it: the spherical harmonics' eigenvalues (closed
// form), the Rossby–Haurwitz wave's westward drift at 2Ω/(l(l + 1) + κ²), which is exact in
// Zeitlin's model for every N (the vector field at the wave equals the rotation's, and a method's
// error after a period falls at the method's order), central differences of H, Eigen's eigensolver
// for the Casimirs.

#include <ddb/core/errors.h>
#include <ddb/integrators/drivers/relax.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "order_fit.h"

namespace ddb::test {
namespace zeitlin_rotation_tests {

using Matrix = Eigen::MatrixXcd;

ZeitlinPhysics physicsOf(double rotation, double kappa_squared) {
  ZeitlinPhysics physics;
  physics.rotation = rotation;
  if (kappa_squared > 0) physics.deformation_radius = 1.0 / std::sqrt(kappa_squared);
  return physics;
}

const ZeitlinHamiltonian& hamiltonianOf(const LiePoissonSystem<SUN>& fluid) {
  return dynamic_cast<const ZeitlinHamiltonian&>(fluid.hamiltonian());
}

// The spectrum of the Hermitian −iQ, ascending: the Casimirs.
Eigen::VectorXd spectrum(const Matrix& Q) {
  const Matrix hermitian = std::complex<double>(0, -1) * Q;
  return Eigen::SelfAdjointEigenSolver<Matrix>(hermitian, Eigen::EigenvaluesOnly).eigenvalues();
}

// A Rossby–Haurwitz wave's relative vorticity: a real combination of T_lm and T_l,−m.
Matrix rossbyHaurwitzWave(const SphericalHarmonicBasis& basis, int l, int m) {
  return basis.element(l, m) + 0.6 * basis.element(l, -m);
}

// The wave W0 rotated about the axis by the angle βt = c t: U W0 Uᴴ, U = diag(e^{i j c t}) (the
// generator of rotations about the axis is X₃ = ħ i diag(j − (N−1)/2); its constant part drops).
Matrix rotated(const Matrix& W0, double angle) {
  const Eigen::Index n = W0.rows();
  Eigen::VectorXcd u(n);
  for (Eigen::Index j = 0; j < n; ++j) u(j) = std::polar(1.0, double(j) * angle);
  return u.asDiagonal() * W0 * u.conjugate().asDiagonal();
}

TEST(ZeitlinRotation, PlanetaryVorticityIsTwiceOmegaTimesTheQuantisedCosine) {
  // cos θ = Y_10/√3 and T_10 is the quantised Y_10 (the basis's eigenvector, not the formula).
  for (const Eigen::Index n : {2, 5, 16}) {
    const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
    const double rotation = -0.7;
    const Matrix expected = (2.0 * rotation / std::sqrt(3.0)) * basis.element(1, 0);
    const Matrix F = zeitlinPlanetaryVorticity(n, rotation);
    EXPECT_LT((F - expected).norm(), 1e-13 * expected.norm()) << "N = " << n;
  }
}

TEST(ZeitlinRotation, TheHelmholtzSolveInvertsDeltaMinusKappaSquaredOnEverySphericalHarmonic) {
  const Eigen::Index n = 9;
  const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
  for (const double kappa_squared : {0.0, 0.3, 4.0}) {
    const HoppeYauLaplacian helmholtz(n, kappa_squared);
    for (int l = 1; l < n; ++l) {
      for (int m = -l; m <= l; ++m) {
        const Matrix T = basis.element(l, m);
        Matrix solved;
        helmholtz.solve(T, solved);
        const Matrix expected = -T / (double(l * (l + 1)) + kappa_squared);
        EXPECT_LT((solved - expected).norm(), 1e-13 * expected.norm())
            << "kappa^2 = " << kappa_squared << ", (l, m) = (" << l << ", " << m << ")";
        Matrix back;
        helmholtz.apply(solved, back);
        EXPECT_LT((back - T).norm(), 1e-12 * T.norm());
      }
    }
  }
}

TEST(ZeitlinRotation, RossbyHaurwitzWaveDriftsWestwardAtTheExactSpeedForEveryN) {
  // At α = 0 the vector field at Q = W0 + F is the rotation's: Q̇ = d/dt (U W0 Uᴴ) at t = 0
  // = i c [diag(j), W0], c = 2Ω/(l(l + 1) + κ²): the wave travels against the sphere's rotation.
  for (const Eigen::Index n : {5, 8, 16, 33}) {
    const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
    for (const auto& [l, m] : {std::pair{1, 1}, {2, 1}, {3, 2}, {4, 4}}) {
      for (const double kappa_squared : {0.0, 2.5}) {
        for (const double rotation : {1.5, -0.7}) {
          const auto fluid = makeZeitlinFluid(n, 0.0, physicsOf(rotation, kappa_squared));
          const Matrix W0 = rossbyHaurwitzWave(basis, l, m);
          const Matrix Q0 = W0 + hamiltonianOf(*fluid).planetaryVorticity();
          const double c = 2.0 * rotation / (double(l * (l + 1)) + kappa_squared);
          Eigen::VectorXcd j = Eigen::VectorXcd::LinSpaced(n, 0.0, double(n - 1));
          const Matrix expected =
              std::complex<double>(0, c) * (j.asDiagonal() * W0 - W0 * j.asDiagonal());
          const Matrix field = fluid->vectorField(Q0);
          EXPECT_LT((field - expected).norm(), 1e-13 * expected.norm())
              << "N = " << n << ", (l, m) = (" << l << ", " << m << "), kappa^2 = " << kappa_squared
              << ", Omega = " << rotation;
        }
      }
    }
  }
}

TEST(ZeitlinRotation, MethodsFollowTheRossbyHaurwitzWaveAtTheirOrderAndKeepQsSpectrum) {
  // One period of the drift, 2π/(m c), against the rotated wave; the fitted order over four
  // step sizes (the DDB methods are second order, so the wave is exact in the model, not in
  // their steps: the moduli |W_ij|, which a rotation keeps, move at O(h²)).
  const Eigen::Index n = 8;
  const int l = 3, m = 2;
  const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
  const Matrix W0 = rossbyHaurwitzWave(basis, l, m);
  for (const double kappa_squared : {0.0, 4.0}) {
    const auto fluid = makeZeitlinFluid(n, 0.0, physicsOf(1.5, kappa_squared));
    const Matrix& F = hamiltonianOf(*fluid).planetaryVorticity();
    const double c = 2.0 * 1.5 / (double(l * (l + 1)) + kappa_squared);
    const double period = 2.0 * M_PI / (m * c);
    for (const auto& [name, order] : {std::pair<std::string, double>{"ddb-cay", 2.0},
                                      {"ddb-exp", 2.0},
                                      {"sddb-cay", 2.0},
                                      {"rk4", 4.0}}) {
      std::vector<double> steps, errors;
      for (const double h : {0.2, 0.1, 0.05, 0.025}) {
        auto method = makeMethod<SUN>(name, fluid);
        const long count = std::lround(period / h);
        Matrix Q = W0 + F;
        for (long k = 0; k < count; ++k) method->advance(Q, double(k) * h, h);
        const Matrix exact = rotated(W0, c * double(count) * h);
        steps.push_back(h);
        errors.push_back((Q - F - exact).norm() / W0.norm());
        if (name != "rk4") {
          const Eigen::VectorXd before = spectrum(W0 + F), after = spectrum(Q);
          EXPECT_LT((after - before).norm(), 1e-12 * before.norm()) << name << ", h = " << h;
        }
      }
      const OrderFit fit = fitOrder(steps, errors);
      EXPECT_EQ(fit.points, 4) << name;
      EXPECT_NEAR(fit.slope, order, 0.2) << name << ", kappa^2 = " << kappa_squared;
    }
  }
}

TEST(ZeitlinRotation, EnergyOfAHarmonicAndTheGradientAgainstCentralDifferences) {
  const Eigen::Index n = 10;
  const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
  for (const double kappa_squared : {0.0, 1.7}) {
    const auto fluid = makeZeitlinFluid(n, 0.0, physicsOf(0.9, kappa_squared));
    const ZeitlinHamiltonian& H = hamiltonianOf(*fluid);
    // H = ‖W‖²/(2ħ(l(l + 1) + κ²)) for W = T_lm: ψ = −W/(l(l + 1) + κ²).
    const Matrix W = basis.element(4, -3);
    const double expected = W.squaredNorm() / (2.0 * H.hbar() * (20.0 + kappa_squared));
    const Matrix Q = W + H.planetaryVorticity();
    EXPECT_NEAR(H.value(Q), expected, 1e-13 * expected);
    // ⟨∂H/∂Q, V⟩ = d/dε H(Q + εV), pairing Re tr(AᴴB).
    const Matrix R = randomVorticity(n, 3) + H.planetaryVorticity();
    const Matrix V = randomVorticity(n, 4);
    const double eps = 1e-5;
    const double difference = (H.value(R + eps * V) - H.value(R - eps * V)) / (2 * eps);
    const double pairing = (H.gradient(R).adjoint() * V).trace().real();
    EXPECT_NEAR(pairing, difference, 1e-7 * std::abs(difference));
  }
}

TEST(ZeitlinRotation, TheDoubleBracketRelaxesOnTheRotatingSphereAndKeepsQsSpectrum) {
  // α > 0: the energy falls at every step and Q's spectrum stays; the Newton search then stops at
  // a steady state of the rotating flow (r ≤ the tolerance), a critical point of H on Q's orbit.
  const Eigen::Index n = 6;
  const auto fluid = makeZeitlinFluid(n, 0.5, physicsOf(2.0, 0.0));
  const Matrix Q0 = randomVorticity(n, 21) + hamiltonianOf(*fluid).planetaryVorticity();
  auto method = makeMethod<SUN>("ddb-cay", fluid);
  const Eigen::VectorXd before = spectrum(Q0);
  double energy = fluid->energy(Q0);
  Matrix Q = Q0;
  for (int k = 0; k < 2000; ++k) {
    method->advance(Q, 0.02 * k, 0.02);
    const double next = fluid->energy(Q);
    ASSERT_LE(next, energy + 1e-14 * std::abs(energy)) << "step " << k;
    energy = next;
  }
  EXPECT_LT((spectrum(Q) - before).norm(), 1e-12 * before.norm());

  // To a steady state: the Newton search on Q's orbit from the relaxed state (integrating the
  // slow modes' last digits takes long).
  RelaxOptions newton;
  newton.newton = true;
  newton.tolerance = 1e-11;
  newton.max_steps = 50;
  const RelaxResult<SUN> search =
      relaxByNewton(*fluid, Q, newton, [](const RelaxState&, const Matrix&) {});
  ASSERT_TRUE(search.steady()) << relaxStopName(search.stop) << ", r = " << search.last.residual
                               << " " << search.failure;
  EXPECT_LE(search.last.energy, energy);
  EXPECT_LT((spectrum(search.final) - before).norm(), 1e-12 * before.norm());
  // Steady on the rotating sphere: ψ = Δ⁻¹(Q − F) commutes with Q.
  const Matrix psi = hamiltonianOf(*fluid).streamMatrix(search.final);
  EXPECT_LT((psi * search.final - search.final * psi).norm(),
            1e-9 * psi.norm() * search.final.norm());
  // ... and not one of the resting sphere's: there ψ would be Δ⁻¹Q.
  const Matrix resting = ZeitlinHamiltonian(n).streamMatrix(search.final);
  EXPECT_GT((resting * search.final - search.final * resting).norm(),
            1e-3 * resting.norm() * search.final.norm());
}

TEST(ZeitlinRotation, BadPhysicsIsRefusedNamingTheParameter) {
  const auto refused = [](const ZeitlinPhysics& physics, const std::string& parameter) {
    try {
      makeZeitlinFluid(6, 0.1, physics);
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(parameter + " = ", 0), 0u) << e.what();
      return;
    }
    ADD_FAILURE() << parameter << " accepted";
  };
  refused(physicsOf(std::nan(""), 0.0), "rotation");
  refused(physicsOf(INFINITY, 0.0), "rotation");
  for (const double radius : {0.0, -1.0, std::nan("")}) {
    ZeitlinPhysics physics;
    physics.deformation_radius = radius;
    refused(physics, "deformation_radius");
  }
}

}  // namespace zeitlin_rotation_tests
}  // namespace ddb::test
