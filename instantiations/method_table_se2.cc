// makeMethod for SE2, compiled once into the library (integrators/methods/method_table.h, its end).
#include <ddb/groups/se2.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/reference.h>

DDB_METHOD_TABLE_INSTANCE(, ::ddb::SE2);
