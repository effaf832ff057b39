// The core library's (ddb::ddb) public C++ names and headers that README.md and docs/guide/*.md
// show, each used so that removing or renaming one fails the build before a user's program does
// (tests/checks/check_public_names.py keeps the list complete). No main(): the compile is the test.

// Every header the docs show, as <ddb/...> or as a path of the library's folders.
#include <ddb/core/autodiff.h>
#include <ddb/core/dissipation_metric.h>
#include <ddb/core/dual_eigenbasis.h>
#include <ddb/core/dual_matrix.h>
#include <ddb/core/group_traits.h>
#include <ddb/core/lagrangian.h>
#include <ddb/core/lie_group.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/core/openblas_kernels.h>
#include <ddb/core/smooth_function.h>
#include <ddb/core/solver_options.h>
#include <ddb/core/thread_pool.h>
#include <ddb/ddb.h>
#include <ddb/groups/direct_product.h>
#include <ddb/groups/dual_number_sun.h>
#include <ddb/groups/se2.h>
#include <ddb/groups/se3.h>
#include <ddb/groups/semidirect_product.h>
#include <ddb/groups/so2.h>
#include <ddb/groups/so3.h>
#include <ddb/groups/son.h>
#include <ddb/groups/special_euclidean.h>
#include <ddb/groups/special_orthogonal.h>
#include <ddb/groups/sun.h>
#include <ddb/groups/swapped_parts_metric.h>
#include <ddb/integrators/drivers/energy_step_control.h>
#include <ddb/integrators/drivers/integrate.h>
#include <ddb/integrators/drivers/relax.h>
#include <ddb/integrators/drivers/run.h>
#include <ddb/integrators/drivers/steady_state_probe.h>
#include <ddb/integrators/matrix_kernels/matrix_conjugation.h>
#include <ddb/integrators/matrix_kernels/matrix_retraction.h>
#include <ddb/integrators/methods/ddb.h>
#include <ddb/integrators/methods/linearly_implicit_ddb.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/one_step_method.h>
#include <ddb/integrators/methods/reference.h>
#include <ddb/integrators/methods/strang_splitting.h>
#include <ddb/integrators/methods/symmetric_ddb.h>
#include <ddb/integrators/solvers/correction_predictor.h>
#include <ddb/integrators/solvers/legendre.h>
#include <ddb/integrators/solvers/legendre_equation.h>
#include <ddb/integrators/solvers/matrix_legendre.h>
#include <ddb/integrators/solvers/orbit_newton.h>
#include <ddb/integrators/solvers/orbit_preconditioner.h>
#include <ddb/systems/body_inertia.h>
#include <ddb/systems/heavy_top.h>
#include <ddb/systems/kirchhoff.h>
#include <ddb/systems/manakov_body.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/planar_kirchhoff.h>
#include <ddb/systems/rigid_body.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/spherical_harmonic_degree_operator.h>
#include <ddb/systems/spherical_harmonic_grid.h>
#include <ddb/systems/zeitlin_exact_flows.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_forcing.h>
#include <ddb/systems/zeitlin_implicit_viscous_step.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_mhd.h>
#include <ddb/systems/zeitlin_spectra.h>
#include <ddb/systems/zeitlin_step_size.h>
#include <ddb/systems/zeitlin_viscosity.h>

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

// Marks its arguments used: functions' addresses, member pointers, values.
template <class... T>
void use(const T&...) {}

using Vec3 = Eigen::Vector3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using ddb::SE3;
using ddb::SO3;
using ddb::SON;
using ddb::SUN;
template <class G>
using Dual = typename G::template Dual<double>;
template <class G>
using System = ddb::LiePoissonSystem<G>;
template <class G>
using SystemPtr = std::shared_ptr<const ddb::LiePoissonSystem<G>>;
template <class G>
using MethodPtr = std::unique_ptr<ddb::OneStepMethod<G>>;
template <class G>
using Observer = void (*)(long, double, const Dual<G>&);
template <class G>
using RelaxSink = void (*)(const ddb::RelaxState&, const Dual<G>&);
// The two overloads of makeMethod<G>: by name and by table entry.
template <class G>
using MakeMethodByName = MethodPtr<G> (*)(std::string_view, SystemPtr<G>);
template <class G>
using MakeMethodByEntry = MethodPtr<G> (*)(const ddb::MethodInfo&, SystemPtr<G>);
template <class G>
using Integrate = void (*)(ddb::OneStepMethod<G>&, const Dual<G>&, double, double, long,
                           Observer<G>&&);

// README.md
[[maybe_unused]] void readmeCpp() {
  auto body = ddb::makeRigidBody({1.0, 1.3, 0.5}, /*alpha=*/0.5);
  auto method = ddb::makeMethod<ddb::SO3>("ddb-cay", body);
  const Eigen::Vector3d m0(0.0, 0.065, 0.5);
  double energy = 0.0, norm = 0.0;
  ddb::integrate(*method, m0, 0.0, /*h=*/0.1, /*steps=*/300,
                 [&](long k, double, const Eigen::Vector3d& m) {
                   if (k % 100 == 0) {
                     energy = body->energy(m);
                     norm = m.norm();
                   }
                 });
  use(energy, norm);
}
[[maybe_unused]] void readmeNames() {
  use(static_cast<SystemPtr<SO3> (*)(const Vec3&, double)>(&ddb::makeRigidBody),
      static_cast<MakeMethodByName<SO3>>(&ddb::makeMethod<SO3>),
      static_cast<Integrate<SO3>>(&ddb::integrate<SO3, Observer<SO3>>),
      static_cast<double (System<SO3>::*)(const Vec3&) const>(&System<SO3>::energy));
}

// docs/guide/getting-started.md: <ddb/ddb.h>, or a per-concept header such as <ddb/groups/so3.h>.
static_assert(std::is_same_v<ddb::SO3::Dual<double>, Eigen::Vector3d>);

// docs/guide/defining-a-system.md
class MyBody : public ddb::AutoDiffLagrangian<MyBody, ddb::SO3> {
 public:
  template <class T>
  T evaluate(const Eigen::Matrix<T, 3, 1>& w) const {
    return ddb::constant<T>(0.5) *
           (w(0) * w(0) + ddb::constant<T>(2.0) * w(1) * w(1) + w(2) * w(2));
  }
};
static_assert(std::is_base_of_v<ddb::Lagrangian<SO3>, MyBody>);
static_assert(std::is_same_v<MyBody::Domain, Vec3> && std::is_same_v<MyBody::Codomain, Vec3>);
static_assert(MyBody::kDim == 3);

class MyHamiltonian final : public ddb::AutoDiffHamiltonian<MyHamiltonian, ddb::SE3> {
 public:
  template <class T>
  T evaluate(const Eigen::Matrix<T, 6, 1>& mu) const {
    T sum = ddb::constant<T>(0.0);
    for (int i = 0; i < 6; ++i) sum += mu(i) * mu(i);
    return ddb::constant<T>(0.5) * sum;
  }
};
static_assert(std::is_base_of_v<ddb::Hamiltonian<SE3>, MyHamiltonian>);

class StiffeningBody : public ddb::AutoDiffLagrangian<StiffeningBody, ddb::SO3> {
 public:
  StiffeningBody(const Eigen::Vector3d& inertia, double beta) : inertia_(inertia), beta_(beta) {}

  template <class T>
  T evaluate(const Eigen::Matrix<T, 3, 1>& omega) const {
    T quadratic = ddb::constant<T>(0.0), norm2 = ddb::constant<T>(0.0);
    for (int i = 0; i < 3; ++i) {
      quadratic += ddb::constant<T>(inertia_(i)) * omega(i) * omega(i);
      norm2 += omega(i) * omega(i);
    }
    return ddb::constant<T>(0.5) * quadratic + ddb::constant<T>(0.25 * beta_) * norm2 * norm2;
  }

 private:
  Eigen::Vector3d inertia_;
  double beta_;
};

[[maybe_unused]] void definingFromTheLagrangian() {
  const auto lagrangian =
      std::make_shared<const StiffeningBody>(Eigen::Vector3d(1.0, 1.3, 0.5), /*beta=*/0.2);
  const auto metric =
      std::make_shared<const ddb::DiagonalMetric<ddb::SO3>>(0.5, Eigen::Vector3d(1.0, 2.0, 0.5));
  const auto system =
      ddb::makeSystemFromLagrangian<ddb::SO3>("stiffening-body", lagrangian, metric);
  ddb::Ddb<ddb::Cayley<ddb::SO3>> ddb_cay(system);
  const Eigen::Vector3d m0 = lagrangian->gradient(Eigen::Vector3d(0.0, 0.05, 1.0));
  double energy = 0.0;
  ddb::integrate(ddb_cay, m0, 0.0, 0.1, 300,
                 [&](long, double, const Eigen::Vector3d& m) { energy = system->energy(m); });

  auto body = ddb::makeRigidBody({1.0, 1.3, 0.5}, /*alpha=*/0.5);
  ddb::ReferenceSolver<ddb::SO3> reference(body);
  use(reference.name());
  Eigen::Vector3d stepped = m0;
  ddb::takeStep(reference, stepped, 0.0, 0.1);
  ddb::Ddb<ddb::Cayley<ddb::SO3>> method(body);
  ddb::Trajectory<ddb::SO3> trajectory;
  ddb::integrate(method, m0, 0.0, 0.1, 300, trajectory.record());
  try {
    ddb::integrate(method, m0, 0.0, 0.1, 300, trajectory.record());
  } catch (const ddb::SolveFailure& failure) {
    use(failure.step(), failure.time(), failure.h(), failure.residual());
  }
  use(energy);
}

[[maybe_unused]] void definingNames() {
  use(static_cast<SystemPtr<SO3> (*)(std::string, std::shared_ptr<const ddb::Lagrangian<SO3>>,
                                     std::shared_ptr<const ddb::DissipationMetric<SO3>>)>(
          &ddb::makeSystemFromLagrangian<SO3>),
      static_cast<const ddb::Lagrangian<SO3>* (System<SO3>::*)() const>(&System<SO3>::lagrangian),
      static_cast<const ddb::Hamiltonian<SO3>& (System<SO3>::*)() const>(&System<SO3>::hamiltonian),
      &ddb::SolveFailure::step, &ddb::SolveFailure::time, &ddb::SolveFailure::h,
      &ddb::SolveFailure::residual, &ddb::Trajectory<SO3>::record);
}
// LegendreHamiltonian: H of a Lagrangian by the inverse Legendre transform.
static_assert(std::is_base_of_v<ddb::Hamiltonian<SO3>, ddb::LegendreHamiltonian<SO3>>);
static_assert(
    std::is_constructible_v<ddb::LegendreHamiltonian<SO3>, std::shared_ptr<const MyBody>>);
// LiePoissonSystem<G>'s own constructor takes the parts through their base classes.
static_assert(
    std::is_constructible_v<System<SO3>, std::string, std::shared_ptr<const ddb::Hamiltonian<SO3>>,
                            std::shared_ptr<const ddb::DissipationMetric<SO3>>,
                            std::shared_ptr<const ddb::Lagrangian<SO3>>>);

// The groups' types (the table of "The groups' types").
template <class G, int kDim, class D, class A, class M, class C>
constexpr bool typesAre() {
  static_assert(G::kDim == kDim);
  static_assert(std::is_same_v<typename G::template Dual<double>, D>);
  static_assert(std::is_same_v<typename G::template Algebra<double>, A>);
  static_assert(std::is_same_v<typename G::template Matrix<double>, M>);
  static_assert(std::is_same_v<typename G::template Casimirs<double>, C>);
  // hat and exp return Matrix<T>: it holds the group's elements too.
  static_assert(std::is_same_v<decltype(G::hat(std::declval<const A&>())), M>);
  static_assert(std::is_same_v<decltype(G::exp(std::declval<const A&>())), M>);
  return true;
}
static_assert(typesAre<SO3, 3, Eigen::Matrix<double, 3, 1>, Eigen::Matrix<double, 3, 1>,
                       Eigen::Matrix<double, 3, 3>, Eigen::Matrix<double, 1, 1>>());
static_assert(typesAre<SE3, 6, Eigen::Matrix<double, 6, 1>, Eigen::Matrix<double, 6, 1>,
                       Eigen::Matrix<double, 4, 4>, Eigen::Matrix<double, 2, 1>>());
static_assert(typesAre<ddb::SO2, 1, Eigen::Matrix<double, 1, 1>, Eigen::Matrix<double, 1, 1>,
                       Eigen::Matrix<double, 2, 2>, Eigen::Matrix<double, 1, 1>>());
static_assert(typesAre<ddb::SE2, 3, Eigen::Matrix<double, 3, 1>, Eigen::Matrix<double, 3, 1>,
                       Eigen::Matrix<double, 3, 3>, Eigen::Matrix<double, 1, 1>>());
static_assert(typesAre<ddb::SemidirectProduct<SO3>, 6, Eigen::Matrix<double, 6, 1>,
                       Eigen::Matrix<double, 6, 1>, Eigen::Matrix<double, 4, 4>,
                       Eigen::Matrix<double, 2, 1>>());
static_assert(typesAre<ddb::DirectProduct<SO3, ddb::SE2>, 6, Eigen::Matrix<double, 6, 1>,
                       Eigen::Matrix<double, 6, 1>, Eigen::Matrix<double, 6, 6>,
                       Eigen::Matrix<double, 2, 1>>());
// Three factors or more: the product of the first and the product of the rest.
static_assert(typesAre<ddb::DirectProduct<ddb::SO2, SO3, ddb::SE2>, 7, Eigen::Matrix<double, 7, 1>,
                       Eigen::Matrix<double, 7, 1>, Eigen::Matrix<double, 8, 8>,
                       Eigen::Matrix<double, 3, 1>>());
static_assert(std::is_base_of_v<ddb::DirectProduct<ddb::SO2, ddb::DirectProduct<SO3, ddb::SE2>>,
                                ddb::DirectProduct<ddb::SO2, SO3, ddb::SE2>>);
static_assert(
    typesAre<ddb::SpecialOrthogonal<4>, 6, Eigen::Matrix<double, 6, 1>, Eigen::Matrix<double, 6, 1>,
             Eigen::Matrix<double, 4, 4>, Eigen::Matrix<double, 2, 1>>());
static_assert(typesAre<ddb::SpecialEuclidean<4>, 10, Eigen::Matrix<double, 10, 1>,
                       Eigen::Matrix<double, 10, 1>, Eigen::Matrix<double, 5, 5>,
                       Eigen::Matrix<double, 2, 1>>());
static_assert(
    std::is_same_v<ddb::SpecialEuclidean<4>, ddb::SemidirectProduct<ddb::SpecialOrthogonal<4>>>);
// A group made of groups: SE2 is SemidirectProduct<SO2>; SemidirectProductTraits<G> states the
// product's name and Casimirs, and optionally expIntegral and expIntegralInverse, and the vector
// forms of the action and the diamond.
static_assert(std::is_same_v<ddb::SE2, ddb::SemidirectProduct<ddb::SO2>>);
static_assert(ddb::SemidirectProductTraits<ddb::SO2>::kNumCasimirs == 1);
[[maybe_unused]] constexpr const char* kSE2Name = ddb::SemidirectProductTraits<ddb::SO2>::kName;
// A semidirect product by another action than G's own matrices (groups/representation.h): the
// ready-made representations, and SemidirectProduct's second parameter, which defaults to G's own.
static_assert(std::is_same_v<
              ddb::SE2, ddb::SemidirectProduct<ddb::SO2, ddb::DefiningRepresentation<ddb::SO2>>>);
static_assert(ddb::AdjointRepresentation<SO3>::kDim == 3 &&
              ddb::CoadjointRepresentation<SO3>::kDim == 3 &&
              ddb::DefiningRepresentation<ddb::SpecialOrthogonal<4>>::kDim == 4);
static_assert(ddb::SemidirectProduct<SO3>::kOwnMatrices &&
              ddb::SemidirectProduct<SO3>::kCayleyOfBlocks);
template <class Representation>
using ActingOnByRepresentation = ddb::SemidirectProduct<SO3, Representation>;
static_assert(std::is_same_v<ActingOnByRepresentation<ddb::DefiningRepresentation<SO3>>,
                             ddb::SemidirectProduct<SO3>>);
[[maybe_unused]] void representations() {
  const Eigen::Matrix3d R = SO3::exp(Eigen::Vector3d(0.1, 0.2, 0.3));
  use(ddb::AdjointRepresentation<SO3>::ofGroup<double>(R),
      ddb::CoadjointRepresentation<SO3>::ofAlgebra<double>(Eigen::Vector3d(0.1, 0.2, 0.3)),
      ddb::DefiningRepresentation<SO3>::ofGroup<double>(R),
      ddb::SemidirectProduct<SO3>::element<double>(R, Eigen::Vector3d(1, 2, 3)));
}
[[maybe_unused]] void groupsMadeOfGroups() {
  const Eigen::Matrix<double, 1, 1> w(0.3);
  const Eigen::Vector2d v(1.0, 2.0);
  use(ddb::SemidirectProductTraits<ddb::SO2>::expIntegral(w, v),
      ddb::SemidirectProductTraits<ddb::SO2>::expIntegralInverse(w, v),
      ddb::SemidirectProductTraits<ddb::SO2>::casimirs(w, v));
  // The optional vector forms of the action and the diamond, and the action's spectral radius:
  // SO(3)'s.
  using SO3Traits = ddb::SemidirectProductTraits<SO3>;
  const Eigen::Vector3d w3(0.1, 0.2, 0.3), v3(1.0, 2.0, 3.0);
  use(SO3Traits::cayAction(w3, v3), SO3Traits::cayActionTransposed(w3, v3),
      SO3Traits::algebraActionTransposed(w3, v3), SO3Traits::diamond(v3, v3),
      SO3Traits::algebraActionRadius(w3));
  static_assert(ddb::SemidirectProduct<SO3>::kVectorForms && !ddb::SE2::kVectorForms);
  const ddb::HeavyTopSetup top;
  const ddb::KirchhoffSetup kirchhoff;
  use(ddb::makeHeavyTopOn<ddb::SemidirectProduct<SO3>>(top.inertia, top.mgl, top.chi, top.alpha,
                                                       top.metric),
      ddb::makeKirchhoffBodyOn<ddb::SE3>(kirchhoff.inertia, kirchhoff.mass, kirchhoff.alpha,
                                         kirchhoff.metric));
  // Ratiu's heavy top on SE(4), from the mass moments of its body.
  const Eigen::Matrix<double, 6, 1> inertia =
      ddb::bodyInertiaOf<4>(Eigen::Vector4d(2.0, 1.5, 1.0, 0.5));
  use(ddb::makeHeavyTopOn<ddb::SpecialEuclidean<4>>(inertia, 0.8, Eigen::Vector4d(0, 0, 0, 1), 0.5,
                                                    Eigen::Matrix<double, 10, 1>::Ones()));
  const auto body =
      ddb::makePlanarKirchhoffBody(0.5, Eigen::Vector2d(1.0, 3.0), 0.5, Eigen::Vector3d::Ones());
  use(ddb::makeMethod<ddb::SE2>("sddb-cay", body));
}
static_assert(typesAre<SON, Eigen::Dynamic, Eigen::MatrixXd, Eigen::MatrixXd, Eigen::MatrixXd,
                       Eigen::VectorXd>());
static_assert(typesAre<SUN, Eigen::Dynamic, Eigen::MatrixXcd, Eigen::MatrixXcd, Eigen::MatrixXcd,
                       Eigen::VectorXd>());
// SUNOn<X>: SU(N) with Algebra and Dual a backend's matrix type X; SUN is the dense one.
static_assert(std::is_same_v<ddb::SUN, ddb::SUNOn<Eigen::MatrixXcd>>);
struct SomeBackendMatrix {};
static_assert(std::is_same_v<ddb::SUNOn<SomeBackendMatrix>::Dual<double>, SomeBackendMatrix>);
static_assert(std::is_same_v<ddb::SUNOn<SomeBackendMatrix>::Algebra<double>, SomeBackendMatrix>);
static_assert(std::is_same_v<System<SO3>::Casimirs, SO3::Casimirs<double>>);

// What a subclass provides: SmoothFunctionFor<Domain, Codomain> and the virtual members, each
// overridden with the signature the headers declare.
static_assert(
    std::is_same_v<ddb::SmoothFunctionFor<Vec3, Vec3>, ddb::SmallSmoothFunction<Vec3, Vec3>>);
static_assert(std::is_same_v<ddb::SmoothFunctionFor<Eigen::MatrixXd, Eigen::MatrixXd>,
                             ddb::SmoothFunction<Eigen::MatrixXd, Eigen::MatrixXd>>);
static_assert(std::is_base_of_v<ddb::SmoothFunctionFor<Vec3, Vec3>, ddb::Hamiltonian<SO3>>);
static_assert(std::is_base_of_v<ddb::SmoothFunctionFor<Vec3, Vec3>, ddb::Lagrangian<SO3>>);
static_assert(std::is_same_v<ddb::Hamiltonian<SO3>::HessianMatrix, Eigen::Matrix3d>);
static_assert(std::is_same_v<ddb::SmoothFunction<Vec3, Vec6>::CodomainType, Vec6>);

class EveryMemberHamiltonian final : public ddb::Hamiltonian<ddb::SO3> {
 public:
  double value(const Eigen::Vector3d& m) const override { return 0.5 * m.squaredNorm(); }
  Eigen::Vector3d gradient(const Eigen::Vector3d& m) const override { return m; }
  Eigen::Vector3d hessianTimes(const Eigen::Vector3d&, const Eigen::Vector3d& v) const override {
    return v;
  }
  void gradientInto(const Eigen::Vector3d& m, Eigen::Vector3d& out) const override { out = m; }
  void hessianTimesInto(const Eigen::Vector3d&, const Eigen::Vector3d& v,
                        Eigen::Vector3d& out) const override {
    out = v;
  }
  HessianMatrix hessian(const Eigen::Vector3d&) const override { return HessianMatrix::Identity(); }
  bool gradientIsASolve() const override { return false; }
};

class EveryMemberLagrangian final : public ddb::Lagrangian<ddb::SO3> {
 public:
  double value(const Eigen::Vector3d& w) const override { return 0.5 * w.squaredNorm(); }
  Eigen::Vector3d gradient(const Eigen::Vector3d& w) const override { return w; }
  Eigen::Vector3d hessianTimes(const Eigen::Vector3d&, const Eigen::Vector3d& v) const override {
    return v;
  }
  void gradientInto(const Eigen::Vector3d& w, Eigen::Vector3d& out) const override { out = w; }
  void hessianTimesInto(const Eigen::Vector3d&, const Eigen::Vector3d& v,
                        Eigen::Vector3d& out) const override {
    out = v;
  }
  HessianMatrix hessian(const Eigen::Vector3d&) const override { return HessianMatrix::Identity(); }
};

class EveryMemberMetric final : public ddb::DissipationMetric<ddb::SO3> {
 public:
  Algebra sharp(const Dual& mu) const override { return 0.5 * mu; }
  void sharpInto(const Dual& mu, Algebra& out) const override { out = 0.5 * mu; }
};

// On SU(N) the override spells the types out: Eigen::MatrixXcd.
class QuarticOnSUN final : public ddb::Hamiltonian<ddb::SUN> {
 public:
  double value(const Eigen::MatrixXcd& M) const override {
    return 0.25 * M.squaredNorm() * M.squaredNorm();
  }
  Eigen::MatrixXcd gradient(const Eigen::MatrixXcd& M) const override {
    return M.squaredNorm() * M;
  }
};

[[maybe_unused]] void definingSubclasses() {
  const auto so3 = ddb::makeLiePoissonSystem(
      "every-member", std::make_shared<const EveryMemberHamiltonian>(),
      std::make_shared<const EveryMemberMetric>(), std::make_shared<const EveryMemberLagrangian>());
  const auto se3 = ddb::makeLiePoissonSystem(
      "autodiff-hamiltonian", std::make_shared<const MyHamiltonian>(),
      std::make_shared<const ddb::DiagonalMetric<ddb::SE3>>(0.5, Vec6::Ones()));
  const auto su3 =
      ddb::makeLiePoissonSystem("quartic-su3", std::make_shared<const QuarticOnSUN>(),
                                std::make_shared<const ddb::ScaledIdentityMetric<ddb::SUN>>(0.5));
  const auto lagrangian = std::make_shared<const MyBody>();
  use(so3, se3, su3, lagrangian->hessian(Vec3::Zero()));
}

// Lagrangian or Hamiltonian form: the solvers, the methods' classes and their options.
using CayleySO3 = ddb::Cayley<ddb::SO3>;
using CayleySUN = ddb::Cayley<ddb::SUN>;
template <class M, class G, class R>
constexpr bool takesFormAndOptions =
    std::is_constructible_v<M, SystemPtr<G>, R, ddb::LegendreForm, ddb::SolverOptions>;
static_assert(takesFormAndOptions<ddb::Ddb<CayleySO3>, SO3, CayleySO3>);
static_assert(takesFormAndOptions<ddb::SymmetricDdb<CayleySO3>, SO3, CayleySO3>);
static_assert(takesFormAndOptions<ddb::LinearlyImplicitDdb<CayleySO3>, SO3, CayleySO3>);
static_assert(takesFormAndOptions<ddb::Ddb<CayleySUN>, SUN, CayleySUN>);
static_assert(std::is_constructible_v<ddb::DiscreteLegendreSolver<CayleySO3>, const System<SO3>&,
                                      const CayleySO3&, ddb::LegendreForm, ddb::SolverOptions>);
static_assert(std::is_constructible_v<ddb::MatrixLegendreSolver<CayleySUN>, const System<SUN>&,
                                      const CayleySUN&, ddb::LegendreForm, ddb::SolverOptions>);

[[maybe_unused]] void definingForms(const SystemPtr<SO3>& system) {
  ddb::SolverOptions options;
  options.relative_tolerance = 1e-13;
  options.max_iterations = 40;
  options.max_sweeps = 0;
  try {
    ddb::Ddb<CayleySO3> ddb_cay(system, CayleySO3(), ddb::LegendreForm::kHamiltonian, options);
    ddb::SymmetricDdb<CayleySO3> sddb(system, CayleySO3(), ddb::LegendreForm::kLagrangian);
    ddb::LinearlyImplicitDdb<CayleySO3> implicit(system, CayleySO3(),
                                                 ddb::LegendreForm::kHamiltonian);
    use(ddb_cay.name(), sddb.name(), implicit.name());
  } catch (const ddb::InvalidArgument& refused) {
    use(refused.what());
  }
  use(&ddb::SolverOptions::relative_tolerance, &ddb::SolverOptions::max_iterations,
      &ddb::SolverOptions::max_sweeps);
}

// On SO(N) and SU(N).
class WeightedBody final : public ddb::Hamiltonian<ddb::SON> {
 public:
  explicit WeightedBody(Eigen::MatrixXd c) : c_(std::move(c)) {}
  double value(const Eigen::MatrixXd& M) const override {
    return 0.5 * M.cwiseProduct(c_.cwiseProduct(M)).sum();
  }
  Eigen::MatrixXd gradient(const Eigen::MatrixXd& M) const override { return c_.cwiseProduct(M); }

 private:
  Eigen::MatrixXd c_;
};

class WeightedMetric final : public ddb::DissipationMetric<ddb::SON> {
 public:
  WeightedMetric(double alpha, Eigen::MatrixXd w) : alpha_(alpha), w_(std::move(w)) {}
  Eigen::MatrixXd sharp(const Eigen::MatrixXd& mu) const override {
    return alpha_ * w_.cwiseProduct(mu);
  }

 private:
  double alpha_;
  Eigen::MatrixXd w_;
};

[[maybe_unused]] void definingOnSON() {
  Eigen::MatrixXd c(4, 4), w = Eigen::MatrixXd::Ones(4, 4);
  c << 1, 2, 3, 4, 2, 1, 2, 3, 3, 2, 1, 2, 4, 3, 2, 1;
  Eigen::MatrixXd M0 = Eigen::MatrixXd::Zero(4, 4);
  M0(0, 1) = 0.3;
  M0(0, 3) = -0.2;
  M0(1, 2) = 0.5;
  M0 -= Eigen::MatrixXd(M0.transpose());
  auto so4 = ddb::makeLiePoissonSystem("weighted-so4", std::make_shared<const WeightedBody>(c),
                                       std::make_shared<const WeightedMetric>(0.5, w));
  const std::vector<std::string> names = ddb::methodNames(ddb::kMatrixGroups);
  auto method = ddb::makeMethod<ddb::SON>("ddb-cay", so4);
  ddb::Trajectory<ddb::SON> trajectory;
  ddb::integrate(*method, M0, 0.0, 0.05, 200, trajectory.record());
  const Eigen::VectorXd drift =
      ddb::SON::casimirs(trajectory.states.back()) - ddb::SON::casimirs(M0);
  use(names, drift, trajectory.times);
}

[[maybe_unused]] void definingMatrixNames() {
  use(static_cast<SystemPtr<SON> (*)(std::string, const std::shared_ptr<const WeightedBody>&,
                                     const std::shared_ptr<const WeightedMetric>&,
                                     std::shared_ptr<const ddb::Lagrangian<SON>>)>(
          &ddb::makeLiePoissonSystem<const WeightedBody, const WeightedMetric>),
      static_cast<std::vector<std::string> (*)(unsigned)>(&ddb::methodNames),
      static_cast<void (*)(Eigen::MatrixXd&)>(&ddb::SON::projectToAlgebra<Eigen::MatrixXd>),
      static_cast<void (*)(Eigen::MatrixXcd&)>(&ddb::SUN::projectToAlgebra<Eigen::MatrixXcd>),
      static_cast<Eigen::VectorXd (*)(const Eigen::MatrixXd&)>(
          &ddb::SON::casimirs<Eigen::MatrixXd>),
      &ddb::Trajectory<SON>::times, &ddb::Trajectory<SON>::states, &ddb::Trajectory<SON>::record);
}

// Choosing the step size h.
// G::adRadius(system->velocity(mu0)) on SO3, SE3, SON and SUN.
template <class G>
double turnRadius(const SystemPtr<G>& system, const Dual<G>& mu0) {
  return G::adRadius(system->velocity(mu0));
}
[[maybe_unused]] void definingStepSize(const SystemPtr<SO3>& system, const Vec3& mu0) {
  const double radius = ddb::SO3::adRadius(system->velocity(mu0));
  use(&turnRadius<SE3>, &turnRadius<SON>, &turnRadius<SUN>);
  const Eigen::MatrixXcd W0 = ddb::randomVorticity(16, 1);
  const double h = ddb::zeitlinDefaultStep(W0, 0.5);
  try {
    auto method = ddb::makeMethod<ddb::SO3>("ddb-exp", system);
    ddb::integrate(*method, mu0, 0.0, h, 10, [](long, double, const Vec3&) {});
  } catch (const ddb::InjectivityLimit& limit) {
    use(limit.limit(), limit.largestH());
  }
  use(radius, ddb::kZeitlinContractionRate, ddb::kZeitlinStiffness,
      static_cast<double (*)(const Eigen::MatrixXcd&, double)>(&ddb::zeitlinDefaultStep),
      static_cast<double (*)(const Vec3&)>(&ddb::SO3::adRadius),
      static_cast<double (*)(const Vec6&)>(&ddb::SE3::adRadius),
      static_cast<double (*)(const Eigen::MatrixXd&)>(&ddb::SON::adRadius<Eigen::MatrixXd>),
      static_cast<double (*)(const Eigen::MatrixXcd&)>(&ddb::SUN::adRadius<Eigen::MatrixXcd>),
      static_cast<Vec3 (System<SO3>::*)(const Vec3&) const>(&System<SO3>::velocity<double>),
      static_cast<Vec6 (System<SE3>::*)(const Vec6&) const>(&System<SE3>::velocity<double>),
      static_cast<Eigen::MatrixXd (System<SON>::*)(const Eigen::MatrixXd&) const>(
          &System<SON>::velocity<double>),
      static_cast<Eigen::MatrixXcd (System<SUN>::*)(const Eigen::MatrixXcd&) const>(
          &System<SUN>::velocity<double>));
  static_assert(std::is_base_of_v<ddb::SolveFailure, ddb::InjectivityLimit>);
}

// Let the energy choose h; check by halving h.
[[maybe_unused]] void definingRelax(const SystemPtr<SO3>& system, const Vec3& m0) {
  auto method = ddb::makeMethod<ddb::SO3>("ddb-cay", system);
  ddb::RelaxOptions options;
  options.control.adaptive = true;
  options.t_end = 30.0;
  options.max_steps = 100000;
  const ddb::RelaxResult<ddb::SO3> run = ddb::relax(*method, *system, m0, /*h0=*/0.1, options);
  const ddb::MethodInfo* info = ddb::findMethod("ddb-cay");
  auto reference = ddb::makeMethod<ddb::SO3>("reference", system);
  use(run.stop, run.last.h, run.steps_rejected, info->order, info->order_without_dissipation,
      reference->name());
}
[[maybe_unused]] void definingRelaxNames() {
  use(static_cast<ddb::RelaxResult<SO3> (*)(ddb::OneStepMethod<SO3>&, const System<SO3>&,
                                            const Vec3&, double, const ddb::RelaxOptions&)>(
          &ddb::relax<SO3>),
      &ddb::RelaxOptions::control, &ddb::StepSizeControl::adaptive, &ddb::RelaxOptions::t_end,
      &ddb::RelaxOptions::max_steps, &ddb::RelaxResult<SO3>::stop, &ddb::RelaxResult<SO3>::last,
      &ddb::RelaxState::h, &ddb::RelaxResult<SO3>::steps_rejected, &ddb::MethodInfo::order,
      &ddb::MethodInfo::order_without_dissipation,
      static_cast<MakeMethodByName<SE3>>(&ddb::makeMethod<SE3>),
      static_cast<MakeMethodByName<SON>>(&ddb::makeMethod<SON>),
      static_cast<MakeMethodByName<SUN>>(&ddb::makeMethod<SUN>));
  // EnergyStepControl: the step control relax() runs with options.control.adaptive.
  static_assert(
      std::is_constructible_v<ddb::EnergyStepControl, const ddb::StepSizeControl&, double>);
}

// docs/guide/choosing-a-method.md
static_assert(!ddb::kMethods.empty());
static_assert(
    std::is_same_v<std::remove_cv_t<decltype(ddb::kMethods)>::value_type, ddb::MethodInfo>);
[[maybe_unused]] void choosingNames(const SystemPtr<SO3>& system) {
  for (const ddb::MethodInfo& row : ddb::kMethods) {
    try {
      auto method = ddb::makeMethod<ddb::SO3>(row.name, system);
      use(method->name());
    } catch (const ddb::SolveFailure& failure) {
      use(failure.step());
    }
  }
  use(static_cast<MakeMethodByEntry<SO3>>(&ddb::makeMethod<SO3>));
}

// docs/guide/matrix-groups-and-the-fluid.md
[[maybe_unused]] void matrixGroupsFluid() {
  const int n = 64;
  const auto fluid = ddb::makeZeitlinFluid(n, 0.5);
  const ddb::ZeitlinHamiltonian hamiltonian(n);
  const ddb::ZeitlinDiagnostics diagnostics(hamiltonian);
  Eigen::MatrixXcd W = ddb::randomVorticity(n, /*seed=*/1);
  const Eigen::VectorXd spectrum0 = ddb::SUN::casimirs(W);
  auto method = ddb::makeMethod<ddb::SUN>("ddb-cay", fluid);
  double energy = 0.0, commutator = 0.0;
  ddb::integrate(*method, W, 0.0, /*h=*/0.002, /*steps=*/500,
                 [&](long, double, const Eigen::MatrixXcd& state) {
                   energy = diagnostics.energy(state);
                   commutator = diagnostics.commutatorNorm(state);
                   W = state;
                 });
  const double drift = (ddb::SUN::casimirs(W) - spectrum0).norm() / spectrum0.norm();
  const Eigen::VectorXd J = Eigen::VectorXd::LinSpaced(5, 1.0, 2.0);
  const auto manakov = ddb::makeManakovBody(J, 0.5);
  use(energy, commutator, drift, manakov);
}
[[maybe_unused]] void matrixGroupsNames() {
  use(static_cast<SystemPtr<SUN> (*)(Eigen::Index, double)>(&ddb::makeZeitlinFluid),
      static_cast<SystemPtr<SON> (*)(const Eigen::VectorXd&, double)>(&ddb::makeManakovBody),
      static_cast<Eigen::MatrixXcd (*)(Eigen::Index, std::uint64_t)>(&ddb::randomVorticity),
      static_cast<Eigen::VectorXd (*)(const Eigen::MatrixXcd&)>(
          &ddb::SUN::casimirs<Eigen::MatrixXcd>),
      static_cast<double (ddb::ZeitlinDiagnostics::*)(const Eigen::MatrixXcd&) const>(
          &ddb::ZeitlinDiagnostics::energy),
      static_cast<double (ddb::ZeitlinDiagnostics::*)(const Eigen::MatrixXcd&) const>(
          &ddb::ZeitlinDiagnostics::commutatorNorm),
      static_cast<Integrate<SUN>>(&ddb::integrate<SUN, Observer<SUN>>));
  static_assert(std::is_constructible_v<ddb::ZeitlinHamiltonian, Eigen::Index>);
  static_assert(std::is_constructible_v<ddb::ZeitlinDiagnostics, const ddb::ZeitlinHamiltonian&>);
  static_assert(std::is_base_of_v<ddb::Hamiltonian<SUN>, ddb::ZeitlinHamiltonian>);
}
[[maybe_unused]] void matrixGroupsRotatingSphere(const Eigen::MatrixXcd& W) {
  const Eigen::Index n = W.rows();
  ddb::ZeitlinPhysics physics;
  physics.rotation = 2.0;            // Ω
  physics.deformation_radius = 0.5;  // κ² = 4
  const auto fluid = ddb::makeZeitlinFluid(n, /*alpha=*/0.0, physics);
  const auto& hamiltonian = dynamic_cast<const ddb::ZeitlinHamiltonian&>(fluid->hamiltonian());
  const Eigen::MatrixXcd Q = W + hamiltonian.planetaryVorticity();  // the state: W + F
  use(Q, ddb::zeitlinPlanetaryVorticity(n, 2.0));
  static_assert(
      std::is_constructible_v<ddb::ZeitlinHamiltonian, Eigen::Index, const ddb::ZeitlinPhysics&>);
  ddb::ZeitlinViscosity viscosity;
  viscosity.viscosity = 1e-4;  // ν
  viscosity.order = 2;         // p: hyperviscosity Δ²
  viscosity.drag = 0.01;       // γ
  ddb::StrangSplitting<ddb::SUN> method(
      ddb::makeMethod<ddb::SUN>("sddb-cay", fluid),
      std::make_unique<ddb::ZeitlinViscousFlow>(n, viscosity, hamiltonian.planetaryVorticity()));
  Eigen::MatrixXcd state = Q;
  method.advance(state, 0.0, 0.01);
  static_assert(std::is_base_of_v<ddb::ExactFlow<SUN>, ddb::ZeitlinViscousFlow>);
  // Forcing (docs/guide/matrix-groups-and-the-fluid.md, "Forcing").
  ddb::ZeitlinStochasticForcing forcing;
  forcing.band_centre = 2;      // L
  forcing.band_half_width = 1;  // D
  forcing.rate = 1e-3;          // ε
  forcing.seed = 7;
  ddb::StrangSplitting<ddb::SUN> forced(
      ddb::makeMethod<ddb::SUN>("sddb-cay", fluid),
      std::make_unique<ddb::ZeitlinStochasticForcingFlow>(n, forcing, physics.kappaSquared()));
  forced.advance(state, 0.01, 0.01);
  ddb::BinaryRecordWriter record;
  forced.saveWarmStart(record);
  use(ddb::counterNormal(forcing.seed, 0, 0));
  ddb::ZeitlinFixedForcingFlow fixed(n, W);
  ddb::ZeitlinDampingAndForcing damping_and_forcing{viscosity, forcing, W};
  use(ddb::zeitlinExactFlows(hamiltonian, damping_and_forcing).size());
  // The order for any placement of the states, given how to make each flow there.
  struct MakeFlows {
    Eigen::Index n;
    std::unique_ptr<ddb::ExactFlow<ddb::SUN>> viscous(const ddb::ZeitlinViscosity& v) const {
      return std::make_unique<ddb::ZeitlinViscousFlow>(n, v);
    }
    std::unique_ptr<ddb::ExactFlow<ddb::SUN>> stochastic(
        const ddb::ZeitlinStochasticForcing& f) const {
      return std::make_unique<ddb::ZeitlinStochasticForcingFlow>(n, f);
    }
    std::unique_ptr<ddb::ExactFlow<ddb::SUN>> fixed(const Eigen::MatrixXcd& phi) const {
      return std::make_unique<ddb::ZeitlinFixedForcingFlow>(n, phi);
    }
  };
  use(ddb::zeitlinExactFlowsBy(MakeFlows{n}, damping_and_forcing).size());
  // The viscous flow's implicit step.
  ddb::ZeitlinViscosity implicit_viscosity = viscosity;
  implicit_viscosity.scheme = ddb::ZeitlinViscousScheme::kImplicit;
  ddb::ZeitlinViscousFlow implicit_flow(n, implicit_viscosity);
  implicit_flow.advance(state, 0.01);
  ddb::ZeitlinImplicitViscousStep implicit_step(n, 1e-3, 2, 0.0,
                                                ddb::SphericalHarmonicBasis::allBlocks(n));
  implicit_step.setStep(0.01);
  fixed.advance(state, 0.01);
  // The field's diagnostics.
  const ddb::SphericalHarmonicBasis basis(hamiltonian.laplacian());
  const Eigen::VectorXd omega = basis.coefficients(W);
  const ddb::ZeitlinSpectra spectra = ddb::zeitlinSpectra(omega, 4.0);
  const ddb::ScaleDecomposition parts =
      ddb::zeitlinScaleDecomposition(W, hamiltonian.streamMatrix(Q));
  const ddb::SphericalHarmonicGrid grid(n);
  const Eigen::MatrixXd field = grid.evaluate(omega);
  const ddb::ZeitlinGammaFromMatrix gammaOf(basis);
  ddb::SphericalHarmonicDegreeOperator filter(basis, Eigen::VectorXd::Ones(n));
  filter.setFactors(basis, Eigen::VectorXd::Constant(n, 0.5));
  Eigen::MatrixXcd filtered = W;
  filter.apply(filtered);
  ddb::SphericalHarmonicBasis::Workspace workspace(n);
  use(filtered, ddb::SphericalHarmonicDegreeOperator::bytes(n), basis.blockVectors(0, workspace));
  use(state, spectra.energy, spectra.enstrophy, ddb::zeitlinGamma(omega), parts.steady,
      parts.remainder, field, grid.colatitudes(), grid.longitudes(), gammaOf(W));
}

// docs/guide/steady-states.md
[[maybe_unused]] const char* steadyStops(ddb::RelaxStop stop) {
  switch (stop) {
    case ddb::RelaxStop::kSteady:
      return "steady";
    case ddb::RelaxStop::kStepCap:
      return "step cap";
    case ddb::RelaxStop::kTimeCap:
      return "time cap";
    case ddb::RelaxStop::kFailure:
      return "failure";
    default:
      return "other";
  }
}
[[maybe_unused]] void steadyNewton(const SystemPtr<SUN>& fluid, const Eigen::MatrixXcd& W0) {
  ddb::RelaxOptions options;
  options.newton = true;
  options.tolerance = 1e-10;
  options.max_steps = 100;
  ddb::Relaxation<ddb::SUN> search(*fluid, W0, options);
  while (search.advance()) {
  }
  const ddb::RelaxResult<ddb::SUN> run = ddb::relaxByNewton(
      *fluid, W0, options, [](const ddb::RelaxState& s, const Eigen::MatrixXcd&) {
        use(s.k, s.t, s.h, s.energy, s.residual);
      });
  ddb::OrbitNewton<ddb::SUN> newton(*fluid, 1.0);
  const auto conservative = fluid->withoutDissipation();
  ddb::LinearlyImplicitDdb<CayleySUN> implicit(fluid, CayleySUN(), ddb::LegendreForm::kHamiltonian);
  ddb::MatrixConjugation<CayleySUN> conjugation;
  const double rho = ddb::energyRoundOff(1.0, 1.0 - 1e-15);
  use(search.current(), run.steps_rejected, conservative, implicit.name(), rho);
  static_cast<void>(newton);
  static_cast<void>(conjugation);
}
[[maybe_unused]] void steadyNames() {
  use(static_cast<ddb::RunResult<SO3> (*)(ddb::OneStepMethod<SO3>&, const System<SO3>&, const Vec3&,
                                          double, long, const ddb::RunOptions&)>(
          &ddb::runMethod<SO3>),
      static_cast<ddb::RelaxResult<SO3> (*)(const System<SO3>&, const Vec3&,
                                            const ddb::RelaxOptions&, RelaxSink<SO3>&&)>(
          &ddb::relaxByNewton<SO3, RelaxSink<SO3>>),
      static_cast<double (*)(double, double)>(&ddb::energyRoundOff),
      static_cast<SystemPtr<SO3> (System<SO3>::*)() const>(&System<SO3>::withoutDissipation),
      &ddb::RelaxOptions::newton, &ddb::RelaxOptions::tolerance, &ddb::RelaxOptions::max_steps,
      &ddb::RelaxOptions::t_end, &ddb::RelaxState::k, &ddb::RelaxState::t, &ddb::RelaxState::h,
      &ddb::RelaxState::energy, &ddb::RelaxState::residual, &ddb::RelaxResult<SO3>::steps_rejected,
      &ddb::Relaxation<SO3>::advance, &ddb::Relaxation<SO3>::current);
  // Relaxation(method, system, μ₀, h₀, options) and, for the Newton search, (system, μ₀, options).
  static_assert(
      std::is_constructible_v<ddb::Relaxation<SO3>, ddb::OneStepMethod<SO3>&, const System<SO3>&,
                              const Vec3&, double, const ddb::RelaxOptions&>);
  static_assert(std::is_constructible_v<ddb::Relaxation<SO3>, const System<SO3>&, const Vec3&,
                                        const ddb::RelaxOptions&>);
  static_assert(std::is_constructible_v<ddb::OrbitNewton<SO3>, const System<SO3>&, double>);
  // The two searches behind Relaxation, and their interface.
  static_assert(std::is_base_of_v<ddb::SteadyStateSearch<SO3>, ddb::TimeRelaxation<SO3>>);
  static_assert(std::is_base_of_v<ddb::SteadyStateSearch<SO3>, ddb::NewtonSearch<SO3>>);
  static_assert(
      std::is_constructible_v<ddb::TimeRelaxation<SO3>, ddb::OneStepMethod<SO3>&,
                              const System<SO3>&, const Vec3&, double, const ddb::RelaxOptions&>);
  static_assert(std::is_constructible_v<ddb::NewtonSearch<SO3>, const System<SO3>&, const Vec3&,
                                        const ddb::RelaxOptions&>);
  static_assert(std::is_base_of_v<ddb::Ddb<CayleySO3>, ddb::LinearlyImplicitDdb<CayleySO3>>);
}

// docs/guide/cluster.md (the distributed layer itself: public_names_distributed.cc)
[[maybe_unused]] void clusterRelaxation(ddb::OneStepMethod<SUN>& method, const System<SUN>& fluid,
                                        const Eigen::MatrixXcd& W0) {
  ddb::RelaxOptions options;
  options.max_steps = 10;
  ddb::Relaxation<ddb::SUN> run(method, fluid, W0, 0.01, options);
  while (run.advance()) {
  }
  use(run.current(), run.result().stop);
}

// docs/guide/gpu.md (the CUDA backend itself: public_names_cuda.cc): the same program's
// host-side names on the dense SU(N).
[[maybe_unused]] void gpuOnTheHost() {
  const Eigen::MatrixXcd W0 = ddb::randomVorticity(64, 1);
  const auto fluid = ddb::makeZeitlinFluid(64, 0.5);
  const auto method = ddb::makeMethod<ddb::SUN>("sddb-cay", fluid);
  ddb::RelaxOptions options;
  options.max_steps = 1000;
  ddb::Relaxation<ddb::SUN> run(*method, *fluid, W0, 0.01, options);
  while (run.advance()) {
  }
  const Eigen::MatrixXcd W = run.current();
  use(W);
}

// docs/guide/performance.md: final parts through makeLiePoissonSystem; the in-place forms on
// matrix groups.
class InPlaceBody final : public ddb::Hamiltonian<ddb::SON> {
 public:
  double value(const Eigen::MatrixXd& M) const override { return 0.5 * M.squaredNorm(); }
  Eigen::MatrixXd gradient(const Eigen::MatrixXd& M) const override { return M; }
  Eigen::MatrixXd hessianTimes(const Eigen::MatrixXd&, const Eigen::MatrixXd& V) const override {
    return V;
  }
  void gradientInto(const Eigen::MatrixXd& M, Eigen::MatrixXd& out) const override { out = M; }
  void hessianTimesInto(const Eigen::MatrixXd&, const Eigen::MatrixXd& V,
                        Eigen::MatrixXd& out) const override {
    out = V;
  }
};
class InPlaceMetric final : public ddb::DissipationMetric<ddb::SON> {
 public:
  Eigen::MatrixXd sharp(const Eigen::MatrixXd& mu) const override { return 0.5 * mu; }
  void sharpInto(const Eigen::MatrixXd& mu, Eigen::MatrixXd& out) const override { out = 0.5 * mu; }
};
[[maybe_unused]] void performanceInPlace() {
  const auto son = ddb::makeLiePoissonSystem("in-place", std::make_shared<const InPlaceBody>(),
                                             std::make_shared<const InPlaceMetric>());
  use(son);
}

// docs/guide/python.md: the C++ names behind the module's functions.
[[maybe_unused]] void pythonNames() {
  using HeavyTop = SystemPtr<SE3> (*)(const Vec3&, double, const Vec3&, double, const Vec6&);
  using Kirchhoff = SystemPtr<SE3> (*)(const Vec3&, const Vec3&, double, const Vec6&);
  using Vorticity = Eigen::MatrixXcd (*)(Eigen::Index, std::uint64_t);
  use(static_cast<SystemPtr<SO3> (*)(const Vec3&, double)>(&ddb::makeRigidBody),
      static_cast<HeavyTop>(&ddb::makeHeavyTop), static_cast<Kirchhoff>(&ddb::makeKirchhoffBody),
      static_cast<SystemPtr<SON> (*)(const Eigen::VectorXd&, double)>(&ddb::makeManakovBody),
      static_cast<SystemPtr<SUN> (*)(Eigen::Index, double)>(&ddb::makeZeitlinFluid),
      static_cast<Vorticity>(&ddb::randomVorticity), static_cast<Vorticity>(&ddb::l1Vorticity),
      static_cast<Vorticity>(&ddb::zonalVorticity));
  // Defaults: Scenario A, HeavyTopSetup, KirchhoffSetup (systems/paper_scenarios.h).
  const ddb::HeavyTopSetup top;
  const ddb::KirchhoffSetup kirchhoff;
  const ddb::RigidBodyScenario& a = ddb::rigidBodyScenario("A");
  use(top.system(), kirchhoff.system(), a.system(), a.mu0(), a.t_end, ddb::rigidBodyScenarios(),
      &ddb::HeavyTopSetup::inertia, &ddb::HeavyTopSetup::mgl, &ddb::HeavyTopSetup::chi,
      &ddb::HeavyTopSetup::alpha, &ddb::HeavyTopSetup::metric, &ddb::HeavyTopSetup::mu0,
      &ddb::KirchhoffSetup::inertia, &ddb::KirchhoffSetup::mass, &ddb::KirchhoffSetup::alpha,
      &ddb::KirchhoffSetup::metric, &ddb::KirchhoffSetup::mu0);
  // ddb.planar_kirchhoff and its defaults, PlanarKirchhoffSetup.
  const ddb::PlanarKirchhoffSetup planar;
  use(planar.system(), &ddb::PlanarKirchhoffSetup::inertia, &ddb::PlanarKirchhoffSetup::mass,
      &ddb::PlanarKirchhoffSetup::alpha, &ddb::PlanarKirchhoffSetup::metric,
      &ddb::PlanarKirchhoffSetup::mu0, &ddb::PlanarKirchhoffSetup::t_end);
  // ddb.zeitlin: ZeitlinDiagnostics, SphericalHarmonicBasis (fluid_energy, enstrophy,
  // commutator_norm, stream_matrix, omega_lm, vorticity, hbar).
  const ddb::ZeitlinHamiltonian hamiltonian(8);
  const ddb::ZeitlinDiagnostics diagnostics(hamiltonian);
  const ddb::SphericalHarmonicBasis basis(hamiltonian.laplacian());
  const Eigen::MatrixXcd W = ddb::randomVorticity(8, 1);
  use(diagnostics.energy(W), diagnostics.enstrophy(W), diagnostics.commutatorNorm(W),
      hamiltonian.streamMatrix(W), hamiltonian.hbar(), basis.matrix(basis.coefficients(W)));
  // System.energy, System.casimirs, System.methods(); ddb.methods(): kMethods' rows.
  use(static_cast<double (System<SO3>::*)(const Vec3&) const>(&System<SO3>::energy),
      static_cast<System<SO3>::Casimirs (System<SO3>::*)(const Vec3&) const>(
          &System<SO3>::casimirs),
      static_cast<bool (*)(const ddb::MethodInfo&, const System<SO3>&)>(&ddb::methodApplies<SO3>),
      static_cast<bool (*)(std::string_view, const System<SO3>&)>(&ddb::methodApplies<SO3>),
      &ddb::MethodInfo::name, &ddb::MethodInfo::description, &ddb::MethodInfo::groups,
      &ddb::MethodInfo::keeps_casimirs, &ddb::MethodInfo::needs_lagrangian,
      &ddb::MethodInfo::needs_scalar_metric, &ddb::MethodInfo::order,
      &ddb::MethodInfo::order_without_dissipation, ddb::kMethods.size());
}
// ddb.integrate: makeMethod + integrate + EveryKth.
using EveryKthSO3 = ddb::EveryKth<Vec3, Observer<SO3>>;
static_assert(std::is_constructible_v<EveryKthSO3, long, Observer<SO3>&>);
[[maybe_unused]] void pythonIntegrate(const SystemPtr<SO3>& system, const Vec3& mu0) {
  Observer<SO3> sink = [](long, double, const Vec3&) {};
  EveryKthSO3 every(10, sink);
  auto method = ddb::makeMethod<ddb::SO3>("ddb-cay", system);
  try {
    ddb::integrate(*method, mu0, 0.0, 0.1, 100, every);
    every.finish();
  } catch (const ddb::NonFiniteState& failure) {
    use(failure.step());
  } catch (const ddb::BudgetExhausted& failure) {
    use(failure.step());
  } catch (const ddb::InjectivityLimit& failure) {
    use(failure.step());
  } catch (const ddb::SolveFailure& failure) {
    use(failure.whatFailed(), failure.step(), failure.time(), failure.h(), failure.residual(),
        failure.tolerance());
  } catch (const ddb::InvalidArgument& refused) {
    use(refused.what());
  }
  use(&EveryKthSO3::finish, &ddb::SolveFailure::whatFailed, &ddb::SolveFailure::tolerance);
  static_assert(std::is_base_of_v<ddb::SolveFailure, ddb::NonFiniteState>);
  static_assert(std::is_base_of_v<ddb::SolveFailure, ddb::BudgetExhausted>);
}

// Magnetohydrodynamics on the sphere (docs/guide/matrix-groups-and-the-fluid.md): the group,
// its states, metric, system, diagnostics and methods.
static_assert(std::is_same_v<ddb::DualNumberSUN, ddb::DualNumberSUNOn<Eigen::MatrixXcd>>);
static_assert(std::is_same_v<Dual<ddb::DualNumberSUN>, ddb::DualMatrix<Eigen::MatrixXcd>>);
static_assert(std::is_base_of_v<ddb::DissipationMetric<ddb::DualNumberSUN>,
                                ddb::SwappedPartsMetric<Eigen::MatrixXcd>>);
// Its Newton search and linearly implicit methods (docs/guide/steady-states.md): the shift's
// preconditioner, the gradient through the pairing's Riesz map; the fluid's weighs entries.
static_assert(std::is_same_v<ddb::OrbitPreconditionerFor<ddb::DualNumberSUN>,
                             ddb::ShiftOrbitPreconditioner<ddb::DualMatrix<Eigen::MatrixXcd>>>);
static_assert(std::is_same_v<ddb::OrbitPreconditionerFor<ddb::SUN>,
                             ddb::OrbitPreconditioner<Eigen::MatrixXcd>>);
static_assert(std::is_same_v<ddb::OrbitPreconditionerFor<ddb::SON>,
                             ddb::OrbitPreconditioner<Eigen::MatrixXd>>);
[[maybe_unused]] void magnetohydrodynamics() {
  const SystemPtr<ddb::DualNumberSUN> mhd = ddb::makeZeitlinMhd(8, 0.5);
  const auto& h = dynamic_cast<const ddb::ZeitlinMhdHamiltonian&>(mhd->hamiltonian());
  const ddb::ZeitlinMhdDiagnostics diagnostics(h);
  ddb::DualMatrix<Eigen::MatrixXcd> mu =
      ddb::zeitlinMhdState(ddb::l1Vorticity(8, 1), ddb::randomVorticity(8, 2));
  ddb::DualNumberSUN::requireState("Theta", "W", mu);
  MethodPtr<ddb::DualNumberSUN> method = ddb::makeMethod<ddb::DualNumberSUN>("ddb-cay", mhd);
  method->advance(mu, 0.0, 0.01);
  use(mu.real, mu.eps, diagnostics.kineticEnergy(mu), diagnostics.magneticEnergy(mu),
      diagnostics.crossHelicity(mu), diagnostics.equilibriumResidual(mu),
      ddb::DualNumberSUN::casimirs(mu), ddb::needsEigenbasis(ddb::kMethods[0]),
      ddb::needsOrbitPreconditioner(ddb::kMethods[0]),
      ddb::HasOrbitPreconditioner<ddb::DualMatrix<Eigen::MatrixXcd>>::value,
      mhd->metric().scalarMultiple());
  ddb::rieszMapInPlace<ddb::DualNumberSUN>(mu);
  // The exponential methods' spectral calculus on dual-number matrices.
  ddb::DualEigenbasis<Eigen::MatrixXcd> basis;
  if (basis.compute(mu)) {
    basis.apply(ddb::PhaseFunction::kCoadjointIncrement, 0.1, mu, mu);
    use(basis.adRadius());
  }
}

}  // namespace
