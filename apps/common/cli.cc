#include "common/cli.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <sstream>

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

double parseNumber(const std::string& flag, const std::string& text, const std::string& item) {
  try {
    std::size_t used = 0;
    const double v = std::stod(item, &used);
    if (used == item.size() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
    // std::stod's invalid_argument and out_of_range: reported below with the flag.
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

std::string projectVersion() { return DDB_VERSION; }

void addVersionFlag(CLI::App& cli, const std::string& app) {
  cli.set_version_flag("--version", app + " " + projectVersion());
}

namespace {

/// Throws a UsageError naming an option given more than once and every value it was
/// given: CLI11 would say only "At Most 1 required but received 2" (or, for a flag,
/// nothing at all), and a silent choice between two values is a wrong number.
void rejectRepeated(const CLI::App& cli, int argc, char** argv) {
  std::map<std::string, std::vector<std::string>> given;
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.rfind("--", 0) != 0) continue;
    const std::size_t equals = word.find('=');
    const std::string name = word.substr(0, equals);
    const CLI::Option* option = cli.get_option_no_throw(name);
    if (option == nullptr) continue;  // an unknown flag: CLI11 reports it
    std::string value;
    if (equals != std::string::npos) {
      value = word.substr(equals + 1);
    } else if (option->get_expected_max() > 0 && i + 1 < argc) {
      value = argv[++i];
    }
    given[name].push_back(value);
  }
  for (const auto& [name, values] : given) {
    if (values.size() < 2) continue;
    const std::string why = "given " + std::to_string(values.size()) + " times; give it once";
    if (cli.get_option(name)->get_expected_max() == 0) throw UsageError(name + ": " + why);
    std::string all;
    for (const auto& value : values) all += (all.empty() ? "" : " and ") + value;
    usageError(name, all, why);
  }
}

}  // namespace

std::optional<int> parseCommandLine(CLI::App& cli, int argc, char** argv) {
  rejectRepeated(cli, argc, argv);
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
  return std::nullopt;
}

}  // namespace ddb::app
