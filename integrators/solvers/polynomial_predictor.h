// PolynomialPredictor: the initial guess of the small Legendre solver (legendre.h), kept apart
// from the solver as CorrectionPredictor is from the matrix-free one.
// The correction c = p − near of a solve's solution over its starting momentum moves smoothly
// along a trajectory of one step size, so the next is extrapolated by the polynomial through
// the last m. Its memory is the table of backward differences ∇ⁱc (i < kMaxOrder) at the newest
// correction, in which the extrapolation of degree m − 1 is Σ_{i<m} ∇ⁱc (Newton's backward
// form), and the order m is the one that predicted the newest correction best: that
// prediction missed c' by exactly ∇ᵐc' of the new table, so remember() compares the misses of
// every order at the cost of forming the table. On a smooth trajectory the best is the highest
// (each degree more divides the miss by 7 to 24 on Scenario A at h = 0.1), where the
// corrections are noise (rounding at a steady state, a forcing) the low orders that amplify
// it least (order m amplifies it up to 2^m − 1 times). The matrix solver's fitted linear
// recurrence (correction_predictor.h) would cost more than the solve it saves at these sizes.
// Measured: docs/results/benchmarks.md, "The small Legendre solver's predictor".
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/errors.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>

namespace ddb {

template <class Vector, int kMaxOrder>
class PolynomialPredictor {
 public:
  /// Forgets the corrections (a new trajectory, or a new h: corrections scale with h).
  void reset() { count_ = order_ = 0; }

  /// The number of corrections the next predict() combines (0 while none is known).
  int order() const { return order_; }

  /// near + the extrapolated correction.
  Vector predict(const Vector& near) const {
    Vector guess = near;
    for (int i = 0; i < order_; ++i) guess += difference(i);
    return guess;
  }

  /// Remembers the correction of the newest solve and chooses the next prediction's order:
  /// the one whose miss of it was the smallest, one higher (up to kMaxOrder) when that was
  /// the highest the table could try, so that the order climbs by one per step.
  void remember(const Vector& correction) {
    Vector miss = correction;  // ∇ᵐc' for m = 0, 1, ...
    const int tried = count_;
    int best = 0;
    double smallest = INFINITY;
    for (int m = 0; m < tried; ++m) {
      Vector next = miss - difference(m);
      difference(m) = miss;
      miss = next;
      const double size = miss.squaredNorm();
      if (size < smallest) {
        smallest = size;
        best = m + 1;
      }
    }
    if (count_ < kMaxOrder) difference(count_++) = miss;
    order_ = best == tried && count_ > tried ? count_ : std::max(best, 1);
  }

  /// Starts from corrections given newest first (a record of the solver's layout of 0.2.0,
  /// which kept three): the table of their differences, extrapolated at their full order.
  template <std::size_t kGiven>
  void restart(const std::array<Vector, kGiven>& newest_first, int count) {
    static_assert(static_cast<int>(kGiven) <= kMaxOrder);
    if (count < 0 || count > static_cast<int>(kGiven)) {
      throw InvalidArgument("count = " + std::to_string(count) + " is invalid: 0.." +
                            std::to_string(kGiven) + " corrections are given");
    }
    reset();
    for (int i = count - 1; i >= 0; --i) remember(newest_first[static_cast<std::size_t>(i)]);
    order_ = count;
  }

  void save(BinaryRecordWriter& out) const {
    out.tag("polynomial predictor");
    out.put(count_);
    out.put(order_);
    for (int i = 0; i < count_; ++i) out.put(difference(i));
  }
  void load(BinaryRecordReader& in) {
    in.expectTag("polynomial predictor");
    reset();
    const int count = in.get<int>(), order = in.get<int>();
    if (count < 0 || count > kMaxOrder || order < 0 || order > count) {
      throw CorruptRecord("predictor counts");
    }
    for (int i = 0; i < count; ++i) in.get(difference(i));
    count_ = count;
    order_ = order;
  }

 private:
  const Vector& difference(int i) const { return differences_[static_cast<std::size_t>(i)]; }
  Vector& difference(int i) { return differences_[static_cast<std::size_t>(i)]; }

  std::array<Vector, kMaxOrder> differences_{};  // ∇ⁱc at the newest correction, i < count_
  int count_ = 0;                                // differences remembered
  int order_ = 0;                                // those the next prediction sums
};

}  // namespace ddb
