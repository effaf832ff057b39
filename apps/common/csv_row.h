// One row of numbers of the apps' CSV files (docs/reference/command-lines-and-files.md):
// comma-separated, 17 significant digits (format.h), formatted into a buffer allocated once for the
// file, so that writing a row allocates nothing however long the run.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace ddb::app {

class CsvRow {
 public:
  /// A row of at most `cells` numbers.
  explicit CsvRow(std::size_t cells);

  /// Appends v as the row's next cell; throws std::logic_error past `cells` cells.
  void put(double v);
  /// Appends the row and its newline to `file` (AtomicFile, JournalFile) and starts a new one.
  template <class File>
  void writeTo(File& file) {
    file.write(take());
  }

 private:
  /// The row with its newline; the next put() starts a new one.
  std::string_view take();

  std::vector<char> buffer_;
  std::size_t used_ = 0;
};

}  // namespace ddb::app
