// A file that grows while a long run goes and outlives the run's death, for the files a
// resumed run continues (history.csv; docs/file-formats.md, "Checkpoints"). It is written
// under the fixed name `<target>.partial`, so that a run resumed from a checkpoint finds
// it, and renamed onto the target by commit(), so that a file under its final name is
// complete. sync() makes what was written durable and returns its length, which the
// checkpoint records; the resumed run opens the file again cut back to that length. An
// I/O error, or destruction without commit() (another file failed), removes the partial
// file, as AtomicFile removes its temporary; only a killed process leaves it behind.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string_view>

namespace ddb::app {

class JournalFile {
 public:
  /// Starts the file afresh (a partial file of an earlier run is replaced); throws IoError.
  explicit JournalFile(std::filesystem::path target);
  /// Continues from its first `length` bytes: the partial file a killed run left, or the
  /// target an interrupted or finished run completed (renamed back to the partial name).
  /// Throws IoError if neither exists or it is shorter than `length`.
  JournalFile(std::filesystem::path target, std::uint64_t length);
  ~JournalFile();
  JournalFile(const JournalFile&) = delete;
  JournalFile& operator=(const JournalFile&) = delete;

  /// Appends (buffered); throws IoError naming the target.
  void write(std::string_view text);
  /// Flushes and fsyncs; returns the length written so far.
  std::uint64_t sync();
  /// Syncs, closes and renames the partial file onto the target (durably).
  void commit();

  const std::filesystem::path& target() const { return target_; }
  /// `<target>.partial`.
  static std::filesystem::path partialOf(const std::filesystem::path& target);

 private:
  [[noreturn]] void fail(const char* what);
  void discard() noexcept;

  std::filesystem::path target_, partial_;
  std::FILE* file_ = nullptr;
};

}  // namespace ddb::app
