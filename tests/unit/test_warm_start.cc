// Warm starts and resumed relaxations (OneStepMethod::saveWarmStart, Relaxation::save,
// core/binary_record.h; docs/reference/command-lines-and-files.md, "Checkpoints"). The reference is
// the uninterrupted run itself: a method (or a relaxation) stopped after K steps, saved, and
// loaded into a fresh instance must take the remaining steps to the bit; a fresh instance
// that is not loaded must not (so the check can fail: the warm start changes the rounding
// of a Legendre solve). A corrupted or truncated record is refused.
#include <ddb/core/binary_record.h>
#include <ddb/integrators/drivers/relax.h>
#include <ddb/integrators/methods/ddb.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <array>
#include <string>

namespace ddb::test {
namespace warm_start_tests {

constexpr long kSteps = 6;  // steps before and after the save

template <class G>
using Dual = typename G::template Dual<double>;

/// mu advanced from step `first` (t = first·h, as integrate() times them) to `first + steps`.
template <class G>
Dual<G> advance(OneStepMethod<G>& method, Dual<G> mu, long first, double h, long steps) {
  for (long k = first; k < first + steps; ++k) method.advance(mu, static_cast<double>(k) * h, h);
  return mu;
}

/// For every method of the table on G: uninterrupted 2K steps against K steps, a save, and
/// K steps of a fresh instance loaded with it; `warm` counts the methods whose fresh
/// instance without the load differs (they have a warm start that matters).
template <class G>
void checkEveryMethod(const std::shared_ptr<const LiePoissonSystem<G>>& system, const Dual<G>& mu0,
                      double h, int& warm) {
  for (const MethodInfo& info : kMethods) {
    if ((info.groups & groupFamilyOf<G>()) == 0) continue;
    if (info.needs_lagrangian && system->lagrangian() == nullptr) continue;
    const std::string name(info.name);
    auto whole = makeMethod<G>(name, system);
    whole->reset();
    const Dual<G> expected = advance(*whole, mu0, 0, h, 2 * kSteps);

    auto first = makeMethod<G>(name, system);
    first->reset();
    const Dual<G> middle = advance(*first, mu0, 0, h, kSteps);
    BinaryRecordWriter out;
    first->saveWarmStart(out);
    BinaryRecordReader in = BinaryRecordReader::unseal(out.sealed());
    auto second = makeMethod<G>(name, system);
    second->reset();
    second->loadWarmStart(in, middle);
    EXPECT_TRUE(in.atEnd()) << name;
    const Dual<G> resumed = advance(*second, middle, kSteps, h, kSteps);
    EXPECT_TRUE(resumed == expected)
        << name << ": resumed differs by " << (resumed - expected).cwiseAbs().maxCoeff();

    auto cold = makeMethod<G>(name, system);
    cold->reset();
    if (!(advance(*cold, middle, kSteps, h, kSteps) == expected)) ++warm;
  }
}

TEST(WarmStart, EveryMethodResumesToTheBitOnTheRigidBody) {
  const RigidBodyScenario& s = rigidBodyScenario("A");
  int warm = 0;
  checkEveryMethod<SO3>(s.system(), s.mu0(), 0.1, warm);
  // The DDB family's Legendre sweeps start from extrapolated corrections; the reference
  // from its last sub-step: at least these have a warm start that changes the rounding.
  EXPECT_GE(warm, 3);
}

TEST(WarmStart, EveryMethodResumesToTheBitOnTheFluid) {
  int warm = 0;
  checkEveryMethod<SUN>(makeZeitlinFluid(6, 0.5), randomVorticity(6, 3), 0.05, warm);
  // ddb-cay, ddb-exp, ddb-exp-exact, sddb-cay, sddb-exp and the three compositions predict
  // their guess from remembered corrections.
  EXPECT_GE(warm, 8);
}

TEST(WarmStart, AnAdaptiveRelaxationResumesToTheBit) {
  const auto system = makeZeitlinFluid(8, 0.5);
  const Dual<SUN> W0 = randomVorticity(8, 2);
  RelaxOptions options;
  options.max_steps = 40;
  options.control.adaptive = true;
  // h = 2 is too large at first: the run rejects steps, so the controller's state matters.
  auto method = makeMethod<SUN>("sddb-cay", system);
  std::vector<Dual<SUN>> expected;
  const RelaxResult<SUN> whole =
      relax(*method, *system, W0, 2.0, options,
            [&](const RelaxState&, const Dual<SUN>& W) { expected.push_back(W); });
  ASSERT_EQ(whole.last.k, 40);
  ASSERT_GT(whole.steps_rejected, 0);

  auto first = makeMethod<SUN>("sddb-cay", system);
  Relaxation<SUN> head(*first, *system, W0, 2.0, options);
  for (int k = 0; k < 17; ++k) ASSERT_TRUE(head.advance());
  BinaryRecordWriter out;
  head.save(out);

  auto second = makeMethod<SUN>("sddb-cay", system);
  RelaxOptions shorter = options;
  shorter.max_steps = 20;  // the resumed run's cap is its own (then extended)
  Relaxation<SUN> tail(*second, *system, W0, 2.0, shorter);
  BinaryRecordReader in(out.bytes());
  tail.load(in);
  EXPECT_TRUE(in.atEnd());
  tail.setCaps(options.max_steps, options.t_end);
  while (tail.advance()) {
    ASSERT_LT(tail.state().k, static_cast<long>(expected.size()));
    EXPECT_TRUE(tail.current() == expected[static_cast<std::size_t>(tail.state().k)])
        << "state " << tail.state().k;
  }
  EXPECT_EQ(tail.result().stop, RelaxStop::kStepCap);
  EXPECT_EQ(tail.state().k, whole.last.k);
  EXPECT_EQ(tail.state().t, whole.last.t);
  EXPECT_EQ(tail.state().h, whole.last.h);
  EXPECT_EQ(tail.result().steps_rejected, whole.steps_rejected);
}

TEST(WarmStart, AnInterruptedRelaxationSaysSo) {
  const RigidBodyScenario& s = rigidBodyScenario("B");
  const auto system = s.system();
  auto method = makeMethod<SO3>("ddb-cay", system);
  RelaxOptions options;
  options.max_steps = 10;
  Relaxation<SO3> run(*method, *system, s.mu0(), 0.1, options);
  ASSERT_TRUE(run.advance());
  run.interrupt();
  EXPECT_FALSE(run.advance());
  EXPECT_EQ(run.result().stop, RelaxStop::kInterrupted);
  EXPECT_TRUE(run.result().ok());
  EXPECT_EQ(run.state().k, 1);
}

// A small solver's warm start as 0.2.0 wrote it (the last three corrections c = p − M, newest
// first, for a quadratic extrapolation) still loads: the resumed steps take fewer sweeps
// than a cold start and agree with the uninterrupted run within the solver's tolerance (not
// to the bit: the predictor then climbs past the quadratic).
TEST(WarmStart, ASmallSolversRecordOf020StillLoads) {
  const RigidBodyScenario& a = rigidBodyScenario("A");
  const auto body = a.system();
  const double h = 0.1;
  Ddb<Cayley<SO3>> whole(body);
  Eigen::Vector3d mu = a.mu0();
  std::array<Eigen::Vector3d, 3> corrections = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                                Eigen::Vector3d::Zero()};  // newest first
  for (long k = 0; k < kSteps; ++k) {
    const Eigen::Vector3d before = mu;
    whole.advance(mu, static_cast<double>(k) * h, h);
    corrections = {whole.legendreSolver().solution() - before, corrections[0], corrections[1]};
  }
  const Eigen::Vector3d middle = mu;
  const Eigen::Vector3d expected = advance<SO3>(whole, middle, kSteps, h, kSteps);

  BinaryRecordWriter out;
  out.tag("discrete legendre solver");
  out.put(3);    // corrections
  out.put(1.0);  // the squared contraction, unknown
  out.put(h);
  for (const Eigen::Vector3d& c : corrections) out.put(c);
  BinaryRecordReader in(out.bytes());
  Ddb<Cayley<SO3>> loaded(body), cold(body);
  loaded.loadWarmStart(in, middle);
  EXPECT_TRUE(in.atEnd());
  Eigen::Vector3d from_record = middle, from_cold = middle;
  loaded.advance(from_record, static_cast<double>(kSteps) * h, h);
  cold.advance(from_cold, static_cast<double>(kSteps) * h, h);
  EXPECT_EQ(loaded.legendreSolver().stats().newton, 0);
  EXPECT_LT(loaded.legendreSolver().stats().fixed_point, cold.legendreSolver().stats().fixed_point);
  const Eigen::Vector3d resumed = advance<SO3>(loaded, from_record, kSteps + 1, h, kSteps - 1);
  EXPECT_LT((resumed - expected).norm(), 1e-13 * expected.norm());

  BinaryRecordWriter other;
  other.tag("discrete legendre solver, another layout");
  BinaryRecordReader other_in(other.bytes());
  EXPECT_THROW(loaded.loadWarmStart(other_in, middle), CorruptRecord);
}

TEST(BinaryRecord, RefusesACorruptedOrTruncatedRecord) {
  BinaryRecordWriter out;
  out.tag("part");
  out.put(3.5);
  out.put(Eigen::MatrixXcd(Eigen::MatrixXcd::Random(3, 2)));
  const std::string sealed = out.sealed();
  EXPECT_NO_THROW(BinaryRecordReader::unseal(sealed));
  for (std::size_t at : {std::size_t{0}, sealed.size() / 2, sealed.size() - 1}) {
    std::string flipped = sealed;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x10);
    EXPECT_THROW(BinaryRecordReader::unseal(flipped), CorruptRecord) << "byte " << at;
  }
  EXPECT_THROW(BinaryRecordReader::unseal(sealed.substr(0, sealed.size() - 5)), CorruptRecord);
  EXPECT_THROW(BinaryRecordReader::unseal(""), CorruptRecord);

  BinaryRecordReader in(out.bytes());
  EXPECT_THROW(in.expectTag("other"), CorruptRecord);
  BinaryRecordReader short_read(out.bytes().substr(0, out.bytes().size() - 1));
  short_read.expectTag("part");
  EXPECT_EQ(short_read.get<double>(), 3.5);
  Eigen::MatrixXcd m;
  EXPECT_THROW(short_read.get(m), CorruptRecord);
  BinaryRecordReader fixed(out.bytes());
  fixed.expectTag("part");
  fixed.get<double>();
  Eigen::Matrix2cd wrong_size;
  EXPECT_THROW(fixed.get(wrong_size), CorruptRecord);
}

}  // namespace warm_start_tests
}  // namespace ddb::test
