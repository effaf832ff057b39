#include "fluid_relax/input.h"

#include <ddb/core/errors.h>
#include <ddb/groups/sun.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <vector>

#include "common/cli.h"
#include "common/exit_status.h"

namespace ddb::fluid {

namespace {

namespace fs = std::filesystem;

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

}  // namespace

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

}  // namespace ddb::fluid
