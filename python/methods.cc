// ddb.methods(): the one method table (integrators/methods/method_table.h) as Python dicts.
#include <ddb/integrators/methods/method_table.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "bindings.h"
#include "system.h"

namespace py = pybind11;

namespace ddb::python {

void bindMethods(py::module_& m) {
  m.def(
      "methods",
      [] {
        py::list rows;
        for (const MethodInfo& method : kMethods) {
          std::vector<std::string> groups;
          if (method.groups & kFixedSizeGroups) {
            groups.insert(groups.end(), {SO3::kName, SE2::kName, SE3::kName});
          }
          if (method.groups & kMatrixGroups) groups.insert(groups.end(), {SON::kName, SUN::kName});
          if (method.groups & kBackendMatrixGroups) groups.emplace_back(DualNumberSUN::kName);
          py::dict row;
          row["name"] = std::string(method.name);
          row["description"] = std::string(method.description);
          row["groups"] = groups;
          row["keeps_casimirs"] = method.keeps_casimirs;
          row["needs_lagrangian"] = method.needs_lagrangian;
          row["needs_scalar_metric"] = method.needs_scalar_metric;
          row["order"] = method.order;
          row["order_without_dissipation"] = method.order_without_dissipation;
          rows.append(std::move(row));
        }
        return rows;
      },
      "Every integrator of the method table, in the paper's order: a list of dicts with "
      "name (what integrate() takes), description, groups (the groups it runs on: SO3, SE2, SE3, "
      "SO(N), SU(N), SU(N) x| su(N)*), keeps_casimirs (the DDB family: states stay on mu0's "
      "coadjoint orbit), "
      "needs_lagrangian (applies only to a system with a Lagrangian: rigid_body, kirchhoff, "
      "planar_kirchhoff), needs_scalar_metric (applies only with the metric alpha * identity: not "
      "heavy_top, kirchhoff, planar_kirchhoff), "
      "order (in mu with alpha != 0; 0 for the adaptive reference) and "
      "order_without_dissipation. System.methods() lists those that apply to a system.");
}

}  // namespace ddb::python
