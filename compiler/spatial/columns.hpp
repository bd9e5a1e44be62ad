// The one spatial index of the compiler: a grid of square columns (x, y), each holding
// its entries in order of their cell's z, then item. Measuring finds close centreline
// points with it, relaxation close segments, and the crossings segments whose boxes
// share a column. Header only.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <unordered_map>
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
    std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) {
      return a.column != b.column ? a.column < b.column
             : a.z != b.z         ? a.z < b.z
             : a.item != b.item   ? a.item < b.item
             : a.sx != b.sx       ? a.sx < b.sx
                                  : a.sy < b.sy;
    });
    columns_.clear();
    columns_.reserve(entries_.size() / 4 + 1);
    for (std::size_t i = 0; i < entries_.size();) {
      std::size_t j = i;
      while (j < entries_.size() && entries_[j].column == entries_[i].column) ++j;
      columns_.emplace(entries_[i].column, std::make_pair(i, j));
      i = j;
    }
  }

  // visit(entry) for the entries of the 3 x 3 columns around `cell` (x, then y) whose z
  // is within one of the cell's, each column in its order: the same sequence every time.
  template <class Visit>
  void near(const glm::i64vec3& cell, Visit&& visit) const {
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) {
        const auto hit = columns_.find(column_key(cell.x + dx, cell.y + dy));
        if (hit == columns_.end()) continue;
        for (std::size_t e = hit->second.first; e < hit->second.second; ++e) {
          const Entry& entry = entries_[e];
          if (entry.z < cell.z - 1) continue;
          if (entry.z > cell.z + 1) break;
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
  double cell_;
  std::vector<Entry> entries_;
  std::unordered_map<std::uint64_t, std::pair<std::size_t, std::size_t>> columns_;
};

}  // namespace knitc::spatial
