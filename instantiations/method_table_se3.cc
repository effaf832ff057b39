// makeMethod for SE3, compiled once into the library (integrators/methods/method_table.h, its end).
#include <ddb/groups/se3.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/reference.h>

DDB_METHOD_TABLE_INSTANCE(, ::ddb::SE3);
