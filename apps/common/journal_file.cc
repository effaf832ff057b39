#include "common/journal_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include "common/atomic_file.h"
#include "common/exit_status.h"

namespace ddb::app {

std::filesystem::path JournalFile::partialOf(const std::filesystem::path& target) {
  return target.string() + ".partial";
}

std::filesystem::path JournalFile::resumeFileOf(const std::filesystem::path& target) {
  const std::filesystem::path partial = partialOf(target);
  return ::access(partial.c_str(), F_OK) == 0 ? partial : target;
}

JournalFile::JournalFile(std::filesystem::path target)
    : target_(std::move(target)), partial_(partialOf(target_)) {
  file_ = std::fopen(partial_.c_str(), "wb");
  if (file_ == nullptr) fail("cannot create");
}

JournalFile::JournalFile(std::filesystem::path target, std::uint64_t length, std::uint64_t digest)
    : target_(std::move(target)), digest_(digest) {
  const std::filesystem::path partial = partialOf(target_);
  if (::access(partial.c_str(), F_OK) != 0 && ::access(target_.c_str(), F_OK) == 0 &&
      std::rename(target_.c_str(), partial.c_str()) != 0) {
    fail("cannot reopen");
  }
  struct stat info {};
  if (::stat(partial.c_str(), &info) != 0) fail("cannot reopen");
  if (static_cast<std::uint64_t>(info.st_size) < length) {
    throw IoError("cannot resume " + target_.string() + ": it has " + std::to_string(info.st_size) +
                  " bytes, the checkpoint recorded " + std::to_string(length));
  }
  if (::truncate(partial.c_str(), static_cast<off_t>(length)) != 0) fail("cannot reopen");
  file_ = std::fopen(partial.c_str(), "ab");
  if (file_ == nullptr) fail("cannot reopen");
  partial_ = partial;
}

JournalFile::~JournalFile() { close(); }

void JournalFile::write(std::string_view text) {
  if (file_ == nullptr) throw std::logic_error("JournalFile::write after commit");
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) fail("cannot write");
  digest_ = fnv1a64(text, digest_);
}

std::uint64_t JournalFile::sync() {
  if (file_ == nullptr) throw std::logic_error("JournalFile::sync after commit");
  if (std::fflush(file_) != 0 || ::fsync(::fileno(file_)) != 0) fail("cannot write");
  const long length = std::ftell(file_);
  if (length < 0) fail("cannot write");
  return static_cast<std::uint64_t>(length);
}

void JournalFile::commit() {
  sync();
  std::FILE* file = file_;
  file_ = nullptr;
  if (std::fclose(file) != 0) fail("cannot write");
  if (std::rename(partial_.c_str(), target_.c_str()) != 0) fail("cannot rename over");
  syncFolderOf(target_);
}

void JournalFile::fail(const char* what) {
  const std::string reason = std::strerror(errno);
  close();
  throw IoError(std::string(what) + " " + target_.string() + ": " + reason);
}

void JournalFile::close() noexcept {
  if (file_ != nullptr) std::fclose(file_);
  file_ = nullptr;
}

}  // namespace ddb::app
