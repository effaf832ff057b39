// A file that grows while a long run goes and outlives the run's death, for the files a
// resumed run continues (history.csv; docs/reference/command-lines-and-files.md, "Checkpoints"). It
// is written under the fixed name `<target>.partial`, so that a run resumed from a checkpoint finds
// it, and renamed onto the target by commit(), so that a file under its final name is
// complete. sync() makes what was written durable and returns its length, which the
// checkpoint records with the FNV-1a hash of those bytes (digest()); the resumed run checks
// both before it opens the file again cut back to that length. No failure removes the file:
// a checkpoint may refer to it, and a run that failed (a full disk, say) must resume once
// the cause is gone (docs/reference/guarantees.md, "Nothing finished is lost").
#pragma once

#include <ddb/core/binary_record.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string_view>

namespace ddb::app {

class JournalFile {
 public:
  /// Starts the file afresh (a partial file of an earlier run is replaced); throws IoError.
  explicit JournalFile(std::filesystem::path target);
  /// Continues from its first `length` bytes, whose hash is `digest`: the partial file a
  /// killed run left, or the target an interrupted or finished run completed (renamed back to
  /// the partial name). Throws IoError if neither exists or it is shorter than `length` (the
  /// caller checked its bytes: resumeFileOf()).
  JournalFile(std::filesystem::path target, std::uint64_t length, std::uint64_t digest);
  ~JournalFile();
  JournalFile(const JournalFile&) = delete;
  JournalFile& operator=(const JournalFile&) = delete;

  /// Appends (buffered); throws IoError naming the target.
  void write(std::string_view text);
  /// Flushes and fsyncs; returns the length written so far.
  std::uint64_t sync();
  /// The FNV-1a hash (core/binary_record.h) of every byte written so far, from the first.
  std::uint64_t digest() const { return digest_; }
  /// Syncs, closes and renames the partial file onto the target (durably).
  void commit();

  const std::filesystem::path& target() const { return target_; }
  /// `<target>.partial`.
  static std::filesystem::path partialOf(const std::filesystem::path& target);
  /// The file a resume of `target` continues: `<target>.partial` if it exists (a killed or
  /// failed run's), else the target (a completed run's).
  static std::filesystem::path resumeFileOf(const std::filesystem::path& target);

 private:
  [[noreturn]] void fail(const char* what);
  void close() noexcept;

  std::filesystem::path target_, partial_;
  std::FILE* file_ = nullptr;
  std::uint64_t digest_ = kFnv1a64Basis;
};

}  // namespace ddb::app
