// Command-line helpers shared by the apps: parsing numbers and vectors with messages
// that name the flag and its value, choices that list the valid names, flags that do
// not apply, --version, and CLI11's own errors turned into usage errors (exit 2;
// docs/reference/command-lines-and-files.md).
#pragma once

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <charconv>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace ddb::app {

/// Throws UsageError("<flag> = <value>: <why>").
[[noreturn]] void usageError(const std::string& flag, const std::string& value,
                             const std::string& why);

/// "a,b,,c" -> {"a", "b", "", "c"}; an empty text gives no items.
std::vector<std::string> split(const std::string& text, char separator = ',');

/// split(text), or a UsageError naming `flag` if an item is empty ("a,,b", "a,").
std::vector<std::string> splitItems(const std::string& flag, const std::string& text);

/// One finite number `item` taken from the value `text` of `flag`.
double parseNumber(const std::string& flag, const std::string& text, const std::string& item);

/// Exactly `count` comma-separated finite numbers.
std::vector<double> parseNumbers(const std::string& flag, const std::string& text, int count);

template <int N>
Eigen::Matrix<double, N, 1> parseVector(const std::string& flag, const std::string& text) {
  const std::vector<double> values = parseNumbers(flag, text, N);
  return Eigen::Map<const Eigen::Matrix<double, N, 1>>(values.data());
}

/// The names of (name, description) pairs, such as describeChoices() lists.
std::vector<std::string> namesOf(const std::vector<std::pair<std::string, std::string>>& choices);

/// Throws a UsageError listing every valid name if `value` is not one of `names`.
void requireChoice(const std::string& flag, const std::string& value,
                   const std::vector<std::string>& names);

/// "  name  description" lines, names padded to one column, for --help.
std::string describeChoices(const std::vector<std::pair<std::string, std::string>>& choices);

/// Throws a UsageError naming `flag` if it was given although it does not apply to
/// `context` (a flag that would be silently ignored is bad input).
void rejectIfGiven(const CLI::App& cli, const std::string& flag, const std::string& context);

/// A check of an integer option's text: CLI11 2.1 reads integers with strtoll/strtoull,
/// which saturate a value beyond the type's range (99999999999999999999 became 2^63 − 1)
/// without a word; this refuses it, naming the range. Other text is left to CLI11's reading.
template <class T>
CLI::Validator fitsIn() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        T value{};
        const char* begin = text.c_str() + (text.rfind('+', 0) == 0 ? 1 : 0);
        const auto result = std::from_chars(begin, text.c_str() + text.size(), value);
        if (result.ec != std::errc::result_out_of_range) return {};
        return text + " is out of range: [" + std::to_string(std::numeric_limits<T>::min()) + ", " +
               std::to_string(std::numeric_limits<T>::max()) + "]";
      },
      "");
}

/// Adds `flag` (a seed, default `seed`'s value) with `description`; a negative value is refused,
/// which CLI11 would otherwise wrap around to 2^64 - 1 without a word.
void addSeedOption(CLI::App& cli, std::uint64_t& seed, const std::string& description,
                   const std::string& flag = "--seed");

/// Adds `--out` (the run folder: one writer, another run's files refused) and `--overwrite`
/// (docs/reference/command-lines-and-files.md, "Run folders: one writer, `--overwrite`").
void addRunFolderFlags(CLI::App& cli, std::string& out, bool& overwrite);

/// The project version from CMake ("0.2.0").
std::string projectVersion();

/// Adds --version, printing "<app> <project version from CMake>".
void addVersionFlag(CLI::App& cli, const std::string& app);

/// Parses the command line: std::nullopt to go on, or the exit status after --help or
/// --version was printed. Any other CLI11 error, and an option given twice, becomes a
/// UsageError.
std::optional<int> parseCommandLine(CLI::App& cli, int argc, char** argv);

}  // namespace ddb::app
