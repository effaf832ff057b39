#include "common/format.h"

#include <cmath>
#include <cstdio>

namespace ddb::app {

int formatNumber(char* buffer, std::size_t size, double v) {
  // printf's spelling of non-finite values varies ("-nan"); the files promise nan/inf.
  if (std::isnan(v)) return std::snprintf(buffer, size, "nan");
  if (std::isinf(v)) return std::snprintf(buffer, size, v > 0 ? "inf" : "-inf");
  return std::snprintf(buffer, size, "%.17g", v);
}

std::string number(double v) {
  char buffer[32];
  const int n = formatNumber(buffer, sizeof buffer, v);
  return std::string(buffer, static_cast<std::size_t>(n));
}

}  // namespace ddb::app
