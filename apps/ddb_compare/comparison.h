// ddb-compare's comparison (docs/reference/command-lines-and-files.md, "ddb-compare"): every method
// that applies runs from μ0 with the trajectory written as it goes, is timed (a median of
// --repeat runs when short), compared with the adaptive reference at the final time and,
// with --sweep-h, over a range of step sizes.
#pragma once

#include <ddb/groups/se2.h>
#include <ddb/groups/se3.h>
#include <ddb/groups/so3.h>
#include <ddb/groups/son.h>
#include <ddb/groups/sun.h>

#include "ddb_compare/options.h"
#include "ddb_compare/problems.h"

namespace ddb::compare {

/// Runs the comparison and writes every file to s.out (report.h); returns kExitOk, or
/// kExitFailed if a method or the reference failed. A method given with --method that
/// does not apply to the system is bad input, thrown before anything is written.
template <class G>
int runComparison(const Options& o, const Settings& s, const Problem<G>& problem);

extern template int runComparison<SO3>(const Options&, const Settings&, const Problem<SO3>&);
extern template int runComparison<SE2>(const Options&, const Settings&, const Problem<SE2>&);
extern template int runComparison<SE3>(const Options&, const Settings&, const Problem<SE3>&);
extern template int runComparison<SON>(const Options&, const Settings&, const Problem<SON>&);
extern template int runComparison<SUN>(const Options&, const Settings&, const Problem<SUN>&);

}  // namespace ddb::compare
