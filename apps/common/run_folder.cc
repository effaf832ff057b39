#include "common/run_folder.h"

#include <ddb/core/binary_record.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>

#include "common/atomic_file.h"
#include "common/cli.h"
#include "common/exit_status.h"

namespace ddb::app {

namespace {

/// A write lock on the whole file.
struct flock wholeFile() {
  struct flock lock {};
  lock.l_type = F_WRLCK;
  lock.l_whence = SEEK_SET;
  lock.l_start = 0;
  lock.l_len = 0;
  return lock;
}

/// The pid holding a lock that conflicts with ours on `fd`, if any.
std::optional<pid_t> conflictingHolder(int fd) {
  struct flock lock = wholeFile();
  if (::fcntl(fd, F_GETLK, &lock) != 0 || lock.l_type == F_UNLCK) return std::nullopt;
  return lock.l_pid;
}

[[noreturn]] void refuseHeld(const std::string& flag, const std::string& text,
                             const std::filesystem::path& folder, pid_t pid) {
  usageError(flag, text,
             "the folder is in use by process " + std::to_string(pid) + " (it holds " +
                 (folder / kRunLockFile).string() +
                 "): a run folder has one writer; wait for that run to end or stop it");
}

std::string listed(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

void removeEach(const std::filesystem::path& folder, const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    std::error_code ec;
    std::filesystem::remove_all(folder / name, ec);
    if (ec) throw IoError("cannot remove " + (folder / name).string() + ": " + ec.message());
  }
}

}  // namespace

RunFolderLock::RunFolderLock(const std::string& flag, const std::string& text,
                             const std::filesystem::path& folder) {
  const std::filesystem::path path = folder / kRunLockFile;
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_NONBLOCK | O_CLOEXEC, 0666);
  if (fd_ < 0) {
    throw IoError("cannot open the lock " + path.string() + ": " + std::strerror(errno));
  }
  struct flock lock = wholeFile();
  if (::fcntl(fd_, F_SETLK, &lock) != 0) {
    const int error = errno;
    const std::optional<pid_t> pid = conflictingHolder(fd_);
    ::close(fd_);
    fd_ = -1;
    if ((error == EACCES || error == EAGAIN) && pid) refuseHeld(flag, text, folder, *pid);
    throw IoError("cannot lock " + path.string() + ": " + std::strerror(error));
  }
}

RunFolderLock::~RunFolderLock() {
  if (fd_ >= 0) ::close(fd_);
}

RunFolderLock::RunFolderLock(RunFolderLock&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }

void RunFolderLock::refuseIfHeld(const std::string& flag, const std::string& text,
                                 const std::filesystem::path& folder) {
  const int fd = ::open((folder / kRunLockFile).c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return;
  const std::optional<pid_t> pid = conflictingHolder(fd);
  ::close(fd);
  if (pid) refuseHeld(flag, text, folder, *pid);
}

bool RunFiles::isTemporary(const std::string& name) const {
  // AtomicFile's temporaries: "." + the target's name + "." + mkstemp's six characters.
  constexpr std::size_t kSuffix = 7;
  if (name.size() < 1 + kSuffix || name.front() != '.') return false;
  const std::string target = name.substr(1, name.size() - 1 - kSuffix);
  return name[name.size() - kSuffix] == '.' &&
         std::find(names.begin(), names.end(), target) != names.end();
}

std::vector<std::string> RunFiles::in(const std::filesystem::path& folder) const {
  std::vector<std::string> found;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    // A folder under a run file's name is nobody's run: writing the file there fails, naming it.
    if (entry.is_directory(ec)) continue;
    const std::string name = entry.path().filename().string();
    if (std::find(names.begin(), names.end(), name) != names.end() || isTemporary(name)) {
      found.push_back(name);
    }
  }
  std::sort(found.begin(), found.end());
  return found;
}

RunFolderLock claimNewRunFolder(const std::string& flag, const std::string& text,
                                const std::filesystem::path& folder, const RunFiles& files,
                                bool overwrite, const std::string& overwrite_flag,
                                const std::string& resume_flag) {
  // The refusals first, while nothing is created: a holder, then another run's files.
  const auto refuseOthers = [&](const std::vector<std::string>& found) {
    std::vector<std::string> runs;
    std::copy_if(found.begin(), found.end(), std::back_inserter(runs),
                 [&](const std::string& name) { return !files.isTemporary(name); });
    if (!runs.empty() && !overwrite) {
      usageError(flag, text,
                 "the folder holds another run's files (" + listed(runs) + "): give " +
                     overwrite_flag + " to replace that run, " +
                     (resume_flag.empty() ? "" : resume_flag + " " + text + " to continue it, ") +
                     "or another " + flag);
    }
  };
  if (std::filesystem::is_directory(folder)) {
    RunFolderLock::refuseIfHeld(flag, text, folder);
    refuseOthers(files.in(folder));
  }
  prepareOutputFolder(flag, text, folder);
  RunFolderLock lock(flag, text, folder);
  // Under the lock, again: another process may have written between the look and the lock.
  const std::vector<std::string> found = files.in(folder);
  refuseOthers(found);
  removeEach(folder, found);
  return lock;
}

void removeTemporaries(const std::filesystem::path& folder, const RunFiles& files) {
  std::vector<std::string> temporaries = files.in(folder);
  temporaries.erase(
      std::remove_if(temporaries.begin(), temporaries.end(),
                     [&](const std::string& name) { return !files.isTemporary(name); }),
      temporaries.end());
  removeEach(folder, temporaries);
}

std::uint64_t requireRegularFile(const std::string& flag, const std::string& text,
                                 const std::filesystem::path& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    usageError(flag, text, "cannot read " + path.string() + ": " + std::strerror(errno));
  }
  if (!S_ISREG(info.st_mode)) {
    const char* kind = S_ISDIR(info.st_mode)                            ? "a folder"
                       : S_ISFIFO(info.st_mode)                         ? "a FIFO"
                       : S_ISCHR(info.st_mode) || S_ISBLK(info.st_mode) ? "a device"
                       : S_ISSOCK(info.st_mode)                         ? "a socket"
                                                                        : "not a regular file";
    usageError(flag, text,
               path.string() + " is " + kind + ", not a regular file: refusing to read it");
  }
  return static_cast<std::uint64_t>(info.st_size);
}

std::string readRegularFile(const std::string& flag, const std::string& text,
                            const std::filesystem::path& path) {
  // Its kind before it is opened (a FIFO would block, /dev/zero never end), and exactly the bytes
  // it has: nothing is allocated beyond the file's length.
  const std::uint64_t size = requireRegularFile(flag, text, path);
  std::ifstream file(path, std::ios::binary);
  std::string bytes(size, '\0');
  if (!file || !file.read(bytes.data(), static_cast<std::streamsize>(size))) {
    usageError(flag, text, "cannot read " + path.string());
  }
  return bytes;
}

std::uint64_t digestOfPrefix(const std::string& flag, const std::string& text,
                             const std::filesystem::path& path, std::uint64_t length) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> block(std::size_t{1} << 20);
  std::uint64_t digest = kFnv1a64Basis;
  for (std::uint64_t left = length; left > 0;) {
    const auto size = static_cast<std::size_t>(std::min<std::uint64_t>(left, block.size()));
    if (!in.read(block.data(), static_cast<std::streamsize>(size))) {
      usageError(flag, text, "cannot read " + path.string());
    }
    digest = fnv1a64(std::string_view(block.data(), size), digest);
    left -= size;
  }
  return digest;
}

}  // namespace ddb::app
