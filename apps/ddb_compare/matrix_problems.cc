#include "ddb_compare/matrix_problems.h"

#include <ddb/core/errors.h>
#include <ddb/systems/manakov_body.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "common/cli.h"
#include "common/initial_vorticity.h"
#include "common/number_csv.h"

namespace ddb::compare {

namespace {

/// Said in every message that refuses an N for being too large.
std::string whyMaxN() {
  return "the reference (RKF 7(8), tol 1e-13) costs O(N^3) per evaluation and would take too "
         "long above " +
         std::to_string(kMaxMatrixN);
}

/// --n if given, else the system's default.
long givenOr(const CLI::App& cli, const Options& o, long fallback) {
  return cli.count("--n") > 0 ? o.n : fallback;
}

/// --n, or the system's default; bad input outside [2, kMaxMatrixN].
long resolution(const CLI::App& cli, const Options& o, long fallback) {
  const long n = givenOr(cli, o, fallback);
  if (n < 2 || n > kMaxMatrixN) {
    app::usageError("--n", std::to_string(n),
                    "must be in [2, " + std::to_string(kMaxMatrixN) + "]: " + whyMaxN());
  }
  return n;
}

/// M₀ from --mu0-file: N rows of N numbers, real skew-symmetric to 1e-12 relative
/// (SON::requireState), not zero; a given --n must be the file's N.
Eigen::MatrixXd readMomentumFile(const CLI::App& cli, const Options& o) {
  const std::string& path = o.mu0_file;
  const auto bad = [&](const std::string& why) { app::usageError("--mu0-file", path, why); };
  const auto rows = app::readNumberCsv("--mu0-file", path, static_cast<std::size_t>(kMaxMatrixN),
                                       "N <= " + std::to_string(kMaxMatrixN) + ": " + whyMaxN());
  const auto n = static_cast<Eigen::Index>(rows.size());
  if (n < 2) bad(std::to_string(n) + " rows; N must be >= 2");
  Eigen::MatrixXd M(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto& row = rows[static_cast<std::size_t>(i)];
    if (static_cast<Eigen::Index>(row.size()) != n) {
      bad("row " + std::to_string(i + 1) + " has " + std::to_string(row.size()) +
          " columns; N = " + std::to_string(n) + " rows need N columns");
    }
    for (Eigen::Index k = 0; k < n; ++k) M(i, k) = row[static_cast<std::size_t>(k)];
  }
  try {
    SON::requireState("M0", M);
  } catch (const InvalidArgument& e) {
    bad(e.what());
  }
  if (M.norm() == 0.0) bad("M0 is zero");
  if (cli.count("--n") > 0 && n != o.n) {
    app::usageError("--n", std::to_string(o.n),
                    "--mu0-file " + path + " has N = " + std::to_string(n));
  }
  return M;
}

}  // namespace

Eigen::VectorXd defaultManakovJ(Eigen::Index n) { return Eigen::VectorXd::LinSpaced(n, 1.0, 2.0); }

Eigen::MatrixXd seededManakovMomentum(Eigen::Index n, std::uint64_t seed) {
  const Eigen::MatrixXd M = randomVorticity(n, seed).real();
  return M * (std::sqrt(double(n)) / M.norm());
}

Problem<SON> manakovProblem(const CLI::App& cli, const Options& o) {
  Problem<SON> p;
  Eigen::MatrixXd M0;
  if (!o.mu0_file.empty()) {
    app::rejectIfGiven(cli, "--seed", "--mu0-file");
    M0 = readMomentumFile(cli, o);
  } else {
    M0 = seededManakovMomentum(resolution(cli, o, kManakovDefaultN), o.seed);
  }
  const Eigen::Index n = M0.rows();
  Eigen::VectorXd J = defaultManakovJ(n);
  if (!o.j.empty()) {
    const std::vector<double> values = app::parseNumbers("--j", o.j, static_cast<int>(n));
    J = Eigen::Map<const Eigen::VectorXd>(values.data(), n);
    if ((J.array() <= 0).any()) app::usageError("--j", o.j, "entries must be > 0");
  }
  p.alpha = optionalNumber("--alpha", o.alpha, kMatrixDefaultAlpha);
  p.system = makeManakovBody(J, p.alpha);
  p.mu0 = M0;
  p.t_end = kMatrixDefaultTEnd;
  const bool custom = !o.mu0_file.empty() || n != kManakovDefaultN || o.seed != Options().seed ||
                      J != defaultManakovJ(n) || p.alpha != kMatrixDefaultAlpha;
  p.scenario = custom ? "custom" : "none";
  p.parameters["n"] = n;
  p.parameters["j"] = app::jsonArray(J);
  p.parameters["alpha"] = p.alpha;
  p.parameters["seed"] = o.mu0_file.empty() ? app::Json(o.seed) : app::Json();
  p.parameters["mu0_file"] = o.mu0_file.empty() ? app::Json() : app::Json(o.mu0_file);
  return p;
}

Problem<SUN> zeitlinProblem(const CLI::App& cli, const Options& o) {
  app::InitialVorticity initial =
      app::initialVorticity(cli, {givenOr(cli, o, kZeitlinDefaultN), o.seed, o.init, o.init_file},
                            {kMaxMatrixN, whyMaxN()});
  Problem<SUN> p;
  p.alpha = optionalNumber("--alpha", o.alpha, kMatrixDefaultAlpha);
  p.system = makeZeitlinFluid(initial.W.rows(), p.alpha);
  p.mu0 = std::move(initial.W);
  p.t_end = kMatrixDefaultTEnd;
  const bool custom = initial.init != "random" || p.mu0.rows() != kZeitlinDefaultN ||
                      o.seed != Options().seed || p.alpha != kMatrixDefaultAlpha;
  p.scenario = custom ? "custom" : "none";
  p.parameters["n"] = p.mu0.rows();
  p.parameters["alpha"] = p.alpha;
  p.parameters["init"] = initial.init;
  p.parameters["seed"] = o.init_file.empty() ? app::Json(o.seed) : app::Json();
  p.parameters["init_file"] = o.init_file.empty() ? app::Json() : app::Json(o.init_file);
  return p;
}

}  // namespace ddb::compare
