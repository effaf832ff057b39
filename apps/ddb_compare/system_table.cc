#include "ddb_compare/system_table.h"

#include <ddb/core/errors.h>

#include <algorithm>

#include "common/cli.h"
#include "ddb_compare/comparison.h"
#include "ddb_compare/matrix_problems.h"
#include "ddb_compare/problems.h"

namespace ddb::compare {

namespace {

/// Every check of the input, in the order the messages name them, then the comparison. The
/// library's checks of the problem's data (InvalidArgument) are bad input too.
template <class G, Problem<G> (*kMake)(const CLI::App&, const Options&)>
int compareOn(const CLI::App& cli, const Options& o) {
  const auto make = [&](const Options& options) {
    try {
      return kMake(cli, options);
    } catch (const InvalidArgument& e) {
      throw app::UsageError(e.what());
    }
  };
  const Problem<G> problem = make(o);
  const Settings settings = commonSettings(o, problem.t_end);
  requireResolvable(o, problem, make);
  return runComparison(o, settings, problem);
}

}  // namespace

bool SystemRow::takes(std::string_view flag) const {
  return std::find(flags.begin(), flags.end(), flag) != flags.end();
}

const std::vector<SystemRow>& systemTable() {
  static const std::vector<SystemRow> systems{
      {"rigid-body",
       "free rigid body on so(3)*, K = alpha I (paper, Section 5)",
       {"--scenario", "--inertia", "--omega0"},
       compareOn<SO3, rigidBodyProblem>},
      {"heavy-top",
       "heavy top on se(3)*, Hamiltonian-form DDB, K = alpha diag(metric)",
       {"--inertia", "--mu0", "--mgl", "--chi", "--metric"},
       compareOn<SE3, heavyTopProblem>},
      {"kirchhoff",
       "rigid body in ideal fluid on se(3)*, K = alpha diag(metric)",
       {"--inertia", "--mu0", "--metric", "--mass"},
       compareOn<SE3, kirchhoffProblem>},
      {"planar-kirchhoff",
       "rigid body in ideal fluid in the plane on se(2)*, K = alpha diag(metric)",
       {"--inertia", "--mu0", "--metric", "--mass"},
       compareOn<SE2, planarKirchhoffProblem>},
      {"manakov",
       "SO(N) generalised rigid body (Manakov) on so(N)*, K = alpha I",
       {"--n", "--j", "--mu0-file", "--seed"},
       compareOn<SON, manakovProblem>},
      {"zeitlin",
       "Zeitlin's SU(N) fluid on the sphere, K = alpha I",
       {"--n", "--seed", "--init", "--init-file"},
       compareOn<SUN, zeitlinProblem>}};
  return systems;
}

std::vector<std::pair<std::string, std::string>> systemDescriptions() {
  std::vector<std::pair<std::string, std::string>> out;
  for (const SystemRow& row : systemTable()) {
    out.emplace_back(std::string(row.name), std::string(row.description));
  }
  return out;
}

const SystemRow& findSystem(const std::string& name) {
  app::requireChoice("--system", name, app::namesOf(systemDescriptions()));
  for (const SystemRow& row : systemTable()) {
    if (row.name == name) return row;
  }
  throw std::logic_error("requireChoice accepted a name not in the system table");
}

std::string systemsTaking(std::string_view flag) {
  std::string names;
  for (const SystemRow& row : systemTable()) {
    if (row.takes(flag)) names += (names.empty() ? "" : ", ") + std::string(row.name);
  }
  return names;
}

void rejectFlagsNotTaken(const CLI::App& cli, const SystemRow& row) {
  for (const SystemFlag& flag : kSystemFlags) {
    if (!row.takes(flag.name)) {
      app::rejectIfGiven(cli, std::string(flag.name), "--system " + std::string(row.name));
    }
  }
}

}  // namespace ddb::compare
