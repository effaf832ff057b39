// DDB_HOST_DEVICE marks a function that a GPU's kernels call too (cuda/detail/cuda_kernels.cu):
// __host__ __device__ under nvcc, nothing for a host compiler, so that one body serves both and
// the host tests check what the kernels run. DDB_UNROLL asks nvcc to unroll a loop of fixed count.
#pragma once

#ifdef __CUDACC__
#define DDB_HOST_DEVICE __host__ __device__
#define DDB_UNROLL _Pragma("unroll")
#else
#define DDB_HOST_DEVICE
#define DDB_UNROLL
#endif
