// One step of each method on the rigid body of Scenario A (h = 0.1), named
// rigid_body/<method> (DESIGN.md §5), with Boost.Odeint's runge_kutta4 on the same
// vector field as the peer `rigid_body/odeint-rk4`. The counter allocs_per_step
// counts global operator new calls per step. Compare methods by ratios of times
// within one run (scripts/bench_ratios.py).
#include <benchmark/benchmark.h>

#include <atomic>
#include <boost/numeric/odeint.hpp>
#include <cstdlib>
#include <functional>
#include <memory>
#include <new>

#include "groups/cayley.h"
#include "groups/exponential.h"
#include "integrators/ddb.h"
#include "integrators/reference.h"
#include "integrators/runge_kutta.h"
#include "systems/rigid_body.h"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size)) return p;
  throw std::bad_alloc();
}
// Counting replacement of the global allocator (malloc-backed, so free matches).
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace {

using namespace ddb;

const Eigen::Vector3d kInertia(1.0, 1.3, 0.5);
const Eigen::Vector3d kM0 = kInertia.cwiseProduct(Eigen::Vector3d(0.0, 0.05, 1.0));
constexpr double kH = 0.1;
constexpr int kScenarioSteps = 300;  // Scenario A: t in [0, 30]

std::shared_ptr<const LiePoissonSystem<SO3>> body() {
  static const auto system = makeRigidBody(kInertia, 0.5);
  return system;
}

// Steps along Scenario A's trajectory, restarting every 300 steps, so that the
// warm starts and states are those of a real run.
void runSteps(benchmark::State& state,
              const std::function<Eigen::Vector3d(const Eigen::Vector3d&, double)>& step) {
  Eigen::Vector3d mu = kM0;
  int k = 0;
  long steps = 0;
  const long before = g_allocations.load();
  for (auto _ : state) {
    mu = step(mu, k * kH);
    benchmark::DoNotOptimize(mu.data());
    if (++k == kScenarioSteps) {
      k = 0;
      mu = kM0;
    }
    ++steps;
  }
  state.counters["allocs_per_step"] =
      static_cast<double>(g_allocations.load() - before) / static_cast<double>(steps);
}

void methodBenchmark(benchmark::State& state, OneStepMethod<SO3>& method) {
  method.reset();
  runSteps(state, [&](const Eigen::Vector3d& mu, double t) { return method.step(mu, t, kH); });
}

void BM_DdbCayley(benchmark::State& state) {
  Ddb<Cayley<SO3>> method(body());
  methodBenchmark(state, method);
}
void BM_DdbExpTruncated(benchmark::State& state) {
  Ddb<TruncatedExponential<SO3>> method(body(), TruncatedExponential<SO3>(2));
  methodBenchmark(state, method);
}
void BM_DdbExpExact(benchmark::State& state) {
  Ddb<Exponential<SO3>> method(body());
  methodBenchmark(state, method);
}
void BM_DdbCayleyHamiltonian(benchmark::State& state) {
  Ddb<Cayley<SO3>> method(body(), Cayley<SO3>(), LegendreForm::kHamiltonian);
  methodBenchmark(state, method);
}
void BM_Rk4(benchmark::State& state) {
  ExplicitRungeKutta<SO3, 4> method(body(), kClassicalRk4);
  methodBenchmark(state, method);
}
void BM_LobattoIIIC(benchmark::State& state) {
  ImplicitRungeKutta<SO3, 3> method(body(), kLobattoIIIC3);
  methodBenchmark(state, method);
}
void BM_Reference(benchmark::State& state) {
  ReferenceSolver<SO3> method(body());
  methodBenchmark(state, method);
}
void BM_OdeintRk4(benchmark::State& state) {
  using State = OdeintSystem<SO3>::State;
  boost::numeric::odeint::runge_kutta4<State> stepper;
  const OdeintSystem<SO3> rhs{*body()};
  runSteps(state, [&](const Eigen::Vector3d& mu, double t) {
    State x;
    Eigen::Map<Eigen::Vector3d>(x.data()) = mu;
    stepper.do_step(rhs, x, t, kH);
    return Eigen::Vector3d(Eigen::Map<const Eigen::Vector3d>(x.data()));
  });
}

BENCHMARK(BM_DdbCayley)->Name("rigid_body/ddb-cay");
BENCHMARK(BM_DdbExpTruncated)->Name("rigid_body/ddb-exp");
BENCHMARK(BM_DdbExpExact)->Name("rigid_body/ddb-exp-exact");
BENCHMARK(BM_DdbCayleyHamiltonian)->Name("rigid_body/ddb-cay-hamiltonian");
BENCHMARK(BM_Rk4)->Name("rigid_body/rk4");
BENCHMARK(BM_LobattoIIIC)->Name("rigid_body/lobatto3c");
BENCHMARK(BM_Reference)->Name("rigid_body/reference");
BENCHMARK(BM_OdeintRk4)->Name("rigid_body/odeint-rk4");

}  // namespace

BENCHMARK_MAIN();
