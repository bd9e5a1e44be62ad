// The spatial index's order: whichever way it indexes (a dense table for a compact
// fabric, a radix sort by column for entries spread over many columns, a full sort for
// entries not added in order), the columns hold their entries in one order, by column,
// then z, then item: the relaxation and the measures visit them in it, so it must not
// depend on the path taken.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <vector>

#include "spatial/columns.hpp"

namespace knitc {
namespace {

struct Added {
  glm::i64vec3 cell;
  std::uint32_t item;
};

// Every column's entries, in the columns' order: (column, z, item) per entry.
std::vector<std::tuple<std::uint64_t, std::int64_t, std::uint32_t>> order_of(const spatial::Columns& grid) {
  std::vector<std::tuple<std::uint64_t, std::int64_t, std::uint32_t>> out;
  grid.each_column([&](std::span<const spatial::Columns::Entry> list) {
    for (const auto& e : list) out.emplace_back(e.column, e.z, e.item);
  });
  return out;
}

// The entries indexed as added (in item order) and added backwards (which only the full
// sort takes): the same order, and the same visits round each cell.
void expect_one_order(const std::vector<Added>& added) {
  spatial::Columns forwards(1.0), backwards(1.0);
  for (const Added& a : added) forwards.add(a.cell, a.item);
  for (auto it = added.rbegin(); it != added.rend(); ++it) backwards.add(it->cell, it->item);
  forwards.index();
  backwards.index();
  const auto order = order_of(forwards);
  ASSERT_EQ(order.size(), added.size());
  EXPECT_EQ(order, order_of(backwards));
  for (std::size_t k = 1; k < order.size(); ++k) ASSERT_LE(order[k - 1], order[k]) << "entry " << k;
  for (const Added& a : added) {
    std::vector<std::uint32_t> f, b;
    forwards.near(a.cell, [&](const spatial::Columns::Entry& e) { f.push_back(e.item); });
    backwards.near(a.cell, [&](const spatial::Columns::Entry& e) { b.push_back(e.item); });
    ASSERT_EQ(f, b);
    ASSERT_FALSE(f.empty());
    // And exactly the entries within a cell of it every way, counted one by one.
    std::vector<std::uint32_t> within;
    for (const Added& o : added)
      if (std::abs(o.cell.x - a.cell.x) <= 1 && std::abs(o.cell.y - a.cell.y) <= 1 && std::abs(o.cell.z - a.cell.z) <= 1)
        within.push_back(o.item);
    std::sort(f.begin(), f.end());
    std::sort(within.begin(), within.end());
    ASSERT_EQ(f, within) << "round cell " << a.cell.x << ", " << a.cell.y << ", " << a.cell.z;
  }
}

TEST(Columns, ACompactFabricsEntriesKeepOneOrder) {
  std::mt19937 rng(21);
  std::uniform_int_distribution<int> xy(0, 30), z(-3, 3);
  std::vector<Added> added;
  for (std::uint32_t i = 0; i < 2000; ++i) added.push_back({{xy(rng), xy(rng), z(rng)}, i});
  expect_one_order(added);
}

TEST(Columns, EntriesSpreadOverManyColumnsKeepOneOrder) {
  // A garment's edges indexed over its whole extent: far more columns than entries, so
  // no dense table; some columns hold several entries at several heights, one more than
  // 32 (sorted by z another way).
  std::mt19937 rng(22);
  std::uniform_int_distribution<int> far(-200000, 200000), z(-5, 5);
  std::vector<Added> added;
  std::uint32_t item = 0;
  for (int k = 0; k < 3000; ++k) {
    const glm::i64vec3 cell(far(rng), far(rng), z(rng));
    added.push_back({cell, item++});
    if (k % 7 == 0) added.push_back({{cell.x, cell.y, z(rng)}, item++});
  }
  for (int k = 0; k < 50; ++k) added.push_back({{12, -7, z(rng)}, item++});
  expect_one_order(added);
}

// The mask holds exactly the columns within one of a chosen point's, whatever the points
// not chosen span (far off here: their extent's columns would be too many to list, and
// the mask would hold every column); none when none is chosen, all when all are.
TEST(Columns, AMaskHoldsTheColumnsBesideTheChosenPointsOnly) {
  std::mt19937 rng(23);
  std::uniform_int_distribution<int> xy(-10, 10), far(-100000, 100000);
  std::vector<glm::i64vec3> cells;
  std::vector<char> chosen;
  for (int k = 0; k < 400; ++k) {
    const bool pick = k % 10 == 0;
    cells.emplace_back(pick ? xy(rng) : far(rng), pick ? xy(rng) : far(rng), 0);
    chosen.push_back(pick ? 1 : 0);
  }
  auto cell = [&](std::size_t i) { return cells[i]; };
  const spatial::ColumnMask mask(cells.size(), cell, [&](std::size_t i) { return chosen[i] != 0; });
  for (int x = -15; x <= 15; ++x)
    for (int y = -15; y <= 15; ++y) {
      bool beside = false;
      for (std::size_t i = 0; i < cells.size(); ++i)
        beside = beside || (chosen[i] && std::abs(cells[i].x - x) <= 1 && std::abs(cells[i].y - y) <= 1);
      ASSERT_EQ(mask.holds({x, y, 0}), beside) << x << ", " << y;
    }
  EXPECT_FALSE(mask.holds({100000, 100000, 0}));
  const spatial::ColumnMask none(cells.size(), cell, [](std::size_t) { return false; });
  EXPECT_FALSE(none.holds(cells[1]));
  EXPECT_FALSE(none.holds({0, 0, 0}));
  const spatial::ColumnMask all(cells.size(), cell, [](std::size_t) { return true; });
  EXPECT_TRUE(all.holds(cells[1]));
  EXPECT_TRUE(all.holds({5000000, -5000000, 0}));
}

}  // namespace
}  // namespace knitc
