// The parent project's program (CMakeLists.txt): one call into ddb, so that it links ddb::ddb.
#include <ddb/groups/so3.h>

int main() { return ddb::SO3::kDim == 3 ? 0 : 1; }
