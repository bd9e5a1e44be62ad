// The one spatial index of the compiler: a grid of square columns (x, y), each holding
// its entries in order of their cell's z, then item. Measuring finds close centreline
// points with it, relaxation close segments, and the crossings segments whose boxes
// share a column. Header only.
#pragma once

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/gtc/type_precision.hpp>

namespace knitc::spatial {

class Columns {
 public:
  struct Entry {
    std::uint64_t column;
    std::int64_t z;
    std::uint32_t item;
    std::int8_t sx = 0, sy = 0;  // for periodic images: which copy of the item this is
  };

  // Cells `cell` wide (> 0), in mm.
  explicit Columns(double cell) : cell_(cell) {}

  double cell() const { return cell_; }
  glm::i64vec3 cell_of(const glm::dvec3& p) const {
    return glm::i64vec3(std::floor(p.x / cell_), std::floor(p.y / cell_), std::floor(p.z / cell_));
  }
  static std::uint64_t column_key(std::int64_t x, std::int64_t y) {
    return static_cast<std::uint64_t>(x + (1ll << 31)) << 32 | (static_cast<std::uint64_t>(y + (1ll << 31)) & 0xffffffffu);
  }

  void reserve(std::size_t n) { entries_.reserve(n); }
  void add(const glm::i64vec3& cell, std::uint32_t item, std::int8_t sx = 0, std::int8_t sy = 0) {
    entries_.push_back({column_key(cell.x, cell.y), cell.z, item, sx, sy});
  }

  // After the last add: sorts the entries and maps each column to its run of them.
  void index() {
    dense_.clear();
    slots_.clear();
    if (entries_.empty()) return;
    if (!in_insertion_order()) {
      std::sort(entries_.begin(), entries_.end(), before);
    } else {
      // In insertion order, a stable sort by column, then by z within each, leaves them
      // as the full sort does, without comparing them all.
      const Extent e = extent();
      const bool dense = index_densely(e);
      if (!dense) by_columns(e);
      by_z_within_columns();
      if (dense) return;
    }
    // Each column's run in an open-addressed table, at most half full.
    std::size_t runs = 0;
    for (std::size_t i = 0; i < entries_.size(); ++i) runs += i == 0 || entries_[i].column != entries_[i - 1].column ? 1 : 0;
    int bits = 4;
    while ((std::size_t{1} << bits) < 2 * runs) ++bits;
    shift_ = 64 - bits;
    slots_.assign(std::size_t{1} << bits, Slot{});
    for (std::size_t i = 0; i < entries_.size();) {
      std::size_t j = i;
      while (j < entries_.size() && entries_[j].column == entries_[i].column) ++j;
      std::size_t at = slot_of(entries_[i].column);
      while (slots_[at].last != 0) at = (at + 1) & (slots_.size() - 1);
      slots_[at] = {entries_[i].column, i, j};
      i = j;
    }
  }

  // visit(entry) for the entries of the 3 x 3 columns around `cell` (x, then y) whose z
  // is within one of the cell's, each column in its order: the same sequence every time.
  template <class Visit>
  void near(const glm::i64vec3& cell, Visit&& visit) const {
    near(cell, 1, visit);
  }
  // The same for the (2 reach + 1)^2 columns around `cell` and z within `reach` (>= 0) of its.
  template <class Visit>
  void near(const glm::i64vec3& cell, int reach, Visit&& visit) const {
    for (int dx = -reach; dx <= reach; ++dx)
      for (int dy = -reach; dy <= reach; ++dy) {
        const auto [first, last] = column(cell.x + dx, cell.y + dy);
        for (std::size_t e = first; e < last; ++e) {
          const Entry& entry = entries_[e];
          if (entry.z < cell.z - reach) continue;
          if (entry.z > cell.z + reach) break;
          visit(entry);
        }
      }
  }

  // visit(entries) for each column's entries, in the columns' key order.
  template <class Visit>
  void each_column(Visit&& visit) const {
    for (std::size_t i = 0; i < entries_.size();) {
      std::size_t j = i;
      while (j < entries_.size() && entries_[j].column == entries_[i].column) ++j;
      visit(std::span<const Entry>(entries_.data() + i, j - i));
      i = j;
    }
  }

 private:
  static bool before(const Entry& a, const Entry& b) {
    return a.column != b.column ? a.column < b.column
           : a.z != b.z         ? a.z < b.z
           : a.item != b.item   ? a.item < b.item
           : a.sx != b.sx       ? a.sx < b.sx
                                : a.sy < b.sy;
  }
  static bool same_place_before(const Entry& a, const Entry& b) { return a.item != b.item ? a.item < b.item : a.sx != b.sx ? a.sx < b.sx : a.sy < b.sy; }

  // The entries of column (x, y): a range of entries_, empty if none.
  std::pair<std::size_t, std::size_t> column(std::int64_t x, std::int64_t y) const {
    if (!dense_.empty()) {
      if (x < x0_ || y < y0_ || x - x0_ >= nx_ || y - y0_ >= ny_) return {0, 0};
      const auto at = static_cast<std::size_t>((x - x0_) * ny_ + (y - y0_));
      return {dense_[at], dense_[at + 1]};
    }
    if (slots_.empty()) return {0, 0};
    const std::uint64_t key = column_key(x, y);
    for (std::size_t at = slot_of(key);; at = (at + 1) & (slots_.size() - 1)) {
      const Slot& slot = slots_[at];
      if (slot.last == 0) return {0, 0};
      if (slot.column == key) return {slot.first, slot.last};
    }
  }
  std::size_t slot_of(std::uint64_t key) const { return static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ull) >> shift_); }

  // Whether the entries came in the order the sort would leave equal places in (item,
  // image).
  bool in_insertion_order() const {
    for (std::size_t i = 1; i < entries_.size(); ++i)
      if (same_place_before(entries_[i], entries_[i - 1])) return false;
    return true;
  }

  // The entries' columns' least and greatest x and y, as the keys hold them.
  struct Extent {
    std::uint64_t xl = UINT64_MAX, xh = 0, yl = UINT64_MAX, yh = 0;
  };
  Extent extent() const {
    Extent r;
    for (const Entry& e : entries_) {
      const std::uint64_t x = e.column >> 32, y = e.column & 0xffffffffu;
      r.xl = std::min(r.xl, x), r.xh = std::max(r.xh, x), r.yl = std::min(r.yl, y), r.yh = std::max(r.yh, y);
    }
    return r;
  }

  // Entries sorted stably by column: a radix sort of the column's rank from the extent's
  // corner (11 bits a pass). A garment's edges are indexed over the whole garment's
  // columns, too many for the dense table.
  void by_columns(const Extent& x) {
    const std::size_t n = entries_.size();
    const std::uint64_t ny = x.yh - x.yl + 1;
    auto rank = [&](const Entry& e) { return ((e.column >> 32) - x.xl) * ny + ((e.column & 0xffffffffu) - x.yl); };
    const std::uint64_t top = (x.xh - x.xl) * ny + (x.yh - x.yl);
    constexpr int bits = 11;
    constexpr std::size_t buckets = std::size_t{1} << bits;
    std::vector<Entry> other(n);
    std::vector<std::size_t> count(buckets + 1);
    for (int shift = 0; shift == 0 || (top >> shift) != 0; shift += bits) {
      std::fill(count.begin(), count.end(), 0);
      for (const Entry& e : entries_) ++count[((rank(e) >> shift) & (buckets - 1)) + 1];
      for (std::size_t k = 1; k <= buckets; ++k) count[k] += count[k - 1];
      for (const Entry& e : entries_) other[count[(rank(e) >> shift) & (buckets - 1)]++] = e;
      entries_.swap(other);
      if (shift + bits >= 64) break;
    }
  }

  // Each column's entries (sorted by column) sorted stably by z: by insertion where a
  // column holds a few, as a fabric's do.
  void by_z_within_columns() {
    const std::size_t n = entries_.size();
    for (std::size_t i = 0; i < n;) {
      std::size_t j = i + 1;
      while (j < n && entries_[j].column == entries_[i].column) ++j;
      if (j - i > 32) {
        std::stable_sort(entries_.begin() + static_cast<std::ptrdiff_t>(i), entries_.begin() + static_cast<std::ptrdiff_t>(j),
                         [](const Entry& a, const Entry& b) { return a.z < b.z; });
      } else {
        for (std::size_t a = i + 1; a < j; ++a)
          for (std::size_t b = a; b > i && entries_[b].z < entries_[b - 1].z; --b) std::swap(entries_[b], entries_[b - 1]);
      }
      i = j;
    }
  }

  // Where the columns are few for the entries (a fabric, not a scatter), a counting sort
  // by column, stable, and a table of every column's run that replaces the map. False
  // (nothing done) otherwise.
  bool index_densely(const Extent& x) {
    const std::size_t n = entries_.size();
    const auto xl = static_cast<std::int64_t>(x.xl), yl = static_cast<std::int64_t>(x.yl);
    const auto cols = static_cast<double>(x.xh - x.xl + 1) * static_cast<double>(x.yh - x.yl + 1);
    if (cols > 4.0 * static_cast<double>(n) + 4096.0) return false;
    x0_ = xl - (std::int64_t{1} << 31), y0_ = yl - (std::int64_t{1} << 31);
    nx_ = static_cast<std::int64_t>(x.xh - x.xl + 1), ny_ = static_cast<std::int64_t>(x.yh - x.yl + 1);
    auto slot = [&](const Entry& e) {
      return static_cast<std::size_t>((static_cast<std::int64_t>(e.column >> 32) - xl) * ny_ +
                                      (static_cast<std::int64_t>(e.column & 0xffffffffu) - yl));
    };
    dense_.assign(static_cast<std::size_t>(nx_ * ny_) + 1, 0);
    for (const Entry& e : entries_) ++dense_[slot(e) + 1];
    for (std::size_t k = 1; k < dense_.size(); ++k) dense_[k] += dense_[k - 1];
    std::vector<Entry> sorted(n);
    std::vector<std::size_t> next(dense_.begin(), dense_.end() - 1);
    for (const Entry& e : entries_) sorted[next[slot(e)]++] = e;  // stable: each column in the order added
    entries_ = std::move(sorted);
    return true;
  }

  double cell_;
  std::vector<Entry> entries_;
  // When not dense: each column's entries [first, last), by its key, in a table of a power
  // of two slots probed in turn from the key's hash (a slot whose last is 0 is empty).
  struct Slot {
    std::uint64_t column = 0;
    std::size_t first = 0, last = 0;
  };
  std::vector<Slot> slots_;
  int shift_ = 64;
  std::vector<std::size_t> dense_;  // when dense: column (x, y)'s entries from dense_[(x - x0_) * ny_ + y - y0_] to the next
  std::int64_t x0_ = 0, y0_ = 0, nx_ = 0, ny_ = 0;
};

// The columns of a grid of `cell`-wide columns within one of a point `chosen` picks: what
// a query round those points (Columns::near, its 3 x 3 columns) can reach, so that the
// rest need not be indexed. `holds` answers true everywhere when every point is chosen or
// the columns would be too many to list (a scatter, not a fabric).
class ColumnMask {
 public:
  // n points, the i-th at cell(i) (a Columns cell), chosen(i) or not.
  template <class Cell, class Chosen>
  ColumnMask(std::size_t n, Cell&& cell, Chosen&& chosen) {
    // The extent of the chosen points' cells only (a column past it holds none of them):
    // a tiled garment chooses a tenth of its points, and the cells cost the time here.
    std::size_t picked = 0;
    std::int64_t xl = INT64_MAX, xh = INT64_MIN, yl = INT64_MAX, yh = INT64_MIN;
    for (std::size_t i = 0; i < n; ++i) {
      if (!chosen(i)) continue;
      const glm::i64vec3 c = cell(i);
      xl = std::min(xl, c.x), xh = std::max(xh, c.x), yl = std::min(yl, c.y), yh = std::max(yh, c.y);
      ++picked;
    }
    if (picked == n) return;
    if (picked == 0) {  // no column
      in_.assign(1, 0);
      return;
    }
    const double columns = (static_cast<double>(xh - xl) + 3.0) * (static_cast<double>(yh - yl) + 3.0);
    if (columns > 4.0 * static_cast<double>(n) + 4096.0) return;
    x0_ = xl - 1, y0_ = yl - 1, nx_ = xh - xl + 3, ny_ = yh - yl + 3;
    in_.assign(static_cast<std::size_t>(nx_ * ny_), 0);
    for (std::size_t i = 0; i < n; ++i) {
      if (!chosen(i)) continue;
      const glm::i64vec3 c = cell(i);
      for (std::int64_t dx = -1; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy) in_[static_cast<std::size_t>((c.x + dx - x0_) * ny_ + (c.y + dy - y0_))] = 1;
    }
  }
  template <class Chosen>
  ColumnMask(const std::vector<glm::dvec3>& pos, const Columns& grid, Chosen&& chosen)
      : ColumnMask(pos.size(), [&](std::size_t i) { return grid.cell_of(pos[i]); }, chosen) {}
  bool holds(const glm::i64vec3& cell) const {
    if (in_.empty()) return true;
    const std::int64_t x = cell.x - x0_, y = cell.y - y0_;
    return x >= 0 && y >= 0 && x < nx_ && y < ny_ && in_[static_cast<std::size_t>(x * ny_ + y)];
  }

 private:
  std::int64_t x0_ = 0, y0_ = 0, nx_ = 0, ny_ = 0;
  std::vector<std::uint8_t> in_;  // empty: every column
};

}  // namespace knitc::spatial
