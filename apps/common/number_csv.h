// A CSV file of numbers given on the command line (--init-file, --mu0-file;
// docs/reference/command-lines-and-files.md): rows of comma-separated finite numbers, blank lines
// skipped, cells trimmed, CRLF accepted. Any fault is bad input naming the flag and the path
// (docs/reference/bad-inputs.md).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace ddb::app {

/// The rows of the file `path` given to `flag`; a UsageError if it is not a readable
/// regular file, has more than `max_rows` rows (then `limit` says why, e.g. "N <= 1024"),
/// or a cell that is not a finite number.
std::vector<std::vector<double>> readNumberCsv(const std::string& flag, const std::string& path,
                                               std::size_t max_rows, const std::string& limit);

}  // namespace ddb::app
