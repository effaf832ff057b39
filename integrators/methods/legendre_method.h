// LegendreMethod: what every DDB-family method holds (GeometricIntegrators.jl style:
// the method's data, and its solver with the warm-start cache, kept apart from the
// step formula in the subclasses Ddb, SymmetricDdb and PaperSymmetricDdb).
#pragma once

#include <ddb/core/group_traits.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/integrators/methods/one_step_method.h>
#include <ddb/integrators/solvers/legendre.h>
#include <ddb/integrators/solvers/matrix_legendre.h>

#include <memory>
#include <string>
#include <type_traits>

namespace ddb {

/// The Legendre solver a retraction's group gets, chosen by its traits: Levenberg–Marquardt with
/// Jet Jacobians for small fixed-size groups, matrix-free iterations for matrix groups.
template <class R>
using LegendreSolverFor = std::conditional_t<isDynamicGroup<typename R::Group>,
                                             MatrixLegendreSolver<R>, DiscreteLegendreSolver<R>>;

template <class R>
class LegendreMethod : public OneStepMethod<typename R::Group> {
 public:
  using G = typename R::Group;
  using Dual = typename G::template Dual<double>;
  using Algebra = typename G::template Algebra<double>;

  LegendreMethod(std::shared_ptr<const LiePoissonSystem<G>> system, R retraction, LegendreForm form,
                 SolverOptions options)
      : system_(std::move(system)),
        retraction_(std::move(retraction)),
        legendre_(*system_, retraction_, form, options) {}
  LegendreMethod(const LegendreMethod&) = delete;  // legendre_ refers to retraction_
  LegendreMethod& operator=(const LegendreMethod&) = delete;

  void reset() override { legendre_.reset(); }
  void saveWarmStart(BinaryRecordWriter& out) const override { legendre_.saveWarmStart(out); }
  void loadWarmStart(BinaryRecordReader& in, const Dual& state) override {
    legendre_.loadWarmStart(in, state);
  }
  bool solvesEquations() const override { return true; }
  /// The last Legendre solve's fixed-point sweeps and Newton steps: the one solve of a step
  /// (subclasses that solve more add theirs).
  long lastStepIterations() const override {
    const LegendreStats& stats = legendre_.stats();
    return stats.fixed_point + stats.newton;
  }
  /// The Legendre solver, for its statistics (iterations of the last solve).
  const LegendreSolverFor<R>& legendreSolver() const { return legendre_; }
  LegendreSolverFor<R>& legendreSolver() { return legendre_; }

 protected:
  /// prefix + retraction name, with "-hamiltonian" for the Hamiltonian form.
  std::string nameWith(const std::string& prefix) const {
    return prefix + R::kName +
           (legendre_.form() == LegendreForm::kHamiltonian ? "-hamiltonian" : "");
  }

  std::shared_ptr<const LiePoissonSystem<G>> system_;
  R retraction_;
  LegendreSolverFor<R> legendre_;
};

}  // namespace ddb
