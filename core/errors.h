// Error types and argument validation. Bad input never yields a NaN downstream:
// it is rejected with a message naming the parameter and its value.
#pragma once

#include <Eigen/Core>
#include <charconv>
#include <cmath>
#include <complex>
#include <sstream>
#include <stdexcept>
#include <string>

namespace ddb {

/// A parameter or state that is out of its domain (non-finite, non-positive, ...).
class InvalidArgument : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

std::string formatValue(double v);

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

  virtual ~SolveFailure() = default;

  SolveFailure atStep(long step, double time, double h) const {
    return SolveFailure(what_failed_, step, std::isnan(time_) ? time : time_,
                        std::isnan(h_) ? h : h_, residual_, tolerance_);
  }
  /// Throws this failure, keeping its type, with the step (and t, h where unknown) filled
  /// in: integrate() knows where a step failed, the thrower inside the step does not.
  [[noreturn]] virtual void rethrowAtStep(long step, double time, double h) const {
    throw atStep(step, time, h);
  }

  const std::string& whatFailed() const { return what_failed_; }
  long step() const { return step_; }
  double time() const { return time_; }
  double h() const { return h_; }
  double residual() const { return residual_; }
  double tolerance() const { return tolerance_; }

 private:
  static std::string describe(const std::string& what_failed, long step, double time, double h,
                              double residual, double tolerance) {
    return what_failed + " did not converge at step " + std::to_string(step) +
           " (t = " + formatValue(time) + ", h = " + formatValue(h) + "): residual " +
           formatValue(residual) + " > tolerance " + formatValue(tolerance);
  }

  std::string what_failed_;
  long step_;
  double time_, h_, residual_, tolerance_;
};

template <class Derived>
std::string formatValue(const Eigen::DenseBase<Derived>& v);
/// A value already written out, e.g. by a matrix backend whose entries are not on the host
/// or not all on this process (MatrixBackend::describe).
struct FormattedValue {
  std::string text;
};
inline std::string formatValue(const FormattedValue& v) { return v.text; }

/// A state that overflowed or became NaN inside a step. It is what it says, not a
/// solver that missed its tolerance: the message names the step, t, h and the offending
/// entry (docs/reference/conventions.md §4). A SolveFailure, so the valid prefix is kept alike.
/// `quantity` names what became non-finite when it is not the state itself (the residual
/// of an implicit equation whose data overflowed).
class NonFiniteState : public SolveFailure {
 public:
  template <class State>
  NonFiniteState(const std::string& method, long step, double time, double h, const State& state,
                 const std::string& quantity = "state")
      : NonFiniteState(method, step, time, h, quantity, formatValue(state)) {}
  const char* what() const noexcept override { return message_.c_str(); }
  [[noreturn]] void rethrowAtStep(long step, double time, double h) const override {
    throw NonFiniteState(method_, step, std::isnan(this->time()) ? time : this->time(),
                         std::isnan(this->h()) ? h : this->h(), quantity_, value_);
  }

 private:
  NonFiniteState(const std::string& method, long step, double time, double h,
                 const std::string& quantity, const std::string& value)
      : SolveFailure(method + " step", step, time, h, INFINITY, 0),
        method_(method),
        quantity_(quantity),
        value_(value),
        message_(describe(method, step, time, h, quantity, value)) {}

  static std::string describe(const std::string& method, long step, double time, double h,
                              const std::string& quantity, const std::string& value) {
    return method + " step " + std::to_string(step) + " (t = " + formatValue(time) +
           ", h = " + formatValue(h) + ") made the " + quantity +
           " non-finite (overflow or NaN): " + quantity + " = " + value;
  }
  std::string method_, quantity_, value_, message_;
};

/// An iterative loop that used up its budget (sub-steps, iterations, series terms)
/// before it converged: every loop has one, so no input runs without bound
/// (docs/reference/guarantees.md). `what` names the loop, `budget` what ran out.
class BudgetExhausted : public SolveFailure {
 public:
  BudgetExhausted(const std::string& what, const std::string& budget, long step, double time,
                  double h)
      : SolveFailure(what, step, time, h, INFINITY, 0),
        budget_(budget),
        message_(what + " ran out of its budget at step " + std::to_string(step) +
                 " (t = " + formatValue(time) + ", h = " + formatValue(h) + "): " + budget) {}
  const char* what() const noexcept override { return message_.c_str(); }
  [[noreturn]] void rethrowAtStep(long step, double time, double h) const override {
    throw BudgetExhausted(whatFailed(), budget_, step,
                          std::isnan(this->time()) ? time : this->time(),
                          std::isnan(this->h()) ? h : this->h());
  }

 private:
  std::string budget_, message_;
};

/// A step of an exponential-map method with |hξ| at or beyond the injectivity limit of
/// exp (π on SO(3), docs/reference/guarantees.md §2): past it the Legendre equation has solutions
/// on other branches and the method would converge to one of them without a word.
/// `largest_h` is the largest admissible h at this state, limit/|ξ|.
class InjectivityLimit : public SolveFailure {
 public:
  InjectivityLimit(const std::string& method, double step_norm, double limit, double largest_h,
                   long step, double time, double h)
      : SolveFailure(method + " step", step, time, h, step_norm, limit),
        method_(method),
        step_norm_(step_norm),
        limit_(limit),
        largest_h_(largest_h),
        message_(method + " step " + std::to_string(step) + " (t = " + formatValue(time) +
                 ", h = " + formatValue(h) + "): |h xi| = " + formatValue(step_norm) +
                 " is at or beyond the injectivity limit " + formatValue(limit) +
                 " of the exponential map (the step would land on another branch); the "
                 "largest admissible h at this state is about " +
                 formatValue(largest_h)) {}
  const char* what() const noexcept override { return message_.c_str(); }
  [[noreturn]] void rethrowAtStep(long step, double time, double h) const override {
    throw InjectivityLimit(method_, step_norm_, limit_, largest_h_, step,
                           std::isnan(this->time()) ? time : this->time(),
                           std::isnan(this->h()) ? h : this->h());
  }
  double limit() const { return limit_; }
  double largestH() const { return largest_h_; }

 private:
  std::string method_;
  double step_norm_, limit_, largest_h_;
  std::string message_;
};

/// v in the shortest form that reads back as the same double ("0.1", not
/// "0.10000000000000001"; std::to_chars, which ignores the locale); "nan", "inf", "-inf".
inline std::string formatValue(double v) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr);
}

namespace detail {
/// An entry of a vector or matrix as formatValue writes it: a double in the shortest form, a
/// complex one as (re,im), another scalar (an automatic-differentiation Jet) as it prints itself.
inline std::string formatEntry(double v) { return formatValue(v); }
inline std::string formatEntry(const std::complex<double>& v) {
  return "(" + formatValue(v.real()) + "," + formatValue(v.imag()) + ")";
}
template <class Scalar>
std::string formatEntry(const Scalar& v) {
  std::ostringstream os;
  os << v;
  return os.str();
}
}  // namespace detail

/// Small vectors in full; a larger object (a 256×256 state) by its size and its
/// largest-magnitude (or first non-finite) entry, never entry by entry.
template <class Derived>
std::string formatValue(const Eigen::DenseBase<Derived>& v) {
  constexpr Eigen::Index kListed = 12;
  std::ostringstream os;
  const auto* data = v.derived().data();
  if (v.size() <= kListed) {
    os << "(";
    for (Eigen::Index i = 0; i < v.size(); ++i)
      os << (i ? ", " : "") << detail::formatEntry(data[i]);
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
     << ", " << worst / rows << "] = " << detail::formatEntry(data[worst]);
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
