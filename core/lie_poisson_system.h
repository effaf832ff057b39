// LiePoissonSystem: a group, a Hamiltonian (and optionally the Lagrangian it comes
// from) and a dissipation metric. The continuous dynamics (paper, eq. (3.4)):
//   μ̇ = ad*_{ξ + φ(ξ)} μ,   ξ = ∂H/∂μ,   φ(ξ) = k♯(ad*_ξ μ),
// so Casimirs are constant and dH/dt = -k(ad*_ξ μ, ad*_ξ μ) (Proposition 3.3).
#pragma once

#include <ddb/core/butcher_tableau.h>
#include <ddb/core/detail/jet_lift.h>
#include <ddb/core/dissipation_metric.h>
#include <ddb/core/errors.h>
#include <ddb/core/explicit_runge_kutta_sweep.h>
#include <ddb/core/group_traits.h>
#include <ddb/core/lagrangian.h>
#include <ddb/core/matrix_backend.h>

#include <array>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>

namespace ddb {

/// The workspaces of a matrix-group system's in-place evaluations (vectorFieldInto and its
/// derivative): no evaluation allocates once resize() has run for the state's size.
template <class G>
struct MatrixFieldWorkspace {
  using Matrix = typename G::template Dual<double>;
  // At μ: P μ, ξ, the commutator [Pμ, ξ], φ, ξ + φ. Along v: P v, δξ, δ[Pμ, ξ], δφ, δ(ξ + φ).
  Matrix argument, xi, commutator, phi, forced, direction, dxi, dcommutator, dphi, dforced;

  /// Every workspace of like's shape (and layout), zero; nothing if they have it already.
  void resize(const Matrix& like) {
    using B = MatrixBackend<Matrix>;
    if (B::sameShape(argument, like)) return;
    for (Matrix* m : {&argument, &xi, &commutator, &phi, &forced, &direction, &dxi, &dcommutator,
                      &dphi, &dforced}) {
      B::zeroLike(*m, like);
    }
  }
};

/// ⟨μ, ξ⟩, the pairing of g* with g: the backend's innerProduct (the Euclidean inner product of
/// the coordinates, or Re tr(μᴴξ): docs/reference/conventions.md §1), or G::pairing where G says
/// its pairing is another (kIndefinitePairing: SU(N) ⋉ su(N)*, groups/dual_number_sun.h).
template <class G, class Dual, class Algebra>
double dualPairing(const Dual& mu, const Algebra& xi) {
  if constexpr (detail::HasIndefinitePairing<G>::value) {
    return G::pairing(mu, xi);
  } else {
    return MatrixBackend<Dual>::innerProduct(mu, xi);
  }
}

/// The small (fixed-size) groups' workspace of vectorFieldInto: the same parts as
/// MatrixFieldWorkspace's at μ, as coordinate vectors (nothing to size).
template <class G>
struct FixedSizeFieldWorkspace {
  using Dual = typename G::template Dual<double>;
  using Algebra = typename G::template Algebra<double>;
  // At μ: μ itself (the argument H saw), ξ, ad*_ξ μ, φ = k♯(ad*_ξ μ), ξ + φ.
  Dual argument, commutator, phi;
  Algebra xi, forced;

  void resize(const Dual&) {}
};

/// What LiePoissonSystem::vectorFieldInto keeps for a group: matrices sized once on matrix
/// groups, fixed-size vectors on the small ones (one method body for both: the backend's
/// algebra, core/matrix_backend.h, serves both too).
template <class G>
using FieldWorkspace =
    std::conditional_t<isDynamicGroup<G>, MatrixFieldWorkspace<G>, FixedSizeFieldWorkspace<G>>;

/// The workspaces of LiePoissonSystem::explicitStep, an explicit S-stage Runge–Kutta step: the
/// slopes, the stage argument, the weighted sum and the field's parts. A small group's are
/// fixed-size vectors, best kept on the caller's stack; a matrix group's are sized once by
/// resize().
template <class G, int S>
struct ExplicitStages {
  using Dual = typename G::template Dual<double>;
  std::array<Dual, S> slopes;
  Dual stage, sum;
  FieldWorkspace<G> field;

  /// Every workspace of mu's shape (and layout); nothing if they have it already.
  void resize(const Dual& mu) {
    using B = MatrixBackend<Dual>;
    field.resize(mu);
    if (B::sameShape(stage, mu)) return;
    for (Dual& k : slopes) B::zeroLike(k, mu);
    B::zeroLike(stage, mu);
    B::zeroLike(sum, mu);
  }
};

/// Matrix groups: ξ = P ∂H/∂μ(Pμ), with Pμ into `argument`. The one place where a matrix
/// group's Hamiltonian is evaluated (docs/reference/conventions.md §2, "Systems on matrix groups");
/// written against the matrix backend, so H may act on distributed matrices.
template <class G, class H, class X>
void matrixVelocityInto(const H& hamiltonian, const X& mu, X& argument, X& xi) {
  MatrixBackend<X>::copy(mu, argument);
  G::projectToAlgebra(argument);
  hamiltonian.gradientInto(argument, xi);
  G::projectToAlgebra(xi);
}

/// Its derivative along v, P D²H(Pμ)[Pv], given `argument` = Pμ from matrixVelocityInto;
/// `direction` is a workspace.
template <class G, class H, class X>
void matrixVelocityDerivativeInto(const H& hamiltonian, const X& argument, const X& v, X& direction,
                                  X& out) {
  MatrixBackend<X>::copy(v, direction);
  G::projectToAlgebra(direction);
  hamiltonian.hessianTimesInto(argument, direction, out);
  G::projectToAlgebra(out);
}

template <class G>
class LiePoissonSystem {
  static_assert(sizeof(GroupTraits<G>) > 0, "checks G's minimum API (core/group_traits.h)");

 public:
  using Group = G;
  template <class T>
  using AlgebraT = typename G::template Algebra<T>;
  template <class T>
  using DualT = typename G::template Dual<T>;
  using Algebra = AlgebraT<double>;
  using Dual = DualT<double>;
  using Casimirs = typename G::template Casimirs<double>;
  /// The matrix groups' arithmetic (docs/design/matrix-backend.md).
  using B = MatrixBackend<Dual>;

  LiePoissonSystem(std::string name, std::shared_ptr<const Hamiltonian<G>> hamiltonian,
                   std::shared_ptr<const DissipationMetric<G>> metric,
                   std::shared_ptr<const Lagrangian<G>> lagrangian = nullptr)
      : name_(std::move(name)),
        hamiltonian_(std::move(hamiltonian)),
        metric_(std::move(metric)),
        lagrangian_(std::move(lagrangian)) {
    if (!hamiltonian_) throw InvalidArgument("hamiltonian must not be null");
    if (!metric_) throw InvalidArgument("metric must not be null");
  }
  virtual ~LiePoissonSystem() = default;
  // Copies share the Hamiltonian and metric; a copy of a TypedLiePoissonSystem through this
  // class is a generic system of the same parts. No assignment: TypedLiePoissonSystem relies on
  // its parts keeping their types.
  LiePoissonSystem(const LiePoissonSystem&) = default;
  LiePoissonSystem(LiePoissonSystem&&) = default;
  LiePoissonSystem& operator=(const LiePoissonSystem&) = delete;
  LiePoissonSystem& operator=(LiePoissonSystem&&) = delete;

  const std::string& name() const { return name_; }
  const Hamiltonian<G>& hamiltonian() const { return *hamiltonian_; }
  const DissipationMetric<G>& metric() const { return *metric_; }
  /// The Lagrangian l with ∂l/∂ξ = μ ⇔ ξ = ∂H/∂μ, or nullptr (e.g. the heavy top).
  const Lagrangian<G>* lagrangian() const { return lagrangian_.get(); }

  /// The same Hamiltonian (and Lagrangian) with k♯ = 0: the conservative part of the flow,
  /// for methods that treat the dissipation apart (LinearlyImplicitDdb).
  std::shared_ptr<const LiePoissonSystem<G>> withoutDissipation() const {
    return std::make_shared<const LiePoissonSystem<G>>(
        name_, hamiltonian_, std::make_shared<const ScaledIdentityMetric<G>>(0.0), lagrangian_);
  }

  double energy(const Dual& mu) const { return hamiltonian_->value(mu); }
  Casimirs casimirs(const Dual& mu) const { return G::casimirs(mu); }

  /// ξ = ∂H/∂μ (double or Jet). On matrix groups ξ = P ∂H/∂μ(P μ) with P = G::projectToAlgebra:
  /// the Hamiltonian sees an element of the algebra (su(N): the DDB Legendre unknown's trace
  /// stays in the solve) and ξ is in the algebra whatever H returns (docs/reference/conventions.md
  /// §2, "Systems on matrix groups").
  template <class T>
  AlgebraT<T> velocity(const DualT<T>& mu) const {
    // T named: a backend's Dual<T> does not depend on T, so it cannot be deduced from mu.
    return velocityOf<Hamiltonian<G>, T>(*hamiltonian_, mu);
  }

  /// In place: ξ = ∂H/∂μ at p into xi and the argument H saw into `argument` (matrix groups:
  /// ξ = P ∂H/∂μ(P p), argument P p, both of p's size; small groups: p itself).
  void velocityInto(const Dual& p, Dual& argument, Algebra& xi) const {
    if constexpr (isDynamicGroup<G>) {
      velocityAt(*hamiltonian_, p, argument, xi);
    } else {
      argument = p;
      xi = velocity(p);
    }
  }

  /// In place: the derivative of velocity() along v, D²H(p)[v] (matrix groups:
  /// P D²H(P p)[P v]), given `argument` from velocityInto; `direction` is a workspace.
  void velocityDerivativeInto(const Dual& argument, const Dual& v, Dual& direction,
                              Algebra& out) const {
    if constexpr (isDynamicGroup<G>) {
      matrixVelocityDerivativeInto<G>(*hamiltonian_, argument, v, direction, out);
    } else {
      static_cast<void>(direction);
      out = hamiltonian_->hessianTimes(argument, v);
    }
  }

  /// out = ad*_ξ μ; matrix groups: [μ, ξ] = μξ − (μξ)ᴴ for skew-Hermitian μ and ξ, one product
  /// into the workspace `product` (small groups: G::adDual, `product` unused).
  static void coadjointInto(const Algebra& xi, const Dual& mu, Dual& product, Dual& out) {
    if constexpr (isDynamicGroup<G>) {
      B::multiply(mu, xi, product);
      B::copy(product, out);
      B::addAdjoint(-1.0, product, out);
    } else {
      static_cast<void>(product);
      out = G::adDual(xi, mu);
    }
  }

  /// φ(ξ) = k♯(ad*_ξ μ), where μ is the momentum paired with ξ (double or Jet).
  template <class T>
  AlgebraT<T> dissipation(const AlgebraT<T>& xi, const DualT<T>& mu) const {
    return dissipationOf(*metric_, xi, mu);
  }

  /// Matrix groups, in place: out = scale·φ, φ = k♯(ad*_ξ p) = k♯([p, ξ]), with
  /// [p, ξ] = pξ − (pξ)ᴴ as p and ξ are skew-Hermitian (one product; `product` and
  /// `commutator` are workspaces of p's size).
  void dissipationInto(const Dual& p, const Algebra& xi, double scale, Dual& product,
                       Dual& commutator, Algebra& out) const {
    B::multiply(p, xi, product);
    B::copy(product, commutator);
    B::addAdjoint(-1.0, product, commutator);
    metric_->sharpInto(commutator, out);
    B::scale(scale, out, out);
  }
  /// The same at ξ = (2/h)a given the product ap = a p: out = hφ/2 = k♯([p, a]) with
  /// [p, a] = (ap)ᴴ − ap. No product.
  void halfStepDissipationInto(const Dual& ap, Dual& commutator, Algebra& out) const {
    G::commutatorFromProduct(ap, commutator);
    metric_->sharpInto(commutator, out);
  }

  /// μ̇ = ad*_{ξ + φ(ξ)} μ (double or Jet). In double through fieldAt: one virtual call in a
  /// TypedLiePoissonSystem with `final` parts, three in one built by LiePoissonSystem's own
  /// constructor.
  template <class T>
  DualT<T> vectorField(const DualT<T>& mu) const {
    if constexpr (std::is_same_v<T, double>) {
      return fieldAt(mu);
    } else {
      return vectorFieldOf(*hamiltonian_, *metric_, mu);
    }
  }

  /// In place: μ̇ = ad*_{ξ+φ} μ into out, the bits of vectorField(mu). Matrix groups:
  /// μ̇ = P ad*_{ξ+φ}(P μ), the vector field on the algebra (the argument projected like the
  /// Hamiltonian's, the result too, so that explicit and implicit Runge–Kutta states stay on
  /// it); `w` is sized by w.resize(mu) and keeps the parts (fieldPartsInto), which the
  /// derivative at this μ needs. Small groups: one inlined evaluation, w untouched (the
  /// explicit steps' cost: docs/design/architecture.md, "Explicit steps").
  void vectorFieldInto(const Dual& mu, FieldWorkspace<G>& w, Dual& out) const {
    if constexpr (isDynamicGroup<G>) {
      fieldInto(mu, w, out);
    } else {
      out = fieldAt(mu);
    }
  }

  /// One step μ ← μ + h Σ b_i k_i of the explicit four-stage `tableau` (ExplicitRungeKutta<G,
  /// 4>: `rk4`), with its stages in w (core/explicit_runge_kutta_sweep.h). The system takes the
  /// step so that a TypedLiePoissonSystem evaluates every stage with its field inlined: one
  /// virtual call a step instead of one a stage, and a small group's stages stay in registers
  /// (through a call they pass by memory, where a load that spans two stores of the caller
  /// stalls: docs/design/architecture.md, "Explicit steps"). The bits of the sweep with
  /// vectorFieldInto, which this generic system runs.
  virtual void explicitStep(const ButcherTableau<4>& tableau, double h, ExplicitStages<G, 4>& w,
                            Dual& mu) const;
  /// The sweep of an explicit S-stage tableau (core/explicit_runge_kutta_sweep.h) with system's
  /// vectorFieldInto: explicitStep's body, and ExplicitRungeKutta's for other than four stages.
  /// With a TypedLiePoissonSystem, a final class, the field's calls are that class's own; always
  /// inlined, so that they are inlined into its explicitStep (out of line, the heavy top's step
  /// took 8 % longer).
  template <class System, int S>
  EIGEN_ALWAYS_INLINE static void explicitSweep(const System& system,
                                                const ButcherTableau<S>& tableau, double h,
                                                ExplicitStages<G, S>& w, Dual& mu) {
    explicitRungeKuttaSweep(tableau, h, mu, w, [&](const Dual& x, Dual& out) {
      system.vectorFieldInto(x, w.field, out);
    });
  }

  /// In place: μ̇ into out as vectorFieldInto, and its parts into w on every group: the
  /// argument H saw, ξ, ad*_ξ μ (`commutator`), φ = k♯(ad*_ξ μ) and ξ + φ (`forced`).
  void fieldPartsInto(const Dual& mu, FieldWorkspace<G>& w, Dual& out) const {
    fieldInto(mu, w, out);
  }

  /// Matrix groups, in place: Df(μ)[v] at the μ of the last vectorFieldInto with `w`, by the
  /// linearised brackets: with x = ξ + φ, δξ = P D²H(Pμ)[Pv] and
  /// δx = δξ + k♯([Pv, ξ] + [Pμ, δξ]), Df(μ)[v] = P([Pv, x] + [Pμ, δx]). Eight products.
  void vectorFieldDerivativeInto(const Dual& v, MatrixFieldWorkspace<G>& w, Dual& out) const {
    static_assert(isDynamicGroup<G>, "the matrix-free derivative is the matrix groups'");
    velocityDerivativeInto(w.argument, v, w.direction, w.dxi);  // P v and δξ
    bracketInto(w.direction, w.xi, w.dcommutator);
    addBracket(w.argument, w.dxi, w.dcommutator);
    metric_->sharpInto(w.dcommutator, w.dphi);
    B::sum(1.0, w.dxi, 1.0, w.dphi, w.dforced);
    bracketInto(w.direction, w.forced, out);
    addBracket(w.argument, w.dforced, out);
    G::projectToAlgebra(out);
  }

 protected:
  /// μ̇ at a double μ. TypedLiePoissonSystem overrides it to call its Hamiltonian and metric
  /// through their concrete types.
  virtual Dual fieldAt(const Dual& mu) const;
  /// fieldPartsInto's evaluation; TypedLiePoissonSystem overrides it like fieldAt.
  virtual void fieldInto(const Dual& mu, FieldWorkspace<G>& w, Dual& out) const;

  // Eq. (3.4) for any Hamiltonian type H and metric type K: the base classes here, the
  // concrete ones in TypedLiePoissonSystem.
  template <class H, class T>
  static AlgebraT<T> velocityOf(const H& hamiltonian, const DualT<T>& mu) {
    if constexpr (isDynamicGroup<G>) {
      static_assert(std::is_same_v<T, double>, "matrix groups are evaluated in double");
      Dual argument;
      Algebra xi;
      B::zeroLike(argument, mu);
      B::zeroLike(xi, mu);
      velocityAt(hamiltonian, mu, argument, xi);
      return xi;
    } else {
      return liftGradient(hamiltonian, mu);
    }
  }
  template <class K, class T>
  static AlgebraT<T> dissipationOf(const K& metric, const AlgebraT<T>& xi, const DualT<T>& mu) {
    return liftLinear([&metric](const Dual& m) { return metric.sharp(m); },
                      G::adDual(xi, mu).eval());
  }
  template <class H, class K, class T>
  static DualT<T> vectorFieldOf(const H& hamiltonian, const K& metric, const DualT<T>& mu) {
    if constexpr (isDynamicGroup<G>) {
      MatrixFieldWorkspace<G> w;
      w.resize(mu);
      Dual out;
      B::zeroLike(out, mu);
      fieldPartsOf(hamiltonian, metric, mu, w, out);
      return out;
    } else {
      const AlgebraT<T> xi = velocityOf(hamiltonian, mu);
      const AlgebraT<T> forced = xi + dissipationOf(metric, xi, mu);
      return G::adDual(forced, mu);
    }
  }

  template <class H>
  static void velocityAt(const H& hamiltonian, const Dual& mu, Dual& argument, Algebra& xi) {
    matrixVelocityInto<G>(hamiltonian, mu, argument, xi);
  }

  // Eq. (3.4) with its parts kept in w. Matrix groups: on the algebra,
  // f(μ) = P ad*_{ξ+φ}(Pμ), ξ = P ∂H/∂μ(Pμ), φ = k♯(ad*_ξ Pμ), with ad*_x μ = [μ, x]; four
  // products, none allocating. Small groups: vectorFieldOf's operations, in its order.
  template <class H, class K>
  static void fieldPartsOf(const H& hamiltonian, const K& metric, const Dual& mu,
                           FieldWorkspace<G>& w, Dual& out) {
    if constexpr (isDynamicGroup<G>) {
      velocityAt(hamiltonian, mu, w.argument, w.xi);
      bracketInto(w.argument, w.xi, w.commutator);
      metric.sharpInto(w.commutator, w.phi);
      B::sum(1.0, w.xi, 1.0, w.phi, w.forced);
      bracketInto(w.argument, w.forced, out);
      G::projectToAlgebra(out);
    } else {
      w.argument = mu;
      w.xi = velocityOf(hamiltonian, mu);
      w.commutator = G::adDual(w.xi, mu);
      w.phi = metric.sharp(w.commutator);
      w.forced = w.xi + w.phi;
      out = G::adDual(w.forced, mu);
    }
  }

  // out = [a, b] = ab − ba, and out += [a, b], without temporaries.
  static void bracketInto(const Dual& a, const Dual& b, Dual& out) {
    B::multiply(a, b, out);
    B::multiplyAdd(-1.0, b, a, out);
  }
  static void addBracket(const Dual& a, const Dual& b, Dual& out) {
    B::multiplyAdd(1.0, a, b, out);
    B::multiplyAdd(-1.0, b, a, out);
  }

 private:
  std::string name_;
  std::shared_ptr<const Hamiltonian<G>> hamiltonian_;
  std::shared_ptr<const DissipationMetric<G>> metric_;
  std::shared_ptr<const Lagrangian<G>> lagrangian_;
};

// The generic system's virtual functions, defined out of the class: GCC compiles a member defined
// in its class in every unit that builds the vtable, even where an `extern template` declares it,
// and for SO(N) and SU(N) these three cost about 7 s and 4 s of a unit's compile. So the library
// compiles them once for the group of each system it ships (DDB_LIE_POISSON_SYSTEM_INSTANCE below,
// declared by the systems' headers and the method tables' units; docs/results/compile-costs.md,
// "The generic system's virtual functions compiled once").
template <class G>
void LiePoissonSystem<G>::explicitStep(const ButcherTableau<4>& tableau, double h,
                                       ExplicitStages<G, 4>& w, Dual& mu) const {
  explicitSweep(*this, tableau, h, w, mu);
}

template <class G>
typename LiePoissonSystem<G>::Dual LiePoissonSystem<G>::fieldAt(const Dual& mu) const {
  return vectorFieldOf<Hamiltonian<G>, DissipationMetric<G>, double>(*hamiltonian_, *metric_, mu);
}

template <class G>
void LiePoissonSystem<G>::fieldInto(const Dual& mu, FieldWorkspace<G>& w, Dual& out) const {
  fieldPartsOf(*hamiltonian_, *metric_, mu, w, out);
}

/// A LiePoissonSystem that knows the concrete types H of its Hamiltonian and K of its metric.
/// Its double vector field calls `gradient` and `sharp` by name through those types, so that
/// when they are `final` the compiler inlines ∂H/∂μ and k♯ into the field: one virtual call
/// per evaluation (fieldAt) instead of two (∂H/∂μ and k♯ through their base classes), and ξ
/// stays in registers. For a small system that is most of the explicit methods' overhead over
/// hand-written code (docs/design/architecture.md, "Explicit steps"). Built by
/// makeLiePoissonSystem.
template <class G, class H, class K>
class TypedLiePoissonSystem final : public LiePoissonSystem<G> {
  static_assert(std::is_base_of_v<Hamiltonian<G>, H>, "H must derive from Hamiltonian<G>");
  static_assert(std::is_base_of_v<DissipationMetric<G>, K>,
                "K must derive from DissipationMetric<G>");

 public:
  using typename LiePoissonSystem<G>::Dual;

  TypedLiePoissonSystem(std::string name, const std::shared_ptr<const H>& hamiltonian,
                        const std::shared_ptr<const K>& metric,
                        std::shared_ptr<const Lagrangian<G>> lagrangian = nullptr)
      : LiePoissonSystem<G>(std::move(name), hamiltonian, metric, std::move(lagrangian)) {}

  // The base's sweep, compiled where the system's type is known and final: its calls to
  // fieldAt and fieldInto are this class's, inlined.
  void explicitStep(const ButcherTableau<4>& tableau, double h, ExplicitStages<G, 4>& w,
                    Dual& mu) const override {
    this->explicitSweep(*this, tableau, h, w, mu);
  }

 protected:
  // The base holds exactly these objects (it has no assignment), so the casts are exact.
  Dual fieldAt(const Dual& mu) const override {
    return this->template vectorFieldOf<H, K, double>(static_cast<const H&>(this->hamiltonian()),
                                                      static_cast<const K&>(this->metric()), mu);
  }
  void fieldInto(const Dual& mu, FieldWorkspace<G>& w, Dual& out) const override {
    this->fieldPartsOf(static_cast<const H&>(this->hamiltonian()),
                       static_cast<const K&>(this->metric()), mu, w, out);
  }
};

/// The system of `hamiltonian` and `metric` (and optionally the Lagrangian they come from),
/// keeping their concrete types (TypedLiePoissonSystem): declare them `final` for the fastest
/// explicit steps.
template <class HP, class KP>
std::shared_ptr<const LiePoissonSystem<typename HP::Group>> makeLiePoissonSystem(
    std::string name, const std::shared_ptr<HP>& hamiltonian, const std::shared_ptr<KP>& metric,
    std::shared_ptr<const Lagrangian<typename HP::Group>> lagrangian = nullptr) {
  using H = std::remove_const_t<HP>;
  using K = std::remove_const_t<KP>;
  return std::make_shared<const TypedLiePoissonSystem<typename H::Group, H, K>>(
      std::move(name), hamiltonian, metric, std::move(lagrangian));
}

}  // namespace ddb

/// The explicit instantiations of LiePoissonSystem<G>'s virtual functions: with `extern` it
/// declares them (a system's header: systems/rigid_body.h; the library's method tables'
/// units, instantiations/method_table_so3.cc), with nothing it defines them
/// (instantiations/lie_poisson_systems.cc). G must be complete.
#define DDB_LIE_POISSON_SYSTEM_INSTANCE(PREFIX, G)                                    \
  PREFIX template void ddb::LiePoissonSystem<G>::explicitStep(                        \
      const ::ddb::ButcherTableau<4>&, double, ::ddb::ExplicitStages<G, 4>&,          \
      ::ddb::LiePoissonSystem<G>::Dual&) const;                                       \
  PREFIX template ::ddb::LiePoissonSystem<G>::Dual ddb::LiePoissonSystem<G>::fieldAt( \
      const ::ddb::LiePoissonSystem<G>::Dual&) const;                                 \
  PREFIX template void ddb::LiePoissonSystem<G>::fieldInto(                           \
      const ::ddb::LiePoissonSystem<G>::Dual&, ::ddb::FieldWorkspace<G>&,             \
      ::ddb::LiePoissonSystem<G>::Dual&) const
