// The distributed matrix layer (docs/design/distributed.md) on 1–4 ranks: the process grid's
// shape, scatter and gather against the block-cyclic layout of ScaLAPACK's users' guide,
// pzgemm_'s product and pzlange_'s Frobenius norm against Eigen's, the element-wise
// operations against the dense backend's bits, and a record held by
// rank 0 read on every rank (RankZeroRecordReader).
#include <ddb/core/binary_record.h>
#include <ddb/core/errors.h>
#include <ddb/distributed/distributed_backend.h>
#include <ddb/distributed/distributed_matrix.h>
#include <ddb/distributed/distributed_product.h>
#include <ddb/distributed/process_grid.h>
#include <ddb/distributed/rank_zero_record_reader.h>
#include <gtest/gtest.h>

#include <complex>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "mpi_test_support.h"

namespace ddb {
namespace distributed_matrix_tests {

using test::randomComplexMatrix;
using test::relativeDistance;

// The default: the most square grid with rows ≥ cols (docs/design/distributed.md, "Layouts").
TEST(ProcessGrid, DefaultIsTheMostSquareFactorisationWithRowsAtLeastCols) {
  const ProcessGrid grid;
  const std::map<int, std::pair<int, int>> expected = {{1, {1, 1}}, {2, {2, 1}}, {3, {3, 1}},
                                                       {4, {2, 2}}, {6, {3, 2}}, {8, {4, 2}}};
  const auto shape = expected.find(grid.size());
  if (shape == expected.end()) GTEST_SKIP() << "no expected shape for " << grid.size() << " ranks";
  EXPECT_EQ(grid.rows(), shape->second.first);
  EXPECT_EQ(grid.cols(), shape->second.second);
  EXPECT_EQ(grid.rankAt(grid.row(), grid.col()), grid.rank());
  for (const auto& [ranks, rows_cols] : expected) {
    EXPECT_EQ(ProcessGrid::defaultRows(ranks), rows_cols.first) << ranks << " ranks";
  }
}

// Every divisor of P as the rows, rank r at (r / cols, r mod cols); others (−1, the
// non-divisors up to P, P + 1) refused on every rank, naming the parameter.
TEST(ProcessGrid, TakesAnyRowsThatDivideTheRanks) {
  const int ranks = ProcessGrid().size();
  for (int rows = -1; rows <= ranks + 1; ++rows) {
    if (rows == 0) continue;  // the default shape
    if (rows >= 1 && ranks % rows == 0) {
      const ProcessGrid grid(MPI_COMM_WORLD, rows);
      EXPECT_EQ(grid.rows(), rows);
      EXPECT_EQ(grid.cols(), ranks / rows);
      EXPECT_EQ(grid.row(), grid.rank() / grid.cols());
      EXPECT_EQ(grid.col(), grid.rank() % grid.cols());
      continue;
    }
    try {
      const ProcessGrid grid(MPI_COMM_WORLD, rows);
      ADD_FAILURE() << rows << " rows accepted on " << ranks << " ranks";
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find("grid rows"), std::string::npos) << e.what();
    }
  }
}

// The suites' grid has the rows the program was started with (--grid-rows=R), else the
// default shape's.
TEST(ProcessGrid, TheTestsGridHasTheRowsAsked) {
  const test::TestGrid grid;
  const int asked = test::gridRowsAsked();
  EXPECT_EQ(grid.rows(), asked > 0 ? asked : ProcessGrid::defaultRows(grid.size()));
}

TEST(DistributedMatrix, RefusesABadBlockSize) {
  const test::TestGrid grid;
  EXPECT_THROW(DistributedMatrix(grid, 8, 0), InvalidArgument);
  EXPECT_THROW(DistributedMatrix(grid, 0, 4), InvalidArgument);
}

// Only rank 0's matrix is read; its wrong size is refused on every rank, none left waiting.
TEST(DistributedMatrix, ScatterRefusesAWrongSizeOnEveryRank) {
  const test::TestGrid grid;
  DistributedMatrix distributed(grid, 8, 3);
  const Eigen::MatrixXcd wrong = Eigen::MatrixXcd::Zero(grid.rank() == 0 ? 7 : 8, 8);
  EXPECT_THROW(distributed.scatterFrom(wrong), InvalidArgument);
}

class DistributedMatrixTest : public test::SizeAndBlockTest {};

// Every local entry is the global entry the users' guide's layout puts there (written
// out here from the guide, not taken from BlockCyclicLayout), and the gather is exact.
TEST_P(DistributedMatrixTest, ScatterPlacesBlockCyclicallyAndGatherRestores) {
  const Eigen::MatrixXcd a = randomComplexMatrix(n(), 11);
  DistributedMatrix distributed(grid_, n(), block());
  distributed.scatterFrom(a);
  const int b = block();
  const auto global = [b](int l, int coordinate, int processes) {
    return (l / b) * b * processes + coordinate * b + l % b;
  };
  int local_entries = distributed.local().size(), all_entries = 0;
  MPI_Allreduce(&local_entries, &all_entries, 1, MPI_INT, MPI_SUM, grid_.comm());
  EXPECT_EQ(all_entries, n() * n());
  for (int lj = 0; lj < distributed.local().cols(); ++lj) {
    for (int li = 0; li < distributed.local().rows(); ++li) {
      const int i = global(li, grid_.row(), grid_.rows()),
                j = global(lj, grid_.col(), grid_.cols());
      ASSERT_LT(i, n());
      ASSERT_LT(j, n());
      ASSERT_EQ(distributed.local()(li, lj), a(i, j)) << "local (" << li << ", " << lj << ")";
    }
  }
  const Eigen::MatrixXcd gathered = distributed.gather();
  if (grid_.rank() == 0) {
    EXPECT_TRUE(gathered == a);
  } else {
    EXPECT_EQ(gathered.size(), 0);
  }
}

TEST_P(DistributedMatrixTest, ProductMatchesEigen) {
  const Eigen::MatrixXcd a = randomComplexMatrix(n(), 21), b = randomComplexMatrix(n(), 22);
  DistributedMatrix da(grid_, n(), block()), db(grid_, n(), block()), dc(grid_, n(), block());
  da.scatterFrom(a);
  db.scatterFrom(b);
  multiply(da, db, dc);
  const Eigen::MatrixXcd c = dc.gather();
  if (grid_.rank() == 0) {
    const Eigen::MatrixXcd reference = a * b;
    EXPECT_LT(relativeDistance(c, reference), 1e-13);
  }
}

// multiplyAdd (pzgemm_ with β = 1) against Eigen's c + s·a b on the gathered matrices.
TEST_P(DistributedMatrixTest, MultiplyAddMatchesEigen) {
  const Eigen::MatrixXcd a = randomComplexMatrix(n(), 23), b = randomComplexMatrix(n(), 24),
                         c = randomComplexMatrix(n(), 25);
  DistributedMatrix da(grid_, n(), block()), db(grid_, n(), block()), dc(grid_, n(), block());
  da.scatterFrom(a);
  db.scatterFrom(b);
  for (const double s : {1.0, -1.0, 0.3}) {
    dc.scatterFrom(c);
    MatrixBackend<DistributedMatrix>::multiplyAdd(s, da, db, dc);
    const Eigen::MatrixXcd result = dc.gather();
    if (grid_.rank() == 0) {
      const Eigen::MatrixXcd reference = c + s * (a * b);
      EXPECT_LT(relativeDistance(result, reference), 1e-13) << "s = " << s;
    }
  }
}

// allFinite answers alike on every rank, whichever rank holds the NaN; flushSubnormals is the
// dense backend's on the local arrays, the same bits gathered.
TEST_P(DistributedMatrixTest, AllFiniteAgreesOnEveryRankAndFlushSubnormalsIsTheDenseOnes) {
  using D = MatrixBackend<DistributedMatrix>;
  Eigen::MatrixXcd a = randomComplexMatrix(n(), 26);
  a(n() - 1, 0) = {std::numeric_limits<double>::denorm_min(), -1.0};
  a(0, n() - 1) = {0.5, -std::numeric_limits<double>::denorm_min() * 7};
  DistributedMatrix da(grid_, n(), block());
  da.scatterFrom(a);
  EXPECT_TRUE(D::allFinite(da));
  D::flushSubnormals(da);
  const Eigen::MatrixXcd flushed = da.gather();
  if (grid_.rank() == 0) {
    Eigen::MatrixXcd dense = a;
    MatrixBackend<Eigen::MatrixXcd>::flushSubnormals(dense);
    EXPECT_EQ(std::memcmp(flushed.data(), dense.data(), sizeof(dense(0)) * dense.size()), 0);
  }
  a(n() - 1, n() - 1) = {NAN, 0.0};  // on the last rank's block for most layouts
  da.scatterFrom(a);
  EXPECT_FALSE(D::allFinite(da));
}

// isZero is "every entry exactly zero", alike on every rank: an entry whose square underflows
// (1e-200) or a NaN on any one rank's block makes it false everywhere, as in the dense backend.
TEST_P(DistributedMatrixTest, IsZeroIsExactAndAgreesOnEveryRank) {
  using D = MatrixBackend<DistributedMatrix>;
  Eigen::MatrixXcd a = Eigen::MatrixXcd::Zero(n(), n());
  DistributedMatrix da(grid_, n(), block());
  da.scatterFrom(a);
  EXPECT_TRUE(D::isZero(da));
  for (const std::complex<double> entry : {std::complex<double>(0.0, 1e-200), {NAN, 0.0}}) {
    for (const int i : {0, n() - 1}) {
      a.setZero();
      a(i, n() - 1 - i) = entry;
      da.scatterFrom(a);
      EXPECT_FALSE(D::isZero(da)) << entry << " at (" << i << ", " << n() - 1 - i << ")";
      EXPECT_EQ(D::isZero(da), MatrixBackend<Eigen::MatrixXcd>::isZero(a));
    }
  }
}

// The backend's adjoints (AdjointExchange) against Eigen's on the gathered matrix: out +
// scale·xᴴ, and the skew-Hermitian part, which must equal the dense backend's bit for bit
// (the step formulas rely on (x − xᴴ)/2 being exactly skew-Hermitian on every layout).
TEST_P(DistributedMatrixTest, AddAdjointMatchesEigen) {
  const Eigen::MatrixXcd a = randomComplexMatrix(n(), 41), c = randomComplexMatrix(n(), 42);
  DistributedMatrix da(grid_, n(), block()), dc(grid_, n(), block());
  da.scatterFrom(a);
  for (const double scale : {1.0, -0.5}) {
    dc.scatterFrom(c);
    MatrixBackend<DistributedMatrix>::addAdjoint(scale, da, dc);
    const Eigen::MatrixXcd result = dc.gather();
    if (grid_.rank() == 0) {
      const Eigen::MatrixXcd reference = c + scale * a.adjoint();
      EXPECT_LT(relativeDistance(result, reference), 1e-15) << "scale " << scale;
    }
  }
}

TEST_P(DistributedMatrixTest, SkewHermitianPartEqualsTheDenseBackendsBitForBit) {
  const Eigen::MatrixXcd a = randomComplexMatrix(n(), 43);
  DistributedMatrix distributed(grid_, n(), block());
  distributed.scatterFrom(a);
  MatrixBackend<DistributedMatrix>::makeSkewHermitian(distributed);
  const Eigen::MatrixXcd result = distributed.gather();
  if (grid_.rank() == 0) {
    Eigen::MatrixXcd dense = a;
    MatrixBackend<Eigen::MatrixXcd>::makeSkewHermitian(dense);
    EXPECT_TRUE(result == dense);
    EXPECT_TRUE(result == Eigen::MatrixXcd(-result.adjoint()));
    EXPECT_LT(relativeDistance(result, 0.5 * (a - a.adjoint())), 1e-15);
  }
}

// The element-wise operations are the dense backend's on the local arrays: gathered, the
// same bits as the dense backend's on the whole matrices.
TEST_P(DistributedMatrixTest, ElementwiseOperationsEqualTheDenseBackendsBitForBit) {
  using Dense = MatrixBackend<Eigen::MatrixXcd>;
  using Distributed = MatrixBackend<DistributedMatrix>;
  const Eigen::MatrixXcd x = randomComplexMatrix(n(), 45), y = randomComplexMatrix(n(), 46),
                         z = randomComplexMatrix(n(), 47);
  DistributedMatrix dx(grid_, n(), block()), dy(grid_, n(), block()), dz(grid_, n(), block());
  dx.scatterFrom(x);
  dy.scatterFrom(y);
  dz.scatterFrom(z);
  const auto expectDense = [&](const DistributedMatrix& distributed, const Eigen::MatrixXcd& dense,
                               const char* operation) {
    const Eigen::MatrixXcd result = distributed.gather();
    if (grid_.rank() == 0) {
      EXPECT_TRUE(result.size() == dense.size() &&
                  std::memcmp(result.data(), dense.data(), sizeof(dense(0)) * dense.size()) == 0)
          << operation;
    }
  };
  DistributedMatrix out;
  Eigen::MatrixXcd dense;
  Distributed::copy(dx, out);
  expectDense(out, x, "copy");
  Distributed::sum(0.3, dx, -1.0, dy, 2.5, dz, out);
  Dense::sum(0.3, x, -1.0, y, 2.5, z, dense);
  expectDense(out, dense, "sum of three");
  Distributed::sum(1.0, dx, -1.0, out, out);
  Dense::sum(1.0, x, -1.0, dense, dense);
  expectDense(out, dense, "sum of two");
  Distributed::addSum(1.0, dy, -1.0, dz, out);
  Dense::addSum(1.0, y, -1.0, z, dense);
  expectDense(out, dense, "addSum");
  Distributed::axpy(-0.7, dx, out);
  Dense::axpy(-0.7, x, dense);
  expectDense(out, dense, "axpy");
  Distributed::scale(3.0, out, out);
  Dense::scale(3.0, dense, dense);
  expectDense(out, dense, "scale");
  Distributed::divide(out, 7.0);
  Dense::divide(dense, 7.0);
  expectDense(out, dense, "divide");
  const Eigen::Vector2d c(0.25, -1.5);
  Distributed::addCombination(
      c, [&](int j) -> const DistributedMatrix& { return j == 0 ? dy : dz; }, 2, out);
  Dense::addCombination(
      c, [&](int j) -> const Eigen::MatrixXcd& { return j == 0 ? y : z; }, 2, dense);
  expectDense(out, dense, "addCombination");
  Distributed::setZero(out);
  expectDense(out, Eigen::MatrixXcd::Zero(n(), n()), "setZero");
}

// ‖x‖₁ (the certificate's bound on ‖a‖₂) against Eigen's largest column sum, on every rank:
// also where the squares underflow (entries near 1e-200) and the norm takes hypot's |z|.
TEST_P(DistributedMatrixTest, OneNormMatchesEigenOnEveryRank) {
  for (const double scale : {1.0, 1e-200}) {
    const Eigen::MatrixXcd a = scale * randomComplexMatrix(n(), 44);
    DistributedMatrix distributed(grid_, n(), block());
    distributed.scatterFrom(a);
    const double expected = a.cwiseAbs().colwise().sum().maxCoeff();
    const double norm = MatrixBackend<DistributedMatrix>::oneNorm(distributed);
    EXPECT_NEAR(norm, expected, 1e-14 * expected) << "scale " << scale;
    double rank_zeros = norm;  // every rank must have rank 0's bits
    MPI_Bcast(&rank_zeros, 1, MPI_DOUBLE, 0, grid_.comm());
    EXPECT_EQ(norm, rank_zeros) << "scale " << scale;
  }
}

TEST_P(DistributedMatrixTest, FrobeniusNormMatchesEigenOnEveryRank) {
  const Eigen::MatrixXcd a = randomComplexMatrix(n(), 31);
  DistributedMatrix distributed(grid_, n(), block());
  distributed.scatterFrom(a);
  EXPECT_NEAR(distributed.frobeniusNorm(), a.norm(), 1e-13 * a.norm());
}

TEST_P(DistributedMatrixTest, ProductRefusesMismatchedBlocks) {
  DistributedMatrix a(grid_, n(), block()), b(grid_, n(), block() + 1), c(grid_, n(), block());
  EXPECT_THROW(multiply(a, b, c), InvalidArgument);
  EXPECT_THROW(multiply(a, a, a), InvalidArgument);
}

// A record held by rank 0 alone, read on every rank: the numbers, the string and the small
// matrix as rank 0 wrote them, and the whole matrix as this rank's blocks of a scatter (the
// placement checked above).
TEST_P(DistributedMatrixTest, RankZeroRecordReaderGivesEveryRankTheRecord) {
  const Eigen::MatrixXcd a = randomComplexMatrix(n(), 41);
  const Eigen::MatrixXd small = Eigen::MatrixXd::Random(3, 2);
  BinaryRecordWriter out;
  if (grid_.rank() == 0) {
    out.tag("part");
    out.put(2.5);
    out.put(std::string("text"));
    out.put(small);
    out.put(a);
    out.put(std::int64_t{7});
  }
  RankZeroRecordReader in(grid_, BinaryRecordReader(out.bytes()));
  in.expectTag("part");
  EXPECT_EQ(in.get<double>(), 2.5);
  EXPECT_EQ(in.get<std::string>(), "text");
  Eigen::MatrixXd read_small;
  in.get(read_small);
  EXPECT_TRUE(read_small == small);
  DistributedMatrix x(grid_, n(), block()), scattered(grid_, n(), block());
  MatrixBackend<DistributedMatrix>::load(in, x);
  scattered.scatterFrom(a);
  EXPECT_TRUE(x.local() == scattered.local());
  EXPECT_FALSE(in.atEnd());
  EXPECT_EQ(in.get<std::int64_t>(), 7);
  EXPECT_TRUE(in.atEnd());
}

// A record that holds a matrix of another size, or ends early, fails on every rank alike
// (each rank throws; none is left waiting in a broadcast).
TEST_P(DistributedMatrixTest, RankZeroRecordReaderFailsOnEveryRank) {
  BinaryRecordWriter other_size, truncated;
  if (grid_.rank() == 0) {
    other_size.put(randomComplexMatrix(n() + 1, 42));
    truncated.put(randomComplexMatrix(n(), 43));
  }
  DistributedMatrix x(grid_, n(), block());
  RankZeroRecordReader wrong(grid_, BinaryRecordReader(other_size.bytes()));
  EXPECT_THROW(MatrixBackend<DistributedMatrix>::load(wrong, x), CorruptRecord);
  const std::string cut = truncated.bytes().substr(0, truncated.bytes().size() / 2);
  RankZeroRecordReader short_record(grid_, BinaryRecordReader(cut));
  EXPECT_THROW(MatrixBackend<DistributedMatrix>::load(short_record, x), CorruptRecord);
  RankZeroRecordReader empty(grid_, BinaryRecordReader(""));
  EXPECT_THROW(empty.get<double>(), CorruptRecord);
}

INSTANTIATE_TEST_SUITE_P(SizesAndBlocks, DistributedMatrixTest,
                         testing::Combine(testing::Values(16, 33, 64), testing::Values(5, 7)),
                         test::sizeAndBlockName);

}  // namespace distributed_matrix_tests
}  // namespace ddb
