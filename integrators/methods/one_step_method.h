// OneStepMethod: the interface every integrator implements; and takeStep(), the one way a loop
// steps one (integrate() and Relaxation alike, in integrators/drivers/).
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/errors.h>
#include <ddb/core/matrix_backend.h>

#include <Eigen/Core>
#include <cmath>
#include <string>

namespace ddb {

template <class G>
class OneStepMethod {
 public:
  using Group = G;
  using Dual = typename G::template Dual<double>;

  virtual ~OneStepMethod() = default;
  virtual std::string name() const = 0;
  /// Forgets warm-start data; integrate() calls it before a new trajectory.
  virtual void reset() {}
  /// The warm start: everything the next step depends on besides (μ, t, h), e.g. the
  /// Legendre solver's predictor history. A method loaded with what another instance saved
  /// takes, from the same μ, t and h, the same steps to the bit (a resumed run continues the
  /// uninterrupted one exactly: docs/reference/command-lines-and-files.md, "Checkpoints"). Methods
  /// without one write nothing.
  virtual void saveWarmStart(BinaryRecordWriter&) const {}
  /// Restores what saveWarmStart wrote, for a run that continues from `state` (a warm start
  /// that holds matrices reads them in its shape and, distributed, layout); throws
  /// CorruptRecord if it is not such a record.
  virtual void loadWarmStart(BinaryRecordReader&, const Dual& /*state*/) {}
  /// μ(t + h) from μ(t). Throws SolveFailure (step index -1) if an implicit solve fails.
  virtual Dual step(const Dual& mu, double t, double h) = 0;
  /// μ ← μ(t + h) in place; integrate() calls this. A method that overrides it can step
  /// without allocating (an N×N state returned by value allocates): on matrix groups every
  /// method of the table does (tests/unit/test_allocations.cc checks each).
  virtual void advance(Dual& mu, double t, double h) { mu = step(mu, t, h); }

  /// Whether the method solves equations in its steps (an implicit method: the DDB family,
  /// Lobatto IIIC); false for an explicit one, whose lastStepIterations() is always 0.
  virtual bool solvesEquations() const { return false; }
  /// The iterations the last step's solves took: fixed-point sweeps plus Newton steps, summed
  /// over every equation the step solved (a composition's substeps, the dissipative factor of
  /// a linearly implicit step). Inner linear iterations (GMRES, CG) are not counted. What the
  /// apps report as iterations per step (docs/reference/command-lines-and-files.md, "fluid-relax").
  virtual long lastStepIterations() const { return 0; }

 protected:
  /// step() of a method whose advance() is the in-place step.
  Dual stepInPlace(const Dual& mu, double t, double h) {
    Dual next = mu;
    advance(next, t, h);
    return next;
  }
};

/// One step of the method, as every loop of the library takes it (integrate(), Relaxation): μ ←
/// μ(t + h), then a state that is not finite is a NonFiniteState (step index -1, which the loop
/// sets), and subnormal entries are flushed to zero. A decaying component that reaches the
/// subnormal range stays there (each step rounds it back to a few multiples of 2^-1074), and
/// every later step would pay the CPU's slow path on it: 1.4 us against 0.065 us a rigid-body
/// ddb-cay step (issue 42). A run whose states stay out of that range is unchanged to the bit;
/// a flushed entry moves by less than 2^-1022.
template <class G>
void takeStep(OneStepMethod<G>& method, typename G::template Dual<double>& mu, double t, double h) {
  using B = MatrixBackend<typename G::template Dual<double>>;
  method.advance(mu, t, h);
  if (!B::allFinite(mu)) throw NonFiniteState(method.name(), -1, t, h, B::describe(mu));
  B::flushSubnormals(mu);
}

}  // namespace ddb

// integrate() and Trajectory live in the drivers' layer since 0.3.0; this header includes them for
// the programs that included it for them (docs/guide/getting-started.md at 0.2.0), until 0.4.0
// (CHANGELOG, "Deprecated"). The one include of a higher layer that check_layers allows.
#include <ddb/integrators/drivers/integrate.h>
