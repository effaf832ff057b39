// The integrators by their contract names (docs/reference/command-lines-and-files.md): one table,
// kMethods, holds each method's name, description, the groups it runs on, whether it keeps the
// Casimirs, its order and its recipe; makeMethod() builds any entry for any group, and
// the apps' choices, --help, messages and the tests all read the same table. Adding an
// integrator is one row here plus its header (and, for a new kind of method, one case
// in makeMethod's switch).
#pragma once

#include <ddb/core/detail/is_complete.h>
#include <ddb/core/errors.h>
#include <ddb/core/group_traits.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/core/matrix_traits.h>
#include <ddb/groups/cayley.h>
#include <ddb/groups/exponential.h>
#include <ddb/integrators/methods/composition.h>
#include <ddb/integrators/methods/ddb.h>
#include <ddb/integrators/methods/linearly_implicit_ddb.h>
#include <ddb/integrators/methods/matrix_free_runge_kutta.h>
#include <ddb/integrators/methods/runge_kutta.h>
#include <ddb/integrators/methods/symmetric_ddb.h>

#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace ddb {

// integrators/methods/reference.h, the one header that brings Boost.Odeint: the library compiles
// makeMethod for its own groups with it (the end of this file), and makeMethod on a group of your
// own needs it included once in that translation unit (checked below, with a message).
template <class G>
class ReferenceSolver;

/// The groups a method runs on: the fixed-size ones (SO3, SE3 and any user group with
/// static sizes), the matrix groups with N at run time (SON, SUN) on dense matrices, and the
/// matrix groups on another backend's matrices (SUNOn<X>: MPI ranks, the test's entries-free
/// backend), where only the methods whose whole step is written against MatrixBackend run
/// (docs/design/matrix-backend.md, "What runs on any backend").
enum GroupFamilies : unsigned {
  kFixedSizeGroups = 1u,
  kMatrixGroups = 2u,
  kBackendMatrixGroups = 4u
};

/// How makeMethod() builds an entry.
enum class MethodKind {
  kDdb,                  ///< Ddb<R> (paper, Section 4.1)
  kLinearlyImplicitDdb,  ///< LinearlyImplicitDdb<R>: DDB, dissipative factor lowering H at any h
  kSymmetricDdb,         ///< SymmetricDdb<R>, the one-step symmetric DDB
  kPaperSymmetricDdb,    ///< PaperSymmetricDdb<R>, the paper's symmetric variant as written
  kComposition,          ///< Composition of the entry `base` by `scheme`
  kExplicitRk4,          ///< ExplicitRungeKutta with kClassicalRk4
  kLobattoIIIC,          ///< ImplicitRungeKutta with kLobattoIIIC3
  kReference,            ///< ReferenceSolver, adaptive RKF 7(8)
};

enum class RetractionKind {
  kNone,
  kCayley,                 ///< Cayley<G>
  kExponential,            ///< Exponential<G>, closed-form dexp^{-1}
  kTruncatedExponential2,  ///< TruncatedExponential<G>(2), as in the paper's runs
};

enum class SchemeKind { kNone, kTripleJump, kYoshida6 };

struct MethodInfo {
  std::string_view name;
  std::string_view description;  ///< one line, for --help and messages
  unsigned groups;               ///< GroupFamilies it applies to
  /// The DDB family: every state on the coadjoint orbit of μ₀, so the Casimirs are kept to
  /// round-off and, with α > 0, the energy falls (the apps watch it).
  bool keeps_casimirs;
  bool needs_lagrangian;     ///< evaluates ∂l/∂ξ at a midpoint, so the system needs l
  bool needs_scalar_metric;  ///< needs k♯ = α·I (DissipationMetric::scalarMultiple)
  /// Order in μ with α ≠ 0 (docs/reference/conventions.md §2); 0 for the adaptive reference,
  /// whose error is set by its tolerance, not by h.
  int order;
  int order_without_dissipation;  ///< order with α = 0
  MethodKind kind;
  RetractionKind retraction;
  SchemeKind scheme;
  std::string_view base;  ///< the composed entry, for kComposition
};

// clang-format off
/// Every method, in the order of the paper's comparison
/// (docs/reference/command-lines-and-files.md).
inline constexpr std::array<MethodInfo, 15> kMethods{{
  {"ddb-cay", "DDB step with the Cayley map (order 1, order 2 at alpha = 0)",
   kFixedSizeGroups | kMatrixGroups | kBackendMatrixGroups, true, false, false, 1, 2,
   MethodKind::kDdb, RetractionKind::kCayley, SchemeKind::kNone, ""},
  {"ddb-exp", "DDB step with exp, dexp^-1 series truncated at order 2 as in the paper",
   kFixedSizeGroups | kMatrixGroups | kBackendMatrixGroups, true, false, false, 1, 2,
   MethodKind::kDdb, RetractionKind::kTruncatedExponential2, SchemeKind::kNone, ""},
  {"ddb-exp-exact", "DDB step with exp and the closed-form dexp^-1",
   kFixedSizeGroups | kMatrixGroups | kBackendMatrixGroups, true, false, false, 1, 2,
   MethodKind::kDdb, RetractionKind::kExponential, SchemeKind::kNone, ""},
  {"ddb-cay-implicit",
   "DDB Cayley step, dissipative factor linearly implicit: moves the energy the flow's way at any h (order 1, order 2 at alpha = 0)",
   kFixedSizeGroups | kMatrixGroups | kBackendMatrixGroups, true, false, true, 1, 2,
   MethodKind::kLinearlyImplicitDdb, RetractionKind::kCayley, SchemeKind::kNone, ""},
  {"ddb-exp-implicit",
   "DDB exp step (closed-form dexp^-1), dissipative factor linearly implicit: moves the energy the flow's way at any h (order 1, order 2 at alpha = 0)",
   kFixedSizeGroups | kMatrixGroups | kBackendMatrixGroups, true, false, true, 1, 2,
   MethodKind::kLinearlyImplicitDdb, RetractionKind::kExponential, SchemeKind::kNone, ""},
  {"sddb-paper-cay", "the paper's symmetric DDB, Cayley (order 1 as written; Lagrangian only)",
   kFixedSizeGroups, true, true, false, 1, 2,
   MethodKind::kPaperSymmetricDdb, RetractionKind::kCayley, SchemeKind::kNone, ""},
  {"sddb-paper-exp", "the paper's symmetric DDB, exp (order 1 as written; Lagrangian only)",
   kFixedSizeGroups, true, true, false, 1, 2,
   MethodKind::kPaperSymmetricDdb, RetractionKind::kExponential, SchemeKind::kNone, ""},
  {"sddb-cay", "one-step symmetric DDB, Cayley (order 2)",
   kFixedSizeGroups | kMatrixGroups | kBackendMatrixGroups, true, false, false, 2, 2,
   MethodKind::kSymmetricDdb, RetractionKind::kCayley, SchemeKind::kNone, ""},
  {"sddb-exp", "one-step symmetric DDB, exp (order 2)",
   kFixedSizeGroups | kMatrixGroups | kBackendMatrixGroups, true, false, false, 2, 2,
   MethodKind::kSymmetricDdb, RetractionKind::kExponential, SchemeKind::kNone, ""},
  {"ddb4-cay", "triple jump of sddb-cay (order 4)",
   kFixedSizeGroups | kMatrixGroups | kBackendMatrixGroups, true, false, false, 4, 4,
   MethodKind::kComposition, RetractionKind::kNone, SchemeKind::kTripleJump, "sddb-cay"},
  {"ddb4-exp", "triple jump of sddb-exp (order 4)",
   kFixedSizeGroups | kMatrixGroups | kBackendMatrixGroups, true, false, false, 4, 4,
   MethodKind::kComposition, RetractionKind::kNone, SchemeKind::kTripleJump, "sddb-exp"},
  {"ddb6-exp", "Yoshida's 7-stage composition of sddb-exp (order 6)",
   kFixedSizeGroups | kMatrixGroups | kBackendMatrixGroups, true, false, false, 6, 6,
   MethodKind::kComposition, RetractionKind::kNone, SchemeKind::kYoshida6, "sddb-exp"},
  {"rk4", "classical Runge-Kutta, order 4 (does not keep Casimirs)",
   kFixedSizeGroups | kMatrixGroups | kBackendMatrixGroups, false, false, false, 4, 4,
   MethodKind::kExplicitRk4, RetractionKind::kNone, SchemeKind::kNone, ""},
  {"lobatto3c", "Lobatto IIIC, 3 stages, order 4 (does not keep Casimirs)",
   kFixedSizeGroups | kMatrixGroups | kBackendMatrixGroups, false, false, false, 4, 4,
   MethodKind::kLobattoIIIC, RetractionKind::kNone, SchemeKind::kNone, ""},
  {"reference", "adaptive Runge-Kutta-Fehlberg 7(8), tolerance 1e-13",
   kFixedSizeGroups | kMatrixGroups, false, false, false, 0, 0,
   MethodKind::kReference, RetractionKind::kNone, SchemeKind::kNone, ""},
}};
// clang-format on

/// Whether the entry needs the matrices' spectral calculus (MatrixBackend<X>::Eigenbasis): the
/// exponential retractions' sweeps and conjugations, and compositions of such entries.
inline bool needsEigenbasis(const MethodInfo& method);

/// Whether the entry needs the Newton search's preconditioner on the orbit (HasOrbitPreconditioner:
/// the Eigenbasis's weights, or the shift's on dual-number matrices): the linearly implicit
/// factor, and compositions of it.
inline bool needsOrbitPreconditioner(const MethodInfo& method);

namespace detail {
/// Trait<G's states>::value on a matrix group; true on the small groups, which need neither the
/// spectral calculus (their exponential is a closed form) nor the orbit preconditioner (theirs is
/// the identity).
template <template <class, class> class Trait, class G>
constexpr bool statesHave() {
  if constexpr (!isDynamicGroup<G>) {
    return true;
  } else {
    return Trait<typename G::template Dual<double>, void>::value;
  }
}
}  // namespace detail

/// Whether G's states have the spectral calculus: a matrix group's backend may lack it (a
/// backend of one's own, core/matrix_backend.h).
template <class G>
constexpr bool groupHasEigenbasis() {
  return detail::statesHave<HasEigenbasis, G>();
}

/// Whether G's states have the orbit preconditioner (HasOrbitPreconditioner, matrix_backend.h).
template <class G>
constexpr bool groupHasOrbitPreconditioner() {
  return detail::statesHave<HasOrbitPreconditioner, G>();
}

/// The families G belongs to.
template <class G>
constexpr unsigned groupFamilyOf() {
  if constexpr (!isDynamicGroup<G>) {
    return kFixedSizeGroups;
  } else {
    return isEigenMatrix<typename G::template Dual<double>> ? kMatrixGroups : kBackendMatrixGroups;
  }
}

/// The entry named `name`, or nullptr.
inline const MethodInfo* findMethod(std::string_view name) {
  for (const MethodInfo& m : kMethods) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

namespace detail {
/// The entry a composition composes (its base's recipe), else the entry itself; nullptr for a
/// composition of a name that is not in the table.
inline const MethodInfo* recipeOf(const MethodInfo& method) {
  if (method.kind != MethodKind::kComposition) return &method;
  const MethodInfo* base = findMethod(method.base);
  return base != nullptr ? recipeOf(*base) : nullptr;
}
}  // namespace detail

inline bool needsEigenbasis(const MethodInfo& method) {
  const MethodInfo* recipe = detail::recipeOf(method);
  return recipe != nullptr && (recipe->retraction == RetractionKind::kExponential ||
                               recipe->retraction == RetractionKind::kTruncatedExponential2);
}

inline bool needsOrbitPreconditioner(const MethodInfo& method) {
  const MethodInfo* recipe = detail::recipeOf(method);
  return recipe != nullptr && recipe->kind == MethodKind::kLinearlyImplicitDdb;
}

/// The names of the entries that run on any of `families`, in table order.
inline std::vector<std::string> methodNames(unsigned families = kFixedSizeGroups | kMatrixGroups) {
  std::vector<std::string> names;
  for (const MethodInfo& m : kMethods) {
    if ((m.groups & families) != 0) names.emplace_back(m.name);
  }
  return names;
}

/// The names of the entries that run on any of `families`, as a message lists them: "a, b, c".
inline std::string methodList(unsigned families = kFixedSizeGroups | kMatrixGroups) {
  std::string list;
  for (const auto& name : methodNames(families)) list += (list.empty() ? "" : ", ") + name;
  return list;
}

/// The names of the methods for matrix groups (SO(N), SU(N)), in table order.
[[deprecated(
    "use methodNames(kMatrixGroups); removed in 0.3.0 (CHANGELOG.md, 0.2.0)")]] inline std::
    vector<std::string>
    matrixGroupMethodNames() {
  return methodNames(kMatrixGroups);
}

/// (name, one-line description) of the entries that run on any of `families`.
inline std::vector<std::pair<std::string, std::string>> methodDescriptions(
    unsigned families = kFixedSizeGroups | kMatrixGroups) {
  std::vector<std::pair<std::string, std::string>> lines;
  for (const MethodInfo& m : kMethods) {
    if ((m.groups & families) != 0) lines.emplace_back(m.name, m.description);
  }
  return lines;
}

/// Whether the entry runs on G and on this system (the paper's symmetric variant
/// evaluates ∂l/∂ξ at the midpoint (ξ_k + ξ_{k+1})/2, so it needs a Lagrangian).
template <class G>
bool methodApplies(const MethodInfo& method, const LiePoissonSystem<G>& system) {
  return (method.groups & groupFamilyOf<G>()) != 0 &&
         (groupHasEigenbasis<G>() || !needsEigenbasis(method)) &&
         (groupHasOrbitPreconditioner<G>() || !needsOrbitPreconditioner(method)) &&
         (!method.needs_lagrangian || system.lagrangian() != nullptr) &&
         (!method.needs_scalar_metric || system.metric().scalarMultiple().has_value());
}

/// methodApplies for a name; false for a name that is not in the table.
template <class G>
bool methodApplies(std::string_view name, const LiePoissonSystem<G>& system) {
  const MethodInfo* method = findMethod(name);
  return method != nullptr && methodApplies(*method, system);
}

namespace detail {

/// The message of a name that is not a method for G's family.
template <class G>
[[noreturn]] void throwNotAMethod(const std::string& name) {
  if constexpr (groupFamilyOf<G>() == kBackendMatrixGroups) {
    throwInvalid("method", name,
                 "is not one of the methods whose step is written against the matrix backend "
                 "alone, which run on " +
                     std::string(G::kName) + "'s matrices: " + methodList(kBackendMatrixGroups));
  } else if constexpr (isDynamicGroup<G>) {
    throwInvalid("method", name,
                 "is not one of the methods for matrix groups: " + methodList(kMatrixGroups));
  } else {
    throwInvalid("method", name,
                 "is not one of the methods for " + std::string(G::kName) + ": " +
                     methodList(kFixedSizeGroups));
  }
}

/// The entries of G's family that G's matrices can build (the spectral calculus and the
/// preconditioner where they need them), as a message lists them: "a, b, c".
template <class G>
std::string buildableMethodList() {
  std::string list;
  for (const MethodInfo& m : kMethods) {
    if ((m.groups & groupFamilyOf<G>()) != 0 && (groupHasEigenbasis<G>() || !needsEigenbasis(m)) &&
        (groupHasOrbitPreconditioner<G>() || !needsOrbitPreconditioner(m))) {
      list += (list.empty() ? "" : ", ") + std::string(m.name);
    }
  }
  return list;
}

/// The message of an entry that needs the spectral calculus on a group whose matrices lack it.
template <class G>
[[noreturn]] void throwNeedsEigenbasis(const std::string& name) {
  throwInvalid("method", name,
               "needs the spectral calculus of the matrices (the exponential map), which " +
                   std::string(G::kName) +
                   "'s have not; these run on it: " + buildableMethodList<G>());
}

/// The message of an entry that needs the orbit preconditioner on a group whose matrices lack it.
template <class G>
[[noreturn]] void throwNeedsOrbitPreconditioner(const std::string& name) {
  throwInvalid("method", name,
               "needs the Newton search's preconditioner on the orbit, which " +
                   std::string(G::kName) +
                   "'s matrices have not; these run on it: " + buildableMethodList<G>());
}

template <class G>
using MethodPointer = std::unique_ptr<OneStepMethod<G>>;

/// A DDB-family method M<R> with the entry's retraction.
template <class G, template <class> class M, class... Args>
MethodPointer<G> withRetraction(RetractionKind r, std::shared_ptr<const LiePoissonSystem<G>> system,
                                Args... args) {
  if (r == RetractionKind::kCayley) {
    return std::make_unique<M<Cayley<G>>>(system, Cayley<G>(), args...);
  }
  if constexpr (groupHasEigenbasis<G>()) {  // else makeMethod refused the row already
    if (r == RetractionKind::kExponential) {
      return std::make_unique<M<Exponential<G>>>(system, Exponential<G>(), args...);
    }
    if (r == RetractionKind::kTruncatedExponential2) {
      return std::make_unique<M<TruncatedExponential<G>>>(system, TruncatedExponential<G>(2),
                                                          args...);
    }
  }
  throw std::logic_error("method table: a retraction the group has not");
}

/// The adaptive reference on G; its header is Boost.Odeint's, so a program includes it only
/// where it builds the reference itself.
template <class G>
MethodPointer<G> makeReferenceSolver(std::shared_ptr<const LiePoissonSystem<G>> system) {
  static_assert(kIsComplete<ReferenceSolver<G>>,
                "makeMethod on a group of your own builds the 'reference' row too: include "
                "<ddb/integrators/methods/reference.h> (Boost.Odeint) in this file");
  return std::make_unique<ReferenceSolver<G>>(std::move(system));
}

inline const CompositionScheme& schemeOf(SchemeKind scheme) {
  if (scheme == SchemeKind::kYoshida6) return yoshida6();
  return tripleJump();
}

}  // namespace detail

/// Builds the entry for this system. `ddb-exp` truncates dexp^{-1} after ad^2, as in
/// the paper's runs; `ddb-exp-exact` and every symmetric or composed exp method use the
/// closed form (a truncated series breaks (dτ^{-1}_{-x})* = Ad*_{τ(x)} (dτ^{-1}_x)*,
/// which symmetry needs). On fixed-size groups the DDB methods use the Lagrangian form
/// when the system has a Lagrangian and the Hamiltonian form otherwise; on matrix groups
/// always the Hamiltonian form with the matrix-free Legendre solver. Throws
/// InvalidArgument naming the method if it does not apply.
template <class G>
std::unique_ptr<OneStepMethod<G>> makeMethod(const MethodInfo& method,
                                             std::shared_ptr<const LiePoissonSystem<G>> system) {
  const std::string name(method.name);
  if ((method.groups & groupFamilyOf<G>()) == 0) detail::throwNotAMethod<G>(name);
  if (!groupHasEigenbasis<G>() && needsEigenbasis(method)) detail::throwNeedsEigenbasis<G>(name);
  if (!groupHasOrbitPreconditioner<G>() && needsOrbitPreconditioner(method)) {
    detail::throwNeedsOrbitPreconditioner<G>(name);
  }
  if (method.needs_lagrangian && system->lagrangian() == nullptr) {
    throwInvalid("method", name, "needs a Lagrangian, which '" + system->name() + "' has not");
  }
  if (method.needs_scalar_metric) detail::requireScalarMetric(*system, name);
  LegendreForm form = LegendreForm::kHamiltonian;
  if constexpr (!isDynamicGroup<G>) {
    if (system->lagrangian()) form = LegendreForm::kLagrangian;
  }
  // On another backend's matrices only the rows of that family are built (the family check
  // above refused the others); the other kinds are not even compiled for such a group.
  constexpr bool kDenseOnly = groupFamilyOf<G>() != kBackendMatrixGroups;
  switch (method.kind) {
    case MethodKind::kDdb:
      return detail::withRetraction<G, Ddb>(method.retraction, system, form);
    case MethodKind::kLinearlyImplicitDdb:
      if constexpr (groupHasOrbitPreconditioner<G>()) {
        return detail::withRetraction<G, LinearlyImplicitDdb>(method.retraction, system, form);
      }
      break;
    case MethodKind::kSymmetricDdb:
      return detail::withRetraction<G, SymmetricDdb>(method.retraction, system, form);
    case MethodKind::kPaperSymmetricDdb:
      if constexpr (!isDynamicGroup<G>) {
        return detail::withRetraction<G, PaperSymmetricDdb>(method.retraction, system);
      }
      break;
    case MethodKind::kComposition: {
      const MethodInfo* base = findMethod(method.base);
      if (base == nullptr) throw std::logic_error("method table: no base for " + name);
      return std::make_unique<Composition<G>>(name, makeMethod<G>(*base, system),
                                              detail::schemeOf(method.scheme));
    }
    case MethodKind::kExplicitRk4:
      return std::make_unique<ExplicitRungeKutta<G, 4>>(system, kClassicalRk4);
    case MethodKind::kLobattoIIIC:
      if constexpr (!isDynamicGroup<G>) {
        return std::make_unique<ImplicitRungeKutta<G, 3>>(system, kLobattoIIIC3);
      } else {
        return std::make_unique<MatrixFreeImplicitRungeKutta<G, 3>>(system, kLobattoIIIC3);
      }
    case MethodKind::kReference:
      if constexpr (kDenseOnly) return detail::makeReferenceSolver<G>(system);
      break;
  }
  throw std::logic_error("method table: " + name + " cannot be built on this group");
}

/// makeMethod for a name of the table; InvalidArgument naming it if it is not one.
template <class G>
std::unique_ptr<OneStepMethod<G>> makeMethod(std::string_view name,
                                             std::shared_ptr<const LiePoissonSystem<G>> system) {
  const MethodInfo* method = findMethod(name);
  if (method == nullptr) detail::throwNotAMethod<G>(std::string(name));
  return makeMethod<G>(*method, std::move(system));
}

// The library compiles makeMethod once for its own groups (instantiations/method_table_*.cc),
// so that a program using them builds none of the methods itself, which is most of what
// compiling a call of makeMethod costs (docs/results/compile-costs.md). The groups are only
// named here, as what that compiled part holds; every other group (your own, SUNOn<X> on
// another backend) instantiates makeMethod where it calls it.
struct SO2;
template <class G>
struct DefiningRepresentation;
template <class G, class Representation>
struct SemidirectProduct;
using SE2 = SemidirectProduct<SO2, DefiningRepresentation<SO2>>;
struct SO3;
struct SE3;
struct SON;
template <class X>
struct SUNOn;
using SUN = SUNOn<Eigen::MatrixXcd>;
template <class X>
struct DualNumberSUNOn;
using DualNumberSUN = DualNumberSUNOn<Eigen::MatrixXcd>;
namespace detail {
/// SE(3) composed from SO(3)'s functions (groups/semidirect_product.h), named for the macro below.
using SE3Composed = SemidirectProduct<SO3, DefiningRepresentation<SO3>>;
}  // namespace detail

}  // namespace ddb

/// The explicit instantiations of makeMethod for G: with `extern` it declares them (below), with
/// nothing it defines them (instantiations/method_table_*.cc).
#define DDB_METHOD_TABLE_INSTANCE(PREFIX, G)                                        \
  PREFIX template std::unique_ptr<::ddb::OneStepMethod<G>> ddb::makeMethod<G>(      \
      const ::ddb::MethodInfo&, std::shared_ptr<const ::ddb::LiePoissonSystem<G>>); \
  PREFIX template std::unique_ptr<::ddb::OneStepMethod<G>> ddb::makeMethod<G>(      \
      std::string_view, std::shared_ptr<const ::ddb::LiePoissonSystem<G>>)

/// The same for a backend's groups, SU(N) and SU(N) ⋉ su(N)* with states of the matrix type X:
/// declared by the backend's header and defined in its compiled library
/// (cuda/cuda_method_table.h, distributed/distributed_method_table.h).
#define DDB_BACKEND_METHOD_TABLES_INSTANCE(PREFIX, X) \
  DDB_METHOD_TABLE_INSTANCE(PREFIX, ::ddb::SUNOn<X>); \
  DDB_METHOD_TABLE_INSTANCE(PREFIX, ::ddb::DualNumberSUNOn<X>)

// Declared for each table the library compiled: CMake's DDB_METHOD_TABLES, all by default,
// defines DDB_NO_COMPILED_METHOD_TABLE_<NAME> for each one it left out, whose methods a program
// then instantiates itself (CMakeLists.txt).
#ifndef DDB_NO_COMPILED_METHOD_TABLE_SE2
DDB_METHOD_TABLE_INSTANCE(extern, ::ddb::SE2);
#endif
#ifndef DDB_NO_COMPILED_METHOD_TABLE_SO3
DDB_METHOD_TABLE_INSTANCE(extern, ::ddb::SO3);
#endif
#ifndef DDB_NO_COMPILED_METHOD_TABLE_SE3
DDB_METHOD_TABLE_INSTANCE(extern, ::ddb::SE3);
#endif
#ifndef DDB_NO_COMPILED_METHOD_TABLE_SON
DDB_METHOD_TABLE_INSTANCE(extern, ::ddb::SON);
#endif
#ifndef DDB_NO_COMPILED_METHOD_TABLE_SUN
DDB_METHOD_TABLE_INSTANCE(extern, ::ddb::SUN);
#endif
#ifndef DDB_NO_COMPILED_METHOD_TABLE_DUAL_NUMBER_SUN
DDB_METHOD_TABLE_INSTANCE(extern, ::ddb::DualNumberSUN);
#endif
#ifndef DDB_NO_COMPILED_METHOD_TABLE_SE3_COMPOSED
DDB_METHOD_TABLE_INSTANCE(extern, ::ddb::detail::SE3Composed);
#endif
