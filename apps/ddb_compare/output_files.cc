#include "ddb_compare/output_files.h"

#include <ddb/integrators/methods/method_table.h>

#include <string>

namespace ddb::compare {

const app::RunFiles& outputFiles() {
  static const app::RunFiles files = [] {
    app::RunFiles f{{"summary.json", "runtime_table.md", "error_vs_h.csv"}};
    for (const auto& name : methodNames(kFixedSizeGroups | kMatrixGroups | kBackendMatrixGroups)) {
      f.names.push_back(name + ".csv");
    }
    // scripts/plot_compare.py's figures, each written as NAME.tmp.png and renamed.
    for (const char* figure :
         {"casimir_vs_t", "error_vs_h", "work_precision", "sphere_trajectory",
          "distance_to_limit_points", "error_vs_reference", "distance_to_great_circle"}) {
      f.names.push_back(std::string(figure) + ".png");
      f.names.push_back(std::string(figure) + ".png.tmp.png");
    }
    return f;
  }();
  return files;
}

}  // namespace ddb::compare
