// MatrixBackend<CudaMatrix> (cuda/cuda_backend.h): the kernels of cuda/detail/cuda_kernels.cu
// and cuBLAS's zgemm, in the operands' context (cuda/cuda_context.h).
#include <cuda_runtime.h>
#include <ddb/cuda/cuda_backend.h>
#include <ddb/cuda/cuda_device.h>
#include <ddb/cuda/detail/cuda_check.h>
#include <ddb/cuda/detail/cuda_context_state.h>
#include <ddb/cuda/detail/cuda_kernels.h>
#include <ddb/cuda/detail/cuda_libraries.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace ddb {

namespace {

using B = MatrixBackend<CudaMatrix>;
using State = CudaContext::State;
namespace k = cuda_kernels;

// x's entries as 2·size reals.
const double* parts(const CudaMatrix& x) { return reinterpret_cast<const double*>(x.deviceData()); }
double* parts(CudaMatrix& x) { return reinterpret_cast<double*>(x.deviceData()); }
long partCount(const CudaMatrix& x) { return 2 * x.size(); }

const cuDoubleComplex* complexData(const CudaMatrix& x) {
  return reinterpret_cast<const cuDoubleComplex*>(x.deviceData());
}
cuDoubleComplex* complexData(CudaMatrix& x) {
  return reinterpret_cast<cuDoubleComplex*>(x.deviceData());
}

// The state of the context the operands share: the operations of two contexts' streams are not
// ordered with each other, so a matrix of another context is refused (an empty one has none).
template <class... More>
State& sharedState(const CudaMatrix& x, const More&... more) {
  const auto require = [&](const CudaMatrix& y) {
    if (x.size() > 0 && y.size() > 0) {
      requireContext(y, x.context(), "matrix", "the context of the operation's other operands");
    }
  };
  (require(more), ...);
  return stateOf(x);
}

// out takes x's shape and context (allocating only when it had another).
void shapeLike(CudaMatrix& out, const CudaMatrix& x) {
  if (!B::sameShape(out, x) || (x.size() > 0 && out.context() != x.context())) {
    out = CudaMatrix(x.rows(), x.cols(), x.context());
  }
}

// out = s·a b + beta·out by one zgemm (nothing to do for an empty product, whose leading
// dimensions cuBLAS would refuse).
void gemm(double s, const CudaMatrix& a, const CudaMatrix& b, double beta, CudaMatrix& out) {
  if (out.size() == 0) return;
  if (a.cols() == 0) {
    if (beta == 0.0) B::setZero(out);
    return;
  }
  State& state = sharedState(a, b, out);
  const cuDoubleComplex alpha = make_cuDoubleComplex(s, 0.0), c = make_cuDoubleComplex(beta, 0.0);
  const int m = static_cast<int>(a.rows()), n = static_cast<int>(b.cols()),
            depth = static_cast<int>(a.cols());
  checkCublas(cublasZgemm(state.cublas, CUBLAS_OP_N, CUBLAS_OP_N, m, n, depth, &alpha,
                          complexData(a), m, complexData(b), depth, &c, complexData(out), m),
              "cublasZgemm");
}

}  // namespace

void B::copy(const X& x, X& out) {
  if (&x == &out) return;
  shapeLike(out, x);
  if (x.size() == 0) return;
  checkCuda(cudaMemcpyAsync(out.deviceData(), x.deviceData(), sizeof(Scalar) * x.size(),
                            cudaMemcpyDeviceToDevice, stateOf(x).stream),
            "cudaMemcpyAsync (device to device)");
}
void B::setZero(X& x) {
  if (x.size() == 0) return;
  checkCuda(cudaMemsetAsync(x.deviceData(), 0, sizeof(Scalar) * x.size(), stateOf(x).stream),
            "cudaMemsetAsync");
}
void B::scale(double a, const X& x, X& out) {
  shapeLike(out, x);
  k::scale(stateOf(x), partCount(x), a, parts(x), parts(out));
}
void B::divide(X& x, double a) { k::divide(stateOf(x), partCount(x), parts(x), a); }
void B::axpy(double a, const X& x, X& y) {
  k::axpy(sharedState(x, y), partCount(x), a, parts(x), parts(y));
}
void B::sum(double a, const X& x, double b, const X& y, X& out) {
  State& state = sharedState(x, y);
  shapeLike(out, x);
  k::sum(state, partCount(x), a, parts(x), b, parts(y), parts(out));
}
void B::sum(double a, const X& x, double b, const X& y, double c, const X& z, X& out) {
  State& state = sharedState(x, y, z);
  shapeLike(out, x);
  k::sum(state, partCount(x), a, parts(x), b, parts(y), c, parts(z), parts(out));
}
void B::addSum(double a, const X& x, double b, const X& y, X& out) {
  k::addSum(sharedState(x, y, out), partCount(x), a, parts(x), b, parts(y), parts(out));
}

FormattedValue B::describe(const X& x) {
  return {"a " + std::to_string(x.rows()) + "x" + std::to_string(x.cols()) +
          " device matrix whose Frobenius norm is " + formatValue(frobeniusNorm(x))};
}

void B::zeroLike(X& x, const X& like) {
  shapeLike(x, like);
  setZero(x);
}

void B::multiply(const X& a, const X& b, X& out) {
  sharedState(a, b);  // before out is replaced: a mix is refused with out as it was
  if (out.rows() != a.rows() || out.cols() != b.cols() ||
      (out.size() > 0 && out.context() != a.context())) {
    out = CudaMatrix(a.rows(), b.cols(), a.context());
  }
  gemm(1.0, a, b, 0.0, out);
}
void B::multiplyAdd(double s, const X& a, const X& b, X& out) { gemm(s, a, b, 1.0, out); }
void B::addAdjoint(double s, const X& x, X& out) {
  k::addAdjoint(sharedState(x, out), out.rows(), out.cols(), s, parts(x), parts(out));
}
void B::makeSkewHermitian(X& x) { k::makeSkewHermitian(stateOf(x), x.cols(), parts(x)); }
B::Scalar B::trace(const X& x) {
  double re = 0.0, im = 0.0;
  k::traceOf(stateOf(x), x.rows(), std::min(x.rows(), x.cols()), parts(x), &re, &im);
  return {re, im};
}
void B::addToDiagonal(X& x, Scalar c) {
  k::addToDiagonal(stateOf(x), x.rows(), std::min(x.rows(), x.cols()), parts(x), c.real(),
                   c.imag());
}
double B::frobeniusNorm(const X& x) {
  return std::sqrt(k::dot(stateOf(x), partCount(x), parts(x), parts(x)));
}
double B::frobeniusDistance(const X& x, const X& y) {
  return std::sqrt(k::squaredDistance(sharedState(x, y), partCount(x), parts(x), parts(y)));
}
double B::oneNorm(const X& x) {
  State& state = stateOf(x);
  const double fast = k::largestColumnSum(state, x.rows(), x.cols(), parts(x), false);
  if (MatrixBackend<Eigen::MatrixXcd>::squaresWereExact(fast)) return fast;
  return k::largestColumnSum(state, x.rows(), x.cols(), parts(x), true);
}
double B::innerProduct(const X& x, const X& y) {
  return k::dot(sharedState(x, y), partCount(x), parts(x), parts(y));
}
bool B::allFinite(const X& x) { return k::countNotFinite(stateOf(x), partCount(x), parts(x)) == 0; }
void B::flushSubnormals(X& x) { k::flushSubnormals(stateOf(x), partCount(x), parts(x)); }
bool B::isZero(const X& x) { return k::countNotZero(stateOf(x), partCount(x), parts(x)) == 0; }

std::vector<long>& B::sampleIndices(const X& x) { return stateOf(x).host_indices; }
std::vector<B::Scalar>& B::sampleValues(const X& x) { return stateOf(x).host_values; }

void B::gather(const X& x, const std::vector<long>& linear, std::vector<Scalar>& values) {
  if (linear.empty()) return;
  // The context's device copies of the indices and the values, kept for the next sample.
  State& state = stateOf(x);
  long* indices = state.sample_indices.reserve<long>(linear.size());
  double* gathered = state.sample_values.reserve<double>(2 * linear.size());
  copyToDevice(state, indices, linear.data(), sizeof(long) * linear.size());
  k::gather(state, static_cast<long>(linear.size()), parts(x), indices, gathered);
  copyToHost(state, values.data(), gathered, sizeof(Scalar) * linear.size());
}

void B::save(BinaryRecordWriter& out, const X& x) { out.put(toHost(x)); }
void B::load(BinaryRecordReader& in, X& x) {
  Eigen::MatrixXcd read;
  in.get(read);
  if (read.rows() != x.rows() || read.cols() != x.cols()) {
    throw CorruptRecord("a matrix of another size than the state");
  }
  toDevice(read, x);  // in x's context
}

}  // namespace ddb
