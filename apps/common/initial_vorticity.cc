#include "common/initial_vorticity.h"

#include <ddb/core/errors.h>
#include <ddb/groups/sun.h>
#include <ddb/systems/zeitlin_initial_conditions.h>

#include "common/atomic_file.h"
#include "common/cli.h"
#include "common/csv_row.h"
#include "common/number_csv.h"

namespace ddb::app {

namespace {

std::string limitText(const ResolutionLimit& limit) {
  return "N <= " + std::to_string(limit.max_n) + (limit.why.empty() ? "" : ": " + limit.why);
}

}  // namespace

Eigen::MatrixXcd readSuNMatrixFile(const std::string& flag, const std::string& path,
                                   const std::string& name, const ResolutionLimit& limit) {
  const auto bad = [&](const std::string& why) { usageError(flag, path, why); };
  const auto rows =
      readNumberCsv(flag, path, static_cast<std::size_t>(limit.max_n), limitText(limit));
  const auto n = static_cast<Eigen::Index>(rows.size());
  if (n < 2) bad(std::to_string(n) + " rows; N must be >= 2");
  Eigen::MatrixXcd W(n, n);
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
    SUN::requireState(name, W);
  } catch (const InvalidArgument& e) {
    bad(e.what());
  }
  return W;
}

const std::vector<std::pair<std::string, std::string>>& initDescriptions() {
  static const std::vector<std::pair<std::string, std::string>> inits{
      {"random", "i.i.d. normal real and imaginary parts, projected to su(N)"},
      {"l1", "W = U X3 U^H, U a random unitary: the orbit of the l = 1 element X3"},
      {"zonal", "i diag(d), d normal: a steady state, [P, W] = 0"}};
  return inits;
}

InitialVorticity initialVorticity(const CLI::App& cli, const VorticityOptions& o,
                                  const ResolutionLimit& limit) {
  if (!o.init_file.empty()) {
    rejectIfGiven(cli, "--init", "--init-file");
    rejectIfGiven(cli, "--seed", "--init-file");
    Eigen::MatrixXcd W = readSuNMatrixFile("--init-file", o.init_file, "W", limit);
    if (W.norm() == 0.0) usageError("--init-file", o.init_file, "W is zero");
    if (cli.count("--n") > 0 && W.rows() != o.n) {
      usageError("--n", std::to_string(o.n),
                 "--init-file " + o.init_file + " has N = " + std::to_string(W.rows()));
    }
    return {std::move(W), "file"};
  }
  if (o.n < 2 || o.n > limit.max_n) {
    usageError("--n", std::to_string(o.n),
               "must be in [2, " + std::to_string(limit.max_n) + "]" +
                   (limit.why.empty() ? "" : ": " + limit.why));
  }
  requireChoice("--init", o.init, namesOf(initDescriptions()));
  if (o.init == "random") return {randomVorticity(o.n, o.seed), o.init};
  if (o.init == "l1") return {l1Vorticity(o.n, o.seed), o.init};
  return {zonalVorticity(o.n, o.seed), o.init};
}

void writeMatrixCsv(const std::filesystem::path& path, const Eigen::MatrixXcd& W) {
  AtomicFile file(path);
  CsvRow row(static_cast<std::size_t>(2 * W.cols()));
  for (Eigen::Index j = 0; j < W.rows(); ++j) {
    for (Eigen::Index k = 0; k < W.cols(); ++k) row.put(W(j, k).real());
    for (Eigen::Index k = 0; k < W.cols(); ++k) row.put(W(j, k).imag());
    row.writeTo(file);
  }
  file.commit();
}

}  // namespace ddb::app
