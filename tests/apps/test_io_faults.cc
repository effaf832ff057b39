// The apps against real I/O faults: tests/support/io_fault_preload.cc, preloaded into the
// unmodified binaries, makes one operation on one output file fail, as a full disk
// (write or fsync: ENOSPC) or an output folder that turned unwritable (creating the
// file or renaming it into place: EACCES) would. Each fault must give exit status 1 and
// a message naming the file, leave no temporary file, and keep every file completed
// before it whole: byte for byte what a run without the fault wrote. A journal (history.csv's
// .partial) stays as far as it got, since a checkpoint may continue it
// (tests/apps/test_run_folder.cc resumes such folders). (A chmod of the
// folder mid-run would not do: tests may run as root, whom a mode of 0555 does not stop.)
#include <gmock/gmock.h>

#include <algorithm>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "app_test_support.h"

namespace io_faults_tests {

using namespace ddb::test;

struct AppCase {
  std::string program, arguments;
  std::vector<std::string> files;      // the output files, in the order the app writes them
  std::vector<std::string> variables;  // added to the environment of every run
  /// Files written as `<name>.partial` beside the faulty one, which may stay as far as they got
  /// (a checkpoint may continue them), unchecked here: mhd-relax's fluid.hdf5.
  std::vector<std::string> journals = {};
};

const std::vector<std::string> kOperations{"write", "fsync", "create", "rename"};

AppResult runWithFault(const AppCase& app, const fs::path& out, const std::string& operation,
                       const std::string& file) {
  RunEnvironment environment{app.variables, 60};
  environment.variables.insert(environment.variables.end(),
                               {std::string("LD_PRELOAD=") + IO_FAULT_PRELOAD,
                                "DDB_IO_FAULT_OP=" + operation, "DDB_IO_FAULT_PATH=" + file});
  // Under AddressSanitizer the preloaded library comes before the sanitizer's runtime.
  const char* asan = std::getenv("ASAN_OPTIONS");
  environment.variables.push_back(std::string("ASAN_OPTIONS=") + (asan ? asan : "") +
                                  ":verify_asan_link_order=0");
  return runProgram(app.program, app.arguments + " --out " + out.string(), environment);
}

void expectFaultsHandled(const AppCase& app, const std::string& prefix,
                         const std::vector<std::string>& faulty_files) {
  const fs::path clean = freshFolder(prefix, "clean");
  ASSERT_EQ(runProgram(app.program, app.arguments + " --out " + clean.string(),
                       RunEnvironment{app.variables, 60})
                .status,
            0);
  for (const std::string& file : faulty_files) {
    for (const std::string& operation : kOperations) {
      const std::string what = operation + " fault on " + file;
      const fs::path out = freshFolder(prefix, "fault");
      const AppResult r = runWithFault(app, out, operation, file);
      EXPECT_EQ(r.status, 1) << what << "\n" << r.output;
      EXPECT_THAT(r.error, ::testing::HasSubstr((out / file).string())) << what;
      // What was written before the faulty file, whole, and nothing else.
      std::set<std::string> expected;
      for (const std::string& name : app.files) {
        if (name == file) break;
        expected.insert(name);
      }
      // The fluid apps' lock (run.lock) stays, empty; a journal that failed (history.csv's
      // .partial) stays as far as it was written, for a resume (docs/reference/guarantees.md).
      std::set<std::string> found;
      for (const auto& entry : fs::directory_iterator(out)) {
        const std::string name = entry.path().filename().string();
        if (name == "run.lock") {
          EXPECT_EQ(readFile(entry.path()), "") << what;
        } else if (std::find(app.journals.begin(), app.journals.end(),
                             name.substr(0, name.size() - std::string(".partial").size())) !=
                       app.journals.end() &&
                   name.size() > std::string(".partial").size() &&
                   name.substr(name.size() - std::string(".partial").size()) == ".partial") {
          continue;
        } else if (name == file + ".partial") {
          const std::string clean_file = readFile(clean / file);
          EXPECT_EQ(clean_file.substr(0, fs::file_size(entry.path())), readFile(entry.path()))
              << what << ": the journal kept is not the clean run's prefix";
        } else {
          found.insert(name);
        }
      }
      EXPECT_EQ(found, expected) << what << ": a temporary or a partial file was left";
      for (const std::string& name : expected) {
        EXPECT_EQ(readFile(out / name), readFile(clean / name)) << what << ": " << name;
      }
    }
  }
}

TEST(IoFaults, DdbCompareExitsOneNamingTheFileAndKeepsTheFilesBefore) {
  // The trajectories, then summary.json and runtime_table.md (whose runtimes differ
  // between runs, so the faults are put on the CSV files only).
  const AppCase app{DDB_COMPARE_PATH,
                    "--quiet --t-end 1 --method ddb-cay,rk4,sddb-cay --repeat 1",
                    {"ddb-cay.csv", "rk4.csv", "sddb-cay.csv", "summary.json", "runtime_table.md"},
                    {}};
  expectFaultsHandled(app, "ddb_io_faults_", {"ddb-cay.csv", "sddb-cay.csv"});
}

TEST(IoFaults, FluidRelaxExitsOneNamingTheFileAndKeepsTheFilesBefore) {
  // history.csv is streamed while the run goes, so its fault arrives inside the run.
  const AppCase app{FLUID_RELAX_PATH,
                    "--quiet --n 8 --steps 20 --seed 2",
                    {"history.csv", "checkpoint.ddb", "W_final.csv", "omega_initial.csv",
                     "omega_final.csv", "summary.json"},
                    {}};
  expectFaultsHandled(app, "fluid_io_faults_", {"history.csv", "omega_initial.csv"});
}

TEST(IoFaults, MhdRelaxExitsOneNamingTheFileAndKeepsTheFilesBefore) {
  // history.csv is streamed while the run goes; fluid.hdf5, written through HDF5's own calls
  // (which the preload does not reach), is a journal beside it. The files after fluid.hdf5 come
  // after a file whose `created` differs between runs, so no fault is put on them here.
  const AppCase app{MHD_RELAX_PATH,
                    "--quiet --n 8 --steps 20",
                    {"history.csv", "fluid.hdf5", "checkpoint.ddb", "W_final.csv",
                     "theta_final.csv", "summary.json"},
                    {},
                    {"fluid.hdf5"}};
  expectFaultsHandled(app, "mhd_io_faults_", {"history.csv"});
}

#ifdef FLUID_RELAX_MPI_PATH
TEST(IoFaults, FluidRelaxMpiExitsOneNamingTheFileAndKeepsTheFilesBefore) {
  // Rank 0 writes fluid-relax's files in fluid-relax's order; the other ranks learn of its
  // failure at the next step (history.csv) or at the end (the final files), and every rank
  // exits 1. The preload reaches the ranks through mpiexec's environment.
  const AppCase app{MPIEXEC_PATH,
                    "-n 2 " FLUID_RELAX_MPI_PATH " --quiet --n 8 --steps 20 --seed 2",
                    {"history.csv", "checkpoint.ddb", "W_final.csv", "omega_initial.csv",
                     "omega_final.csv", "summary.json"},
                    kMpiVariables};
  expectFaultsHandled(app, "fluid_mpi_io_faults_", {"history.csv", "omega_initial.csv"});
}
#endif

}  // namespace io_faults_tests
