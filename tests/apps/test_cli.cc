// The apps' command-line helpers (apps/common/cli.h): numbers read as std::stod read them
// but without the locale, and options given twice rejected as CLI11's own parse counted
// them (docs/reference/bad-inputs.md, "Repeated flags").
#include <gmock/gmock.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "common/cli.h"
#include "common/exit_status.h"

namespace cli_tests {

using ddb::app::parseNumber;
using ddb::app::UsageError;
using ::testing::HasSubstr;

double parse(const std::string& text) { return parseNumber("--x", text, text); }

TEST(Cli, NumbersAreReadAsStodReadThem) {
  EXPECT_EQ(parse("0.1"), 0.1);
  EXPECT_EQ(parse("+0.25"), 0.25);
  EXPECT_EQ(parse("-1e-3"), -1e-3);
  EXPECT_EQ(parse(" 2"), 2.0);  // leading white space, as strtod skips it
  EXPECT_EQ(parse("1."), 1.0);
  EXPECT_EQ(parse(".5"), 0.5);
  EXPECT_EQ(parse("0x10"), 16.0);
  EXPECT_TRUE(std::signbit(parse("-0")));
  EXPECT_EQ(parse("2.2250738585072014e-308"), std::numeric_limits<double>::min());
}

TEST(Cli, NotANumberIsRejectedWithTheFlagAndItem) {
  for (const std::string text : {"", "1,5", "1.5 ", "1e5x", "--1", "+-1", "-+1", "0x", "e5", "nan",
                                 "inf", "-inf", "1e400"}) {
    try {
      parse(text);
      ADD_FAILURE() << "'" << text << "' was accepted";
    } catch (const UsageError& e) {
      EXPECT_EQ(std::string(e.what()), "--x = " + text + ": '" + text + "' is not a finite number");
    }
  }
}

TEST(Cli, ANumberBelowTheLeastNormalDoubleIsRejectedAsSuch) {
  // Finite, so "not a finite number" would be false (issue 42); 0 and normal values pass.
  for (const std::string text : {"1e-310", "-1e-310", "4.9e-324", "1e-400", "0x1p-1030"}) {
    try {
      parse(text);
      ADD_FAILURE() << "'" << text << "' was accepted";
    } catch (const UsageError& e) {
      EXPECT_EQ(std::string(e.what()),
                "--x = " + text + ": '" + text +
                    "' is below the least normal double (2.2250738585072014e-308): give 0 or a "
                    "number of larger magnitude");
    }
  }
  EXPECT_EQ(parse("0"), 0.0);
  EXPECT_EQ(parse("2.2250738585072014e-308"), std::numeric_limits<double>::min());
}

/// parseCommandLine() on an app with an option --out, a number --h and a flag --plot;
/// "" if it accepts `words`, else its message.
std::string parseError(std::vector<std::string> words) {
  CLI::App cli;
  std::string out, h;
  bool plot = false;
  cli.add_option("--out", out);
  cli.add_option("--h", h);
  cli.add_flag("--plot", plot);
  words.insert(words.begin(), "app");
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  try {
    ddb::app::parseCommandLine(cli, static_cast<int>(argv.size()), argv.data());
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(Cli, RepeatedOptionsAreCountedByCli11sOwnParse) {
  EXPECT_EQ(parseError({"--h", "0.1", "--h=0.2"}),
            "--h = 0.1 and 0.2: given 2 times; give it once");
  EXPECT_EQ(parseError({"--plot", "--plot"}), "--plot: given 2 times; give it once");
  // CLI11 takes --plot as --out's value here: --out is given twice, --plot not at all.
  EXPECT_EQ(parseError({"--out", "--plot", "--out", "x"}),
            "--out = --plot and x: given 2 times; give it once");
  EXPECT_EQ(parseError({"--out", "--plot", "--plot"}), "");
  // An --out without a value is CLI11's error, not a repeat.
  EXPECT_THAT(parseError({"--out", "x", "--out"}), HasSubstr("--out: 1 required"));
  // After "--" nothing is an option.
  EXPECT_THAT(parseError({"--h", "0.1", "--", "--h", "0.2"}), HasSubstr("not expected"));
  EXPECT_EQ(parseError({"--h", "0.1", "--out", "x", "--plot"}), "");
}

}  // namespace cli_tests
