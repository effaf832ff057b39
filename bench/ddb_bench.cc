// One step (h = 0.1) of every method of the method table on the rigid body of Scenario A and on
// the default heavy top (systems/paper_scenarios.h), named rigid_body/<method> and
// heavy_top/<method> (docs/reference/command-lines-and-files.md), the same heavy top on SE(3)
// composed from SO(3) (SemidirectProduct<SO3>) as heavy_top_composed/<method>, with Boost.Odeint's
// runge_kutta4 on the same vector field as the peer `rigid_body/odeint-rk4`, and RK4 written out by
// hand as the floor `rigid_body/rk4-handwritten`. The counter allocs_per_step counts mallocs per
// step (tools/malloc_counter.h). The fluid's benchmarks are in zeitlin_bench.cc. Compare methods by
// ratios of times within one run (scripts/bench_ratios.py).
#include <benchmark/benchmark.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/reference.h>
#include <ddb/systems/heavy_top.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/rigid_body.h>

#include <boost/numeric/odeint.hpp>
#include <cstdlib>
#include <functional>
#include <memory>

#include "malloc_counter.h"
#include "zeitlin_bench.h"

namespace {

using namespace ddb;

constexpr double kH = 0.1;
constexpr int kScenarioSteps = 300;  // Scenario A: t in [0, 30]

// Steps along a real trajectory from mu0, restarting every 300 steps (calling `restart`,
// as a new run would), so that the warm starts and states are those of a run; counts heap
// allocations per step and, when `stats` reports the Legendre solve of the last step, the
// mean Newton iterations and predictor sweeps.
template <class Dual>
void runSteps(benchmark::State& state, const Dual& mu0,
              const std::function<Dual(const Dual&, double)>& step,
              const std::function<const LegendreStats*()>& stats = nullptr,
              const std::function<void()>& restart = nullptr) {
  Dual mu = mu0;
  int k = 0;
  long steps = 0, iterations = 0, sweeps = 0;
  const long before = tools::mallocCount();
  for (auto _ : state) {
    mu = step(mu, k * kH);
    benchmark::DoNotOptimize(mu.data());
    if (stats) {
      const LegendreStats* last = stats();
      iterations += last->newton;
      sweeps += last->fixed_point;
    }
    if (++k == kScenarioSteps) {
      k = 0;
      mu = mu0;
      if (restart) restart();
    }
    ++steps;
  }
  const double per_step = 1.0 / static_cast<double>(steps);
  state.counters["allocs_per_step"] = static_cast<double>(tools::mallocCount() - before) * per_step;
  if (stats) {
    state.counters["newton_per_step"] = static_cast<double>(iterations) * per_step;
    state.counters["sweeps_per_step"] = static_cast<double>(sweeps) * per_step;
  }
}

// The statistics of a DDB-family method's last Legendre solve (one solve per step), or
// nullptr for the other methods (the compositions run several solves per step).
template <class G, class R>
std::function<const LegendreStats*()> statsReaderFor(const OneStepMethod<G>& method) {
  const auto* legendre = dynamic_cast<const LegendreMethod<R>*>(&method);
  if (legendre == nullptr) return nullptr;
  return [legendre] { return &legendre->legendreSolver().stats(); };
}
template <class G>
std::function<const LegendreStats*()> statsReader(const OneStepMethod<G>& method) {
  if (auto reader = statsReaderFor<G, Cayley<G>>(method)) return reader;
  if (auto reader = statsReaderFor<G, Exponential<G>>(method)) return reader;
  return statsReaderFor<G, TruncatedExponential<G>>(method);
}

// One benchmark per applicable method of the table, named <prefix>/<method>.
template <class G>
void registerMethods(const std::string& prefix, std::shared_ptr<const LiePoissonSystem<G>> system,
                     const typename G::template Dual<double>& mu0) {
  using Dual = typename G::template Dual<double>;
  for (const auto& name : methodNames()) {
    if (!methodApplies(name, *system)) continue;
    benchmark::RegisterBenchmark((prefix + "/" + name).c_str(), [=](benchmark::State& state) {
      auto method = makeMethod<G>(name, system);
      method->reset();
      runSteps<Dual>(
          state, mu0, [&](const Dual& mu, double t) { return method->step(mu, t, kH); },
          statsReader(*method), [&] { method->reset(); });
    });
  }
}

// Boost.Odeint's runge_kutta4 on the same vector field: the peer of our rk4.
void BM_OdeintRk4(benchmark::State& state, std::shared_ptr<const LiePoissonSystem<SO3>> body,
                  Eigen::Vector3d mu0) {
  using State = OdeintSystem<SO3>::State;
  boost::numeric::odeint::runge_kutta4<State> stepper;
  const OdeintSystem<SO3> rhs{*body, 3, 1};
  runSteps<Eigen::Vector3d>(state, mu0, [&](const Eigen::Vector3d& mu, double t) {
    State x;
    Eigen::Map<Eigen::Vector3d>(x.data()) = mu;
    stepper.do_step(rhs, x, t, kH);
    return Eigen::Vector3d(Eigen::Map<const Eigen::Vector3d>(x.data()));
  });
}

// The floor reference: RK4 written out by hand on the rigid body's formula (eq. (3.6)),
// Ṁ = M × Ω + α M × (M × Ω), Ω = 𝕀⁻¹M, with no framework in between.
void BM_HandwrittenRk4(benchmark::State& state, Eigen::Vector3d inertia, double alpha,
                       Eigen::Vector3d mu0) {
  const Eigen::Vector3d inverse = inertia.cwiseInverse();
  const auto field = [&](const Eigen::Vector3d& m) -> Eigen::Vector3d {
    const Eigen::Vector3d turn = m.cross(inverse.cwiseProduct(m));
    return turn + alpha * m.cross(turn);
  };
  runSteps<Eigen::Vector3d>(state, mu0, [&](const Eigen::Vector3d& m, double) {
    const Eigen::Vector3d k1 = field(m);
    const Eigen::Vector3d k2 = field(m + (0.5 * kH) * k1);
    const Eigen::Vector3d k3 = field(m + (0.5 * kH) * k2);
    const Eigen::Vector3d k4 = field(m + kH * k3);
    return Eigen::Vector3d(m + (kH / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4));
  });
}

}  // namespace

int main(int argc, char** argv) {
  const RigidBodyScenario& a = rigidBodyScenario("A");
  const auto body = a.system();
  registerMethods<SO3>("rigid_body", body, a.mu0());
  benchmark::RegisterBenchmark("rigid_body/odeint-rk4", BM_OdeintRk4, body, a.mu0());
  benchmark::RegisterBenchmark("rigid_body/rk4-handwritten", BM_HandwrittenRk4, a.inertia, a.alpha,
                               a.mu0());
  const HeavyTopSetup top;
  registerMethods<SE3>("heavy_top", top.system(), top.mu0);
  registerMethods<SemidirectProduct<SO3>>(
      "heavy_top_composed",
      makeHeavyTopOn<SemidirectProduct<SO3>>(top.inertia, top.mgl, top.chi, top.alpha, top.metric),
      top.mu0);
  bench::registerZeitlinBenchmarks();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
