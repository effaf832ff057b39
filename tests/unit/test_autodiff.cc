// AutoDiffLagrangian on a non-quadratic l whose gradient and Hessian are known in
// closed form: l(ξ) = exp(a·ξ) + ¼(ξ·Bξ)² + sin(ξ₁ξ₂).
#include <ddb/core/autodiff.h>
#include <gmock/gmock.h>

#include "test_support.h"

namespace ddb::test {
namespace autodiff_tests {

const Eigen::Vector3d kA(0.3, -0.7, 0.2);
const Eigen::Matrix3d kB = (Eigen::Matrix3d() << 2, 0.5, 0, 0.5, 1, -0.3, 0, -0.3, 3).finished();

class TestLagrangian : public AutoDiffLagrangian<TestLagrangian, SO3> {
 public:
  template <class T>
  T evaluate(const Eigen::Matrix<T, 3, 1>& x) const {
    T ax = constant<T>(0.0), q = constant<T>(0.0);
    for (int i = 0; i < 3; ++i) {
      ax += constant<T>(kA(i)) * x(i);
      for (int j = 0; j < 3; ++j) q += x(i) * constant<T>(kB(i, j)) * x(j);
    }
    using std::exp;
    using std::sin;
    return exp(ax) + constant<T>(0.25) * q * q + sin(x(0) * x(1));
  }
};

TEST(AutoDiffLagrangian, GradientAndHessianMatchClosedForm) {
  TestLagrangian l;
  Sampler s(99);
  for (int i = 0; i < 10; ++i) {
    const Eigen::Vector3d x = s.vector<Eigen::Vector3d>(), v = s.vector<Eigen::Vector3d>();
    const double e = std::exp(kA.dot(x)), q = x.dot(kB * x), c = std::cos(x(0) * x(1)),
                 sn = std::sin(x(0) * x(1));
    const Eigen::Vector3d Bx = kB * x;
    const Eigen::Vector3d grad = e * kA + q * Bx + c * Eigen::Vector3d(x(1), x(0), 0);
    Eigen::Matrix3d hess = e * kA * kA.transpose() + 2 * Bx * Bx.transpose() + q * kB;
    hess(0, 0) += -sn * x(1) * x(1);
    hess(1, 1) += -sn * x(0) * x(0);
    hess(0, 1) += c - sn * x(0) * x(1);
    hess(1, 0) += c - sn * x(0) * x(1);
    EXPECT_NEAR(l.value(x), e + 0.25 * q * q + sn, 1e-12);
    EXPECT_LT((l.gradient(x) - grad).norm(), 1e-12);
    EXPECT_LT((l.hessianTimes(x, v) - hess * v).norm(), 1e-12);
  }
}

}  // namespace autodiff_tests
}  // namespace ddb::test
