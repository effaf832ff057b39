#include "common/csv_row.h"

#include <stdexcept>
#include <string_view>

#include "common/format.h"

namespace ddb::app {

// Each cell takes at most kMaxNumberChars and its separator (',' or the final '\n').
CsvRow::CsvRow(std::size_t cells) : buffer_((kMaxNumberChars + 1) * cells) {}

void CsvRow::put(double v) {
  if (buffer_.size() - used_ < kMaxNumberChars + 1) {
    throw std::logic_error("CsvRow: more cells than the row was made for");
  }
  // The previous cell's '\n' becomes its separator: the row always ends in '\n'.
  if (used_ > 0) buffer_[used_ - 1] = ',';
  used_ += static_cast<std::size_t>(formatNumber(buffer_.data() + used_, kMaxNumberChars, v));
  buffer_[used_++] = '\n';
}

std::string_view CsvRow::take() {
  const std::string_view row(buffer_.data(), used_);
  used_ = 0;
  return row;
}

}  // namespace ddb::app
