// Shared helpers for the test suite: seeded random samples and the type lists of
// the generic suites. Adding a group: one entry in kGroups-style lists below.
#pragma once

#include <ddb/groups/cayley.h>
#include <ddb/groups/exponential.h>
#include <ddb/groups/se3.h>
#include <ddb/groups/so3.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <numeric>
#include <random>
#include <vector>

namespace ddb::test {

// ---- Adding a group: include its header above and append it here. Both generic
// suites (test_groups.cc: every group; test_retractions.cc: every group with the
// Cayley and exponential retractions) are instantiated from this one list. ----
template <class... Gs>
struct GroupList {
  using Groups = ::testing::Types<Gs...>;
  using Retractions = ::testing::Types<Cayley<Gs>..., Exponential<Gs>...>;
};
using AllGroups = GroupList<SO3, SE3>;

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

/// Algebra elements of a given size: identity, near identity, random, and (for
/// groups whose exp is periodic) near the cut locus |x| = π.
template <class G>
std::vector<typename G::template Algebra<double>> samplePoints(Sampler& s, bool near_pi) {
  using A = typename G::template Algebra<double>;
  std::vector<A> points{A::Zero()};
  A tiny = s.vector<A>();
  points.push_back(1e-8 * tiny / tiny.norm());
  for (int i = 0; i < 4; ++i) points.push_back(s.vector<A>());
  if (near_pi) {
    A d = s.vector<A>();
    points.push_back((M_PI - 1e-6) * d / d.norm());
  }
  return points;
}

/// Matrix-exponential relative tolerance scale: values are O(1) unless noted.
inline constexpr double kTight = 1e-13;

}  // namespace ddb::test
