// makeMethod for DualNumberSUN (SU(N) ⋉ su(N)*, the magnetic fluid's group), compiled once into
// the library (integrators/methods/method_table.h, its end).
#include <ddb/core/lie_poisson_system.h>
#include <ddb/groups/dual_number_sun.h>
#include <ddb/integrators/methods/method_table.h>

// The generic system's virtual functions, which some methods build a system of, are compiled in
// instantiations/lie_poisson_systems.cc, not here (core/lie_poisson_system.h).
DDB_LIE_POISSON_SYSTEM_INSTANCE(extern, ::ddb::DualNumberSUN);
DDB_METHOD_TABLE_INSTANCE(, ::ddb::DualNumberSUN);
