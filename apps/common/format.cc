#include "common/format.h"

#include <cmath>
#include <cstring>

namespace ddb::app {

namespace {

int copy(char* buffer, std::size_t size, const char* text) {
  const std::size_t n = std::strlen(text);
  std::memcpy(buffer, text, n < size ? n : size);
  return static_cast<int>(n);
}

}  // namespace

int formatNumber(char* buffer, std::size_t size, double v) {
  // printf's spelling of non-finite values varies ("-nan"); the files promise nan/inf.
  if (std::isnan(v)) return copy(buffer, size, "nan");
  if (std::isinf(v)) return copy(buffer, size, v > 0 ? "inf" : "-inf");
  // std::to_chars with a precision is specified as printf's %.*g (C++17 [charconv.to.chars]).
  const auto result = std::to_chars(buffer, buffer + size, v, std::chars_format::general, 17);
  return static_cast<int>(result.ptr - buffer);
}

std::string number(double v) {
  char buffer[kMaxNumberChars];
  const int n = formatNumber(buffer, sizeof buffer, v);
  return std::string(buffer, static_cast<std::size_t>(n));
}

std::string number(double v, std::chars_format format, int precision) {
  // %.*e of 1e308 with up to 17 digits, or %.*g: well below 64 characters.
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v, format, precision);
  return std::string(buffer, result.ptr);
}

}  // namespace ddb::app
