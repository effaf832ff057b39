// Shared helpers for the test suite: seeded random samples and the type lists of
// the generic suites. Adding a group: one entry in GroupsWith below.
#pragma once

#include <ddb/core/group_traits.h>
#include <ddb/groups/cayley.h>
#include <ddb/groups/direct_product.h>
#include <ddb/groups/exponential.h>
#include <ddb/groups/se2.h>
#include <ddb/groups/se3.h>
#include <ddb/groups/so2.h>
#include <ddb/groups/so3.h>
#include <ddb/groups/son.h>
#include <ddb/groups/special_euclidean.h>
#include <ddb/groups/special_orthogonal.h>
#include <ddb/groups/sun.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "symmetric_matrices_representation.h"

namespace ddb::test {

/// ‖x‖₁ by loops: the largest column sum of std::abs (hypot: exact |z| at every scale), a
/// reference for MatrixBackend::oneNorm.
inline double oneNormByLoops(const Eigen::MatrixXcd& x) {
  double largest = 0.0;
  for (Eigen::Index j = 0; j < x.cols(); ++j) {
    double sum = 0.0;
    for (Eigen::Index i = 0; i < x.rows(); ++i) sum += std::abs(x(i, j));
    largest = std::max(largest, sum);
  }
  return largest;
}

/// A group under test and the retraction R under test. A matrix group is checked at every N of
/// Samples::sizes() within one instantiation: one type per N cost a compile of the whole suite
/// each (test_groups.cc took 240 s for its 12 types).
template <class G, template <class> class R = Cayley>
struct GroupAt {
  using Group = G;
  using Retraction = R<G>;
};

// ---- Adding a group: include its header above and append it here. Both generic
// suites (test_groups.cc: every group; test_retractions.cc: every group with the
// Cayley and exponential retractions) are instantiated from these lists. Matrix
// groups run at N = 2..6 (Samples::sizes). SemidirectProduct<SO3> is SE(3) composed from SO(3)'s
// functions (groups/semidirect_product.h); DirectProduct<SO2, SO3, SE2> is the product of SO2
// and DirectProduct<SO3, SE2>, which pairs a group with a product (groups/direct_product.h);
// SpecialOrthogonal<4> and SpecialEuclidean<4> are SO(4) and SE(4) of a fixed size, through
// LieGroupBase's deduced functions (groups/special_orthogonal.h). SemidirectProduct<SO3,
// SymmetricMatrices> is SO(3) acting on symmetric 3×3 matrices, a representation of the user's
// own (symmetric_matrices_representation.h). ----
template <template <class> class R>
using GroupsWith =
    ::testing::Types<GroupAt<SO2, R>, GroupAt<SO3, R>, GroupAt<SE2, R>, GroupAt<SE3, R>,
                     GroupAt<SemidirectProduct<SO3>, R>,
                     GroupAt<SemidirectProduct<SO3, SymmetricMatrices>, R>,
                     GroupAt<DirectProduct<SO2, SO3, SE2>, R>, GroupAt<SpecialOrthogonal<4>, R>,
                     GroupAt<SpecialEuclidean<4>, R>, GroupAt<SON, R>, GroupAt<SUN, R>>;
struct AllGroups {
  using Groups = GroupsWith<Cayley>;
  template <template <class> class R>
  using With = GroupsWith<R>;
};

/// Deterministic random vectors with entries in [-1, 1].
class Sampler {
 public:
  explicit Sampler(unsigned seed = 12345) : rng_(seed) {}
  template <class V>
  V vector() {
    V v;
    for (Eigen::Index i = 0; i < v.size(); ++i) v(i) = dist_(rng_);
    return v;
  }
  double uniform() { return dist_(rng_); }

 private:
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> dist_{-1.0, 1.0};
};

/// Samples of a group under test (Sophus supplies samples per group the same way):
/// algebra and dual elements, group elements, and the points where formulas are checked:
/// identity, near identity, random, and near the cut locus of exp (spectral radius π).
template <class TG>
class Samples {
 public:
  using G = typename TG::Group;
  using A = typename G::template Algebra<double>;
  using D = typename G::template Dual<double>;
  static constexpr bool kMatrix = isDynamicGroup<G>;

  explicit Samples(Sampler& s) : s_(s) {}

  /// The N of a matrix group's samples (0 for fixed-size groups): 2..6.
  static std::vector<int> sizes() {
    if constexpr (kMatrix) {
      return {2, 3, 4, 5, 6};
    } else {
      return {0};
    }
  }
  /// Samples of size N from here on (a matrix group's).
  void resize(int n) { n_ = n; }
  /// Runs `check` with samples of every N of sizes(), naming N in failures.
  template <class Check>
  void forEachSize(const Check& check) {
    for (const int n : sizes()) {
      resize(n);
      SCOPED_TRACE("N = " + std::to_string(n));
      check();
    }
  }
  int n() const { return n_; }

  /// Fixed-size: entries in [-1, 1]. Matrix groups: a random element of so(N) or su(N)
  /// (skew part, trace removed) scaled to Frobenius norm 1.5, well inside exp's domain.
  A algebra() {
    if constexpr (kMatrix) {
      return 1.5 * unitMatrix();
    } else {
      return s_.vector<A>();
    }
  }
  D dual() {
    if constexpr (kMatrix) {
      return unitMatrix() * (1.0 + s_.uniform());
    } else {
      return s_.vector<D>();
    }
  }
  auto element() { return G::exp(algebra()); }

  std::vector<A> points(bool near_pi) {
    std::vector<A> points{A(algebra() * 0.0)};
    const A tiny = algebra();
    points.push_back(1e-8 * tiny / tiny.norm());
    for (int i = 0; i < 4; ++i) points.push_back(algebra());
    if constexpr (kMatrix) {
      // Per-group special case: a diagonal (maximal torus) element, repeated eigenvalues.
      A diagonal = A::Zero(n_, n_);
      for (int j = 0; j < n_ / 2; ++j) diagonal(2 * j, 2 * j + 1) = 0.7;
      points.push_back(G::vee(A(diagonal - diagonal.adjoint())));
    }
    if (near_pi) {
      // Fixed size: |x| = π − 1e-6; matrix groups: spectral radius π − 1e-6.
      const A d = algebra();
      const double radius = kMatrix ? spectralRadius(d) : d.norm();
      points.push_back((M_PI - 1e-6) / radius * d);
    }
    return points;
  }

  /// The spectral radius of ad_x, where dexp⁻¹'s series has its poles at 2π: the group's
  /// adRadius for fixed-size groups (|ω| on SO(3), SE(2) and SE(3), 0 on SO(2)), the spread of
  /// the eigenvalues of −ix for matrix groups.
  static double adRadius(const A& x) {
    if constexpr (kMatrix) {
      const auto spectrum = G::casimirs(x);
      return spectrum.maxCoeff() - spectrum.minCoeff();
    } else {
      return G::adRadius(x);
    }
  }

  /// Tolerance scale of an identity in the given data: 1 for the O(1) vectors of
  /// fixed-size groups; the product of max(1, ‖·‖) for matrix groups, whose norms grow with N.
  template <class... Xs>
  static double scale(const Xs&... xs) {
    if constexpr (kMatrix) {
      return (1.0 * ... * std::max(1.0, xs.norm()));
    } else {
      return 1.0;
    }
  }

 private:
  A unitMatrix() {
    A x(n_, n_);
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      if constexpr (Eigen::NumTraits<typename A::Scalar>::IsComplex) {
        x.data()[i] = typename A::Scalar(s_.uniform(), s_.uniform());
      } else {
        x.data()[i] = s_.uniform();
      }
    }
    x = G::vee(x);
    x.diagonal().array() -= x.trace() / double(n_);
    return x / x.norm();
  }
  static double spectralRadius(const A& x) { return G::casimirs(x).cwiseAbs().maxCoeff(); }
  Sampler& s_;
  int n_ = 0;
};

/// Whether G's Cayley map is the matrix Cayley map of its hat (LieGroupBase::cay, which the
/// closed forms are checked against): every group but a semidirect product by a representation
/// other than G's own matrices (SemidirectProduct::kCayleyOfBlocks).
template <class G, class = void>
struct CayleyOfBlocks : std::true_type {};
template <class G>
struct CayleyOfBlocks<G, std::void_t<decltype(G::kCayleyOfBlocks)>>
    : std::bool_constant<G::kCayleyOfBlocks> {};

/// Tolerance for identities on O(1) data; matrix groups scale it by Samples::scale.
inline constexpr double kTight = 1e-13;

}  // namespace ddb::test
