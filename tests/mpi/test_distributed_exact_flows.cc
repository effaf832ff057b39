// The damping and forcing of Zeitlin's fluid on 1–4 ranks (distributed/
// distributed_zeitlin_exact_flows.h): the viscous flow against the serial ZeitlinViscousFlow and
// one mode's closed-form decay, the stochastic forcing's kicks against the serial flow's and the
// same on every number of ranks, the fixed forcing against W + hΦ, the stream's position through
// a record, and bad input refused on every rank.
#include <ddb/core/binary_record.h>
#include <ddb/core/errors.h>
#include <ddb/distributed/distributed_matrix.h>
#include <ddb/distributed/distributed_zeitlin_exact_flows.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_forcing.h>
#include <ddb/systems/zeitlin_hamiltonian.h>
#include <ddb/systems/zeitlin_viscosity.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <utility>
#include <vector>

#include "mpi_test_support.h"

namespace ddb {
namespace distributed_exact_flows_tests {

using test::randomVorticity;
using test::relativeDistance;

ZeitlinViscosity viscosity(double nu, int order, double drag) {
  ZeitlinViscosity v;
  v.viscosity = nu;
  v.order = order;
  v.drag = drag;
  return v;
}

class DistributedExactFlowsTest : public test::SizeAndBlockTest {
 protected:
  DistributedMatrix scattered(const Eigen::MatrixXcd& w) const {
    DistributedMatrix d(grid_, n(), block());
    d.scatterFrom(w);
    return d;
  }
};

// Three steps, the second of another h (the kept operator or the implicit step's factors made
// again), on a rotating sphere (F taken out and put back on the main diagonal's owner), against
// the serial flow, for both schemes.
TEST_P(DistributedExactFlowsTest, TheViscousFlowIsTheSerialFlow) {
  const double rotation = 1.5;
  for (const auto scheme : {ZeitlinViscousScheme::kExact, ZeitlinViscousScheme::kImplicit}) {
    ZeitlinViscosity v = viscosity(2e-3, 2, 0.1);
    v.scheme = scheme;
    const Eigen::MatrixXcd F = zeitlinPlanetaryVorticity(n(), rotation);
    const Eigen::MatrixXcd Q0 = randomVorticity(n(), 51) + F;
    DistributedMatrix Q = scattered(Q0);
    DistributedZeitlinViscousFlow flow(Q.layout(), v, rotation);
    ZeitlinViscousFlow serial(n(), v, F);
    Eigen::MatrixXcd expected = Q0;
    for (const double h : {0.3, 0.05, 0.05}) {
      flow.advance(Q, h);
      serial.advance(expected, h);
    }
    const Eigen::MatrixXcd found = Q.gather();
    if (grid_.rank() == 0) {
      EXPECT_LT(relativeDistance(found, expected), 1e-13)
          << (scheme == ZeitlinViscousScheme::kExact ? "exact" : "implicit");
    }
  }
}

// T_lm + F decays to exp(−(ν (l(l + 1))^p + γ) h) T_lm + F: the closed form, for modes on the
// main diagonal, near it and on the last one.
TEST_P(DistributedExactFlowsTest, OneModeDecaysByTheClosedForm) {
  const double rotation = -0.7, h = 0.4;
  const ZeitlinViscosity v = viscosity(1e-3, 1, 0.02);
  const Eigen::MatrixXcd F = zeitlinPlanetaryVorticity(n(), rotation);
  const SphericalHarmonicBasis basis{HoppeYauLaplacian(n())};
  const Eigen::Index last = n() - 1;
  for (const auto& [l, m] : std::vector<std::pair<Eigen::Index, Eigen::Index>>{
           {1, 0}, {3, -2}, {3, 1}, {last, -last}, {last, last - 1}}) {
    const Eigen::MatrixXcd T = basis.element(l, m);
    DistributedMatrix Q = scattered(T + F);
    DistributedZeitlinViscousFlow flow(Q.layout(), v, rotation);
    flow.advance(Q, h);
    const double rate = 1e-3 * double(l) * double(l + 1) + 0.02;
    const Eigen::MatrixXcd found = Q.gather();
    if (grid_.rank() == 0) {
      EXPECT_LT((found - F - std::exp(-rate * h) * T).norm(), 1e-13 * T.norm())
          << "l = " << l << ", m = " << m;
    }
  }
}

// Each kick's coefficients are a function of (seed, kick, mode): the serial flow's kicks, and
// every rank count's sums in the same order.
TEST_P(DistributedExactFlowsTest, TheStochasticForcingKicksAsTheSerialFlow) {
  ZeitlinStochasticForcing forcing;
  forcing.band_centre = std::min(4, n() - 2);
  forcing.band_half_width = 1;
  forcing.rate = 0.3;
  forcing.seed = 17;
  const double kappa_squared = 2.0;
  const Eigen::MatrixXcd W0 = randomVorticity(n(), 53);
  DistributedMatrix W = scattered(W0);
  DistributedZeitlinStochasticForcingFlow flow(W.layout(), forcing, kappa_squared);
  ZeitlinStochasticForcingFlow serial(n(), forcing, kappa_squared);
  EXPECT_EQ(flow.amplitude(), serial.amplitude());
  Eigen::MatrixXcd expected = W0;
  for (const double h : {0.1, 0.1, 0.25}) {
    flow.advance(W, h);
    serial.advance(expected, h);
  }
  EXPECT_EQ(flow.draws(), 3u);
  const Eigen::MatrixXcd found = W.gather();
  if (grid_.rank() == 0) {
    EXPECT_LT(relativeDistance(found, expected), 1e-15);
    EXPECT_GT((found - W0).norm(), 1e-3 * W0.norm());  // the kicks did something
  }
  // The stream's position through a record (a checkpoint's): the next kick is the same.
  BinaryRecordWriter record;
  flow.save(record);
  DistributedZeitlinStochasticForcingFlow resumed(W.layout(), forcing, kappa_squared);
  BinaryRecordReader in(record.bytes());
  resumed.load(in);
  DistributedMatrix a = scattered(W0), b = scattered(W0);
  flow.advance(a, 0.1);
  resumed.advance(b, 0.1);
  const Eigen::MatrixXcd ga = a.gather(), gb = b.gather();
  if (grid_.rank() == 0) {
    EXPECT_EQ(ga, gb);
  }
}

TEST_P(DistributedExactFlowsTest, TheFixedForcingAddsHTimesPhi) {
  const Eigen::MatrixXcd W0 = randomVorticity(n(), 55), phi = randomVorticity(n(), 57);
  DistributedMatrix W = scattered(W0);
  DistributedZeitlinFixedForcingFlow flow(W.layout(), phi);
  flow.advance(W, 0.2);
  flow.advance(W, 0.3);
  const Eigen::MatrixXcd found = W.gather();
  if (grid_.rank() == 0) {
    EXPECT_LT(relativeDistance(found, W0 + 0.5 * phi), 1e-15);
  }
}

// The flows in the serial order around nothing else: all three composed, against the serial
// zeitlinExactFlows' list on a rotating quasi-geostrophic fluid.
TEST_P(DistributedExactFlowsTest, TheListIsTheSerialList) {
  ZeitlinPhysics physics;
  physics.rotation = 2.0;
  physics.deformation_radius = 0.5;
  ZeitlinDampingAndForcing d;
  d.viscosity = viscosity(1e-3, 1, 0.05);
  d.forcing.band_centre = 2;
  d.forcing.band_half_width = 1;
  d.forcing.rate = 0.1;
  d.forcing.seed = 3;
  d.fixed_forcing = randomVorticity(n(), 59);
  const Eigen::MatrixXcd Q0 = randomVorticity(n(), 61) + zeitlinPlanetaryVorticity(n(), 2.0);
  DistributedMatrix Q = scattered(Q0);
  auto flows = distributedZeitlinExactFlows(Q.layout(), physics, d);
  const auto fluid = makeZeitlinFluid(n(), 0.0, physics);
  auto serial = zeitlinExactFlows(dynamic_cast<const ZeitlinHamiltonian&>(fluid->hamiltonian()), d);
  ASSERT_EQ(flows.size(), 3u);
  ASSERT_EQ(serial.size(), 3u);
  Eigen::MatrixXcd expected = Q0;
  for (std::size_t i = 0; i < flows.size(); ++i) {
    EXPECT_EQ(flows[i]->name(), serial[i]->name());
    flows[i]->advance(Q, 0.2);
    serial[i]->advance(expected, 0.2);
  }
  const Eigen::MatrixXcd found = Q.gather();
  if (grid_.rank() == 0) {
    EXPECT_LT(relativeDistance(found, expected), 1e-13);
  }
}

INSTANTIATE_TEST_SUITE_P(SizesAndBlocks, DistributedExactFlowsTest,
                         testing::Combine(testing::Values(4, 16, 33), testing::Values(1, 5)),
                         test::sizeAndBlockName);

// Bad input throws the library's error naming the parameter on every rank (each checks the same
// arguments), so no rank goes on alone.
TEST(DistributedExactFlows, RefuseBadInputOnEveryRank) {
  const test::TestGrid grid;
  const DistributedMatrix w(grid, 8, 3);
  const auto names = [&](const auto& make, const std::string& parameter) {
    try {
      make();
      ADD_FAILURE() << parameter << " accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find(parameter), std::string::npos) << e.what();
    }
  };
  names([&] { DistributedZeitlinViscousFlow(w.layout(), viscosity(-1.0, 1, 0.0)); }, "viscosity");
  names([&] { DistributedZeitlinViscousFlow(w.layout(), viscosity(0.0, 1, NAN)); }, "drag");
  ZeitlinStochasticForcing wide;
  wide.band_centre = 7;
  wide.band_half_width = 1;
  wide.rate = 1.0;
  names([&] { DistributedZeitlinStochasticForcingFlow(w.layout(), wide); }, "band_centre");
  const Eigen::MatrixXcd hermitian = Eigen::MatrixXcd::Identity(8, 8);
  names([&] { DistributedZeitlinFixedForcingFlow(w.layout(), hermitian); }, "forcing");
  names([&] { DistributedZeitlinFixedForcingFlow(w.layout(), Eigen::MatrixXcd::Zero(7, 7)); },
        "forcing");
}

}  // namespace distributed_exact_flows_tests
}  // namespace ddb
