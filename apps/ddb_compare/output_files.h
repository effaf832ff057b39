// The files a ddb-compare run writes in --out (docs/reference/command-lines-and-files.md,
// "ddb-compare"): what makes a folder another run's, refused without --overwrite and removed
// with it, as fluid-relax's run folders (apps/common/run_folder.h).
#pragma once

#include "common/run_folder.h"

namespace ddb::compare {

/// Every method's <method>.csv, summary.json, runtime_table.md, error_vs_h.csv and the
/// figures of scripts/plot_compare.py (with the temporaries it renames them from).
const app::RunFiles& outputFiles();

}  // namespace ddb::compare
