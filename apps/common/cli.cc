#include "common/cli.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <string_view>

#include "common/exit_status.h"

namespace ddb::app {

void usageError(const std::string& flag, const std::string& value, const std::string& why) {
  throw UsageError(flag + " = " + value + ": " + why);
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> items;
  if (text.empty()) return items;
  std::size_t begin = 0;
  for (std::size_t end; (end = text.find(separator, begin)) != std::string::npos; begin = end + 1) {
    items.push_back(text.substr(begin, end - begin));
  }
  items.push_back(text.substr(begin));
  return items;
}

namespace {

/// `item` read as std::stod read it, but without the locale (a comma-decimal LC_NUMERIC
/// must not change what a flag means): leading white space, a sign ('+' too, which
/// std::from_chars does not take), decimal or 0x hexadecimal, and nothing left over.
/// std::nullopt where std::stod threw, which includes results below the smallest normal
/// double (glibc's strtod sets ERANGE for them, std::stod's out_of_range).
std::optional<double> readDouble(std::string_view item) {
  const std::size_t begin = item.find_first_not_of(" \t\n\v\f\r");
  if (begin == std::string_view::npos) return std::nullopt;
  item.remove_prefix(begin);
  const bool negative = item.front() == '-';
  if (negative || item.front() == '+') item.remove_prefix(1);
  auto format = std::chars_format::general;
  if (item.size() >= 2 && item[0] == '0' && (item[1] == 'x' || item[1] == 'X')) {
    format = std::chars_format::hex;
    item.remove_prefix(2);
  }
  // std::from_chars takes a '-' of its own: a second sign ("--1", "+-1") is not a number.
  if (item.empty() || item.front() == '-') return std::nullopt;
  double v = 0.0;
  const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), v, format);
  if (error != std::errc() || end != item.data() + item.size()) return std::nullopt;
  if (v != 0.0 && std::abs(v) < std::numeric_limits<double>::min()) return std::nullopt;
  return negative ? -v : v;
}

}  // namespace

double parseNumber(const std::string& flag, const std::string& text, const std::string& item) {
  const std::optional<double> v = readDouble(item);
  if (v && std::isfinite(*v)) return *v;
  // A number too small for a normal double (which readDouble refuses) is refused as such:
  // strtod reads it, to a subnormal or zero.
  errno = 0;
  char* end = nullptr;
  const double tiny = std::strtod(item.c_str(), &end);
  if (end != item.c_str() && *end == '\0' && std::isfinite(tiny) &&
      std::abs(tiny) < std::numeric_limits<double>::min() && (tiny != 0 || errno == ERANGE)) {
    usageError(flag, text,
               "'" + item +
                   "' is below the least normal double (2.2250738585072014e-308): give 0 "
                   "or a number of larger magnitude");
  }
  usageError(flag, text, "'" + item + "' is not a finite number");
}

std::vector<std::string> splitItems(const std::string& flag, const std::string& text) {
  std::vector<std::string> items = split(text);
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i].empty()) usageError(flag, text, "item " + std::to_string(i + 1) + " is empty");
  }
  return items;
}

std::vector<double> parseNumbers(const std::string& flag, const std::string& text, int count) {
  const std::vector<std::string> items = splitItems(flag, text);
  if (static_cast<int>(items.size()) != count) {
    usageError(flag, text, "expected " + std::to_string(count) + " comma-separated numbers");
  }
  std::vector<double> values;
  for (const auto& item : items) values.push_back(parseNumber(flag, text, item));
  return values;
}

std::vector<std::string> namesOf(const std::vector<std::pair<std::string, std::string>>& choices) {
  std::vector<std::string> names;
  for (const auto& choice : choices) names.push_back(choice.first);
  return names;
}

void requireChoice(const std::string& flag, const std::string& value,
                   const std::vector<std::string>& names) {
  if (std::find(names.begin(), names.end(), value) != names.end()) return;
  std::string valid;
  for (const auto& name : names) valid += (valid.empty() ? "" : ", ") + name;
  usageError(flag, value, "unknown; valid: " + valid);
}

std::string describeChoices(const std::vector<std::pair<std::string, std::string>>& choices) {
  std::size_t width = 0;
  for (const auto& choice : choices) width = std::max(width, choice.first.size());
  std::string s;
  for (const auto& [name, description] : choices) {
    s += "  " + name + std::string(width - name.size() + 2, ' ') + description + "\n";
  }
  return s;
}

void rejectIfGiven(const CLI::App& cli, const std::string& flag, const std::string& context) {
  if (cli.count(flag) == 0) return;
  const CLI::Option* option = cli.get_option(flag);
  const std::string value = option->results().empty() ? "" : option->results().back();
  usageError(flag, value, "does not apply to " + context);
}

void addSeedOption(CLI::App& cli, std::uint64_t& seed, const std::string& description,
                   const std::string& flag) {
  cli.add_option(flag, seed, description)
      ->capture_default_str()
      ->check(fitsIn<std::uint64_t>())
      ->check(
          [](const std::string& text) {
            return text.rfind('-', 0) != 0 ? std::string()
                                           : text + " is negative; a seed is in [0, 2^64)";
          },
          "");
}

void addRunFolderFlags(CLI::App& cli, std::string& out, bool& overwrite) {
  cli.add_option("--out", out,
                 "output folder; one process writes it at a time (OUT/run.lock), and a new run "
                 "into a folder that holds another run's files is refused without --overwrite")
      ->capture_default_str();
  cli.add_flag("--overwrite", overwrite,
               "let a new run replace the run whose files are in --out: every file of that run "
               "is removed first (files of other names are kept)");
}

std::string projectVersion() { return DDB_VERSION; }

void addVersionFlag(CLI::App& cli, const std::string& app) {
  cli.set_version_flag("--version", app + " " + projectVersion());
}

namespace {

/// Throws a UsageError naming an option given more than once and every value it was
/// given: CLI11 would say only "At Most 1 required but received 2" (or, for a flag,
/// nothing at all), and a silent choice between two values is a wrong number. The counts
/// are CLI11's own, from the parse itself, so that a word is a value or a flag here
/// exactly as CLI11 read it (`--out --plot`: --out has no value, --plot is the flag).
void rejectRepeated(const CLI::App& cli) {
  for (const CLI::Option* option : cli.get_options()) {
    const std::size_t count = option->count();
    if (count < 2) continue;
    const std::string name = option->get_name();
    const std::string why = "given " + std::to_string(count) + " times; give it once";
    if (option->get_expected_max() == 0) throw UsageError(name + ": " + why);
    std::string all;
    for (const auto& value : option->results()) all += (all.empty() ? "" : " and ") + value;
    usageError(name, all, why);
  }
}

}  // namespace

std::optional<int> parseCommandLine(CLI::App& cli, int argc, char** argv) {
  // Every option keeps all its values through the parse (CLI11's default policy would
  // stop at the second with its own message); rejectRepeated() then names them.
  for (CLI::Option* option : cli.get_options()) {
    option->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  }
  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what());
  }
  rejectRepeated(cli);
  return std::nullopt;
}

}  // namespace ddb::app
