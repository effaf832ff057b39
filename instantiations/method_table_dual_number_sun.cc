// makeMethod for DualNumberSUN (SU(N) ⋉ su(N)*, the magnetic fluid's group), compiled once into
// the library (integrators/methods/method_table.h, its end).
#include <ddb/groups/dual_number_sun.h>
#include <ddb/integrators/methods/method_table.h>

DDB_METHOD_TABLE_INSTANCE(, ::ddb::DualNumberSUN);
