// One step (h = 0.1) of every registry method on the rigid body of Scenario A and on
// the default heavy top (include/ddb/systems/paper_scenarios.h), named rigid_body/<method> and
// heavy_top/<method> (docs/file-formats.md), with Boost.Odeint's runge_kutta4 on the same vector
// field as the peer `rigid_body/odeint-rk4`. The counter allocs_per_step counts mallocs per
// step (tools/malloc_counter.h). The fluid's benchmarks are in zeitlin_bench.cc. Compare methods by
// ratios of times within one run (scripts/bench_ratios.py).
#include <benchmark/benchmark.h>
#include <ddb/integrators/method_registry.h>
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

// Steps along a real trajectory from mu0, restarting every 300 steps, so that the
// warm starts and states are those of a run; counts heap allocations per step.
template <class Dual>
void runSteps(benchmark::State& state, const Dual& mu0,
              const std::function<Dual(const Dual&, double)>& step) {
  Dual mu = mu0;
  int k = 0;
  long steps = 0;
  const long before = tools::mallocCount();
  for (auto _ : state) {
    mu = step(mu, k * kH);
    benchmark::DoNotOptimize(mu.data());
    if (++k == kScenarioSteps) {
      k = 0;
      mu = mu0;
    }
    ++steps;
  }
  state.counters["allocs_per_step"] =
      static_cast<double>(tools::mallocCount() - before) / static_cast<double>(steps);
}

// One benchmark per applicable registry method, named <prefix>/<method>.
template <class G>
void registerMethods(const std::string& prefix, std::shared_ptr<const LiePoissonSystem<G>> system,
                     const typename G::template Dual<double>& mu0) {
  using Dual = typename G::template Dual<double>;
  for (const auto& name : methodNames()) {
    if (!methodApplies(name, *system)) continue;
    benchmark::RegisterBenchmark((prefix + "/" + name).c_str(), [=](benchmark::State& state) {
      auto method = makeMethod<G>(name, system);
      method->reset();
      runSteps<Dual>(state, mu0, [&](const Dual& mu, double t) { return method->step(mu, t, kH); });
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

}  // namespace

int main(int argc, char** argv) {
  const RigidBodyScenario& a = rigidBodyScenario("A");
  const auto body = a.system();
  registerMethods<SO3>("rigid_body", body, a.mu0());
  benchmark::RegisterBenchmark("rigid_body/odeint-rk4", BM_OdeintRk4, body, a.mu0());
  const HeavyTopSetup top;
  registerMethods<SE3>("heavy_top", top.system(), top.mu0);
  bench::registerZeitlinBenchmarks();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
