// fluid-relax: relaxes Zeitlin's SU(N) fluid on the sphere (docs/conventions.md §2) with
// double-bracket dissipation towards a steady flow, with the command line and files of
// docs/file-formats.md ("fluid-relax"). Exit status (apps/common/exit_status.h): 2 for
// bad input, checked in full before anything is written; 1 if a step failed (history.csv
// keeps every state before it) or a file could not be written.
#include <ddb/integrators/method_table.h>
#include <ddb/integrators/run.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <vector>

#include "common/atomic_file.h"
#include "common/cli.h"
#include "common/csv_row.h"
#include "common/energy_rises.h"
#include "common/exit_status.h"
#include "common/format.h"
#include "common/json.h"
#include "common/logging.h"
#include "common/plot.h"
#include "common/progress.h"

namespace {

using namespace ddb;
namespace fs = std::filesystem;
using Matrix = Eigen::MatrixXcd;

constexpr const char* kApp = "fluid-relax";
// The app's largest N, below SUN::kMaxN: a DDB step costs about 20 complex N×N products
// (docs/conventions.md §4), some seconds each step at N = 1024 on two cores, and every
// state's spectrum is computed for spectrum_drift.
constexpr Eigen::Index kMaxN = 1024;
constexpr long kMaxSteps = 1000000000L;
// Default step: h = kStepFactor·ħ/‖P₀‖₂, the fixed point's contraction rate h‖P‖₂/ħ of
// docs/conventions.md §2 kept small, so that a Legendre solve takes a few iterations.
constexpr double kStepFactor = 0.02;

const std::vector<std::pair<std::string, std::string>>& initDescriptions() {
  static const std::vector<std::pair<std::string, std::string>> inits{
      {"random", "i.i.d. normal real and imaginary parts, projected to su(N)"},
      {"l1", "W = U X3 U^H, U a random unitary: the orbit of the l = 1 element X3"},
      {"zonal", "i diag(d), d normal: a steady state, [P, W] = 0"}};
  return inits;
}

/// The methods for the fluid: every entry of the method table for matrix groups but the
/// dense reference, with the table's descriptions.
std::vector<std::pair<std::string, std::string>> fluidMethods() {
  std::vector<std::pair<std::string, std::string>> methods;
  for (const MethodInfo& m : kMethods) {
    if ((m.groups & kMatrixGroups) != 0 && m.kind != MethodKind::kReference) {
      methods.emplace_back(m.name, m.description);
    }
  }
  return methods;
}

// ---- the command line (docs/file-formats.md) ----
struct Options {
  long n = 32, steps = 0, every = 1;
  std::uint64_t seed = 1;
  std::string alpha = "0.5", h, t_end, init = "random", init_file, method = "ddb-cay";
  std::string out = "results-fluid";
  bool plot = false;
  app::LogFlags log;
};

void addOptions(CLI::App& cli, Options& o) {
  cli.add_option("--n", o.n, "resolution N, 2 <= N <= " + std::to_string(kMaxN))
      ->capture_default_str();
  cli.add_option("--alpha", o.alpha,
                 "double-bracket coefficient (> 0 relaxes to lower energy, < 0 raises it)")
      ->capture_default_str();
  cli.add_option("--h", o.h,
                 "step size (default " + app::number(kStepFactor) +
                     " hbar/||P0||_2, P0 the initial stream matrix; recorded in summary.json)");
  cli.add_option("--steps", o.steps, "number of steps (exactly one of --steps and --t-end)");
  cli.add_option("--t-end", o.t_end,
                 "final time: round(T/h) steps of the given --h, or with the default h the "
                 "smallest step count whose equal steps are no longer than it");
  cli.add_option("--seed", o.seed, "seed of the initial vorticity")
      ->capture_default_str()
      ->check(
          [](const std::string& text) {
            // CLI11 would wrap a negative seed around to 2^64 - 1 without a word.
            return text.rfind('-', 0) != 0 ? std::string()
                                           : text + " is negative; a seed is in [0, 2^64)";
          },
          "");
  cli.add_option("--init", o.init, "initial vorticity (listed below)")->capture_default_str();
  cli.add_option("--init-file", o.init_file,
                 "read W0 from a CSV of N rows x 2N columns (row j: Re W[j,:] then Im W[j,:]); "
                 "N is taken from the file");
  cli.add_option("--method", o.method, "integrator (listed below)")->capture_default_str();
  cli.add_option("--every", o.every, "write every K-th state and the last one to history.csv")
      ->capture_default_str();
  cli.add_option("--out", o.out, "output folder")->capture_default_str();
  cli.add_flag("--plot", o.plot, "render PNG figures (python3 with matplotlib and scipy)");
  app::addLogFlags(cli, o.log);
  app::addVersionFlag(cli, kApp);
  cli.footer(
      "\nInitial vorticities (--init; all scaled to ||W||_F = sqrt(N), seeded by --seed):\n" +
      app::describeChoices(initDescriptions()) + "\nMethods (--method):\n" +
      app::describeChoices(fluidMethods()) +
      "\nFiles in --out: history.csv, W_final.csv, omega_initial.csv, omega_final.csv, "
      "summary.json\n(docs/file-formats.md).\nExit status: 0 ok, 1 a step failed or a "
      "file could not be written, 2 bad input (nothing written).\n");
}

/// The text of a cell with surrounding blanks removed.
std::string trimmed(const std::string& text) {
  const auto begin = text.find_first_not_of(" \t");
  if (begin == std::string::npos) return "";
  return text.substr(begin, text.find_last_not_of(" \t") + 1 - begin);
}

/// W0 from --init-file: N rows of 2N numbers (docs/file-formats.md), N in [2, kMaxN],
/// skew-Hermitian and traceless to 1e-12 relative (SUN::requireState) and not zero.
Matrix readInitFile(const std::string& path) {
  const auto bad = [&](const std::string& why) { app::usageError("--init-file", path, why); };
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) bad("not a readable file");
  std::ifstream in(path);
  if (!in) bad("cannot be opened");
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (trimmed(line).empty()) continue;
    if (static_cast<Eigen::Index>(rows.size()) == kMaxN) {
      bad("more than " + std::to_string(kMaxN) + " rows (N <= " + std::to_string(kMaxN) + ")");
    }
    rows.emplace_back();
    for (const auto& cell : app::split(line)) {
      rows.back().push_back(app::parseNumber("--init-file", path, trimmed(cell)));
    }
  }
  if (in.bad()) bad("read error");
  const auto n = static_cast<Eigen::Index>(rows.size());
  if (n < 2) bad(std::to_string(n) + " rows; N must be >= 2");
  Matrix W(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto& row = rows[static_cast<std::size_t>(j)];
    if (static_cast<Eigen::Index>(row.size()) != 2 * n) {
      bad("row " + std::to_string(j + 1) + " has " + std::to_string(row.size()) +
          " columns; N = " + std::to_string(n) + " rows need 2N = " + std::to_string(2 * n));
    }
    for (Eigen::Index k = 0; k < n; ++k) {
      W(j, k) = {row[static_cast<std::size_t>(k)], row[static_cast<std::size_t>(n + k)]};
    }
  }
  try {
    SUN::requireState("W", W);
  } catch (const InvalidArgument& e) {
    bad(e.what());
  }
  if (W.norm() == 0.0) bad("W is zero");
  return W;
}

/// Everything the run needs, validated.
struct Settings {
  Matrix W0;
  double alpha = 0.0, h = 0.0;
  bool default_h = false;
  long steps = 0;
  std::string init;  // random, l1, zonal or file
  fs::path out;
};

Matrix initialVorticity(const CLI::App& cli, const Options& o, std::string& init) {
  if (!o.init_file.empty()) {
    app::rejectIfGiven(cli, "--init", "--init-file");
    app::rejectIfGiven(cli, "--seed", "--init-file");
    Matrix W = readInitFile(o.init_file);
    if (cli.count("--n") > 0 && W.rows() != o.n) {
      app::usageError("--n", std::to_string(o.n),
                      "--init-file " + o.init_file + " has N = " + std::to_string(W.rows()));
    }
    init = "file";
    return W;
  }
  if (o.n < 2 || o.n > kMaxN) {
    app::usageError("--n", std::to_string(o.n), "must be in [2, " + std::to_string(kMaxN) + "]");
  }
  app::requireChoice("--init", o.init, app::namesOf(initDescriptions()));
  init = o.init;
  if (o.init == "random") return randomVorticity(o.n, o.seed);
  if (o.init == "l1") return l1Vorticity(o.n, o.seed);
  return zonalVorticity(o.n, o.seed);
}

/// Bad input if the first step would overflow: the DDB step squares its dissipative part
/// h|α|‖P₀‖₂‖W₀‖₂/ħ, which past √(largest double) ≈ 1e154 becomes inf and then NaN
/// (measured without this check at N = 8 and 32 with the default h: α = 1e155 ran, and
/// 1e160 made the state NaN at step 0).
/// The check keeps a margin, kMaxDissipativeStep. A huge α below it is valid: the flow
/// relaxes within the step. The flag named is --alpha if α alone makes it too large
/// (with the default α it would pass), else --h if given, else the initial vorticity.
constexpr double kMaxDissipativeStep = 1e150;
void requireRepresentableStep(const CLI::App& cli, const Options& o, const Settings& s) {
  const ZeitlinHamiltonian hamiltonian(s.W0.rows());
  const double scale = SUN::spectralNorm(hamiltonian.streamMatrix(s.W0)) * SUN::spectralNorm(s.W0) /
                       hamiltonian.hbar() * s.h;
  // NaN (0 · inf) fails too.
  const auto fits = [&](double alpha) { return std::abs(alpha) * scale <= kMaxDissipativeStep; };
  if (fits(s.alpha)) return;
  const std::string why = fmt::format(
      "the dissipative step h|alpha||P0|_2|W0|_2/hbar = {:.3g} exceeds {:g} and would "
      "overflow",
      std::abs(s.alpha) * scale, kMaxDissipativeStep);
  if (fits(app::parseNumber("--alpha", Options().alpha, Options().alpha))) {
    app::usageError("--alpha", o.alpha, why);
  }
  if (cli.count("--h") > 0) app::usageError("--h", o.h, why);
  if (!o.init_file.empty()) app::usageError("--init-file", o.init_file, why);
  throw std::logic_error("a generated vorticity overflows: " + why);
}

Settings settings(const CLI::App& cli, const Options& o) {
  Settings s;
  app::requireChoice("--method", o.method, app::namesOf(fluidMethods()));
  s.alpha = app::parseNumber("--alpha", o.alpha, o.alpha);
  const bool by_steps = cli.count("--steps") > 0, by_time = cli.count("--t-end") > 0;
  if (by_steps == by_time) {
    throw app::UsageError(std::string("--steps, --t-end: give exactly one of them (") +
                          (by_steps ? "both" : "neither") + " given)");
  }
  if (by_steps && (o.steps < 1 || o.steps > kMaxSteps)) {
    app::usageError("--steps", std::to_string(o.steps), "must be in [1, 1e9]");
  }
  if (o.every < 1) app::usageError("--every", std::to_string(o.every), "must be >= 1");
  s.W0 = initialVorticity(cli, o, s.init);

  double t_end = 0.0;
  if (by_time) {
    t_end = app::parseNumber("--t-end", o.t_end, o.t_end);
    if (!(t_end > 0)) app::usageError("--t-end", o.t_end, "must be > 0");
  }
  s.default_h = o.h.empty();
  if (s.default_h) {
    const ZeitlinHamiltonian hamiltonian(s.W0.rows());
    s.h = kStepFactor * hamiltonian.hbar() / SUN::spectralNorm(hamiltonian.streamMatrix(s.W0));
  } else {
    s.h = app::parseNumber("--h", o.h, o.h);
    if (!(s.h > 0)) app::usageError("--h", o.h, "must be > 0");
  }
  s.steps = o.steps;
  if (by_time) {
    // With the default h, equal steps that end exactly at T and are no longer than it.
    const double count = s.default_h ? std::ceil(t_end / s.h) : std::round(t_end / s.h);
    if (count > static_cast<double>(kMaxSteps)) {
      app::usageError("--t-end", o.t_end, fmt::format("more than 1e9 steps of h = {}", s.h));
    }
    s.steps = std::max(1L, static_cast<long>(count));
    if (s.default_h) s.h = t_end / static_cast<double>(s.steps);
  }
  requireRepresentableStep(cli, o, s);
  // Only valid input is warned about: bad input gives its one line and nothing else.
  const double reached = static_cast<double>(s.steps) * s.h;
  if (by_time && std::abs(reached - t_end) > 1e-9 * t_end) {
    spdlog::warn("--t-end {} is not a multiple of --h {}: {} steps end at t = {}", t_end, s.h,
                 s.steps, reached);
  }
  s.out = o.out;
  return s;
}

/// W in the layout of --init-file: row j is Re W[j, :] then Im W[j, :].
void writeMatrixCsv(const fs::path& path, const Matrix& W) {
  app::AtomicFile file(path);
  app::CsvRow row(static_cast<std::size_t>(2 * W.cols()));
  for (Eigen::Index j = 0; j < W.rows(); ++j) {
    for (Eigen::Index k = 0; k < W.cols(); ++k) row.put(W(j, k).real());
    for (Eigen::Index k = 0; k < W.cols(); ++k) row.put(W(j, k).imag());
    row.writeTo(file);
  }
  file.commit();
}

/// The real spherical-harmonic coefficients ω_lm of W (docs/conventions.md §2), one row
/// "l,m,omega" each, for the figures.
void writeOmegaCsv(const fs::path& path, const SphericalHarmonicBasis& basis, const Matrix& W) {
  const Eigen::VectorXd omega = basis.coefficients(W);
  app::AtomicFile file(path);
  file.write("l,m,omega\n");
  app::CsvRow row(3);
  for (Eigen::Index l = 0; l < basis.size(); ++l) {
    for (Eigen::Index m = -l; m <= l; ++m) {
      row.put(static_cast<double>(l));
      row.put(static_cast<double>(m));
      row.put(omega(SphericalHarmonicBasis::index(l, m)));
      row.writeTo(file);
    }
  }
  file.commit();
}

/// ‖spec(W) − spec(W₀)‖/‖spec(W₀)‖, spectra sorted (SUN::casimirs).
class SpectrumDrift {
 public:
  explicit SpectrumDrift(const Matrix& W0) : initial_(SUN::casimirs(W0)) {}
  double operator()(const Matrix& W) const {
    return (SUN::casimirs(W) - initial_).norm() / initial_.norm();
  }

 private:
  Eigen::VectorXd initial_;
};

int relax(const Options& o, const Settings& s) {
  const Eigen::Index n = s.W0.rows();
  const auto system = makeZeitlinFluid(n, s.alpha);
  const auto& hamiltonian = dynamic_cast<const ZeitlinHamiltonian&>(system->hamiltonian());
  const ZeitlinDiagnostics diagnostics(hamiltonian);
  const auto method = makeMethod<SUN>(o.method, system);
  // The DDB methods' Legendre solver reports its iterations; rk4 has none.
  const auto* legendre = dynamic_cast<const LegendreMethod<Cayley<SUN>>*>(method.get());
  app::prepareOutputFolder("--out", o.out, s.out);
  // ---- from here on, files are written: failures are exit status 1 ----

  spdlog::info("N = {}, alpha = {}, {} init{}, {}: {} steps of h = {}{} to t = {}", n, s.alpha,
               s.init, s.init == "file" ? " " + o.init_file : "", o.method, s.steps, s.h,
               s.default_h ? " (default)" : "", static_cast<double>(s.steps) * s.h);
  const SpectrumDrift spectrumDrift(s.W0);
  double drift = 0.0, drift_max = 0.0;
  long iterations_total = 0, iterations_max = 0;

  app::AtomicFile history_file(s.out / "history.csv");
  history_file.write("t,energy,enstrophy,commutator_norm,spectrum_drift\n");
  app::CsvRow row(5);
  auto historyRow = [&](long, double t, const Matrix& W) {
    row.put(t);
    row.put(diagnostics.energy(W));
    row.put(diagnostics.enstrophy(W));
    row.put(diagnostics.commutatorNorm(W));
    row.put(drift);
    row.writeTo(history_file);
  };
  EveryKth<Matrix, decltype(historyRow)> history(o.every, historyRow);

  const bool watch_energy =
      app::EnergyRises::applies(findMethod(o.method)->keeps_casimirs, s.alpha);
  app::EnergyRises rises;
  app::Progress progress(o.log.quiet);
  const std::string label = o.method + " N=" + std::to_string(n);
  const RunResult<SUN> run = runMethod(
      *method, *system, s.W0, s.h, s.steps, RunOptions{}, [&](long k, double t, const Matrix& W) {
        if (k > 0 && legendre != nullptr) {
          const auto& stats = legendre->legendreSolver().stats();
          const long iterations = stats.fixed_point + stats.newton;
          iterations_total += iterations;
          iterations_max = std::max(iterations_max, iterations);
        }
        if (watch_energy) rises.observe(k, t, diagnostics.energy(W));
        drift = spectrumDrift(W);
        drift_max = std::max(drift_max, drift);
        history(k, t, W);
        progress.update(label, k, s.steps, [&] {
          return fmt::format("E {:.6g}  |[P,W]| {:.3g}", diagnostics.energy(W),
                             diagnostics.commutatorNorm(W));
        });
      });
  history.finish();
  history_file.commit();
  progress.clear();
  rises.warnIfAny(o.method);

  const double commutator_final = diagnostics.commutatorNorm(run.final);
  app::Json summary;
  summary["version"] = app::projectVersion();
  summary["status"] = run.ok() ? "ok" : "FAILED";
  summary["n"] = n;
  summary["alpha"] = s.alpha;
  summary["h"] = s.h;
  summary["h_source"] = s.default_h ? "default" : "--h";
  summary["steps"] = run.steps;
  summary["steps_requested"] = s.steps;
  summary["t_end"] = run.t_final;
  summary["every"] = o.every;
  summary["method"] = o.method;
  summary["init"] = s.init;
  summary["seed"] = s.init == "file" ? app::Json() : app::Json(o.seed);
  summary["init_file"] = s.init == "file" ? app::Json(o.init_file) : app::Json();
  summary["energy_initial"] = diagnostics.energy(s.W0);
  summary["energy_final"] = diagnostics.energy(run.final);
  summary["enstrophy_initial"] = diagnostics.enstrophy(s.W0);
  summary["enstrophy"] = diagnostics.enstrophy(run.final);
  summary["spectrum_drift_max"] = drift_max;
  summary["commutator_initial"] = diagnostics.commutatorNorm(s.W0);
  summary["commutator_final"] = commutator_final;
  summary["runtime_s"] = run.runtime_s;
  summary["iterations_mean"] =
      run.steps > 0 ? static_cast<double>(iterations_total) / run.steps : 0.0;
  summary["iterations_max"] = iterations_max;
  if (watch_energy) summary["energy_rises"] = rises.count();
  if (!run.ok()) {
    // A failed run writes no final state: W_final.csv and omega_final.csv would claim a
    // time the run did not reach (docs/file-formats.md).
    summary["failed_step"] = run.failed_step;
    summary["failure"] = run.failure;
    app::writeJsonFile(s.out / "summary.json", summary);
    spdlog::error("{}", run.failure);
    spdlog::error("history.csv holds the {} steps before the failure; wrote {}", run.steps,
                  s.out.string());
    return app::kExitFailed;
  }
  writeMatrixCsv(s.out / "W_final.csv", run.final);
  const SphericalHarmonicBasis basis(hamiltonian.laplacian());
  writeOmegaCsv(s.out / "omega_initial.csv", basis, s.W0);
  writeOmegaCsv(s.out / "omega_final.csv", basis, run.final);
  app::writeJsonFile(s.out / "summary.json", summary);
  spdlog::info("E {} -> {}, |[P,W]| {} -> {}, spectrum drift <= {:.2e}, {:.3g} s; wrote {}",
               diagnostics.energy(s.W0), diagnostics.energy(run.final),
               diagnostics.commutatorNorm(s.W0), commutator_final, drift_max, run.runtime_s,
               s.out.string());
  return app::kExitOk;
}

int runRelax(int argc, char** argv) {
  CLI::App cli{"Relax Zeitlin's SU(N) fluid on the sphere with double-bracket dissipation", kApp};
  Options o;
  addOptions(cli, o);
  if (const auto status = app::parseCommandLine(cli, argc, argv)) return *status;
  app::setupLogging(o.log);
  const Settings s = settings(cli, o);
  const int status = relax(o, s);
  if (o.plot && status == app::kExitOk) return app::runPlotScript(DDB_PLOT_SCRIPT, s.out);
  if (o.plot) spdlog::error("no figures: the run failed");
  return status;
}

}  // namespace

int main(int argc, char** argv) { return ddb::app::runMain(kApp, runRelax, argc, argv); }
