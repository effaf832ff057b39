// The flags of relax() that the apps share (docs/reference/command-lines-and-files.md,
// docs/guide/steady-states.md): --until-steady TOL, --adaptive and --adaptive-tol E, read into
// RelaxOptions with the checks of docs/reference/bad-inputs.md. What --adaptive applies to and the
// caps are the app's.
#pragma once

#include <ddb/integrators/drivers/relax.h>

#include <CLI/CLI.hpp>
#include <string>

namespace ddb::app {

/// The flags as given (numbers as text, which messages quote).
struct RelaxFlags {
  std::string until_steady, adaptive_tol;  // empty: not given
  bool adaptive = false;
};

/// Adds the three flags; `until_steady_help` and `adaptive_help` say what r is and what
/// --adaptive applies to and caps in this app.
void addRelaxFlags(CLI::App& cli, RelaxFlags& flags, const std::string& until_steady_help,
                   const std::string& adaptive_help);

/// The tolerances and `adaptive` into `options` (not its caps): --until-steady and
/// --adaptive-tol must be in (0, 1), --adaptive-tol needs --adaptive.
void readRelaxFlags(const RelaxFlags& flags, RelaxOptions& options);

}  // namespace ddb::app
