// CorrectionPredictor: the initial guess of the matrix-free Legendre solver, kept apart
// from the solver (as GeometricIntegrators.jl keeps its initial guesses).
// The correction c = p − M_k of the solution p over the state M_k moves smoothly along a
// trajectory, a mixture of slowly varying parts (the conservative flow) and of parts that
// decay geometrically from step to step (the fast modes the double bracket damps). Both
// obey a linear recurrence, so the next correction is predicted by one (linear prediction):
//   c_{k+1} ≈ Σ_{j=1..m} β_j c_{k+1−j},  β = argmin ‖c_k − Σ_j β_j c_{k−j}‖,
// with m ≤ kOrder real coefficients fitted to the newest corrections. A polynomial
// extrapolation of degree m − 1 is the special case β_j = (−1)^{j+1} C(m, j); with
// dissipation the fast modes decay geometrically, which no polynomial follows and a fitted
// recurrence does. The errors of both and the choice kOrder = 8 are measured in
// docs/design/architecture.md ("The initial guess: linear prediction").
// The fit is a least-squares problem of m unknowns on a sketch, a fixed sample of entries,
// so it costs O(sample·m²), not O(N²) per coefficient; the prediction reads m corrections.
// Written against the matrix backend (core/matrix_backend.h): the sample is of entries of the
// whole matrix, so a distributed run predicts exactly what a dense one does.
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/matrix_backend.h>

#include <Eigen/Core>
#include <Eigen/QR>
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace ddb {

template <class Matrix>
class CorrectionPredictor {
  using B = MatrixBackend<Matrix>;

 public:
  /// The most corrections a prediction combines.
  static constexpr int kOrder = 8;

  /// Forgets the corrections (a new trajectory, or a new h: corrections scale with h).
  void reset() { count_ = order_ = 0; }

  /// The number of corrections the next predict() combines (0 while none is known).
  int order() const { return order_; }

  /// out = near + the predicted correction. A predicted correction more than twice the
  /// largest remembered one (on the sketch) means the state does not continue the
  /// remembered ones (a caller that skipped reset()): then the newest correction alone.
  void predict(const Matrix& near, Matrix& out) const {
    B::copy(near, out);
    if (count_ == 0) return;
    const int m = order_;
    predicted_.setZero();
    double largest = 0.0;
    for (int j = 0; j < m; ++j) {
      predicted_ += coefficients_(j) * sketches_.col(sketchSlot(j));
      largest = std::max(largest, sketches_.col(sketchSlot(j)).norm());
    }
    if (!(predicted_.norm() <= 2.0 * largest)) {
      B::axpy(1.0, correction(0), out);
      return;
    }
    B::addCombination(
        coefficients_, [&](int j) -> const Matrix& { return correction(j); }, m, out);
  }

  /// The remembered corrections, their sketches and the fitted coefficients
  /// (OneStepMethod::saveWarmStart).
  void save(BinaryRecordWriter& out) const {
    out.tag("correction predictor");
    out.put(count_);
    out.put(order_);
    const int kept = std::min(count_, kOrder);  // slots 0..kept−1 are filled
    for (int i = 0; i < kept; ++i) B::save(out, corrections_[static_cast<std::size_t>(i)]);
    if (kept > 0) {
      out.put(sketches_);
      out.put(coefficients_);
    }
  }
  /// Restores what save() wrote, for states of the size (and, distributed, the layout) of
  /// `like`.
  void load(BinaryRecordReader& in, const Matrix& like) {
    in.expectTag("correction predictor");
    reset();
    const int count = in.get<int>(), order = in.get<int>();
    if (count < 0 || order < 0 || order > kOrder) throw CorruptRecord("predictor counts");
    const int kept = std::min(count, kOrder);
    if (kept == 0) return;
    allocate(like);
    for (int i = 0; i < kept; ++i) B::load(in, corrections_[static_cast<std::size_t>(i)]);
    const Eigen::Index samples = sketches_.rows();
    in.get(sketches_);
    in.get(coefficients_);
    if (sketches_.rows() != samples || sketches_.cols() != kSketches) {
      throw CorruptRecord("predictor sketches of another size");
    }
    count_ = count;
    order_ = order;
  }

  /// Remembers the correction solution − near and fits the coefficients of the next
  /// prediction.
  void remember(const Matrix& solution, const Matrix& near) {
    allocate(near);
    ++count_;
    Matrix& c = corrections_[static_cast<std::size_t>((count_ - 1) % kOrder)];
    B::sum(1.0, solution, -1.0, near, c);
    auto sketch = sketches_.col(sketchSlot(0));
    B::sampleEntries(c, sample_, sketch);
    fit();
  }

 private:
  using Scalar = typename B::Scalar;
  static constexpr bool kComplex = Eigen::NumTraits<Scalar>::IsComplex;
  static constexpr int kRelations = 3;  // recurrences fitted at once (fit())
  static constexpr int kSketches = kOrder + kRelations;
  static constexpr Eigen::Index kMaxSample = 512;  // entries: ≫ kOrder equations per relation
  /// Pivots of the fit below this fraction of the largest count as zero.
  static constexpr double kRankThreshold = 1e-10;

  // The correction, and the column of its sketch, j steps before the newest.
  const Matrix& correction(int j) const {
    return corrections_[static_cast<std::size_t>((count_ - 1 - j) % kOrder)];
  }
  int sketchSlot(int j) const { return (count_ - 1 - j) % kSketches; }
  // A sketch column as real numbers (real and imaginary parts interleaved).
  Eigen::Map<const Eigen::VectorXd> reals(int j) const {
    return {reinterpret_cast<const double*>(sketches_.col(sketchSlot(j)).data()),
            sketches_.rows() * (kComplex ? 2 : 1)};
  }

  // β for c_i ≈ Σ_{j=1..m} β_j c_{i−j} on the sketch, for the newest kRelations values of
  // i at once (one would leave β undetermined when the corrections span fewer than m
  // directions, as near steady states), then used as c_{k+1} ≈ Σ_j β_j c_{k+1−j}. The
  // corrections are nearly collinear, so the fit is a rank-revealing QR whose pivots below
  // kRankThreshold of the largest are dropped: they are at the corrections' own rounding
  // (the solver's tolerance), and fitting them would amplify it. Qᵀ is applied and R solved
  // by hand in a preallocated vector (Eigen's solve() and its Householder sequence
  // allocate). With one correction, or a fit that is not finite, the newest one is repeated.
  void fit() {
    // The order climbs as corrections arrive, kRelations relations once there are enough.
    const int m = std::min(kOrder, std::max(count_ - kRelations, std::min(count_ - 1, 1)));
    coefficients_.setZero();
    coefficients_(0) = 1.0;
    order_ = std::max(m, 1);
    if (m == 0) return;
    const int relations = std::min(kRelations, std::min(count_, kSketches) - m);
    const Eigen::Index block = sketches_.rows() * (kComplex ? 2 : 1);
    system_.setZero();
    rhs_.setZero();
    for (int r = 0; r < relations; ++r) {
      for (int j = 1; j <= m; ++j) system_.block(r * block, j - 1, block, 1) = reals(r + j);
      rhs_.segment(r * block, block) = reals(r);
    }
    auto& qr = qr_[static_cast<std::size_t>(m - 1)];
    qr.compute(system_.leftCols(m));
    const Eigen::Index rank = qr.nonzeroPivots();
    if (rank == 0) return;
    const Eigen::Index rows = rhs_.size();
    // rhs ← H_k rhs for k < rank, H_k = I − τ_k v vᵀ, v = (1, essential_k): rhs ← Qᵀ rhs.
    for (Eigen::Index k = 0; k < rank; ++k) {
      const auto essential = qr.matrixQR().col(k).tail(rows - k - 1);
      const double projection =
          qr.hCoeffs()(k) * (rhs_(k) + essential.dot(rhs_.tail(rows - k - 1)));
      rhs_(k) -= projection;
      rhs_.tail(rows - k - 1) -= projection * essential;
    }
    qr.matrixQR()
        .topLeftCorner(rank, rank)
        .template triangularView<Eigen::Upper>()
        .solveInPlace(rhs_.head(rank));
    solution_.setZero();
    for (Eigen::Index i = 0; i < rank; ++i) solution_(qr.colsPermutation().indices()(i)) = rhs_(i);
    if (solution_.allFinite()) coefficients_ = solution_;
  }

  void allocate(const Matrix& like) {
    if (!corrections_.empty() && B::sameShape(corrections_[0], like)) return;
    corrections_.resize(kOrder);
    for (Matrix& c : corrections_) B::zeroLike(c, like);
    // A fixed pseudo-random sample of entries (linear congruential, Knuth's MMIX constants).
    const Eigen::Index size = B::globalSize(like);
    const Eigen::Index samples =
        std::clamp<Eigen::Index>(size / 16, std::min<Eigen::Index>(size, 64), kMaxSample);
    sample_.resize(samples);
    std::uint64_t state = 1;
    for (Eigen::Index s = 0; s < samples; ++s) {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      sample_(s) = static_cast<Eigen::Index>((state >> 11) % static_cast<std::uint64_t>(size));
    }
    sketches_.setZero(samples, kSketches);
    predicted_.setZero(samples);
    const Eigen::Index rows = kRelations * samples * (kComplex ? 2 : 1);
    system_.setZero(rows, kOrder);
    rhs_.setZero(rows);
    for (int m = 1; m <= kOrder; ++m) {
      auto& qr = qr_[static_cast<std::size_t>(m - 1)];
      qr = Eigen::ColPivHouseholderQR<Eigen::MatrixXd>(rows, m);
      qr.setThreshold(kRankThreshold);
    }
    count_ = order_ = 0;
  }

  std::vector<Matrix> corrections_;
  Eigen::Matrix<Eigen::Index, Eigen::Dynamic, 1> sample_;
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> sketches_;
  mutable Eigen::Matrix<Scalar, Eigen::Dynamic, 1> predicted_;
  Eigen::MatrixXd system_;
  Eigen::VectorXd rhs_;
  // One factorisation per order, so that no compute() resizes (no allocation in a step).
  std::array<Eigen::ColPivHouseholderQR<Eigen::MatrixXd>, kOrder> qr_;
  Eigen::Matrix<double, kOrder, 1> coefficients_, solution_;
  int count_ = 0, order_ = 0;
};

}  // namespace ddb
