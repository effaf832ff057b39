#include "common/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/cli.h"
#include "common/exit_status.h"

namespace ddb::app {

namespace {

// mkstemp creates files with mode 0600; outputs get the usual 0666 minus the umask.
mode_t outputMode() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
  const std::filesystem::path folder =
      target_.has_parent_path() ? target_.parent_path() : std::filesystem::path(".");
  std::string pattern = (folder / ("." + target_.filename().string() + ".XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) fail("cannot create a temporary file for");
  temporary_ = name.data();
  if (::fchmod(fd, outputMode()) != 0 || (file_ = ::fdopen(fd, "w")) == nullptr) {
    const int error = errno;
    ::close(fd);
    errno = error;
    fail("cannot open a temporary file for");
  }
}

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::write(std::string_view text) {
  if (file_ == nullptr) throw std::logic_error("AtomicFile::write after commit");
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) fail("cannot write");
}

void AtomicFile::commit() {
  if (file_ == nullptr) throw std::logic_error("AtomicFile::commit twice");
  if (std::fflush(file_) != 0 || ::fsync(::fileno(file_)) != 0) fail("cannot write");
  std::FILE* file = file_;
  file_ = nullptr;
  if (std::fclose(file) != 0) fail("cannot write");
  if (std::rename(temporary_.c_str(), target_.c_str()) != 0) fail("cannot rename over");
  temporary_.clear();
  syncFolderOf(target_);
}

void syncFolderOf(const std::filesystem::path& file) {
  const std::filesystem::path folder =
      file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

void AtomicFile::fail(const char* what) {
  const std::string reason = std::strerror(errno);
  discard();
  throw IoError(std::string(what) + " " + target_.string() + ": " + reason);
}

void AtomicFile::discard() noexcept {
  if (file_ != nullptr) std::fclose(file_);
  file_ = nullptr;
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
  temporary_.clear();
}

void writeFileAtomically(const std::filesystem::path& target, std::string_view content) {
  AtomicFile file(target);
  file.write(content);
  file.commit();
}

void prepareOutputFolder(const std::string& flag, const std::string& text,
                         const std::filesystem::path& folder) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec || !std::filesystem::is_directory(folder)) {
    usageError(flag, text,
               "cannot create the folder" + (ec ? ": " + ec.message() : ": a file is in the way"));
  }
  if (::access(folder.c_str(), W_OK | X_OK) != 0) usageError(flag, text, "folder is not writable");
}

}  // namespace ddb::app
