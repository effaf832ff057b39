// The C++ peer of bench/python_overhead.py (docs/results/python-overhead.md, "Speed"): the run that
// ddb.integrate(system, method, mu0, h, steps) makes, written in C++ as a user would
// (makeMethod, integrate, every state kept in a buffer sized beforehand), timed over
// `repeats` runs. Prints one JSON object: {"system", "method", "steps", "seconds": [...]}.
//
// Usage: ddb-python-peer rigid-body|zeitlin METHOD STEPS H REPEATS [N]
// The rigid body is Scenario A's, the fluid zeitlin(N, 0.5) from zeitlinVorticity random seed 1.
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

template <class G>
std::vector<double> timeRuns(std::shared_ptr<const ddb::LiePoissonSystem<G>> system,
                             const std::string& name, const typename G::template Dual<double>& mu0,
                             long steps, double h, int repeats) {
  using Dual = typename G::template Dual<double>;
  std::vector<double> seconds;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    auto method = ddb::makeMethod<G>(name, system);
    std::vector<double> times(static_cast<std::size_t>(steps + 1));
    std::vector<Dual> states(static_cast<std::size_t>(steps + 1), mu0);
    ddb::integrate(*method, mu0, 0.0, h, steps, [&](long k, double t, const Dual& mu) {
      times[static_cast<std::size_t>(k)] = t;
      states[static_cast<std::size_t>(k)] = mu;
    });
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return seconds;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 6) {
    std::fprintf(stderr, "usage: %s rigid-body|zeitlin METHOD STEPS H REPEATS [N]\n", argv[0]);
    return 2;
  }
  const std::string system = argv[1], method = argv[2];
  const long steps = std::atol(argv[3]);
  const double h = std::atof(argv[4]);
  const int repeats = std::atoi(argv[5]);
  if (repeats < 1) {
    std::fprintf(stderr, "REPEATS = %s must be >= 1\n", argv[5]);
    return 2;
  }
  std::vector<double> seconds;
  if (system == "rigid-body") {
    const ddb::RigidBodyScenario& a = ddb::rigidBodyScenario("A");
    seconds = timeRuns<ddb::SO3>(a.system(), method, a.mu0(), steps, h, repeats);
  } else if (system == "zeitlin" && argc > 6) {
    const long n = std::atol(argv[6]);
    seconds = timeRuns<ddb::SUN>(ddb::makeZeitlinFluid(n, 0.5), method, ddb::randomVorticity(n, 1),
                                 steps, h, repeats);
  } else {
    std::fprintf(stderr, "unknown system %s (zeitlin needs N)\n", system.c_str());
    return 2;
  }
  std::printf("{\"system\": \"%s\", \"method\": \"%s\", \"steps\": %ld, \"seconds\": [", argv[1],
              argv[2], steps);
  for (std::size_t i = 0; i < seconds.size(); ++i) {
    std::printf("%s%.9g", i ? ", " : "", seconds[i]);
  }
  std::printf("]}\n");
}
