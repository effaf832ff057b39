// makeMethod for SON, compiled once into the library (integrators/methods/method_table.h, its end).
#include <ddb/core/lie_poisson_system.h>
#include <ddb/groups/son.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/reference.h>

// The generic system's virtual functions, which some methods build a system of, are compiled in
// instantiations/lie_poisson_systems.cc, not here (core/lie_poisson_system.h).
DDB_LIE_POISSON_SYSTEM_INSTANCE(extern, ::ddb::SON);
DDB_METHOD_TABLE_INSTANCE(, ::ddb::SON);
