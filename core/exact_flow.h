// ExactFlow: a part of a vector field whose flow is known exactly (a linear damping, a forcing),
// which a splitting method takes apart from the Lie–Poisson part (StrangSplitting,
// integrators/methods/strang_splitting.h). Such a part generally leaves the coadjoint orbit: it is
// the physics the double bracket does not model (docs/guide/matrix-groups-and-the-fluid.md).
#pragma once

#include <ddb/core/binary_record.h>

#include <string>

namespace ddb {

template <class G>
class ExactFlow {
 public:
  using Group = G;
  using Dual = typename G::template Dual<double>;

  virtual ~ExactFlow() = default;
  virtual std::string name() const = 0;
  /// μ ← φ_h(μ), this part's flow over a time h.
  virtual void advance(Dual& mu, double h) = 0;
  /// The flow's own state that a resumed run needs (a random stream's position), into a
  /// checkpoint and back; none by default.
  virtual void save(BinaryRecordWriter&) const {}
  virtual void load(BinaryRecordReader&) {}
};

}  // namespace ddb
