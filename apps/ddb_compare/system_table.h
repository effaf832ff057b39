// ddb-compare's systems by their --system names (docs/reference/command-lines-and-files.md,
// "ddb-compare"): one table, as integrators/methods/method_table.h is for the methods. A row holds
// a system's name, its description, the system flags it takes and how the comparison runs on it;
// --system's choices, --help, the flags' help, the messages refusing a flag a system does not
// take, the flags a bad-input message may blame and the tests all read it. Adding a system is
// one row here plus its problem (problems.h, matrix_problems.h), and a new flag one entry of
// kSystemFlags plus its option.
#pragma once

#include <CLI/CLI.hpp>
#include <array>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ddb_compare/options.h"

namespace ddb::compare {

/// A flag that only some systems take.
struct SystemFlag {
  std::string_view name;
  /// The option's text in Options when its absence means the system's default (the flags a
  /// bad-input message may blame, requireResolvable), else nullptr.
  std::string Options::*text;
};

/// Every system flag, in the order a bad-input message blames them (after --alpha, before
/// --t-end, which every system takes) and the flags a system does not take are refused.
inline const std::array<SystemFlag, 14> kSystemFlags{{
    {"--scenario", nullptr},
    {"--inertia", &Options::inertia},
    {"--omega0", &Options::omega0},
    {"--mu0", &Options::mu0},
    {"--mgl", &Options::mgl},
    {"--chi", &Options::chi},
    {"--metric", &Options::metric},
    {"--mass", &Options::mass},
    {"--n", nullptr},
    {"--j", &Options::j},
    {"--mu0-file", &Options::mu0_file},
    {"--seed", nullptr},
    {"--init", nullptr},
    {"--init-file", &Options::init_file},
}};

struct SystemRow {
  std::string_view name;
  std::string_view description;         ///< one line, for --help
  std::vector<std::string_view> flags;  ///< the system flags it takes, of kSystemFlags
  /// Checks the input for this system (bad input: app::UsageError, nothing written) and runs
  /// the comparison; returns the exit status.
  int (*compare)(const CLI::App& cli, const Options& o);

  bool takes(std::string_view flag) const;
};

/// Every system, in --help's order; the first is the default.
const std::vector<SystemRow>& systemTable();

/// The row of --system's value; bad input listing the names if there is none.
const SystemRow& findSystem(const std::string& name);

/// The (name, description) pairs of the table, for --help and messages.
std::vector<std::pair<std::string, std::string>> systemDescriptions();

/// The systems that take `flag`, "heavy-top, kirchhoff", for the flag's help.
std::string systemsTaking(std::string_view flag);

/// Bad input naming the first system flag given that `row` does not take.
void rejectFlagsNotTaken(const CLI::App& cli, const SystemRow& row);

}  // namespace ddb::compare
