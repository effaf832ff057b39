// makeMethod for the CUDA backend's groups, compiled once into ddb::cuda
// (cuda/cuda_method_table.h).
#include <ddb/cuda/cuda_method_table.h>
#include <ddb/cuda/cuda_zeitlin_fluid.h>
#include <ddb/cuda/cuda_zeitlin_mhd.h>

DDB_BACKEND_METHOD_TABLES_INSTANCE(, ::ddb::CudaMatrix);
