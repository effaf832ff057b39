// One step of a method on Zeitlin's fluid, N = 32..256, against one complex N×N product
// (zeitlin/gemm/<N>) in the same run: products per step = step time / product time
// (scripts/fluid_bench_table.py). State: the seeded random vorticity (seed 1, ‖W‖_F = √N),
// h = 0.02 ħ/‖P₀‖₂, Legendre tolerance 1e-12 relative. Counters: iterations (fixed-point
// sweeps and Newton steps), Krylov products, frozen refinements and mallocs per step. The
// timed steps are steps 10..109 of the trajectory from that state (stepFluid). At N = 512
// and 1024 only ddb-cay (α = 0.5) and the product run, over steps 10..29 (a step there
// takes up to seconds): zeitlin/ddb-cay/<N> at that h, beyond the dissipation's stability
// bound there (the energy rises), and zeitlin-resolved/ddb-cay/<N> at
// h = min(0.02 ħ/‖P₀‖₂, 4 ħ/(|α| ‖W₀‖₂²)) within it (docs/design/architecture.md, "Large N: the
// step's stability bound"; fluid-relax's default, systems/zeitlin_step_size.h). The BLAS thread
// count is the environment's (OPENBLAS_NUM_THREADS).
// The exact flows a damped or forced step adds, at every N beside the product:
// zeitlin-viscosity/<N> one ZeitlinViscousFlow::advance (ν = 1e-4, p = 2, γ = 0.01, on a rotating
// sphere), zeitlin-viscosity-implicit/<N> the same by the implicit scheme, zeitlin-forcing/<N> one
// ZeitlinStochasticForcingFlow::advance (band 10:2, or 2:1 at N = 32); a Strang step takes two of
// each.
// Magnetohydrodynamics on the sphere (systems/zeitlin_mhd.h) beside them: zeitlin-mhd/<method>/<N>,
// one step of ddb-cay, sddb-cay or rk4 (α = 0.5) on the magnetic fluid (stepMhd).
#include "zeitlin_bench.h"

#include <benchmark/benchmark.h>
#include <ddb/integrators/methods/ddb.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/symmetric_ddb.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_forcing.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_mhd.h>
#include <ddb/systems/zeitlin_step_size.h>
#include <ddb/systems/zeitlin_viscosity.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include "malloc_counter.h"

namespace ddb::bench {
namespace {

using Matrix = Eigen::MatrixXcd;
constexpr int kSizes[] = {32, 64, 128, 256};
constexpr int kLargeSizes[] = {512, 1024};
constexpr double kTolerance = 1e-12;
constexpr long kWarmUp = 10;
constexpr long kWindow = 100;
constexpr long kLargeWindow = 20;

template <class G>
std::unique_ptr<OneStepMethod<G>> makeBenchMethod(
    const std::string& name, std::shared_ptr<const LiePoissonSystem<G>> system) {
  SolverOptions options;
  options.relative_tolerance = kTolerance;
  if (name == "ddb-cay") {
    return std::make_unique<Ddb<Cayley<G>>>(system, Cayley<G>(), LegendreForm::kHamiltonian,
                                            options);
  }
  if (name == "sddb-cay") {
    return std::make_unique<SymmetricDdb<Cayley<G>>>(system, Cayley<G>(),
                                                     LegendreForm::kHamiltonian, options);
  }
  return makeMethod<G>(name, system);
}

// The Legendre statistics of the method's last step, for the single-step DDB methods of
// each retraction (nullptr for explicit methods and compositions).
template <class G>
const LegendreStats* legendreStats(const OneStepMethod<G>& method) {
  if (const auto* m = dynamic_cast<const LegendreMethod<Cayley<G>>*>(&method)) {
    return &m->legendreSolver().stats();
  }
  if constexpr (groupHasEigenbasis<G>()) {
    if (const auto* m = dynamic_cast<const LegendreMethod<Exponential<G>>*>(&method)) {
      return &m->legendreSolver().stats();
    }
    if (const auto* m = dynamic_cast<const LegendreMethod<TruncatedExponential<G>>*>(&method)) {
      return &m->legendreSolver().stats();
    }
  }
  return nullptr;
}

template <class G>
void stepOn(benchmark::State& state, std::shared_ptr<const LiePoissonSystem<G>> system,
            const typename G::template Dual<double>& W0, double h, const std::string& method_name,
            long window) {
  auto method = makeBenchMethod<G>(method_name, system);
  typename G::template Dual<double> W = W0;
  long k = 0;  // the step of the trajectory from W0
  // Untimed steps from W0: the first sizes the workspaces, the others fill the Legendre
  // predictor's history (its six corrections), as in every run longer than kWarmUp steps.
  const auto restart = [&] {
    method->reset();
    W = W0;
    for (k = 0; k < kWarmUp; ++k) method->advance(W, k * h, h);
  };
  long timed = 0, iterations = 0, krylov = 0, refinements = 0, allocated = 0;
  // Whole windows: the timed steps are steps kWarmUp .. kWarmUp + kWindow − 1 of the
  // trajectory, each as often, whatever the number of iterations Google Benchmark chooses
  // (the fluid relaxes as it goes, and later steps are cheaper to predict).
  while (state.KeepRunningBatch(window)) {
    state.PauseTiming();
    restart();
    state.ResumeTiming();
    for (long j = 0; j < window; ++j, ++k) {
      const long mallocs = tools::mallocCount();
      try {
        method->advance(W, k * h, h);
      } catch (const SolveFailure& failure) {
        state.SkipWithError(failure.what());
        return;
      }
      allocated += tools::mallocCount() - mallocs;
      benchmark::DoNotOptimize(&W);
      ++timed;
      if (const LegendreStats* stats = legendreStats(*method)) {
        iterations += stats->fixed_point + stats->newton;
        krylov += stats->krylov;
        refinements += stats->refinements;
      }
    }
  }
  const double per_step = 1.0 / static_cast<double>(timed);
  state.counters["iterations_per_step"] = static_cast<double>(iterations) * per_step;
  state.counters["krylov_per_step"] = static_cast<double>(krylov) * per_step;
  state.counters["refinements_per_step"] = static_cast<double>(refinements) * per_step;
  state.counters["allocs_per_step"] = static_cast<double>(allocated) * per_step;
}

void stepFluid(benchmark::State& state, const std::string& method_name, double alpha, int n,
               long window, bool resolved) {
  const Matrix W0 = randomVorticity(n, 1);
  const double h = resolved ? zeitlinDefaultStep(W0, alpha) : zeitlinContractionStep(W0);
  stepOn<SUN>(state, makeZeitlinFluid(n, alpha), W0, h, method_name, window);
}

// The magnetic fluid (systems/zeitlin_mhd.h) from W0, the fluid's seeded vorticity, and Θ0 the
// seeded random potential scaled so that ‖ΔΘ0‖₂ = ‖Δ⁻¹W0‖₂ (ξ's two parts alike), at half the
// fluid's h: zeitlin-mhd/<method>/<N>, products per step beside the fluid's (issue 57).
void stepMhd(benchmark::State& state, const std::string& method_name, double alpha, int n) {
  const Matrix W0 = randomVorticity(n, 1), T = randomVorticity(n, 2);
  const HoppeYauLaplacian laplacian(n);
  Matrix P(n, n), B(n, n);
  laplacian.solve(W0, P);
  laplacian.apply(T, B);
  const auto spectral = [](const Matrix& x) {
    return Eigen::JacobiSVD<Matrix>(x).singularValues()(0);
  };
  const DualMatrix<Matrix> mu0 = zeitlinMhdState(W0, spectral(P) / spectral(B) * T);
  stepOn<DualNumberSUN>(state, makeZeitlinMhd(n, alpha), mu0, 0.5 * zeitlinContractionStep(W0),
                        method_name, kWindow);
}

void product(benchmark::State& state, int n) {
  const Matrix A = randomVorticity(n, 2), B = randomVorticity(n, 3);
  Matrix C(n, n);
  for (auto _ : state) {
    MatrixBackend<Matrix>::multiply(A, B, C);  // the step's own product, on the same threads
    benchmark::DoNotOptimize(C.data());
  }
}

/// One advance of `flow` over h = 0.01 per iteration, each from the seeded vorticity: a damping
/// applied again and again would take the small scales into subnormal numbers, a hundred times
/// slower to compute with, which no run meets (integrate() and Relaxation flush them after each
/// step: docs/results/benchmarks.md, "Subnormal numbers: the flush after each step").
void exactFlow(benchmark::State& state,
               const std::function<std::unique_ptr<ExactFlow<SUN>>()>& make, int n) {
  const auto flow = make();
  const Matrix W0 = randomVorticity(n, 1);
  Matrix W = W0;
  flow->advance(W, 0.01);  // sizes what it sizes once
  long allocated = 0, steps = 0;
  for (auto _ : state) {
    state.PauseTiming();
    W = W0;
    state.ResumeTiming();
    const long mallocs = tools::mallocCount();
    flow->advance(W, 0.01);
    allocated += tools::mallocCount() - mallocs;
    ++steps;
    benchmark::DoNotOptimize(W.data());
  }
  state.counters["allocs_per_step"] = static_cast<double>(allocated) / static_cast<double>(steps);
}

void registerExactFlows(int n) {
  const std::string size = "/" + std::to_string(n);
  const auto viscousBy = [n](ZeitlinViscousScheme scheme) {
    ZeitlinViscosity viscosity;
    viscosity.viscosity = 1e-4;
    viscosity.order = 2;
    viscosity.drag = 0.01;
    viscosity.scheme = scheme;
    return std::unique_ptr<ExactFlow<SUN>>(
        std::make_unique<ZeitlinViscousFlow>(n, viscosity, zeitlinPlanetaryVorticity(n, 2.0)));
  };
  const auto viscous = [viscousBy] { return viscousBy(ZeitlinViscousScheme::kExact); };
  const auto implicit = [viscousBy] { return viscousBy(ZeitlinViscousScheme::kImplicit); };
  const auto forced = [n] {
    ZeitlinStochasticForcing forcing;
    forcing.band_centre = n > 32 ? 10 : 2;
    forcing.band_half_width = n > 32 ? 2 : 1;
    forcing.rate = 1e-3;
    return std::unique_ptr<ExactFlow<SUN>>(
        std::make_unique<ZeitlinStochasticForcingFlow>(n, forcing));
  };
  benchmark::RegisterBenchmark(("zeitlin-viscosity" + size).c_str(), exactFlow,
                               std::function<std::unique_ptr<ExactFlow<SUN>>()>(viscous), n)
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark(("zeitlin-viscosity-implicit" + size).c_str(), exactFlow,
                               std::function<std::unique_ptr<ExactFlow<SUN>>()>(implicit), n)
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark(("zeitlin-forcing" + size).c_str(), exactFlow,
                               std::function<std::unique_ptr<ExactFlow<SUN>>()>(forced), n)
      ->Unit(benchmark::kMicrosecond);
}

}  // namespace

void registerZeitlinBenchmarks() {
  for (int n : kSizes) {
    const std::string size = "/" + std::to_string(n);
    benchmark::RegisterBenchmark(("zeitlin/gemm" + size).c_str(), product, n)
        ->Unit(benchmark::kMicrosecond);
    for (const MethodInfo& info : kMethods) {  // the table's matrix-group methods
      if ((info.groups & kMatrixGroups) == 0 || info.kind == MethodKind::kReference) continue;
      const std::string method(info.name);
      benchmark::RegisterBenchmark(("zeitlin/" + method + size).c_str(), stepFluid, method, 0.5, n,
                                   kWindow, false)
          ->Unit(benchmark::kMicrosecond);
    }
    benchmark::RegisterBenchmark(("zeitlin-euler/ddb-cay" + size).c_str(), stepFluid,
                                 std::string("ddb-cay"), 0.0, n, kWindow, false)
        ->Unit(benchmark::kMicrosecond);
    for (const std::string method : {"ddb-cay", "sddb-cay", "ddb-exp-exact", "sddb-exp", "rk4"}) {
      benchmark::RegisterBenchmark(("zeitlin-mhd/" + method + size).c_str(), stepMhd, method, 0.5,
                                   n)
          ->Unit(benchmark::kMicrosecond);
    }
    registerExactFlows(n);
  }
  // One window each: a window outlasts Google Benchmark's minimum time.
  for (int n : kLargeSizes) {
    const std::string size = "/" + std::to_string(n);
    benchmark::RegisterBenchmark(("zeitlin/gemm" + size).c_str(), product, n)
        ->Unit(benchmark::kMicrosecond);
    for (const bool resolved : {false, true}) {
      const std::string name = resolved ? "zeitlin-resolved/ddb-cay" : "zeitlin/ddb-cay";
      benchmark::RegisterBenchmark((name + size).c_str(), stepFluid, std::string("ddb-cay"), 0.5, n,
                                   kLargeWindow, resolved)
          ->Unit(benchmark::kMicrosecond);
    }
    registerExactFlows(n);
  }
}

}  // namespace ddb::bench
