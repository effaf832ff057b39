// C = A·B (and C += s·A·B) for distributed N×N matrices (pzgemm_): one complex product, the
// matrix groups' cost unit (docs/reference/conventions.md §4), spread over the grid.
#pragma once

#include <ddb/core/errors.h>
#include <ddb/distributed/distributed_matrix.h>
#include <ddb/distributed/scalapack.h>

#include <complex>
#include <string>

namespace ddb {

/// How a factor of a product enters it: as it is or as its adjoint (conjugate transpose).
enum class Factor : char { kAsIs = 'N', kAdjoint = 'C' };

/// c = alpha·op_a(a)·op_b(b) + beta·c (pzgemm_); the three matrices share the grid, N and the
/// block size, and c aliases neither.
inline void multiplyInto(std::complex<double> alpha, const DistributedMatrix& a,
                         const DistributedMatrix& b, std::complex<double> beta,
                         DistributedMatrix& c, Factor op_a = Factor::kAsIs,
                         Factor op_b = Factor::kAsIs) {
  for (const DistributedMatrix* m : {&b, static_cast<const DistributedMatrix*>(&c)}) {
    if (m->size() != a.size() || m->layout().block() != a.layout().block() ||
        &m->layout().grid() != &a.layout().grid()) {
      throwInvalid(
          "matrix",
          "N = " + std::to_string(m->size()) + ", block " + std::to_string(m->layout().block()),
          "must share the grid, N = " + std::to_string(a.size()) + " and block " +
              std::to_string(a.layout().block()) + " with the product's first factor");
    }
  }
  if (&c == &a || &c == &b) throwInvalid("product", "c", "must not alias a factor");
  const int n = a.size(), one = 1;
  const char transa = static_cast<char>(op_a), transb = static_cast<char>(op_b);
  pzgemm_(&transa, &transb, &n, &n, &n, &alpha, a.data(), &one, &one, a.descriptor(), b.data(),
          &one, &one, b.descriptor(), &beta, c.data(), &one, &one, c.descriptor());
}

/// c = a·b.
inline void multiply(const DistributedMatrix& a, const DistributedMatrix& b, DistributedMatrix& c) {
  multiplyInto(1.0, a, b, 0.0, c);
}

}  // namespace ddb
