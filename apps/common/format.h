// Numbers as the apps print them: 17 significant digits (docs/file-formats.md), and
// non-finite values as nan, inf, -inf in messages and CSV cells (JSON writes null
// instead: see json.h).
#pragma once

#include <cstddef>
#include <string>

namespace ddb::app {

/// Writes v into buffer (at least 32 chars) with %.17g; returns the length.
int formatNumber(char* buffer, std::size_t size, double v);

/// v with %.17g: "0.10000000000000001", "nan", "inf", "-inf".
std::string number(double v);

}  // namespace ddb::app
