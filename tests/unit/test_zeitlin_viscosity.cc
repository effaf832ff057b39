// Viscosity, hyperviscosity and drag of Zeitlin's fluid (systems/zeitlin_viscosity.h) by Strang
// splitting (integrators/methods/strang_splitting.h), against what the code did not use: the
// spherical-harmonic coefficients scaled one by one, the closed-form decay
// exp(−(ν (l(l + 1))^p + γ) t) of a steady flow, and a fitted order of 2 against Runge–Kutta on the
// whole vector field written here with a step 1/16 of the smallest.

#include <ddb/core/errors.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/strang_splitting.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/spherical_harmonic_degree_operator.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_viscosity.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "order_fit.h"

namespace ddb::test {
namespace zeitlin_viscosity_tests {

using Matrix = Eigen::MatrixXcd;

const ZeitlinHamiltonian& hamiltonianOf(const LiePoissonSystem<SUN>& fluid) {
  return dynamic_cast<const ZeitlinHamiltonian&>(fluid.hamiltonian());
}

std::unique_ptr<OneStepMethod<SUN>> split(const std::string& name,
                                          const std::shared_ptr<const LiePoissonSystem<SUN>>& fluid,
                                          const ZeitlinViscosity& viscosity) {
  const Eigen::Index n = hamiltonianOf(*fluid).laplacian().size();
  return std::make_unique<StrangSplitting<SUN>>(
      makeMethod<SUN>(name, fluid), std::make_unique<ZeitlinViscousFlow>(
                                        n, viscosity, hamiltonianOf(*fluid).planetaryVorticity()));
}

TEST(ZeitlinViscosity, TheDegreeFunctionScalesEveryCoefficient) {
  for (const Eigen::Index n : {2, 7, 16}) {
    const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
    const Matrix W = randomVorticity(n, 5);
    const Eigen::VectorXd factors = Eigen::VectorXd::LinSpaced(n, 1.0, 0.1).array().square();
    Eigen::VectorXd omega = basis.coefficients(W);
    for (Eigen::Index l = 0; l < n; ++l) {
      for (Eigen::Index m = -l; m <= l; ++m) {
        omega(SphericalHarmonicBasis::index(l, m)) *= factors(l);
      }
    }
    const Matrix expected = basis.matrix(omega);
    Matrix filtered = W;
    basis.applyDegreeFunction(factors, filtered);
    EXPECT_LT((filtered - expected).norm(), 1e-13 * W.norm()) << "N = " << n;
    // The kept operator (folded by the blocks' reversal symmetry), built for other factors first
    // and then given these.
    SphericalHarmonicDegreeOperator kept(basis, Eigen::VectorXd::Ones(n));
    kept.setFactors(basis, factors);
    Matrix applied = W;
    kept.apply(applied);
    EXPECT_LT((applied - expected).norm(), 1e-13 * W.norm()) << "N = " << n;
  }
}

// A share of the diagonals at a time (a rank's, DistributedZeitlinViscousFlow): each diagonal m
// and −m taken out as a vector, alone or as a pair, through the basis and through an operator that
// keeps only some blocks, against the coefficients scaled one by one.
TEST(ZeitlinViscosity, TheDegreeFunctionActsOnEachDiagonalAlone) {
  for (const Eigen::Index n : {2, 7, 16}) {
    const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
    const Matrix W = randomVorticity(n, 7);
    const Eigen::VectorXd factors = Eigen::VectorXd::LinSpaced(n, 0.2, 1.3);
    Eigen::VectorXd omega = basis.coefficients(W);
    for (Eigen::Index l = 0; l < n; ++l) {
      for (Eigen::Index m = -l; m <= l; ++m) {
        omega(SphericalHarmonicBasis::index(l, m)) *= factors(l);
      }
    }
    const Matrix expected = basis.matrix(omega);
    // The odd blocks kept, the even ones through the basis.
    std::vector<Eigen::Index> odd;
    for (Eigen::Index m = 1; m < n; m += 2) odd.push_back(m);
    SphericalHarmonicDegreeOperator kept(basis, factors, odd);
    SphericalHarmonicBasis::Workspace w(n);
    Matrix filtered = W;
    for (Eigen::Index m = 0; m < n; ++m) {
      Eigen::VectorXcd plus = filtered.diagonal(m), minus = filtered.diagonal(-m);
      // Diagonals 1 and −1 one at a time, the others as pairs (the main diagonal alone).
      const bool pair = m > 1;
      if (kept.kept(m)) {
        kept.applyToDiagonals(m, plus.data(), pair ? minus.data() : nullptr);
        if (m == 1) kept.applyToDiagonals(m, minus.data());
      } else {
        basis.applyDegreeFunctionToDiagonals(factors, m, plus.data(), pair ? minus.data() : nullptr,
                                             w);
      }
      filtered.diagonal(m) = plus;
      if (m > 0) filtered.diagonal(-m) = minus;
    }
    EXPECT_LT((filtered - expected).norm(), 1e-13 * W.norm()) << "N = " << n;
    EXPECT_FALSE(kept.kept(0));
    EXPECT_THROW(kept.applyToDiagonals(0, filtered.data()), InvalidArgument);
    EXPECT_THROW(SphericalHarmonicDegreeOperator(basis, factors, {n}), InvalidArgument);
  }
}

// f_l = −l(l + 1) is the Laplacian itself: the kept operator against HoppeYauLaplacian::apply's
// three-term formula (no eigenvector in it), at odd and even N (blocks of every length).
TEST(ZeitlinViscosity, TheKeptDegreeOperatorOfMinusLTimesLPlusOneIsTheLaplacian) {
  for (const Eigen::Index n : {2, 3, 8, 17, 40}) {
    const HoppeYauLaplacian laplacian(n);
    const SphericalHarmonicBasis basis(laplacian);
    Eigen::VectorXd factors(n);
    for (Eigen::Index l = 0; l < n; ++l) factors(l) = -double(l) * double(l + 1);
    SphericalHarmonicDegreeOperator kept(basis, factors);
    const Matrix W = randomVorticity(int(n), 11);
    Matrix expected(n, n);
    laplacian.apply(W, expected);
    Matrix applied = W;
    kept.apply(applied);
    EXPECT_LT((applied - expected).norm(), 1e-12 * expected.norm()) << "N = " << n;
  }
}

TEST(ZeitlinViscosity, ASteadyFlowDecaysByTheClosedForm) {
  // One degree l is steady for the Euler part ([P, W] = 0), zonal flows on the rotating sphere
  // too ([ψ, Q] = 0, all diagonal): the split step is then the decay alone, to rounding.
  const Eigen::Index n = 10;
  const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
  ZeitlinViscosity viscosity;
  viscosity.viscosity = 0.002;
  viscosity.order = 2;
  viscosity.drag = 0.05;
  struct Case {
    double rotation;
    Matrix W0;
    int l;
  };
  for (const Case& c : {Case{0.0, Matrix(basis.element(4, 3) + 0.5 * basis.element(4, -1)), 4},
                        Case{2.0, Matrix(basis.element(3, 0)), 3}}) {
    ZeitlinPhysics physics;
    physics.rotation = c.rotation;
    const auto fluid = makeZeitlinFluid(n, 0.0, physics);
    const Matrix& F = hamiltonianOf(*fluid).planetaryVorticity();
    // Methods that keep a steady state to rounding (ddb-cay keeps it to its Legendre solve's
    // tolerance, about 1e-7 here).
    for (const std::string name : {"ddb-exp", "sddb-exp", "rk4"}) {
      const auto method = split(name, fluid, viscosity);
      Matrix Q = c.W0 + F;
      const double h = 0.1;
      for (int k = 0; k < 20; ++k) method->advance(Q, k * h, h);
      const double rate = 0.002 * std::pow(c.l * (c.l + 1.0), 2) + 0.05;
      const Matrix expected = std::exp(-rate * 2.0) * c.W0;
      EXPECT_LT((Q - F - expected).norm(), 1e-12 * c.W0.norm())
          << name << ", rotation " << c.rotation;
      EXPECT_NE(method->name().find("+viscosity"), std::string::npos) << method->name();
    }
  }
}

// Ẇ of the whole model at Q: the Lie–Poisson field plus L(Q − F), L applied through the
// coefficients (not applyDegreeFunction).
Matrix wholeField(const LiePoissonSystem<SUN>& fluid, const SphericalHarmonicBasis& basis,
                  const ZeitlinViscosity& viscosity, const Matrix& F, const Matrix& Q) {
  Eigen::VectorXd omega = basis.coefficients(Q - F);
  for (Eigen::Index l = 0; l < basis.size(); ++l) {
    for (Eigen::Index m = -l; m <= l; ++m) {
      omega(SphericalHarmonicBasis::index(l, m)) *= -viscosity.rate(l);
    }
  }
  return fluid.vectorField(Q) + basis.matrix(omega);
}

TEST(ZeitlinViscosity, TheSplitStepIsSecondOrderOnANonlinearFlow) {
  const Eigen::Index n = 6;
  ZeitlinPhysics physics;
  physics.rotation = 1.0;
  const auto fluid = makeZeitlinFluid(n, 0.3, physics);
  const Matrix& F = hamiltonianOf(*fluid).planetaryVorticity();
  const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
  ZeitlinViscosity viscosity;
  viscosity.viscosity = 0.02;
  viscosity.drag = 0.1;
  const Matrix Q0 = randomVorticity(n, 9) + F;
  const double t_end = 1.0;
  // The reference: classical RK4 on the whole field, h = 1/1600.
  Matrix reference = Q0;
  const int reference_steps = 1600;
  const double r = t_end / reference_steps;
  const auto field = [&](const Matrix& Q) { return wholeField(*fluid, basis, viscosity, F, Q); };
  for (int k = 0; k < reference_steps; ++k) {
    const Matrix k1 = field(reference), k2 = field(reference + 0.5 * r * k1);
    const Matrix k3 = field(reference + 0.5 * r * k2), k4 = field(reference + r * k3);
    reference += (r / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  // The symmetric (second-order) DDB methods: ddb-cay's dissipative factor is first order in h.
  // The viscous flow exact, then by its implicit step (second order itself).
  for (const auto scheme : {ZeitlinViscousScheme::kExact, ZeitlinViscousScheme::kImplicit}) {
    viscosity.scheme = scheme;
    for (const std::string name : {"sddb-cay", "sddb-exp"}) {
      std::vector<double> steps, errors;
      for (const int count : {10, 20, 40, 80}) {
        const auto method = split(name, fluid, viscosity);
        const double h = t_end / count;
        Matrix Q = Q0;
        for (int k = 0; k < count; ++k) method->advance(Q, k * h, h);
        steps.push_back(h);
        errors.push_back((Q - reference).norm() / Q0.norm());
      }
      const OrderFit fit = fitOrder(steps, errors);
      EXPECT_EQ(fit.points, 4) << name;
      EXPECT_NEAR(fit.slope, 2.0, 0.2) << name;
    }
  }
}

// The implicit step multiplies each ω_lm by R(z) = 1/(1 + z + z²/2), z = (ν (l(l + 1))^p + γ) h:
// the coefficients scaled one by one (the transform, not the banded solve), on a rotating
// sphere, for Laplacian viscosity, hyperviscosity and a stiff case whose smallest scales' z is
// about 1e5 (R ≈ 2e-10 there: L-stable, every factor in (0, 1)). The step's rounding is about
// ε ‖hA‖ (forming (−Δ)^p; systems/zeitlin_implicit_viscous_step.h), hence the tolerance.
TEST(ZeitlinViscosity, TheImplicitStepScalesEachModeByItsRationalFactor) {
  struct Case {
    Eigen::Index n;
    double viscosity;
    int order;
    double drag, h;
  };
  for (const Case& c :
       {Case{2, 0.1, 1, 0.0, 0.3}, Case{7, 1e-2, 1, 0.05, 0.2}, Case{16, 1e-3, 2, 0.0, 0.1},
        Case{17, 1e-10, 5, 0.02, 0.5}, Case{16, 1.0, 2, 0.0, 2.0}}) {
    const SphericalHarmonicBasis basis{HoppeYauLaplacian(c.n)};
    ZeitlinViscosity v;
    v.viscosity = c.viscosity;
    v.order = c.order;
    v.drag = c.drag;
    v.scheme = ZeitlinViscousScheme::kImplicit;
    const Matrix F = zeitlinPlanetaryVorticity(c.n, 0.8);
    const Matrix W = randomVorticity(int(c.n), 13);
    Eigen::VectorXd omega = basis.coefficients(W);
    for (Eigen::Index l = 0; l < c.n; ++l) {
      const double z = v.rate(l) * c.h, factor = 1.0 / (1.0 + z + 0.5 * z * z);
      ASSERT_GT(factor, 0.0);
      ASSERT_LE(factor, 1.0);
      for (Eigen::Index m = -l; m <= l; ++m) omega(SphericalHarmonicBasis::index(l, m)) *= factor;
    }
    const Matrix expected = basis.matrix(omega) + F;
    const double tolerance = (1e-13 + 1e-15 * v.rate(c.n - 1) * c.h) * W.norm();
    ZeitlinViscousFlow flow(c.n, v, F);
    Matrix Q = W + F;
    flow.advance(Q, c.h);
    EXPECT_LT((Q - expected).norm(), tolerance) << "N = " << c.n << ", p = " << c.order;
    // A second step of the same h reuses the factors; one of another h makes them again.
    Matrix twice = W + F, other = W + F;
    flow.advance(twice, c.h);
    flow.advance(twice, c.h);
    flow.advance(other, 2 * c.h);
    Eigen::VectorXd twice_omega = basis.coefficients(W), other_omega = basis.coefficients(W);
    for (Eigen::Index l = 0; l < c.n; ++l) {
      const double z = v.rate(l) * c.h, z2 = 2 * z;
      const double once = 1.0 / (1.0 + z + 0.5 * z * z), doubled = 1.0 / (1.0 + z2 + 0.5 * z2 * z2);
      for (Eigen::Index m = -l; m <= l; ++m) {
        twice_omega(SphericalHarmonicBasis::index(l, m)) *= once * once;
        other_omega(SphericalHarmonicBasis::index(l, m)) *= doubled;
      }
    }
    EXPECT_LT((twice - F - basis.matrix(twice_omega)).norm(), 2 * tolerance) << "N = " << c.n;
    EXPECT_LT((other - F - basis.matrix(other_omega)).norm(), 2 * tolerance) << "N = " << c.n;
  }
}

TEST(ZeitlinViscosity, BadParametersAreRefusedNamingThem) {
  const auto refused = [](const ZeitlinViscosity& viscosity, const std::string& parameter) {
    try {
      ZeitlinViscousFlow flow(4, viscosity);
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(parameter + " = ", 0), 0u) << e.what();
      return;
    }
    ADD_FAILURE() << parameter << " accepted";
  };
  ZeitlinViscosity v;
  v.viscosity = -1e-3;
  refused(v, "viscosity");
  v.viscosity = std::nan("");
  refused(v, "viscosity");
  v = ZeitlinViscosity{};
  v.order = 0;
  refused(v, "order");
  v = ZeitlinViscosity{};
  v.drag = -0.1;
  refused(v, "drag");
  v.drag = INFINITY;
  refused(v, "drag");
}

}  // namespace zeitlin_viscosity_tests
}  // namespace ddb::test
