// Error types and argument validation. Bad input never yields a NaN downstream:
// it is rejected with a message naming the parameter and its value.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace ddb {

/// A parameter or state that is out of its domain (non-finite, non-positive, ...).
class InvalidArgument : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// An implicit equation that the solver did not bring below its tolerance.
/// `step` is the index k of the step from t_k that failed (-1 while unknown to
/// the thrower), `time` and `h` NaN while unknown; integrate() fills them in.
class SolveFailure : public std::runtime_error {
 public:
  SolveFailure(std::string what_failed, long step, double time, double h, double residual,
               double tolerance)
      : std::runtime_error(describe(what_failed, step, time, h, residual, tolerance)),
        what_failed_(std::move(what_failed)),
        step_(step),
        time_(time),
        h_(h),
        residual_(residual),
        tolerance_(tolerance) {}

  SolveFailure atStep(long step, double time, double h) const {
    return SolveFailure(what_failed_, step, std::isnan(time_) ? time : time_,
                        std::isnan(h_) ? h : h_, residual_, tolerance_);
  }

  long step() const { return step_; }
  double time() const { return time_; }
  double h() const { return h_; }
  double residual() const { return residual_; }
  double tolerance() const { return tolerance_; }

 private:
  static std::string describe(const std::string& what_failed, long step, double time, double h,
                              double residual, double tolerance) {
    std::ostringstream os;
    os.precision(17);
    os << what_failed << " did not converge at step " << step << " (t = " << time << ", h = " << h
       << "): residual " << residual << " > tolerance " << tolerance;
    return os.str();
  }

  std::string what_failed_;
  long step_;
  double time_, h_, residual_, tolerance_;
};

std::string formatValue(double v);
template <class Derived>
std::string formatValue(const Eigen::DenseBase<Derived>& v);

/// A state that overflowed or became NaN inside a step. It is what it says, not a
/// solver that missed its tolerance: the message names the step, t, h and the offending
/// entry (docs/conventions.md §4). A SolveFailure, so the valid prefix is kept alike.
class NonFiniteState : public SolveFailure {
 public:
  template <class State>
  NonFiniteState(const std::string& method, long step, double time, double h, const State& state)
      : SolveFailure(method + " step", step, time, h, INFINITY, 0),
        message_(describe(method, step, time, h, formatValue(state))) {}
  const char* what() const noexcept override { return message_.c_str(); }

 private:
  static std::string describe(const std::string& method, long step, double time, double h,
                              const std::string& state) {
    std::ostringstream os;
    os.precision(17);
    os << method << " step " << step << " (t = " << time << ", h = " << h
       << ") made the state non-finite (overflow or NaN): state = " << state;
    return os.str();
  }
  std::string message_;
};

inline std::string formatValue(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

/// Small vectors in full; a larger object (a 256×256 state) by its size and its
/// largest-magnitude (or first non-finite) entry, never entry by entry.
template <class Derived>
std::string formatValue(const Eigen::DenseBase<Derived>& v) {
  constexpr Eigen::Index kListed = 12;
  std::ostringstream os;
  os.precision(17);
  const auto* data = v.derived().data();
  if (v.size() <= kListed) {
    os << "(";
    for (Eigen::Index i = 0; i < v.size(); ++i) os << (i ? ", " : "") << data[i];
    os << ")";
    return os.str();
  }
  Eigen::Index worst = 0;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    using std::abs;
    if (!std::isfinite(abs(data[i]))) {
      worst = i;
      break;
    }
    if (abs(data[i]) > abs(data[worst])) worst = i;
  }
  const Eigen::Index rows = v.rows() > 0 ? v.rows() : 1;
  os << "a " << v.rows() << "x" << v.cols() << " object whose largest entry is [" << worst % rows
     << ", " << worst / rows << "] = " << data[worst];
  return os.str();
}

[[noreturn]] inline void throwInvalid(const std::string& name, const std::string& value,
                                      const std::string& requirement) {
  throw InvalidArgument(name + " = " + value + " is invalid: " + requirement);
}

inline double requireFinite(const std::string& name, double v) {
  if (!std::isfinite(v)) throwInvalid(name, formatValue(v), "must be finite");
  return v;
}

inline double requirePositive(const std::string& name, double v) {
  if (!std::isfinite(v) || !(v > 0)) throwInvalid(name, formatValue(v), "must be finite and > 0");
  return v;
}

template <class Derived>
const Derived& requireFinite(const std::string& name, const Eigen::DenseBase<Derived>& v) {
  if (!v.derived().allFinite()) throwInvalid(name, formatValue(v), "every entry must be finite");
  return v.derived();
}

template <class Derived>
const Derived& requirePositive(const std::string& name, const Eigen::DenseBase<Derived>& v) {
  if (!v.derived().allFinite() || !(v.derived().array() > 0).all()) {
    throwInvalid(name, formatValue(v), "every entry must be finite and > 0");
  }
  return v.derived();
}

}  // namespace ddb
