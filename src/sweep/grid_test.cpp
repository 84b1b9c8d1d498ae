#include "sweep/grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace tribolab::sweep {
namespace {

GridSpec seed_grid_spec() {
  // Seed 001, figure 53: collision angle 100-170 deg x spin 30-50 rad/s at |vy| = 4 m/s.
  GridSpec g;
  g.axes = {Axis{Quantity::theta_deg, 100, 170, 71}, Axis{Quantity::omega, 30, 50, 21}};
  return g;
}

TEST(Axis, EndpointsAreExactAndSpacingUniform) {
  const Axis a{Quantity::theta_deg, 100, 170, 71};
  EXPECT_EQ(a.value(0), 100.0);
  EXPECT_EQ(a.value(70), 170.0);
  EXPECT_EQ(a.value(35), 135.0);  // (170-100)*35/70 is exact in binary
  const Axis b{Quantity::omega, 0.1, 0.7, 7};
  for (int i = 0; i < 7; ++i) EXPECT_NEAR(b.value(i), 0.1 + 0.1 * i, 1e-15);  // a few ulps
  EXPECT_EQ(b.value(6), 0.7);
}

TEST(Axis, SingleValueAndDecreasingRanges) {
  EXPECT_EQ((Axis{Quantity::speed, 4, 4, 1}).value(0), 4.0);
  EXPECT_EQ((Axis{Quantity::speed, 4, 4, 1}).validate(), "");
  const Axis down{Quantity::omega, 50, 30, 3};
  EXPECT_EQ(down.validate(), "");
  EXPECT_EQ(down.value(1), 40.0);
}

TEST(Axis, ValidateNamesTheQuantity) {
  EXPECT_NE((Axis{Quantity::omega, 1, 2, 0}).validate().find("omega: count"), std::string::npos);
  EXPECT_NE((Axis{Quantity::omega, 1, 2, 1}).validate().find("lo = hi"), std::string::npos);
  EXPECT_NE((Axis{Quantity::omega, 1, 1, 5}).validate().find("use count 1"), std::string::npos);
  EXPECT_NE((Axis{Quantity::speed, -1, 2, 5}).validate().find("> 0"), std::string::npos);
  EXPECT_NE((Axis{Quantity::mu, -0.1, 2, 5}).validate().find(">= 0"), std::string::npos);
  EXPECT_NE((Axis{Quantity::theta_deg, 0, std::nan(""), 5}).validate().find("finite"), std::string::npos);
}

TEST(GridSpec, ValidateRequiresThetaAndExactlyOneSpinAxis) {
  GridSpec g = seed_grid_spec();
  EXPECT_EQ(g.validate(), "");
  g.axes.push_back(Axis{Quantity::ratio, 1, 2, 2});
  EXPECT_NE(g.validate().find("exactly one of omega and ratio"), std::string::npos);
  g.axes = {Axis{Quantity::omega, 30, 50, 21}};
  EXPECT_NE(g.validate().find("theta_deg"), std::string::npos);
  g.axes = {Axis{Quantity::omega, 30, 50, 21}, Axis{Quantity::theta_deg, 100, 170, 71}};
  EXPECT_NE(g.validate().find("canonical order"), std::string::npos);
  sort_axes(g.axes);
  EXPECT_EQ(g.validate(), "");
  g.fixed_speed = 0;
  EXPECT_NE(g.validate().find("speed"), std::string::npos);
}

TEST(GridSpec, RejectsCellCountsBeyondTwoToThe53) {
  GridSpec g;
  g.axes = {Axis{Quantity::speed, 1, 2, 1 << 20}, Axis{Quantity::mu, 0, 1, 1 << 20},
            Axis{Quantity::theta_deg, 0, 1, 1 << 10}, Axis{Quantity::omega, 0, 1, 1 << 10}};
  EXPECT_NE(g.validate().find("too many cells"), std::string::npos);
}

TEST(GridSpec, CellOrderIsRowMajorLastAxisFastest) {
  const GridSpec g = seed_grid_spec();
  EXPECT_EQ(g.cell_count(), 71 * 21);
  EXPECT_EQ(g.cell(0).theta_deg, 100.0);
  EXPECT_EQ(g.cell(0).omega, 30.0);
  EXPECT_EQ(g.cell(1).theta_deg, 100.0);  // omega varies fastest
  EXPECT_EQ(g.cell(1).omega, 31.0);
  EXPECT_EQ(g.cell(21).theta_deg, 101.0);
  EXPECT_EQ(g.cell(21).omega, 30.0);
  EXPECT_EQ(g.cell(71 * 21 - 1).theta_deg, 170.0);
  EXPECT_EQ(g.cell(71 * 21 - 1).omega, 50.0);
  EXPECT_EQ(g.cell(5).speed, 4.0);
  EXPECT_EQ(g.cell(5).mu, 0.5);
  EXPECT_EQ(g.cell(5).ratio, 35.0 / 4.0);
}

TEST(GridSpec, IndexAndCoordinatesRoundTrip) {
  GridSpec g;
  g.axes = {Axis{Quantity::speed, 4, 8, 3}, Axis{Quantity::mu, 0.2, 0.8, 4},
            Axis{Quantity::theta_deg, 100, 170, 5}, Axis{Quantity::ratio, 5, 15, 6}};
  ASSERT_EQ(g.validate(), "");
  for (std::int64_t i = 0; i < g.cell_count(); ++i) {
    const auto idx = g.indices(i);
    EXPECT_EQ(g.index_of(idx), i);
    const CellInput in = g.cell(i);
    std::vector<double> coords;
    for (std::size_t k = 0; k < g.axes.size(); ++k) coords.push_back(g.axes[k].value(idx[k]));
    const CellInput at = g.at(coords);
    // cell() and at() must give bit-identical inputs (contour refinement relies on it).
    EXPECT_EQ(at.theta_deg, in.theta_deg);
    EXPECT_EQ(at.omega, in.omega);
    EXPECT_EQ(at.speed, in.speed);
    EXPECT_EQ(at.mu, in.mu);
    EXPECT_EQ(at.ratio, in.ratio);
    EXPECT_EQ(in.omega, in.ratio * in.speed);  // ratio swept: omega derived
  }
}

TEST(Shard, InterleavedShardsCoverEveryCellOnce) {
  for (std::int64_t total : {0, 1, 2, 7, 100, 101}) {
    for (std::int64_t n : {1, 2, 3, 7, 200}) {
      std::multiset<std::int64_t> seen;
      for (std::int64_t i = 0; i < n; ++i) {
        const Shard s{i, n};
        for (std::int64_t k = 0; k < s.cells(total); ++k) seen.insert(s.global(k));
      }
      ASSERT_EQ(static_cast<std::int64_t>(seen.size()), total) << total << " cells, " << n << " shards";
      std::int64_t expect = 0;
      for (std::int64_t v : seen) EXPECT_EQ(v, expect++);
    }
  }
}

TEST(Shard, ValidateRejectsOutOfRangeIndex) {
  EXPECT_EQ((Shard{0, 1}).validate(), "");
  EXPECT_NE((Shard{3, 3}).validate(), "");
  EXPECT_NE((Shard{-1, 3}).validate(), "");
  EXPECT_NE((Shard{0, 0}).validate(), "");
}

TEST(Quantity, NamesRoundTrip) {
  for (int i = 0; i < kQuantityCount; ++i) {
    const auto q = static_cast<Quantity>(i);
    EXPECT_EQ(quantity_from_name(quantity_name(q)), q);
  }
  EXPECT_FALSE(quantity_from_name("spin").has_value());
}

}  // namespace
}  // namespace tribolab::sweep
