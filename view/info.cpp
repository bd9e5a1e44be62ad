#include "view/info.hpp"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "language/chart.hpp"
#include "language/words.hpp"
#include "mesh/bounds.hpp"

namespace knitc::view {

namespace {

using json = nlohmann::ordered_json;

double tenth_um(double v) {
  const double r = std::round(v * 1e4) / 1e4;
  return r == 0.0 ? 0.0 : r;
}

// At most this many centreline points a loop: enough to draw it and point at it.
constexpr std::size_t points_per_loop = 12;

}  // namespace

std::string fabric_info(const Pattern& pattern, const Fabric& fabric) {
  const layout::Layout& layout = fabric.layout;
  json doc;
  doc["pattern"] = pattern.name;
  doc["knitting"] = pattern.knitting == Knitting::flat ? "flat" : "round";

  // Per loop: the chart row it belongs to (0: the cast-on) and its cell in that row.
  std::vector<int> loop_cell(layout.loops.size(), -1);
  std::vector<std::vector<std::size_t>> by_course(static_cast<std::size_t>(layout.courses));
  for (std::size_t i = 0; i < layout.loops.size(); ++i) {
    const int c = layout.loops[i].course;
    if (c >= 0 && c < layout.courses) by_course[static_cast<std::size_t>(c)].push_back(i);
  }
  json rows = json::array();
  for (std::size_t r = 0; r < pattern.courses.size(); ++r) {
    const Course& course = pattern.courses[r];
    // The course's loops, left to right in face view, shared out to its stitches by what
    // each leaves on the needle: layout course r + 1 is pattern course r.
    auto loops = r + 1 < by_course.size() ? by_course[r + 1] : std::vector<std::size_t>{};
    std::sort(loops.begin(), loops.end(), [&](std::size_t a, std::size_t b) { return layout.loops[a].wale < layout.loops[b].wale; });
    int produced = 0;
    for (const Op& op : course.ops) produced += stitch(op.stitch).produces;
    const bool shared = produced == static_cast<int>(loops.size());
    json cells = json::array();
    std::size_t next = 0;
    for (std::size_t k = 0; k < course.ops.size(); ++k) {
      const Op& op = course.ops[k];
      const StitchDef& s = stitch(op.stitch);
      json made = json::array();
      for (int n = 0; shared && n < s.produces; ++n, ++next) {
        made.push_back(loops[next]);
        loop_cell[loops[next]] = static_cast<int>(k);
      }
      cells.push_back({{"symbol", language::chart_cell(op.stitch)},
                       {"abbreviation", std::string(s.name)},
                       {"name", std::string(language::long_name(op.stitch))},
                       {"width", std::max(1, std::max(s.consumes, s.produces))},
                       {"yarn", pattern.yarns[static_cast<std::size_t>(op.yarn)].id},
                       {"loops", std::move(made)}});
    }
    rows.push_back({{"row", r + 1},
                    {"side", course.side == Side::right ? "right" : "wrong"},
                    {"file", course.where.file},
                    {"line", course.where.line},
                    {"cells", std::move(cells)}});
  }
  doc["rows"] = std::move(rows);

  // Per loop: [row, cell, x, y, z, x, y, z, ...] with up to points_per_loop points of its
  // centreline as the fabric's curves pass through it.
  std::vector<json> loops(layout.loops.size(), json::array());
  for (const CurvePiece& piece : fabric.pieces) {
    for (std::size_t j = 0; j < piece.path.loops.size(); ++j) {
      const auto index = static_cast<std::size_t>(piece.path.loops[j]);
      const std::size_t first = piece.path.loop_first[j], last = piece.path.loop_last[j];
      const layout::Loop& loop = layout.loops[index];
      json entry = json::array({loop.course, loop_cell[index]});
      const std::size_t count = std::min(points_per_loop, last - first + 1);
      for (std::size_t n = 0; n < count; ++n) {
        const std::size_t k = count == 1 ? first : first + (last - first) * n / (count - 1);
        const glm::dvec3& p = piece.path.data_points[k];
        entry.push_back(tenth_um(p.x));
        entry.push_back(tenth_um(p.y));
        entry.push_back(tenth_um(p.z));
      }
      loops[index] = std::move(entry);
    }
  }
  doc["loops"] = std::move(loops);

  // The figures: size from the mesh, gauge from the loops across and up it, yarn per colour.
  const mesh::Bounds box = mesh::bounds(fabric.mesh);
  const double width = box.empty ? 0.0 : box.max.x - box.min.x, height = box.empty ? 0.0 : box.max.y - box.min.y;
  std::vector<double> length(pattern.yarns.size(), 0.0);
  for (const CurvePiece& piece : fabric.pieces)
    if (!piece.arc_length.empty()) length[static_cast<std::size_t>(piece.path.yarn)] += piece.arc_length.back();
  json yarns = json::array();
  for (std::size_t y = 0; y < pattern.yarns.size(); ++y) {
    const Yarn& yarn = pattern.yarns[y];
    yarns.push_back({{"id", yarn.id},
                     {"color", yarn.color},
                     {"metres", tenth_um(length[y] / 1000.0)},
                     {"grams", tenth_um(length[y] / 1000.0 * yarn.grams_per_metre)}});
  }
  doc["figures"] = {{"width_cm", tenth_um(width / 10.0)},
                    {"height_cm", tenth_um(height / 10.0)},
                    {"stitches_per_10cm", width > 0.0 ? tenth_um(layout.wales * 100.0 / width) : 0.0},
                    {"rows_per_10cm", height > 0.0 ? tenth_um(layout.courses * 100.0 / height) : 0.0},
                    {"loops", layout.loops.size()},
                    {"yarns", std::move(yarns)}};
  return doc.dump();
}

}  // namespace knitc::view
