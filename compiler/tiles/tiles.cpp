#include "tiles/tiles.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include <glm/geometric.hpp>

#include "parallel.hpp"
#include "tubes/tubes.hpp"

namespace knitc::tiles {

namespace {

// A yarn's way through one cell in one course: samples [from, to] of a piece, `to` the
// first sample of the next loop along the yarn (in the next cell), so that consecutive
// runs share their cut sample.
struct Run {
  std::size_t piece = 0, from = 0, to = 0;
  int course = 0, yarn = 0, wale = 0;  // course and first loop's wale within the cell
  auto key() const { return std::tuple(course, yarn, wale); }
};

struct Cell {
  std::vector<Run> runs;
  int loops = 0;
  bool broken = false;  // a run that does not go on into the next cell along its course
};

// One stretch of a piece to mesh: samples [first, last], where it is cut, and where its
// vertices go.
struct Part {
  std::size_t piece = 0, first = 0, last = 0;
  bool cut_start = false, cut_end = false;
  glm::dvec3 offset{0.0};
  mesh::Primitive* into = nullptr;
  std::size_t vertex = 0, index = 0;
};

bool matches(const curves::CurvePiece& a, std::size_t ia, const curves::CurvePiece& b, std::size_t ib, const glm::dvec3& shift) {
  if (glm::distance(a.frames.origin[ia], b.frames.origin[ib] + shift) > same_place) return false;
  if (glm::distance(a.frames.tangent[ia], b.frames.tangent[ib]) > same_place) return false;
  if (a.pressed.empty() != b.pressed.empty()) return false;
  // A pressing is an axis: the same either way along it.
  return a.pressed.empty() || std::min(glm::distance(a.pressed[ia], b.pressed[ib]), glm::distance(a.pressed[ia], -b.pressed[ib])) <= same_place;
}

// Whether cell x repeats cell r moved by `shift` (x's first sample less r's).
bool repeats(const Cell& x, const Cell& r, std::span<const curves::CurvePiece> pieces, glm::dvec3& shift) {
  if (x.broken || x.loops != r.loops || x.runs.size() != r.runs.size() || x.runs.empty()) return false;
  shift = pieces[x.runs[0].piece].frames.origin[x.runs[0].from] - pieces[r.runs[0].piece].frames.origin[r.runs[0].from];
  for (std::size_t k = 0; k < x.runs.size(); ++k) {
    const Run& a = x.runs[k];
    const Run& b = r.runs[k];
    if (a.key() != b.key() || a.to - a.from != b.to - b.from) return false;
    const auto& pa = pieces[a.piece];
    const auto& pb = pieces[b.piece];
    // (Lengths are not compared: u runs along each stretch from 0, the tile's for all.)
    for (std::size_t i = 0; i <= a.to - a.from; ++i)
      if (!matches(pa, a.from + i, pb, b.from + i, shift)) return false;
  }
  return true;
}

// The strands of samples [first, last] of a piece and what write_stretch needs of them.
void write_part(const Part& part, const curves::CurvePiece& piece, const Yarn& yarn, int sides) {
  const std::size_t n = part.last - part.first + 1;
  sweep::Frames f;
  auto sub = [&](const std::vector<glm::dvec3>& v) {
    return std::vector<glm::dvec3>(v.begin() + static_cast<std::ptrdiff_t>(part.first),
                                   v.begin() + static_cast<std::ptrdiff_t>(part.last + 1));
  };
  f.origin = sub(piece.frames.origin);
  f.tangent = sub(piece.frames.tangent);
  f.normal = sub(piece.frames.normal);
  f.binormal = sub(piece.frames.binormal);
  const std::vector<double> s(piece.arc_length.begin() + static_cast<std::ptrdiff_t>(part.first),
                              piece.arc_length.begin() + static_cast<std::ptrdiff_t>(part.last + 1));
  const std::vector<glm::dvec3> pressed = piece.pressed.empty() ? std::vector<glm::dvec3>{} : sub(piece.pressed);
  const auto strands = sweep::strands(f, s, tubes::cross_section(yarn), pressed);
  // u: the length along the stretch, scaled to a whole number of mm.
  const double length = s.back() - s.front();
  const double scale = length > 0.0 ? std::max(1.0, std::round(length)) / length : 0.0;
  std::vector<double> u(n), phase(n);
  for (std::size_t i = 0; i < n; ++i) u[i] = (s[i] - s.front()) * scale;
  const int ring = tubes::ring_sides(yarn, sides);
  std::size_t vertex = part.vertex, index = part.index;
  for (const sweep::Strand& strand : strands) {
    // The seam's angle at each cut, turned linearly along the stretch (the nearest way).
    const double a = sweep::seam_angle(strand, 0), b0 = sweep::seam_angle(strand, n - 1);
    double from = part.cut_start ? a : (part.cut_end ? b0 : 0.0), to = part.cut_end ? b0 : from;
    if (part.cut_start && part.cut_end) {
      while (to - from > std::numbers::pi) to -= 2.0 * std::numbers::pi;
      while (to - from < -std::numbers::pi) to += 2.0 * std::numbers::pi;
    }
    for (std::size_t i = 0; i < n; ++i) phase[i] = from + (to - from) * (length > 0.0 ? (s[i] - s.front()) / length : 0.0);
    const sweep::Stretch stretch{0, n - 1, !part.cut_start, !part.cut_end};
    sweep::write_stretch(strand, stretch, u, phase, part.offset, ring, *part.into, vertex, index);
    const auto size = sweep::stretch_size(stretch, ring);
    vertex += size.vertices;
    index += size.indices;
  }
}

}  // namespace

Tiling tile(std::span<const Yarn> yarns, const layout::Layout& layout, std::span<const curves::CurvePiece> pieces,
            const Lattice& lattice, int sides, int threads) {
  Tiling out;
  if (lattice.wales <= 0 || lattice.courses <= 0) {
    out.declined = "the fabric has no repeat to tile";
    return out;
  }
  for (const auto& p : pieces)
    if (tubes::strand_count(yarns[static_cast<std::size_t>(p.path.yarn)]) > 1) {
      out.declined = "a plied yarn's twist does not repeat with the tile";
      return out;
    }
  const int across = (layout.wales - lattice.wale0) / lattice.wales, up = (layout.courses - lattice.course0) / lattice.courses;
  if (across < 1 || up < 1) {
    out.declined = "the repeat does not fit in the fabric";
    return out;
  }
  auto cell_of = [&](const layout::Loop& l) -> long {
    if (l.wale < lattice.wale0 || l.course < lattice.course0) return -1;
    const int i = (l.wale - lattice.wale0) / lattice.wales, j = (l.course - lattice.course0) / lattice.courses;
    if (i >= across || j >= up) return -1;
    return static_cast<long>(j) * across + i;
  };
  std::vector<Cell> cells(static_cast<std::size_t>(across) * static_cast<std::size_t>(up));
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    const auto& path = pieces[p].path;
    std::size_t j = 0;
    while (j < path.loops.size()) {
      const auto& loop = layout.loops[static_cast<std::size_t>(path.loops[j])];
      const long c = cell_of(loop);
      std::size_t end = j + 1;
      while (end < path.loops.size()) {
        const auto& next = layout.loops[static_cast<std::size_t>(path.loops[end])];
        if (next.course != loop.course || cell_of(next) != c) break;
        ++end;
      }
      if (c >= 0) {
        Cell& cell = cells[static_cast<std::size_t>(c)];
        cell.loops += static_cast<int>(end - j);
        const bool goes_on = end < path.loops.size() &&
                             layout.loops[static_cast<std::size_t>(path.loops[end])].course == loop.course;
        if (!goes_on) {
          cell.broken = true;
        } else {
          int first_wale = loop.wale;
          for (std::size_t k = j; k < end; ++k)
            first_wale = std::min(first_wale, layout.loops[static_cast<std::size_t>(path.loops[k])].wale);
          cell.runs.push_back({p, pieces[p].loop_samples[j].first, pieces[p].loop_samples[end].first,
                               loop.course - lattice.course0 - ((loop.course - lattice.course0) / lattice.courses) * lattice.courses,
                               path.yarn, first_wale - lattice.wale0 - ((first_wale - lattice.wale0) / lattice.wales) * lattice.wales});
        }
      }
      j = end;
    }
  }
  const int full = lattice.wales * lattice.courses;
  for (auto& cell : cells) {
    std::stable_sort(cell.runs.begin(), cell.runs.end(), [](const Run& a, const Run& b) { return a.key() < b.key(); });
    if (cell.loops == full && !cell.broken) ++out.complete;
  }
  // The reference: the complete cell nearest the middle.
  long reference = -1;
  double best = 1e300;
  for (int j = 0; j < up; ++j)
    for (int i = 0; i < across; ++i) {
      const Cell& cell = cells[static_cast<std::size_t>(j) * static_cast<std::size_t>(across) + static_cast<std::size_t>(i)];
      if (cell.broken || cell.loops != full) continue;
      const double d = std::hypot(i + 0.5 - 0.5 * across, j + 0.5 - 0.5 * up);
      if (d < best) {
        best = d;
        reference = static_cast<long>(j) * across + i;
      }
    }
  if (reference < 0) {
    out.declined = "no cell of the repeat is whole in the fabric";
    return out;
  }
  const Cell& ref = cells[static_cast<std::size_t>(reference)];
  std::vector<glm::dvec3> shift(cells.size(), glm::dvec3(0.0));
  std::vector<char> placed(cells.size(), 0);
  parallel_for(cells.size(), thread_count(threads), [&](std::size_t c) {
    placed[c] = static_cast<char>(static_cast<long>(c) == reference || repeats(cells[c], ref, pieces, shift[c]));
  });
  out.cells = static_cast<std::size_t>(std::count(placed.begin(), placed.end(), 1));
  if (out.cells < 2) {
    out.declined = "no two cells of the repeat are alike";
    return out;
  }

  // The materials as the flat mesh has them; a plain and a tile primitive per yarn.
  mesh::Mesh& mesh = out.mesh;
  const std::vector<int> material_of = tubes::add_materials(yarns, pieces, mesh);
  std::vector<mesh::Primitive> plain(yarns.size()), tile(yarns.size());
  const glm::dvec3 origin = pieces[ref.runs[0].piece].frames.origin[ref.runs[0].from];

  // The parts: the reference cell's runs into the tile, and per piece what no placed cell
  // covers into the plain primitives.
  std::vector<Part> parts;
  for (const Run& r : ref.runs) {
    tile[static_cast<std::size_t>(pieces[r.piece].path.yarn)].mode = mesh::Mode::triangles;
    parts.push_back({r.piece, r.from, r.to, true, true, origin, &tile[static_cast<std::size_t>(pieces[r.piece].path.yarn)]});
  }
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> covered(pieces.size());
  for (std::size_t c = 0; c < cells.size(); ++c)
    if (placed[c])
      for (const Run& r : cells[c].runs) covered[r.piece].push_back({r.from, r.to});
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    auto& spans = covered[p];
    std::sort(spans.begin(), spans.end());
    const std::size_t last = pieces[p].samples.size() - 1;
    std::size_t at = 0;
    bool cut = false;
    mesh::Primitive* into = &plain[static_cast<std::size_t>(pieces[p].path.yarn)];
    for (const auto& [from, to] : spans) {
      if (from > at) parts.push_back({p, at, from, cut, true, glm::dvec3(0.0), into});
      at = to;
      cut = true;
    }
    if (at < last) parts.push_back({p, at, last, cut, false, glm::dvec3(0.0), into});
  }
  // Sizes, then every part written in parallel at its own offsets.
  for (Part& part : parts) {
    const Yarn& yarn = yarns[static_cast<std::size_t>(pieces[part.piece].path.yarn)];
    const auto size = sweep::stretch_size({part.first, part.last, !part.cut_start, !part.cut_end}, tubes::ring_sides(yarn, sides));
    const std::size_t strands = tubes::strand_count(yarn);
    part.vertex = part.into->positions.size();
    part.index = part.into->indices.size();
    part.into->positions.resize(part.vertex + strands * size.vertices);
    part.into->indices.resize(part.index + strands * size.indices);
  }
  for (auto* group : {&plain, &tile})
    for (auto& prim : *group) {
      prim.normals.resize(prim.positions.size());
      prim.uvs.resize(prim.positions.size());
    }
  parallel_for(parts.size(), thread_count(threads), [&](std::size_t i) {
    const Part& part = parts[i];
    write_part(part, pieces[part.piece], yarns[static_cast<std::size_t>(pieces[part.piece].path.yarn)], sides);
  });
  mesh::Instances instances;
  for (std::size_t y = 0; y < yarns.size(); ++y) {
    plain[y].material = tile[y].material = material_of[y];
    if (!plain[y].indices.empty()) mesh.primitives.push_back(std::move(plain[y]));
    if (!tile[y].indices.empty()) instances.primitives.push_back(std::move(tile[y]));
  }
  for (std::size_t c = 0; c < cells.size(); ++c)
    if (placed[c]) instances.translations.emplace_back(origin + shift[c]);
  mesh.instanced.push_back(std::move(instances));
  return out;
}

mesh::Mesh flatten(const mesh::Mesh& mesh, int threads) {
  mesh::Mesh out;
  out.materials = mesh.materials;
  // Per material: its plain primitive, then each instance's copies of its tile primitive.
  std::vector<mesh::Primitive> by_material(mesh.materials.size());
  std::vector<char> used(mesh.materials.size(), 0);
  struct Copy {
    const mesh::Primitive* from;
    glm::vec3 shift;
    std::size_t material, vertex, index;
  };
  std::vector<Copy> copies;
  std::vector<std::size_t> vertices(mesh.materials.size(), 0), indices(mesh.materials.size(), 0);
  auto plan = [&](const mesh::Primitive& p, glm::vec3 shift) {
    const auto m = static_cast<std::size_t>(p.material);
    used[m] = 1;
    copies.push_back({&p, shift, m, vertices[m], indices[m]});
    vertices[m] += p.positions.size();
    indices[m] += p.indices.size();
  };
  for (const auto& p : mesh.primitives) plan(p, glm::vec3(0.0f));
  for (const auto& group : mesh.instanced)
    for (const glm::vec3& t : group.translations)
      for (const auto& p : group.primitives) plan(p, t);
  // Each array reserved once and appended to, copy by copy: written once, never zero-filled
  // first (a garment's are a gigabyte and more); the arrays are built side by side.
  for (std::size_t m = 0; m < by_material.size(); ++m) by_material[m].material = static_cast<int>(m);
  parallel_for(4 * by_material.size(), thread_count(threads), [&](std::size_t task) {
    const std::size_t m = task / 4;
    mesh::Primitive& to = by_material[m];
    switch (task % 4) {
      case 0:
        to.positions.reserve(vertices[m]);
        for (const Copy& c : copies)
          if (c.material == m) {
            const std::size_t at = to.positions.size();
            to.positions.insert(to.positions.end(), c.from->positions.begin(), c.from->positions.end());
            for (std::size_t v = at; v < to.positions.size(); ++v) to.positions[v] += c.shift;
          }
        break;
      case 1:
        to.normals.reserve(vertices[m]);
        for (const Copy& c : copies)
          if (c.material == m) to.normals.insert(to.normals.end(), c.from->normals.begin(), c.from->normals.end());
        break;
      case 2:
        to.uvs.reserve(vertices[m]);
        for (const Copy& c : copies)
          if (c.material == m) to.uvs.insert(to.uvs.end(), c.from->uvs.begin(), c.from->uvs.end());
        break;
      default:
        to.indices.reserve(indices[m]);
        for (const Copy& c : copies)
          if (c.material == m) {
            const std::size_t at = to.indices.size();
            const auto base = static_cast<std::uint32_t>(c.vertex);
            to.indices.insert(to.indices.end(), c.from->indices.begin(), c.from->indices.end());
            for (std::size_t k = at; k < to.indices.size(); ++k) to.indices[k] += base;
          }
    }
  });
  for (std::size_t m = 0; m < by_material.size(); ++m)
    if (used[m] && !by_material[m].indices.empty()) out.primitives.push_back(std::move(by_material[m]));
  return out;
}

Drawn drawn(const mesh::Mesh& mesh) {
  Drawn d;
  for (const auto& p : mesh.primitives) {
    d.triangles += p.mode == mesh::Mode::triangles ? p.indices.size() / 3 : 0;
    d.vertices += p.positions.size();
    d.stored_vertices += p.positions.size();
  }
  for (const auto& group : mesh.instanced)
    for (const auto& p : group.primitives) {
      d.triangles += group.translations.size() * (p.indices.size() / 3);
      d.vertices += group.translations.size() * p.positions.size();
      d.stored_vertices += p.positions.size();
    }
  return d;
}

}  // namespace knitc::tiles
