// Numbers as the apps print them: 17 significant digits
// (docs/reference/command-lines-and-files.md), and non-finite values as nan, inf, -inf in messages
// and CSV cells (JSON writes null instead: see json.h). Formatting goes through std::to_chars,
// which ignores the locale: a comma-decimal LC_NUMERIC never reaches a file.
#pragma once

#include <charconv>
#include <cstddef>
#include <string>

namespace ddb::app {

/// The longest cell formatNumber() writes: a sign, 17 digits, a point and "e-308".
constexpr std::size_t kMaxNumberChars = 24;

/// Writes v into buffer (at least kMaxNumberChars chars) as %.17g in the C locale
/// would; returns the length.
int formatNumber(char* buffer, std::size_t size, double v);

/// v with %.17g: "0.10000000000000001", "nan", "inf", "-inf".
std::string number(double v);

/// v in `format` with `precision` as printf would in the C locale: general 6 is %.6g,
/// scientific 3 is %.3e.
std::string number(double v, std::chars_format format, int precision);

}  // namespace ddb::app
