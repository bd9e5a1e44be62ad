#include <cmath>

#include <nlohmann/json.hpp>

#include "writers/writers.hpp"

namespace knitc::writers {

namespace {

using json = nlohmann::ordered_json;

double micro(double v) {
  const double r = std::round(v * 1e6) / 1e6;
  return r == 0.0 ? 0.0 : r;  // no "-0.0"
}

json xyz(const glm::dvec3& p) { return json::array({micro(p.x), micro(p.y), micro(p.z)}); }

}  // namespace

std::string centreline_json(const Pattern& pattern, const Fabric& fabric, yarn_paths::LoopModel model) {
  json doc;
  doc["units"] = "mm";
  doc["loop_model"] = model == yarn_paths::LoopModel::paper ? "paper" : "smooth";

  json yarns = json::array();
  std::vector<std::size_t> first_point(fabric.pieces.size());  // each piece's first index in its yarn's points
  for (std::size_t y = 0; y < pattern.yarns.size(); ++y) {
    json points = json::array(), pieces = json::array();
    for (std::size_t i = 0; i < fabric.pieces.size(); ++i) {
      const CurvePiece& piece = fabric.pieces[i];
      if (piece.path.yarn != static_cast<int>(y)) continue;
      first_point[i] = points.size();
      pieces.push_back(json::array({points.size(), piece.frames.size()}));
      for (const auto& p : piece.frames.origin) points.push_back(xyz(p));
    }
    if (pieces.empty()) continue;
    yarns.push_back({{"id", pattern.yarns[y].id},
                     {"color", pattern.yarns[y].color},
                     {"free_diameter", micro(pattern.yarns[y].diameter)},
                     {"core_diameter", micro(pattern.yarns[y].core_diameter)},
                     {"points", std::move(points)},
                     {"pieces", std::move(pieces)}});
  }
  doc["yarns"] = std::move(yarns);

  // Loops in layout order, each with the samples of the piece that owns them.
  std::vector<json> loops(fabric.layout.loops.size());
  for (std::size_t i = 0; i < fabric.pieces.size(); ++i) {
    const CurvePiece& piece = fabric.pieces[i];
    for (std::size_t j = 0; j < piece.path.loops.size(); ++j) {
      const int index = piece.path.loops[j];
      const layout::Loop& loop = fabric.layout.loops[index];
      // The points the curve passes through for this loop, as the piece holds them: in the
      // mesh's space (wrapped onto the tube in the round, moved when relaxed) and in the
      // order of its samples.
      json data = json::array(), samples = json::array();
      for (std::size_t k = piece.path.loop_first[j]; k <= piece.path.loop_last[j]; ++k)
        data.push_back(xyz(piece.path.data_points[k]));
      for (std::size_t s = piece.loop_samples[j].first; s <= piece.loop_samples[j].second; ++s)
        samples.push_back(xyz(piece.frames.origin[s]));
      // The script line of the row that made it (the cast-on's and a bind-off's have none).
      const bool worked = loop.course >= 1 && static_cast<std::size_t>(loop.course) <= pattern.courses.size();
      const SourceLocation where = worked ? pattern.courses[static_cast<std::size_t>(loop.course) - 1].where : SourceLocation{};
      loops[index] = {{"course", loop.course},
                      {"wale", loop.wale},
                      {"stitch", std::string(stitch(loop.stitch).name)},
                      {"yarn", pattern.yarns[loop.yarn].id},
                      {"file", where.file},
                      {"line", where.line},
                      {"data_points", std::move(data)},
                      {"samples", std::move(samples)},
                      // The same samples as a range of its yarn's points: [first, last].
                      {"points", json::array({first_point[i] + piece.loop_samples[j].first,
                                              first_point[i] + piece.loop_samples[j].second})}};
    }
  }
  doc["loops"] = std::move(loops);
  return doc.dump() + "\n";
}

}  // namespace knitc::writers
