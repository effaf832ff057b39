// Systems a user writes on the matrix groups by subclassing Hamiltonian<G>
// (docs/guide/defining-a-system.md; docs/reference/conventions.md §2, "Systems on matrix
// groups"): the system hands the Hamiltonian an element of the algebra and projects the ξ it
// returns, so how a user writes H off the algebra does not change a trajectory, and the default
// hessianTimes serves Newton–Krylov.
#include <ddb/integrators/methods/ddb.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <Eigen/QR>
#include <complex>
#include <iostream>
#include <memory>

#include "test_support.h"

namespace ddb::test {
namespace user_systems_tests {

using Matrix = Eigen::MatrixXcd;
using C = std::complex<double>;

// H(μ) = ½ Re tr(μᴴ (c ∘ μ)) + (β/4)‖μᴴμ‖²_F, c_ij = 1/(J_i + J_j): a weighted quadratic
// part and a quartic one, ∂H/∂μ = c ∘ μ + β μ μᴴ μ for the pairing Re tr(AᴴB).
// How the user writes it: on the argument as given (naive), on its traceless part
// (careful), with the gradient returned through the skew projection (X − Xᴴ)/2 (skew),
// with or without the Hessian's formula.
struct QuarticStyle {
  bool traceless_argument = false;
  bool skew_projected_gradient = false;
};

class QuarticHamiltonian final : public Hamiltonian<SUN> {
 public:
  QuarticHamiltonian(const Eigen::VectorXd& J, double beta, QuarticStyle style)
      : beta_(beta), style_(style) {
    const Eigen::Index n = J.size();
    c_.resize(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j) c_(i, j) = 1.0 / (J(i) + J(j));
  }
  double value(const Matrix& mu) const override {
    const Matrix q = argument(mu);
    return 0.5 * (q.adjoint() * c_.cwiseProduct(q)).trace().real() +
           0.25 * beta_ * (q.adjoint() * q).squaredNorm();
  }
  Matrix gradient(const Matrix& mu) const override {
    const Matrix q = argument(mu);
    const Matrix x = c_.cwiseProduct(q) + beta_ * q * q.adjoint() * q;
    if (style_.skew_projected_gradient) return (x - x.adjoint()) / 2.0;
    return x;
  }
  // hessianTimes is not written: the default (a central difference) serves.

 private:
  Matrix argument(const Matrix& mu) const {
    Matrix q = mu;
    if (style_.traceless_argument) q.diagonal().array() -= mu.trace() / double(mu.rows());
    return q;
  }
  Matrix c_;
  double beta_;
  QuarticStyle style_;
};

// The same H with its Hessian's formula, δ(∂H/∂μ) = c ∘ v + β(v μᴴμ + μ vᴴ μ + μ μᴴ v).
class QuarticWithHessian final : public Hamiltonian<SUN> {
 public:
  QuarticWithHessian(const Eigen::VectorXd& J, double beta)
      : plain_(J, beta, QuarticStyle{}), beta_(beta), J_(J) {}
  double value(const Matrix& mu) const override { return plain_.value(mu); }
  Matrix gradient(const Matrix& mu) const override { return plain_.gradient(mu); }
  Matrix hessianTimes(const Matrix& mu, const Matrix& v) const override {
    Matrix c(mu.rows(), mu.cols());
    for (Eigen::Index i = 0; i < c.rows(); ++i)
      for (Eigen::Index j = 0; j < c.cols(); ++j) c(i, j) = 1.0 / (J_(i) + J_(j));
    return c.cwiseProduct(v) +
           beta_ * (v * mu.adjoint() * mu + mu * v.adjoint() * mu + mu * mu.adjoint() * v);
  }

 private:
  QuarticHamiltonian plain_;
  double beta_;
  Eigen::VectorXd J_;
};

const Eigen::Vector3d kJ(0.3, 0.7, 1.1);
constexpr double kBeta = 0.4;

std::shared_ptr<const LiePoissonSystem<SUN>> quartic(QuarticStyle style, double alpha) {
  return makeLiePoissonSystem("quartic",
                              std::make_shared<const QuarticHamiltonian>(kJ, kBeta, style),
                              std::make_shared<const ScaledIdentityMetric<SUN>>(alpha));
}

// U diag(iλ) Uᴴ with U Haar-random: in su(3) to rounding only, as a user's state usually is.
Matrix initialState() {
  const Matrix U = randomUnitary(3, 5);
  const Eigen::Vector3cd lambda(C(0, -0.9), C(0, 0.2), C(0, 0.7));
  return U * lambda.asDiagonal() * U.adjoint();
}

TEST(ProjectToAlgebra, IsTheOrthogonalProjectionOntoSuNAndSoN) {
  Sampler s(41);
  for (int n : {2, 3, 5}) {
    Matrix X(n, n), Y(n, n);
    for (Eigen::Index i = 0; i < X.size(); ++i) {
      X(i) = C(s.uniform(), s.uniform());
      Y(i) = C(s.uniform(), s.uniform());
    }
    Matrix P = X;
    SUN::projectToAlgebra(P);
    EXPECT_EQ((P + P.adjoint()).norm(), 0.0);  // skew-Hermitian bit for bit
    EXPECT_LT(std::abs(P.trace()), 1e-15);
    Matrix Q = P;
    SUN::projectToAlgebra(Q);
    EXPECT_LT((Q - P).norm(), 1e-15);  // idempotent
    // X − PX is orthogonal to su(N) (an element Y − Yᴴ − (tr(Y − Yᴴ)/N) I of it).
    Matrix Z = Y - Y.adjoint();
    Z.diagonal().array() -= Z.trace() / double(n);
    EXPECT_LT(std::abs(((X - P).adjoint() * Z).trace().real()), 1e-14);
    Eigen::MatrixXd R = X.real(), S = R;
    SON::projectToAlgebra(S);
    EXPECT_EQ((S + S.transpose()).norm(), 0.0);
    EXPECT_LT((S - (R - R.transpose()) / 2.0).norm(), 1e-15);
  }
}

// A user who writes H by its formula on the argument and one who writes it on the traceless
// part give the same DDB Cayley trajectory: the Legendre unknown's trace stays in the solve.
TEST(UserSystems, NaiveAndCarefulQuarticHamiltoniansGiveTheSameDdbTrajectory) {
  const Matrix W0 = initialState();
  for (double alpha : {0.0, 0.5}) {
    Ddb<Cayley<SUN>> naive(quartic({false, false}, alpha), Cayley<SUN>(),
                           LegendreForm::kHamiltonian);
    Ddb<Cayley<SUN>> careful(quartic({true, false}, alpha), Cayley<SUN>(),
                             LegendreForm::kHamiltonian);
    Matrix x = W0, y = W0;
    double worst = 0.0;
    for (int k = 0; k < 200; ++k) {
      naive.advance(x, 0.05 * k, 0.05);
      careful.advance(y, 0.05 * k, 0.05);
      worst = std::max(worst, (x - y).norm() / W0.norm());
    }
    std::cout << "alpha " << alpha << ": naive vs careful, max relative difference " << worst
              << "\n";
    EXPECT_LT(worst, 1e-13) << alpha;
  }
}

// ∂H/∂μ returned as (X − Xᴴ)/2 does not remove the Hermitian part of a state that is in su(N)
// to rounding only; the double bracket amplifies that part (for iμ the bracket's sign flips).
// The vector field is projected onto su(N), so explicit states stay there to t = 100.
TEST(UserSystems, SkewProjectedGradientStaysOnTheAlgebraWithRk4AndTheReference) {
  const Matrix W0 = initialState();
  const auto system = quartic({false, true}, 0.5);
  for (const char* name : {"rk4", "reference"}) {
    auto method = makeMethod<SUN>(name, system);
    Matrix last;
    integrate(*method, W0, 0.0, 0.05, 2000, [&](long, double, const Matrix& W) { last = W; });
    const double hermitian = (last + last.adjoint()).norm(), trace = std::abs(last.trace());
    std::cout << name << " at t = 100: |mu + mu^H| = " << hermitian << ", |tr mu| = " << trace
              << ", |mu| = " << last.norm() << "\n";
    ASSERT_TRUE(last.allFinite()) << name;
    EXPECT_LT(hermitian, 1e-14 * W0.norm()) << name;
    EXPECT_LT(trace, 1e-12 * W0.norm()) << name;
    // Proposition 3.3: the energy falls (and the Frobenius norm, a Casimir, barely moves).
    EXPECT_LT(system->energy(last), system->energy(W0)) << name;
    EXPECT_NEAR(last.norm(), W0.norm(), 1e-6) << name;
  }
}

// The default hessianTimes (a central difference of the gradient) against the formula.
TEST(UserSystems, DefaultHessianTimesMatchesTheFormula) {
  const QuarticHamiltonian plain(kJ, kBeta, QuarticStyle{});
  const QuarticWithHessian exact(kJ, kBeta);
  const Matrix mu = initialState();
  Sampler s(42);
  for (int i = 0; i < 5; ++i) {
    Matrix v(3, 3);
    for (Eigen::Index k = 0; k < v.size(); ++k) v(k) = C(s.uniform(), s.uniform());
    SUN::projectToAlgebra(v);
    const Matrix reference = exact.hessianTimes(mu, v);
    EXPECT_LT((plain.hessianTimes(mu, v) - reference).norm(), 1e-8 * reference.norm());
  }
}

// Newton–Krylov on the DDB Legendre equation converges with the default hessianTimes and
// gives the fixed point's trajectory; Newton with the formula's Hessian gives it too.
TEST(UserSystems, NewtonKrylovConvergesWithTheDefaultHessianTimes) {
  const Matrix W0 = initialState();
  const auto metric = std::make_shared<const ScaledIdentityMetric<SUN>>(0.5);
  const auto fd = makeLiePoissonSystem(
      "quartic", std::make_shared<const QuarticHamiltonian>(kJ, kBeta, QuarticStyle{}), metric);
  const auto formula = makeLiePoissonSystem(
      "quartic", std::make_shared<const QuarticWithHessian>(kJ, kBeta), metric);
  Ddb<Cayley<SUN>> fixed(fd, Cayley<SUN>(), LegendreForm::kHamiltonian);
  Ddb<Cayley<SUN>> newton(fd, Cayley<SUN>(), LegendreForm::kHamiltonian);
  Ddb<Cayley<SUN>> exact(formula, Cayley<SUN>(), LegendreForm::kHamiltonian);
  fixed.legendreSolver().setStrategy(MatrixLegendreStrategy::kFixedPoint);
  newton.legendreSolver().setStrategy(MatrixLegendreStrategy::kNewtonKrylov);
  exact.legendreSolver().setStrategy(MatrixLegendreStrategy::kNewtonKrylov);
  Matrix x = W0, y = W0, z = W0;
  int newton_steps = 0;
  for (int k = 0; k < 50; ++k) {
    fixed.advance(x, 0.2 * k, 0.2);
    newton.advance(y, 0.2 * k, 0.2);
    exact.advance(z, 0.2 * k, 0.2);
    newton_steps += newton.legendreSolver().stats().newton;
  }
  EXPECT_GT(newton_steps, 0);
  EXPECT_LT((x - y).norm(), 1e-12 * W0.norm());
  EXPECT_LT((z - y).norm(), 1e-12 * W0.norm());
}

// docs/guide/defining-a-system.md's example: a quadratic H on SO(4) with weights that are not
// Manakov's, damped by a weighted metric. RK4 agrees with RK4 written here on
// Ṁ = [M, Ω + α w ∘ [M, Ω]], Ω = c ∘ M; DDB keeps the spectrum and lowers the energy at every step.
class WeightedBody final : public Hamiltonian<SON> {
 public:
  explicit WeightedBody(Eigen::MatrixXd c) : c_(std::move(c)) {}
  double value(const Eigen::MatrixXd& M) const override {
    return 0.5 * M.cwiseProduct(c_.cwiseProduct(M)).sum();
  }
  Eigen::MatrixXd gradient(const Eigen::MatrixXd& M) const override { return c_.cwiseProduct(M); }

 private:
  Eigen::MatrixXd c_;
};

class WeightedMetric final : public DissipationMetric<SON> {
 public:
  WeightedMetric(double alpha, Eigen::MatrixXd w) : alpha_(alpha), w_(std::move(w)) {}
  Eigen::MatrixXd sharp(const Eigen::MatrixXd& mu) const override {
    return alpha_ * w_.cwiseProduct(mu);
  }

 private:
  double alpha_;
  Eigen::MatrixXd w_;
};

TEST(UserSystems, WeightedBodyOnSO4AgreesWithAnIndependentRk4) {
  Sampler s(43);
  Eigen::MatrixXd c(4, 4), w(4, 4), a(4, 4);
  for (Eigen::Index i = 0; i < 16; ++i) {
    c(i) = 1.5 + s.uniform();
    w(i) = 1.0 + s.uniform();
    a(i) = s.uniform();
  }
  c = (c + c.transpose()).eval() / 2.0;
  w = (w + w.transpose()).eval() / 2.0;
  const Eigen::MatrixXd M0 = a - a.transpose();
  const double alpha = 0.5, h = 0.05;
  auto so4 = makeLiePoissonSystem("weighted-so4", std::make_shared<const WeightedBody>(c),
                                  std::make_shared<const WeightedMetric>(alpha, w));
  const auto field = [&](const Eigen::MatrixXd& M) -> Eigen::MatrixXd {
    const Eigen::MatrixXd omega = c.cwiseProduct(M);
    const Eigen::MatrixXd forced = omega + alpha * w.cwiseProduct(M * omega - omega * M);
    return M * forced - forced * M;
  };
  auto rk4 = makeMethod<SON>("rk4", so4);
  Eigen::MatrixXd x = M0, y = M0;
  for (int k = 0; k < 200; ++k) {
    rk4->advance(x, h * k, h);
    const Eigen::MatrixXd k1 = field(y), k2 = field(y + h / 2 * k1), k3 = field(y + h / 2 * k2),
                          k4 = field(y + h * k3);
    y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  EXPECT_LT((x - y).norm(), 1e-13 * M0.norm());

  auto ddb = makeMethod<SON>("ddb-cay", so4);
  const Eigen::VectorXd spectrum0 = SON::casimirs(M0);
  Eigen::MatrixXd M = M0;
  double energy = so4->energy(M0);
  for (int k = 0; k < 200; ++k) {
    ddb->advance(M, h * k, h);
    EXPECT_LE(so4->energy(M), energy * (1 + 1e-15)) << "step " << k;
    energy = so4->energy(M);
  }
  EXPECT_LT((SON::casimirs(M) - spectrum0).norm(), 1e-13 * spectrum0.norm());
  EXPECT_LT(energy, so4->energy(M0));
}

}  // namespace user_systems_tests
}  // namespace ddb::test
