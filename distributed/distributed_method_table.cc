// makeMethod for the distributed layer's groups, compiled once into ddb::distributed
// (distributed/distributed_method_table.h).
#include <ddb/distributed/distributed_method_table.h>
#include <ddb/distributed/distributed_zeitlin_fluid.h>
#include <ddb/distributed/distributed_zeitlin_mhd.h>

DDB_BACKEND_METHOD_TABLES_INSTANCE(, ::ddb::DistributedMatrix);
