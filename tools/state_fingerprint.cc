// The bits of every method on every system, as one FNV-1a hash per run: integrate() (advance),
// two step() calls, relax() with the adaptive step control and the probe's residual and energy,
// the Newton search, and the probe at the initial state, on the rigid body, the heavy top, the
// Kirchhoff body, the Manakov body (SO(5)), the fluid (SU(12)) and the magnetic fluid
// (SU(12) ⋉ su(12)*, both fields nonzero). A change that must keep every
// state to the bit (a refactoring) prints the same lines before and after:
//   scripts/state_fingerprint.sh build > before.txt   (at the old commit)
//   scripts/state_fingerprint.sh build > after.txt && diff before.txt after.txt
#include <ddb/ddb.h>
#include <ddb/integrators/methods/reference.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
using namespace ddb;
template <class M>
std::uint64_t fnv(const M& m, std::uint64_t h = 1469598103934665603ull) {
  const unsigned char* p = reinterpret_cast<const unsigned char*>(m.data());
  for (std::size_t i = 0; i < sizeof(typename M::Scalar) * m.size(); ++i) {
    h ^= p[i];
    h *= 1099511628211ull;
  }
  return h;
}
// A dual-number state: its 1-part (Θ), then its ε-part (W).
std::uint64_t fnv(const DualMatrix<Eigen::MatrixXcd>& m, std::uint64_t h = 1469598103934665603ull) {
  return fnv(m.eps, fnv(m.real, h));
}
std::uint64_t fnvd(double d, std::uint64_t h) {
  Eigen::Matrix<double, 1, 1> x;
  x(0) = d;
  return fnv(x, h);
}
template <class G>
void run(const char* sys, std::shared_ptr<const LiePoissonSystem<G>> s,
         typename G::template Dual<double> mu0, double h, long steps) {
  for (const std::string& name : methodNames()) {
    if (!methodApplies(name, *s)) continue;
    try {
      auto m = makeMethod<G>(name, s);
      std::uint64_t hash = 1469598103934665603ull;
      integrate(*m, mu0, 0.0, h, steps,
                [&](long, double, const auto& mu) { hash = fnv(mu, hash); });
      auto m2 = makeMethod<G>(name, s);
      auto x = m2->step(mu0, 0.0, h);
      x = m2->step(x, h, h);
      std::uint64_t h2 = fnv(x);
      RelaxOptions o;
      o.max_steps = steps;
      o.control.adaptive = true;
      o.tolerance = 1e-12;
      auto m3 = makeMethod<G>(name, s);
      std::uint64_t h3 = 1469598103934665603ull;
      auto r = relax(*m3, *s, mu0, h, o, [&](const RelaxState& st, const auto& mu) {
        h3 = fnv(mu, fnvd(st.residual, fnvd(st.energy, fnvd(st.h, h3))));
      });
      std::printf("%s %s adv=%016llx step=%016llx relax=%016llx\n", sys, name.c_str(),
                  (unsigned long long)hash, (unsigned long long)h2, (unsigned long long)h3);
    } catch (const std::exception& e) {
      std::printf("%s %s threw %s\n", sys, name.c_str(), e.what());
    }
  }
  try {
    RelaxOptions o;
    o.newton = true;
    o.tolerance = 1e-12;
    o.max_steps = 30;
    std::uint64_t h4 = 1469598103934665603ull;
    auto r = relaxByNewton(*s, mu0, o, [&](const RelaxState& st, const auto& mu) {
      h4 = fnv(mu, fnvd(st.residual, fnvd(st.energy, fnvd(st.h, h4))));
    });
    std::printf("%s newton=%016llx\n", sys, (unsigned long long)h4);
  } catch (const std::exception& e) {
    std::printf("%s newton threw %s\n", sys, e.what());
  }
  std::printf("%s probe=%016llx\n", sys, (unsigned long long)fnvd(steadyStateResidual(*s, mu0), 0));
}
int main() {
  run<SO3>("rigid", makeRigidBody({1.0, 2.0, 3.5}, 0.3), Eigen::Vector3d(0.3, -1.1, 0.7), 0.05, 12);
  Eigen::Matrix<double, 6, 1> k;
  k << 1, 0.5, 2, 0.7, 1.3, 0.9;
  Eigen::Matrix<double, 6, 1> m0;
  m0 << 0.2, -0.4, 0.9, 0.1, 0.3, -0.8;
  run<SE3>("heavy", makeHeavyTop({1.0, 1.5, 2.2}, 0.7, {0.1, 0.2, 0.9}, 0.2, k), m0, 0.05, 12);
  run<SE3>("kirch", makeKirchhoffBody({1.0, 1.5, 2.2}, {2.0, 3.0, 1.5}, 0.2, k), m0, 0.05, 12);
  Eigen::VectorXd J(5);
  J << 1, 1.3, 1.9, 2.4, 3.1;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(5, 5);
  for (int i = 0; i < 5; ++i)
    for (int j = i + 1; j < 5; ++j) {
      A(i, j) = std::sin(1.0 + i + 2 * j);
      A(j, i) = -A(i, j);
    }
  run<SON>("manakov", makeManakovBody(J, 0.2), A, 0.05, 8);
  run<SUN>("fluid", makeZeitlinFluid(12, 0.5), randomVorticity(12, 7), 0.02, 6);
  run<DualNumberSUN>(
      "mhd", makeZeitlinMhd(12, 0.5),
      DualMatrix<Eigen::MatrixXcd>{0.02 * randomVorticity(12, 8), randomVorticity(12, 7)}, 0.005,
      6);
}
