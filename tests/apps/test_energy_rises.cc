// energy_rises (docs/reference/command-lines-and-files.md, "Energy rises"): with α > 0 a DDB run
// whose h is too large lets the energy rise; both apps count such steps in summary.json and warn.
// The count is checked against the energy column of the app's own CSV, read here and
// counted with the documented definition, E_k − E_{k−1} > 8 ε max(|E_{k−1}|, |E_k|); a
// resolved step size must give 0.
#include <gmock/gmock.h>

#include <cmath>
#include <limits>
#include <string>

#include "app_test_support.h"

namespace energy_rises_tests {

using namespace ddb::test;

/// The rises in column `column` of a CSV written with --every 1 (every state).
long risesInCsv(const fs::path& csv, std::size_t column) {
  std::string header;
  const auto rows = readCsv(csv, &header);
  long rises = 0;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const double before = rows[k - 1][column], after = rows[k][column];
    const double roundoff =
        8 * std::numeric_limits<double>::epsilon() * std::max(std::abs(before), std::abs(after));
    if (after - before > roundoff) ++rises;
  }
  return rises;
}

/// summary.json's "energy_rises": fluid-relax's, or ddb-compare's for ddb-cay; -1 if absent.
long summaryRises(const fs::path& summary) {
  const nlohmann::ordered_json json = readJson(summary);
  const auto& holder = json.contains("methods") ? json.at("methods").at("ddb-cay") : json;
  return holder.contains("energy_rises") ? holder.at("energy_rises").get<long>() : -1;
}

TEST(EnergyRises, DdbCompareCountsRisesOfATooLargeStepAndNoneOfASmallOne) {
  // α = 20 on Scenario A: h = 1 leaves the dissipation unresolved (h α |M₀| ≈ 10).
  const std::string common = "--method ddb-cay --alpha 20 --t-end 20 --every 1 --repeat 1 --out ";
  const fs::path large = freshFolder("energy_rises_", "compare_large");
  const AppResult r = runProgram(DDB_COMPARE_PATH, "--h 1 " + common + large.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const long rises = risesInCsv(large / "ddb-cay.csv", 4);  // t,m1,m2,m3,energy,casimir
  EXPECT_GT(rises, 0);
  EXPECT_EQ(summaryRises(large / "summary.json"), rises);
  EXPECT_THAT(r.error, ::testing::HasSubstr("ddb-cay: the energy rose beyond round-off in " +
                                            std::to_string(rises) + " steps"));

  const fs::path small = freshFolder("energy_rises_", "compare_small");
  const AppResult s = runProgram(DDB_COMPARE_PATH, "--h 0.01 " + common + small.string());
  ASSERT_EQ(s.status, 0) << s.output;
  EXPECT_EQ(risesInCsv(small / "ddb-cay.csv", 4), 0);
  EXPECT_EQ(summaryRises(small / "summary.json"), 0);
  EXPECT_THAT(s.error, ::testing::Not(::testing::HasSubstr("energy rose")));
}

TEST(EnergyRises, FluidRelaxCountsRisesOfATooLargeStepAndNoneOfASmallOne) {
  const std::string common = "--quiet --n 8 --seed 3 --alpha 5 --method ddb-cay --out ";
  const fs::path large = freshFolder("energy_rises_", "fluid_large");
  const AppResult r = runProgram(FLUID_RELAX_PATH, "--h 0.3 --steps 40 " + common + large.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const long rises = risesInCsv(large / "history.csv", 1);  // t,energy,...
  EXPECT_GT(rises, 0);
  EXPECT_EQ(summaryRises(large / "summary.json"), rises);

  const fs::path small = freshFolder("energy_rises_", "fluid_small");
  ASSERT_EQ(runProgram(FLUID_RELAX_PATH, "--steps 40 " + common + small.string()).status, 0);
  EXPECT_EQ(risesInCsv(small / "history.csv", 1), 0);
  EXPECT_EQ(summaryRises(small / "summary.json"), 0);
}

TEST(EnergyRises, AreNotCountedWhereNoMonotoneEnergyIsPromised) {
  // rk4 is not a DDB method, and α < 0 raises the energy on purpose: no count, not 0.
  const fs::path out = freshFolder("energy_rises_", "null");
  ASSERT_EQ(
      runProgram(FLUID_RELAX_PATH, "--quiet --n 8 --steps 5 --method rk4 --out " + out.string())
          .status,
      0);
  EXPECT_EQ(summaryRises(out / "summary.json"), -1);
  ASSERT_EQ(runProgram(FLUID_RELAX_PATH,
                       "--quiet --n 8 --steps 5 --alpha -0.5 --overwrite --out " + out.string())
                .status,
            0);
  EXPECT_EQ(summaryRises(out / "summary.json"), -1);
}

}  // namespace energy_rises_tests
