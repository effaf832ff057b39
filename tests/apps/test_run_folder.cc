// A fluid-relax run folder keeps what a user made (docs/reference/guarantees.md, "Nothing finished
// is lost"; docs/reference/command-lines-and-files.md, "Run folders"): one writer at a time
// (run.lock), a new run that would mix with another run's files refused unless --overwrite, every
// check of a --resume (checkpoint, history.csv, fluid.hdf5, their agreement) made before anything
// is touched, special files refused by kind, a checkpoint's sizes checked against its length,
// and a run stopped by a full disk resumable once there is space. Each refusal is checked
// with the folder's bytes before and after, and each repaired folder by resuming it to the
// bytes of the uninterrupted run.
#include <ddb/core/binary_record.h>
#include <fcntl.h>
#include <gmock/gmock.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "app_test_support.h"

namespace run_folder_tests {

using namespace ddb::test;
using ::testing::HasSubstr;

const std::string kRun = "--quiet --n 8 --seed 3 --checkpoint-every 5";
const std::vector<std::string> kCompared{"history.csv", "W_final.csv", "omega_final.csv",
                                         "checkpoint.ddb"};

fs::path freshFolder(const std::string& name) {
  return ddb::test::freshFolder("run_folder_test_", name);
}

AppResult run(const std::string& arguments, const std::vector<std::string>& variables = {}) {
  return runProgram(FLUID_RELAX_PATH, arguments, RunEnvironment{variables, 60});
}

/// The folder's entries: a regular file's bytes, or the kind of anything else (never opened,
/// so that a FIFO does not block the test). run.lock is not opened either: closing a
/// descriptor of it would drop a lock this process holds (HeldLock); its size is recorded.
std::map<std::string, std::string> contentsOf(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const fs::file_status status = fs::symlink_status(entry.path());
    const std::string name = entry.path().filename().string();
    if (name == "run.lock") {
      files[name] = "<lock of " + std::to_string(fs::file_size(entry.path())) + " bytes>";
      continue;
    }
    files[name] = fs::is_regular_file(status)
                      ? readFile(entry.path())
                      : "<kind " + std::to_string(static_cast<int>(status.type())) + ">";
  }
  return files;
}

/// Runs `arguments` and expects exit status 2 with `message` on stderr and `dir` unchanged.
void expectRefused(const std::string& arguments, const std::string& message, const fs::path& dir) {
  const auto before = contentsOf(dir);
  const AppResult r = run(arguments);
  EXPECT_EQ(r.status, 2) << arguments << "\n" << r.output;
  EXPECT_THAT(r.error, HasSubstr(message)) << arguments;
  EXPECT_EQ(contentsOf(dir), before) << arguments << ": the folder changed";
}

/// Expects `dir`'s outputs to be those of the uninterrupted run in `reference`.
void expectSameOutputs(const fs::path& reference, const fs::path& dir) {
  for (const std::string& name : kCompared) {
    EXPECT_EQ(readFile(dir / name), readFile(reference / name)) << name;
  }
}

/// The offset just past the tag `name` (a length-prefixed string) in a record's bytes.
std::size_t afterTag(const std::string& bytes, const std::string& name) {
  std::string tag(sizeof(std::uint64_t), '\0');
  const std::uint64_t size = name.size();
  std::memcpy(tag.data(), &size, sizeof size);
  tag += name;
  const std::size_t at = bytes.find(tag);
  EXPECT_NE(at, std::string::npos) << name;
  return at + tag.size();
}

/// A sealed record with the 8 bytes at `offset` replaced by `value` and its checksum made
/// anew, as a deliberate edit (not a corruption) would leave it.
template <class T>
std::string withField(std::string sealed, std::size_t offset, T value) {
  std::string bytes = sealed.substr(0, sealed.size() - sizeof(std::uint64_t));
  std::memcpy(bytes.data() + offset, &value, sizeof value);
  const std::uint64_t sum = ddb::fnv1a64(bytes);
  bytes.append(reinterpret_cast<const char*>(&sum), sizeof sum);
  return bytes;
}

class RunFolder : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    reference_ = new fs::path(freshFolder("reference"));
    ASSERT_EQ(run(kRun + " --h5 --steps 40 --out " + reference_->string()).status, 0);
  }
  static void TearDownTestSuite() { delete reference_; }
  /// A finished run of 20 steps (with --h5 unless `h5` is false), to be resumed to 40.
  static fs::path finished(const std::string& name, bool h5 = true) {
    const fs::path out = freshFolder(name);
    EXPECT_EQ(run(kRun + (h5 ? " --h5" : "") + " --steps 20 --out " + out.string()).status, 0);
    return out;
  }
  static fs::path* reference_;
};
fs::path* RunFolder::reference_ = nullptr;

TEST_F(RunFolder, AFailedResumeKeepsEveryFileAndResumesOnceTheCauseIsGone) {
  const fs::path out = finished("repaired");
  const std::string resume = "--quiet --resume " + out.string() + " --steps 40";
  const std::string h5 = readFile(out / "fluid.hdf5"), history = readFile(out / "history.csv");
  const auto put = [&](const std::string& name, const std::string& content) {
    std::ofstream(out / name, std::ios::binary) << content;
  };
  fs::remove(out / "fluid.hdf5");
  expectRefused(resume, (out / "fluid.hdf5").string() + ": No such file", out);
  put("fluid.hdf5", h5.substr(0, h5.size() / 2));
  expectRefused(resume, (out / "fluid.hdf5").string(), out);
  put("fluid.hdf5", std::string(4096, 'x'));
  expectRefused(resume, "not an HDF5 file", out);
  fs::remove(out / "fluid.hdf5");
  ASSERT_EQ(::mkfifo((out / "fluid.hdf5").c_str(), 0644), 0);
  expectRefused(resume, (out / "fluid.hdf5").string() + " is a FIFO", out);
  fs::remove(out / "fluid.hdf5");
  put("fluid.hdf5", h5);
  put("history.csv", history.substr(0, history.size() / 2));
  expectRefused(resume, "its checkpoint recorded: it is not the history its checkpoint continues",
                out);
  std::string altered = history;
  altered[altered.size() / 3] = altered[altered.size() / 3] == '1' ? '2' : '1';
  put("history.csv", altered);
  expectRefused(resume, "is not the history its checkpoint continues", out);
  fs::remove(out / "history.csv");
  fs::create_directory(out / "history.csv");
  expectRefused(resume, (out / "history.csv").string() + " is a folder", out);
  fs::remove(out / "history.csv");
  ASSERT_EQ(::mkfifo((out / "history.csv").c_str(), 0644), 0);
  expectRefused(resume, (out / "history.csv").string() + " is a FIFO", out);
  fs::remove(out / "history.csv");
  put("history.csv", history);

  const AppResult resumed = run(resume);
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expectSameOutputs(*reference_, out);
}

TEST_F(RunFolder, AnotherRunsCheckpointOrFilesAreRefused) {
  const fs::path out = finished("foreign");
  const std::string resume = "--quiet --resume " + out.string() + " --steps 40";
  const std::string own = readFile(out / "checkpoint.ddb");
  // Runs that differ in N, alpha, seed and method: their checkpoints copied in.
  for (const char* other :
       {"--n 12 --seed 3", "--n 8 --seed 3 --alpha 0.7", "--n 8 --seed 9",
        "--n 8 --seed 3 --method ddb-exp", "--n 8 --seed 3 --method sddb-cay"}) {
    const fs::path donor = freshFolder("donor");
    ASSERT_EQ(
        run(std::string("--quiet --h5 --steps 20 ") + other + " --out " + donor.string()).status,
        0);
    fs::copy_file(donor / "checkpoint.ddb", out / "checkpoint.ddb",
                  fs::copy_options::overwrite_existing);
    expectRefused(resume, "not the history its checkpoint continues", out);
  }
  std::ofstream(out / "checkpoint.ddb", std::ios::binary) << own;
  // A run without --h5 beside another run's fluid.hdf5.
  const fs::path plain = finished("plain", false);
  fs::copy_file(out / "fluid.hdf5", plain / "fluid.hdf5");
  expectRefused("--quiet --resume " + plain.string() + " --steps 40",
                "the checkpoint's run writes none", plain);
  // Another run's fluid.hdf5 beside this run's history.
  const fs::path donor = freshFolder("donor_h5");
  ASSERT_EQ(run("--quiet --n 8 --seed 5 --h5 --steps 20 --out " + donor.string()).status, 0);
  fs::copy_file(donor / "fluid.hdf5", out / "fluid.hdf5", fs::copy_options::overwrite_existing);
  expectRefused(resume, (out / "fluid.hdf5").string() + " is another run's: its ", out);
}

TEST_F(RunFolder, ACheckpointThatIsNoRegularFileOrHoldsSizesBeyondItIsRefused) {
  const fs::path out = finished("special");
  const std::string resume = "--quiet --resume " + out.string() + " --steps 40";
  const fs::path checkpoint = out / "checkpoint.ddb";
  const std::string bytes = readFile(checkpoint);
  fs::remove(checkpoint);
  ASSERT_EQ(::mkfifo(checkpoint.c_str(), 0644), 0);
  expectRefused(resume, checkpoint.string() + " is a FIFO", out);
  fs::remove(checkpoint);
  fs::create_symlink("/dev/zero", checkpoint);
  expectRefused(resume, checkpoint.string() + " is a device", out);
  fs::remove(checkpoint);
  fs::create_directory(checkpoint);
  expectRefused(resume, checkpoint.string() + " is a folder", out);
  fs::remove(checkpoint);

  // Fields altered with the checksum recomputed: each is refused before it is used.
  const std::size_t settings = afterTag(bytes, "settings"), options = afterTag(bytes, "options");
  const std::size_t files = afterTag(bytes, "files");
  // The settings end with the forcing's L, D (32-bit), ε and seed, the fixed forcing Φ (here
  // empty: its two 64-bit sizes) and the viscous scheme (32-bit), before the tag "tally".
  const std::size_t tally = afterTag(bytes, "tally") - sizeof(std::uint64_t) - 5;
  const std::vector<std::pair<std::string, std::string>> edits{
      {"--forcing-band's D -1", withField<std::int32_t>(bytes, tally - 40, -1)},
      {"--forcing-rate -1", withField<double>(bytes, tally - 36, -1.0)},
      {"Phi of 2^61 rows", withField<std::int64_t>(bytes, tally - 20, std::int64_t{1} << 61)},
      {"Phi of 3 x 0", withField<std::int64_t>(bytes, tally - 20, 3)},
      {"viscous scheme 2", withField<std::int32_t>(bytes, tally - 4, 2)},
      {"W0 of 2^61 rows", withField<std::int64_t>(bytes, settings, std::int64_t{1} << 61)},
      {"W0 of 2^61 columns", withField<std::int64_t>(bytes, settings + 8, std::int64_t{1} << 61)},
      {"--every -3", withField<long>(bytes, options + 16, -3)},
      {"history_bytes 2^32", withField<std::uint64_t>(bytes, files, std::uint64_t{1} << 32)},
      {"h5_frames -1", withField<std::int64_t>(bytes, files + 8, -1)}};
  for (const auto& [what, edited] : edits) {
    std::ofstream(checkpoint, std::ios::binary) << edited;
    const auto before = contentsOf(out);
    const AppResult r = run(resume);
    EXPECT_EQ(r.status, 2) << what << "\n" << r.output;
    EXPECT_THAT(r.error, HasSubstr("--resume = " + out.string() + ": " + out.string())) << what;
    EXPECT_EQ(contentsOf(out), before) << what << ": the folder changed";
  }
  std::ofstream(checkpoint, std::ios::binary) << bytes;
  ASSERT_EQ(run(resume).status, 0);
  expectSameOutputs(*reference_, out);
}

/// Writes `bytes` (a record without its checksum) as a checkpoint of `layout`: the layout number
/// after the record's tag, then the checksum.
void resealAs(std::string bytes, std::int32_t layout, const fs::path& checkpoint) {
  std::memcpy(bytes.data() + afterTag(bytes, "fluid-relax checkpoint"), &layout, sizeof layout);
  const std::uint64_t sum = ddb::fnv1a64(bytes);
  bytes.append(reinterpret_cast<const char*>(&sum), sizeof sum);
  std::ofstream(checkpoint, std::ios::binary) << bytes;
}

/// Each line of `csv` without its last column (history.csv as a build before 0.3.0 wrote it).
std::string withoutLastColumn(const std::string& csv) {
  std::string out;
  std::stringstream lines(csv);
  for (std::string line; std::getline(lines, line);) out += line.substr(0, line.rfind(',')) + "\n";
  return out;
}

TEST_F(RunFolder, CheckpointsOfLayoutsTwoToSevenResume) {
  // Layout 7 (before the viscous scheme): the record without the options' last entry
  // (--viscous-scheme "exact", before "given flags": its 8-byte length and 5 bytes) and the
  // settings' last (the scheme, 32-bit, before "tally"); its files are those of today's layout.
  // Layout 6 (before the fixed forcing), also: the record without the options' next entry
  // (--forcing-file "", before "given flags": its 8-byte length) and the settings' last (Φ, an
  // empty matrix: its two 8-byte sizes, before "tally"); its files are those of today's layout.
  // Layout 5 (before the forcing), also: the record without the options' three entries
  // (--forcing-band "", --forcing-rate "0" and --forcing-seed, the last before "given flags") and
  // the settings' four numbers (L and D as 32-bit integers, ε and the seed, the last before
  // "tally"); its files are those of today's layout. Layout 4 (before the fluid's damping and the
  // files' field diagnostics): the same record without the byte after the "files" part's hash that
  // says the files have the diagnostics, the options' three entries (--viscosity "0",
  // --hyperviscosity-order 1 and --drag "0", the last before "given flags") and the settings' three
  // numbers (ν, p as a 32-bit integer and γ, the last before "tally"); its history.csv has no gamma
  // column, so the column goes from the file and the recorded length and hash are those of the
  // shorter rows. Layout 3 (before the fluid's physics) also without the options' two texts
  // (--rotation "0" and
  // --deformation-radius "") and the settings' two numbers before those. Layout 2 (before
  // history.csv's hash) also without the hash after the "files" part's two lengths. The layout
  // number follows the record's tag. The resumed run goes on without gamma: its history is the
  // reference's without that column, its final state the reference's.
  const auto beforeTag = [](const std::string& bytes, const std::string& name) {
    return afterTag(bytes, name) - sizeof(std::uint64_t) - name.size();
  };
  const std::string reference_history = withoutLastColumn(readFile(*reference_ / "history.csv"));
  for (const std::int32_t layout : {7, 6, 5, 4, 3, 2}) {
    const fs::path out = finished("layout" + std::to_string(layout), /*h5=*/false);
    const fs::path checkpoint = out / "checkpoint.ddb";
    const std::string sealed = readFile(checkpoint);
    std::string bytes = sealed.substr(0, sealed.size() - 8);
    bytes.erase(beforeTag(bytes, "tally") - 4, 4);
    bytes.erase(beforeTag(bytes, "given flags") - 13, 13);
    if (layout <= 6) {
      bytes.erase(beforeTag(bytes, "tally") - 16, 16);
      bytes.erase(beforeTag(bytes, "given flags") - 8, 8);
    }
    if (layout == 5) {
      bytes.erase(beforeTag(bytes, "tally") - 24, 24);
      bytes.erase(beforeTag(bytes, "given flags") - 25, 25);
    }
    if (layout >= 5) {
      resealAs(bytes, layout, checkpoint);
      const AppResult resumed = run("--quiet --resume " + out.string() + " --steps 40");
      ASSERT_EQ(resumed.status, 0) << "layout " << layout << "\n" << resumed.output;
      for (const std::string name : {"history.csv", "W_final.csv", "omega_final.csv"}) {
        EXPECT_EQ(readFile(out / name), readFile(*reference_ / name))
            << "layout " << layout << ": " << name;
      }
      continue;
    }
    bytes.erase(beforeTag(bytes, "tally") - 24, 24);
    bytes.erase(beforeTag(bytes, "given flags") - 25, 25);
    const std::size_t files = afterTag(bytes, "files");
    std::uint64_t length = 0;
    std::memcpy(&length, bytes.data() + files, sizeof length);
    const std::string history = readFile(out / "history.csv");
    const std::string rows = withoutLastColumn(history.substr(0, length));
    std::ofstream(out / "history.csv", std::ios::binary) << withoutLastColumn(history);
    length = rows.size();
    const std::uint64_t digest = ddb::fnv1a64(rows);
    std::memcpy(bytes.data() + files, &length, sizeof length);
    std::memcpy(bytes.data() + files + 16, &digest, sizeof digest);
    bytes.erase(files + 24, 1);
    if (layout == 2) bytes.erase(files + 16, 8);
    bytes.erase(beforeTag(bytes, "tally") - 20, 20);
    bytes.erase(beforeTag(bytes, "given flags") - 26, 26);
    if (layout <= 3) {
      bytes.erase(beforeTag(bytes, "tally") - 16, 16);
      bytes.erase(beforeTag(bytes, "given flags") - 17, 17);
    }
    resealAs(bytes, layout, checkpoint);
    const AppResult resumed = run("--quiet --resume " + out.string() + " --steps 40");
    ASSERT_EQ(resumed.status, 0) << "layout " << layout << "\n" << resumed.output;
    EXPECT_EQ(readFile(out / "history.csv"), reference_history) << "layout " << layout;
    for (const std::string name : {"W_final.csv", "omega_final.csv"}) {
      EXPECT_EQ(readFile(out / name), readFile(*reference_ / name)) << name;
    }
  }
}

TEST_F(RunFolder, ANewRunIntoAnotherRunsFolderNeedsOverwriteAndThenNothingOfItStays) {
  const fs::path out = finished("replaced");
  std::ofstream(out / "notes.txt") << "the user's own file\n";
  expectRefused(kRun + " --steps 10 --out " + out.string(),
                "the folder holds another run's files (W_final.csv, checkpoint.ddb, "
                "fluid.hdf5, history.csv, omega_final.csv, omega_initial.csv, summary.json)",
                out);
  expectRefused("--quiet --resume " + out.string() + " --steps 40 --overwrite",
                "--overwrite: a resumed run continues", out);
  // A stale temporary of a killed run's checkpoint goes too.
  std::ofstream(out / ".checkpoint.ddb.Ab3xY9") << "stale";
  const AppResult replaced = run(kRun + " --steps 10 --overwrite --out " + out.string());
  ASSERT_EQ(replaced.status, 0) << replaced.output;
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(out)) {
    names.insert(entry.path().filename().string());
  }
  EXPECT_EQ(names, (std::set<std::string>{"W_final.csv", "checkpoint.ddb", "history.csv",
                                          "notes.txt", "omega_final.csv", "omega_initial.csv",
                                          "run.lock", "summary.json"}));
  std::string header;
  EXPECT_EQ(readCsv(out / "history.csv", &header).size(), 11U);
}

/// Holds `dir`/run.lock as fluid-relax does (a POSIX write lock), from this process.
class HeldLock {
 public:
  explicit HeldLock(const fs::path& dir)
      : fd_(::open((dir / "run.lock").c_str(), O_RDWR | O_CREAT, 0644)) {
    struct flock lock {};
    lock.l_type = F_WRLCK;
    lock.l_whence = SEEK_SET;
    EXPECT_EQ(::fcntl(fd_, F_SETLK, &lock), 0);
  }
  ~HeldLock() { ::close(fd_); }

 private:
  int fd_;
};

TEST_F(RunFolder, AFolderHasOneWriterAndAKilledWriterLeavesNoLock) {
  const fs::path out = finished("locked");
  const std::string held = "the folder is in use by process " + std::to_string(::getpid());
  {
    const HeldLock lock(out);
    expectRefused("--quiet --resume " + out.string() + " --steps 40", held, out);
    expectRefused(kRun + " --steps 10 --overwrite --out " + out.string(), held, out);
  }
  // A real second writer: a run that is going (a checkpoint every step, so that it is
  // resumable once killed), then SIGKILL, after which the kernel has dropped its lock.
  const fs::path going = freshFolder("going");
  std::vector<std::string> words{
      FLUID_RELAX_PATH, "--quiet", "--n",   "24",          "--checkpoint-every", "1",
      "--steps",        "1000000", "--out", going.string()};
  const pid_t child = startUntilCheckpoint(words, going);
  const std::string busy = "the folder is in use by process " + std::to_string(child);
  const AppResult second = run("--quiet --resume " + going.string() + " --steps 2000000");
  EXPECT_EQ(second.status, 2) << second.output;
  EXPECT_THAT(second.error, HasSubstr(busy));
  const AppResult third = run(kRun + " --steps 10 --overwrite --out " + going.string());
  EXPECT_EQ(third.status, 2) << third.output;
  EXPECT_THAT(third.error, HasSubstr(busy));
  ::kill(child, SIGKILL);
  ASSERT_EQ(waitForExit(child), -SIGKILL);
  // Resumed for a few more steps after the kill: the lock is free, the folder consistent.
  std::string header;
  const AppResult resumed =
      run("--quiet --resume " + going.string() + " --steps " +
          std::to_string(readCsv(going / "history.csv.partial", &header).size() + 3));
  EXPECT_EQ(resumed.status, 0) << resumed.output;
}

TEST_F(RunFolder, ARunStoppedByAFullDiskResumesToTheUninterruptedRun) {
  // The disk fills while history.csv, fluid.hdf5's flush or a checkpoint is written
  // (tests/support/io_fault_preload.cc after some writes succeeded): exit status 1 naming the file,
  // and the folder as its last good checkpoint left it, which resumes once there is space.
  // How many matching calls succeed first: about half the run's (a row is a write, a
  // checkpoint a write and a flush, each checkpoint an fsync of both files).
  const std::map<std::string, std::string> after{{"history.csv write", "40"},
                                                 {"history.csv fsync", "3"},
                                                 {"checkpoint.ddb write", "6"},
                                                 {"checkpoint.ddb fsync", "3"}};
  for (const std::string file : {"history.csv", "checkpoint.ddb"}) {
    for (const std::string operation : {"write", "fsync"}) {
      const std::string what = operation + " fault on " + file;
      const fs::path out = freshFolder("full_disk");
      const AppResult r = run(
          kRun + " --h5 --steps 40 --out " + out.string(),
          {std::string("LD_PRELOAD=") + IO_FAULT_PRELOAD, "DDB_IO_FAULT_OP=" + operation,
           "DDB_IO_FAULT_PATH=" + file, "DDB_IO_FAULT_AFTER=" + after.at(file + " " + operation)});
      EXPECT_EQ(r.status, 1) << what << "\n" << r.output;
      EXPECT_THAT(r.error, HasSubstr((out / file).string())) << what;
      ASSERT_TRUE(fs::exists(out / "checkpoint.ddb")) << what;
      const AppResult resumed = run("--quiet --resume " + out.string());
      ASSERT_EQ(resumed.status, 0) << what << "\n" << resumed.output;
      expectSameOutputs(*reference_, out);
    }
  }
}

}  // namespace run_folder_tests
