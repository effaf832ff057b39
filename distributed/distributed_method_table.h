// The method table (integrators/methods/method_table.h) for the distributed layer's groups, SU(N)
// and SU(N) ⋉ su(N)* on DistributedMatrix, compiled once into ddb::distributed
// (distributed/distributed_method_table.cc) as the library compiles it for its own groups, so that
// a program building a method on MPI ranks instantiates none of the methods itself
// (docs/results/compile-costs.md). The fluid's and the magnetic fluid's headers include it.
#pragma once

#include <ddb/integrators/methods/method_table.h>

namespace ddb {
class DistributedMatrix;
}  // namespace ddb

DDB_BACKEND_METHOD_TABLES_INSTANCE(extern, ::ddb::DistributedMatrix);
