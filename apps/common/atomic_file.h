// Atomic output files: the content goes to a unique temporary file in the target's
// folder (mkstemp), which is flushed, fsync'ed and renamed over the target, so that a
// reader sees either the old file or the complete new one, concurrent runs never share
// a temporary name, and a failure leaves no temporary behind. Content is streamed: a
// trajectory of 1e9 rows never has to fit in memory.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

namespace ddb::app {

class AtomicFile {
 public:
  /// Creates the temporary file next to `target`; throws IoError naming `target`.
  explicit AtomicFile(std::filesystem::path target);
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// Appends to the (buffered) temporary file; throws IoError naming the target.
  void write(std::string_view text);
  /// Flushes, fsyncs, renames the temporary over the target and fsyncs the folder;
  /// throws IoError (the temporary removed) if any of it fails.
  void commit();

  const std::filesystem::path& target() const { return target_; }

 private:
  [[noreturn]] void fail(const char* what);
  void discard() noexcept;

  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::FILE* file_ = nullptr;
};

/// Fsyncs the folder holding `file`: a rename into it is durable once its entry is on disk.
void syncFolderOf(const std::filesystem::path& file);

/// The whole content at once, through AtomicFile.
void writeFileAtomically(const std::filesystem::path& target, std::string_view content);

/// Creates the output folder `folder` (given as `text` to `flag`) if missing and checks
/// that it is writable, or throws UsageError: apps call it after every other check, so
/// that bad input creates nothing (docs/reference/command-lines-and-files.md).
void prepareOutputFolder(const std::string& flag, const std::string& text,
                         const std::filesystem::path& folder);

}  // namespace ddb::app
