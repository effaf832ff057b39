// ddb-compare's command line (docs/reference/command-lines-and-files.md, "ddb-compare"): the
// options, --help with every system, scenario and method, and the settings every system shares,
// validated (bad input is a UsageError naming the flag, docs/reference/bad-inputs.md).
#pragma once

#include <ddb/integrators/drivers/relax.h>

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "common/cli.h"
#include "common/logging.h"
#include "common/relax_flags.h"

namespace ddb::compare {

constexpr const char* kApp = "ddb-compare";

/// The most steps a run or the reference may take (docs/reference/bad-inputs.md): more is bad
/// input.
constexpr long kMaxSteps = 1000000000L;
// Each timed run is shorter than 1 s: 1000 of them per method bound the timing to
// minutes, where 1e9 would take years.
constexpr int kMaxRepeat = 1000;

/// The options as given (numbers as text, parsed and checked by commonSettings() and the
/// problems, so that messages quote the text).
struct Options {
  std::string system = "rigid-body", scenario = "A", methods, out = "results", sweep;
  std::string h = "0.1", t_end, alpha, mgl, inertia, omega0, mu0, chi, metric, mass;
  // The matrix systems (manakov, zeitlin); --n's default is the system's.
  long n = 0;
  std::uint64_t seed = 1;
  std::string j, mu0_file, init = "random", init_file;
  app::RelaxFlags relax;  // --until-steady, --adaptive, --adaptive-tol
  bool plot = false;
  bool overwrite = false;  // a new run may replace another run's files in --out
  int repeat = 5;
  long every = 1;
  app::LogFlags log;
};

/// Adds every option of Options, --version and the --help footer.
void addOptions(CLI::App& cli, Options& o);

struct Sweep {
  double h_min = 0, h_max = 0;
  int count = 0;
  std::vector<double> steps() const {
    std::vector<double> hs;
    for (int i = 0; i < count; ++i) {
      const double s = count == 1 ? 0.0 : double(i) / (count - 1);
      hs.push_back(h_max * std::pow(h_min / h_max, s));  // log-spaced, largest first
    }
    return hs;
  }
};

/// What every system shares, validated.
struct Settings {
  double h = 0.0, t_end = 0.0;
  long steps = 0;
  Sweep sweep;
  std::vector<std::string> methods;
  std::filesystem::path out;
  /// Every run is relax()'s (docs/guide/steady-states.md): --until-steady, --adaptive and
  /// --adaptive-tol, capped by the step count or, with --adaptive, by t_end.
  RelaxOptions relax;

  /// --until-steady or --adaptive given: the runs may end before t_end, each at its own time.
  bool relaxing() const { return relax.tolerance > 0 || relax.control.adaptive; }
};

/// round(t_end / h), at least 1; more than kMaxSteps is bad input naming `flag` = `text`.
long stepCount(double t_end, double h, const std::string& flag, const std::string& text);

/// `text` parsed as `flag`'s number, or `fallback` if the flag was not given.
double optionalNumber(const std::string& flag, const std::string& text, double fallback);

/// `text` parsed as `flag`'s N numbers, or `fallback` if the flag was not given.
template <int N>
Eigen::Matrix<double, N, 1> optionalVector(const std::string& flag, const std::string& text,
                                           const Eigen::Matrix<double, N, 1>& fallback) {
  return text.empty() ? fallback : app::parseVector<N>(flag, text);
}

/// h, t-end, steps, sweep and method names; `default_t_end` is the system's or scenario's.
Settings commonSettings(const Options& o, double default_t_end);

}  // namespace ddb::compare
