// A run folder (--out, --resume) has one writer (docs/reference/command-lines-and-files.md, "Run
// folders"): the process that holds FOLDER/run.lock, a POSIX record lock (fcntl) that the kernel
// releases when its process ends however it ends, SIGKILL included, so that no lock is ever left
// stale. A second process is refused (exit status 2) naming the holder's pid, and changes
// nothing: the lock file is empty and never written. A new run into a folder that holds
// another run's files is refused unless the user says to replace that run, and then none
// of its files stays beside the new run's.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace ddb::app {

/// The lock file's name in a run folder.
constexpr const char* kRunLockFile = "run.lock";

class RunFolderLock {
 public:
  /// Takes FOLDER's lock (creating run.lock if missing) for the folder given as `text` to
  /// `flag`; if another process holds it, a UsageError naming the folder and the holder's pid.
  /// The folder must exist. While the lock is held this process must not open run.lock
  /// again: closing any descriptor of the file would release a POSIX lock.
  RunFolderLock(const std::string& flag, const std::string& text,
                const std::filesystem::path& folder);
  ~RunFolderLock();
  RunFolderLock(RunFolderLock&& other) noexcept;
  RunFolderLock& operator=(RunFolderLock&&) = delete;
  RunFolderLock(const RunFolderLock&) = delete;
  RunFolderLock& operator=(const RunFolderLock&) = delete;

  /// The refusal the constructor gives if another process holds FOLDER's lock, given without
  /// creating anything: for the checks that must come before the lock is taken. Not to be
  /// called on a folder this process has locked (it opens run.lock).
  static void refuseIfHeld(const std::string& flag, const std::string& text,
                           const std::filesystem::path& folder);

 private:
  int fd_ = -1;
};

/// The files of a run, by name (fluid-relax's outputs, checkpoint and journals), that make a
/// folder another run's and that a replacement removes; with the temporaries of atomic
/// writes of them (AtomicFile's ".NAME.XXXXXX") that a killed run leaves behind.
struct RunFiles {
  std::vector<std::string> names;

  /// Those of FOLDER's entries that are the run's files or their temporaries, sorted (not
  /// folders of those names, which hold no run).
  std::vector<std::string> in(const std::filesystem::path& folder) const;
  /// Whether `name` is a temporary of one of the files.
  bool isTemporary(const std::string& name) const;
};

/// The folder of a new run (--out), after every other check of the input: creates it if
/// missing, checks that it is writable and takes its lock. A folder that holds another run's
/// files (`files`) is refused with a UsageError naming them, before anything is created or
/// locked, unless `overwrite`: then they are removed once the lock is held (an IoError names
/// one that cannot be). Temporaries alone are a killed run's leftovers and always removed.
/// The refusal names `resume_flag` too where the app can continue a run (fluid-relax's
/// --resume); "" where it cannot (ddb-compare).
RunFolderLock claimNewRunFolder(const std::string& flag, const std::string& text,
                                const std::filesystem::path& folder, const RunFiles& files,
                                bool overwrite, const std::string& overwrite_flag,
                                const std::string& resume_flag);

/// Removes the temporaries of `files` in FOLDER (a resumed run's, once its checks passed and
/// its lock is held); an IoError names one that cannot be removed.
void removeTemporaries(const std::filesystem::path& folder, const RunFiles& files);

/// Checks that `path` exists and is a regular file (or a link to one) before it is opened, so
/// that a FIFO, a device or a folder in its place is refused instead of blocking, reading
/// forever or failing without its name; returns its size. Throws UsageError naming `flag`,
/// `text` and the file.
std::uint64_t requireRegularFile(const std::string& flag, const std::string& text,
                                 const std::filesystem::path& path);

/// requireRegularFile(), then the file's bytes (a resume's checkpoint); a file that cannot be
/// read is a UsageError naming `flag`, `text` and the file.
std::string readRegularFile(const std::string& flag, const std::string& text,
                            const std::filesystem::path& path);

/// The FNV-1a hash (core/binary_record.h) of the first `length` bytes of `path`, which has at
/// least that many (JournalFile::digest of a journal a resume continues); a file that cannot be
/// read is a UsageError naming `flag` and `text`.
std::uint64_t digestOfPrefix(const std::string& flag, const std::string& text,
                             const std::filesystem::path& path, std::uint64_t length);

}  // namespace ddb::app
