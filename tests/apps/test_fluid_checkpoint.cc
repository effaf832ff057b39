// fluid-relax's checkpoints, --resume and stop signals (docs/reference/command-lines-and-files.md,
// "Checkpoints"). The reference is the uninterrupted run: a run killed with SIGKILL at
// whatever step it reached, or stopped by SIGINT/SIGTERM, and resumed, must end with
// history.csv, W_final.csv, the ω files, summary.json (runtime_s aside) and the final
// checkpoint byte-identical to it; so must a finished run extended by --resume --steps. A
// checkpoint that is corrupted or truncated, a flag that would change the run and a cap
// already reached are refused with exit status 2, and nothing in the folder changes.
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gmock/gmock.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "app_test_support.h"

namespace fluid_checkpoint_tests {

using namespace ddb::test;

const std::vector<std::string> kOutputs{"history.csv", "W_final.csv", "omega_initial.csv",
                                        "checkpoint.ddb", "omega_final.csv"};
// N = 12 from a seeded random vorticity, rows every 7 steps (so that runs end on held-back
// rows) and a checkpoint every 50.
const std::string kRun = "--quiet --n 12 --seed 4 --every 7 --checkpoint-every 50";

fs::path freshFolder(const std::string& name) {
  return ddb::test::freshFolder("fluid_checkpoint_test_", name);
}

AppResult run(const std::string& arguments) { return runProgram(FLUID_RELAX_PATH, arguments); }

/// summary.json without its one wall-clock field.
nlohmann::ordered_json summaryOf(const fs::path& out) {
  nlohmann::ordered_json summary = readJson(out / "summary.json");
  summary.erase("runtime_s");
  return summary;
}

void expectSameOutputs(const fs::path& expected, const fs::path& found) {
  for (const std::string& name : kOutputs) {
    EXPECT_EQ(readFile(found / name), readFile(expected / name)) << name;
  }
  EXPECT_EQ(summaryOf(found), summaryOf(expected));
}

/// Starts fluid-relax with `arguments` (output discarded), waits until it has written a
/// checkpoint, and sends `signal` (`times` times in a row); returns its exit status
/// (-signal if killed by it).
int startAndSignal(const std::string& arguments, const fs::path& out, int signal, int times = 1) {
  std::vector<std::string> words{FLUID_RELAX_PATH};
  std::stringstream ss(arguments + " --out " + out.string());
  for (std::string word; ss >> word;) words.push_back(word);
  const pid_t child = startUntilCheckpoint(words, out);
  for (int i = 0; i < times; ++i) ::kill(child, signal);
  return waitForExit(child);
}

class Checkpoint : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // ctest runs each test in its own process, in parallel: one reference folder each.
    reference_ = new fs::path(freshFolder("reference_" + std::to_string(::getpid())));
    ASSERT_EQ(run(kRun + " --steps 4000 --out " + reference_->string()).status, 0);
  }
  static void TearDownTestSuite() {
    delete reference_;
    reference_ = nullptr;
  }
  static fs::path* reference_;
};
fs::path* Checkpoint::reference_ = nullptr;

TEST_F(Checkpoint, AKilledRunResumesToTheByte) {
  const fs::path out = freshFolder("killed");
  // Killed right after its first checkpoint appears: at some step past 50, mid-run.
  ASSERT_EQ(startAndSignal(kRun + " --steps 4000", out, SIGKILL), -SIGKILL);
  ASSERT_FALSE(fs::exists(out / "summary.json")) << "the run finished before the kill";
  EXPECT_TRUE(fs::exists(out / "history.csv.partial"));
  const AppResult resumed = run("--quiet --resume " + out.string());
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expectSameOutputs(*reference_, out);
  EXPECT_FALSE(fs::exists(out / "history.csv.partial"));
}

TEST_F(Checkpoint, SigintAndSigtermStopAfterTheStepWithOutputsAndResume) {
  for (const int signal : {SIGINT, SIGTERM}) {
    const fs::path out = freshFolder(signal == SIGINT ? "sigint" : "sigterm");
    ASSERT_EQ(startAndSignal(kRun + " --steps 4000", out, signal), 128 + signal);
    const auto summary = readJson(out / "summary.json");
    EXPECT_EQ(summary["status"], "interrupted");
    EXPECT_EQ(summary["stop"], "interrupted");
    EXPECT_LT(summary["steps"].get<long>(), 4000);
    for (const std::string& name : kOutputs) EXPECT_TRUE(fs::exists(out / name)) << name;
    const AppResult resumed = run("--quiet --resume " + out.string());
    ASSERT_EQ(resumed.status, 0) << resumed.output;
    expectSameOutputs(*reference_, out);
  }
}

TEST_F(Checkpoint, ASecondSigintExitsAtOnceAndTheLastCheckpointStaysGood) {
  const fs::path out = freshFolder("sigint_twice");
  ASSERT_EQ(startAndSignal(kRun + " --steps 4000", out, SIGINT, 2), 130);
  const AppResult resumed = run("--quiet --resume " + out.string());
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expectSameOutputs(*reference_, out);
}

TEST_F(Checkpoint, AFinishedRunExtendedByResumeIsTheLongerRun) {
  const fs::path out = freshFolder("extended");
  ASSERT_EQ(run(kRun + " --steps 1500 --out " + out.string()).status, 0);
  const AppResult extended = run("--quiet --resume " + out.string() + " --steps 4000");
  ASSERT_EQ(extended.status, 0) << extended.output;
  expectSameOutputs(*reference_, out);
}

TEST_F(Checkpoint, AnAdaptiveRunKilledAndResumedIsTheUninterruptedOne) {
  const std::string adaptive = kRun + " --adaptive --steps 5000 --h 0.5";
  const fs::path whole = freshFolder("adaptive_whole"), out = freshFolder("adaptive_killed");
  ASSERT_EQ(run(adaptive + " --out " + whole.string()).status, 0);
  ASSERT_GT(readJson(whole / "summary.json")["steps_rejected"].get<long>(), 0);
  ASSERT_EQ(startAndSignal(adaptive, out, SIGKILL), -SIGKILL);
  ASSERT_FALSE(fs::exists(out / "summary.json")) << "the run finished before the kill";
  ASSERT_EQ(run("--quiet --resume " + out.string()).status, 0);
  expectSameOutputs(whole, out);
}

/// Runs `arguments` whole into NAME_whole and again into NAME_killed, killed by SIGKILL before it
/// ends and resumed there: the two folders must hold the same files.
void expectKilledAndResumedIsTheWhole(const std::string& arguments, const std::string& name) {
  const fs::path whole = freshFolder(name + "_whole"), out = freshFolder(name + "_killed");
  ASSERT_EQ(run(arguments + " --out " + whole.string()).status, 0);
  ASSERT_EQ(startAndSignal(arguments, out, SIGKILL), -SIGKILL);
  ASSERT_FALSE(fs::exists(out / "summary.json")) << "the run finished before the kill";
  ASSERT_EQ(run("--quiet --resume " + out.string()).status, 0);
  expectSameOutputs(whole, out);
}

// A damped run (--viscosity, --drag, on a rotating sphere) killed and resumed writes the
// uninterrupted run's files: the checkpoint keeps the damping (layout 5).
TEST_F(Checkpoint, ADampedRunKilledAndResumedIsTheUninterruptedOne) {
  expectKilledAndResumedIsTheWhole(
      kRun + " --steps 4000 --rotation 0.7 --viscosity 1e-3 --hyperviscosity-order 2 --drag 0.01",
      "damped");
}

// A forced run (--forcing-band, --forcing-rate, --forcing-seed, with viscosity on a rotating
// sphere) killed and resumed writes the uninterrupted run's files: the checkpoint keeps the
// forcing (layout 6) and the random stream's position (the method's record, ExactFlow::save).
TEST_F(Checkpoint, AForcedRunKilledAndResumedIsTheUninterruptedOne) {
  expectKilledAndResumedIsTheWhole(kRun +
                                       " --steps 4000 --rotation 0.7 --viscosity 1e-3 "
                                       "--forcing-band 4:1 --forcing-rate 1e-3 --forcing-seed 9",
                                   "forced");
}

// A run with a fixed forcing (--forcing-file) killed and resumed writes the uninterrupted run's
// files, although the file holds another Φ when it resumes: the checkpoint keeps Φ (layout 7).
TEST_F(Checkpoint, AFixedForcedRunKilledAndResumedIsTheUninterruptedOneWhateverItsFileBecomes) {
  const fs::path files = freshFolder("phi_files");
  fs::create_directories(files);
  const auto writePhi = [&](double scale) {
    writeMatrix(files / "phi.csv", scale * ddb::zeitlinX3(12));
  };
  writePhi(1e-3);
  const std::string arguments =
      kRun + " --steps 4000 --viscosity 1e-3 --forcing-file " + (files / "phi.csv").string();
  const fs::path whole = freshFolder("fixed_forced_whole"),
                 out = freshFolder("fixed_forced_killed");
  ASSERT_EQ(run(arguments + " --out " + whole.string()).status, 0);
  ASSERT_EQ(startAndSignal(arguments, out, SIGKILL), -SIGKILL);
  ASSERT_FALSE(fs::exists(out / "summary.json")) << "the run finished before the kill";
  writePhi(2e-3);
  ASSERT_EQ(run("--quiet --resume " + out.string()).status, 0);
  expectSameOutputs(whole, out);
}

/// The folder's files and their bytes.
std::map<std::string, std::string> contentsOf(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    files[entry.path().filename().string()] = readFile(entry.path());
  }
  return files;
}

TEST_F(Checkpoint, RefusesACorruptCheckpointAFlagThatChangesTheRunAndAReachedCap) {
  const fs::path out = freshFolder("refusals");
  ASSERT_EQ(run(kRun + " --steps 120 --out " + out.string()).status, 0);
  const auto before = contentsOf(out);
  const auto refused = [&](const std::string& arguments, const std::string& message) {
    const AppResult r = run("--quiet --resume " + out.string() + " " + arguments);
    EXPECT_EQ(r.status, 2) << arguments << "\n" << r.output;
    EXPECT_THAT(r.error, ::testing::HasSubstr(message)) << arguments;
    EXPECT_EQ(contentsOf(out), before) << arguments << ": the folder changed";
  };
  refused("--steps 200 --alpha 0.7", "--alpha = 0.7: a resumed run keeps its settings");
  refused("--steps 200 --method sddb-cay", "--method = sddb-cay");
  refused("--steps 200 --every 3", "--every = 3");
  refused("--steps 200 --rotation 1", "--rotation = 1: a resumed run keeps its settings");
  refused("--steps 200 --deformation-radius 2", "--deformation-radius = 2");
  refused("--steps 200 --viscosity 1e-4", "--viscosity = 1e-4: a resumed run keeps its settings");
  refused("--steps 200 --hyperviscosity-order 2", "--hyperviscosity-order = 2");
  refused("--steps 200 --drag 0.1", "--drag = 0.1");
  refused("--steps 200 --viscous-scheme implicit",
          "--viscous-scheme = implicit: a resumed run keeps its settings (it ran with "
          "--viscous-scheme = exact)");
  refused("--steps 200 --forcing-band 3:1 --forcing-rate 1e-3", "--forcing-band = 3:1");
  refused("--steps 200 --forcing-seed 5", "--forcing-seed = 5");
  refused("", "the run has taken 120 steps, its cap 120");
  refused("--steps 100", "the run has taken 120 steps");
  refused("--steps 200 --t-end 9", "--steps, --t-end");
  refused("--steps 200 --out " + out.string() + "_other", "--out");
  // The same values as the run's are no change.
  EXPECT_EQ(run("--quiet --resume " + out.string() + " --steps 121 --n 12 --alpha 0.5 --every 7 " +
                "--out " + out.string())
                .status,
            0);

  std::string bytes = readFile(out / "checkpoint.ddb");
  const auto corrupt = [&](const std::string& content) {
    std::ofstream(out / "checkpoint.ddb", std::ios::binary) << content;
    const auto now = contentsOf(out);
    const AppResult r = run("--quiet --resume " + out.string() + " --steps 300");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_THAT(r.error, ::testing::HasSubstr("is corrupt"));
    EXPECT_EQ(contentsOf(out), now) << "the folder changed";
  };
  std::string flipped = bytes;
  flipped[flipped.size() / 2] = static_cast<char>(flipped[flipped.size() / 2] ^ 0x01);
  corrupt(flipped);
  corrupt(bytes.substr(0, bytes.size() / 3));
  corrupt("");
  const AppResult missing = run("--quiet --resume " + out.string() + "_missing --steps 300");
  EXPECT_EQ(missing.status, 2);
  EXPECT_THAT(missing.error, ::testing::HasSubstr("no checkpoint to resume from"));
  EXPECT_FALSE(fs::exists(out.string() + "_missing"));
}

}  // namespace fluid_checkpoint_tests
