#include "compile.hpp"

#include "parallel.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace knitc {

sweep::FrameKind frame_kind(yarn_paths::LoopModel model) {
  return model == yarn_paths::LoopModel::paper ? sweep::FrameKind::frenet
                                               : sweep::FrameKind::rotation_minimising;
}

Density density(Quality quality) {
  switch (quality) {
    case Quality::draft: return {6, 0.05};
    case Quality::normal: return {12, 0.01};
    case Quality::fine: return {24, 0.0025};
  }
  return {12, 0.01};
}

sweep::CrossSection cross_section(const Yarn& yarn) {
  sweep::CrossSection c;
  c.radius = 0.5 * yarn.diameter;
  switch (yarn.section) {
    case Section::circle: c.shape = sweep::CrossSection::Shape::circle; break;
    case Section::ellipse:
      c.shape = sweep::CrossSection::Shape::ellipse;
      c.aspect = yarn.aspect;
      c.flat_normal = {0.0, 0.0, 1.0};  // pressed flat in the fabric's plane
      break;
    case Section::plied:
      c.shape = sweep::CrossSection::Shape::plied;
      c.plies = yarn.plies;
      c.twist = (yarn.z_twist ? 1.0 : -1.0) * yarn.twist / 100.0;  // turns per mm
      break;
  }
  return c;
}

glm::vec3 linear_rgb(const std::string& hex) {
  assert(hex.size() == 7 && hex[0] == '#');
  glm::vec3 rgb;
  for (int i = 0; i < 3; ++i) {
    const double s = static_cast<double>(std::strtol(hex.substr(1 + 2 * i, 2).c_str(), nullptr, 16)) / 255.0;
    rgb[i] = static_cast<float>(s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4));
  }
  return rgb;
}

namespace {

// A twisted ply needs samples along its helix even where the centreline is straight.
double max_sample_step(const Yarn& yarn) {
  return yarn.section == Section::plied && yarn.twist > 0.0 ? (100.0 / yarn.twist) / 12.0
                                                            : std::numeric_limits<double>::infinity();
}

std::uint64_t strand_count(const Yarn& yarn) {
  return yarn.section == Section::plied ? static_cast<std::uint64_t>(yarn.plies) : 1;
}

CurvePiece trace_curve(yarn_paths::Piece path, const Pattern& pattern, const CompileOptions& options) {
  CurvePiece piece;
  piece.path = std::move(path);
  nurbs::InterpolationOptions io;
  io.parametrisation = options.parametrisation;
  piece.curve = nurbs::interpolate(piece.path.data_points, io);

  // Sample span by span between the loops' ends, so every loop join is a sample and each
  // loop owns its samples; floats, turns and tails are spans of their own.
  const Yarn& yarn = pattern.yarns[piece.path.yarn];
  const double d = yarn.diameter;
  const double tolerance = options.chord_tolerance * d;
  const double max_step = max_sample_step(yarn);
  const auto& u = piece.curve.parameters;
  const std::size_t last = u.size() - 1;
  std::vector<std::size_t> breaks = {0, last};
  breaks.insert(breaks.end(), piece.path.loop_first.begin(), piece.path.loop_first.end());
  breaks.insert(breaks.end(), piece.path.loop_last.begin(), piece.path.loop_last.end());
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  std::vector<std::size_t> sample_at(u.size(), 0);  // the sample at each break
  piece.samples.push_back(u[0]);
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const auto s = sweep::sample_parameters(piece.curve.curve, u[breaks[k]], u[breaks[k + 1]], tolerance, 0.5 * d, max_step);
    piece.samples.insert(piece.samples.end(), s.begin() + 1, s.end());
    sample_at[breaks[k + 1]] = piece.samples.size() - 1;
  }
  for (std::size_t j = 0; j < piece.path.loops.size(); ++j)
    piece.loop_samples.emplace_back(sample_at[piece.path.loop_first[j]], sample_at[piece.path.loop_last[j]]);
  piece.frames = sweep::frames(piece.curve.curve, piece.samples, frame_kind(options.loop_model));
  piece.arc_length.assign(piece.samples.size(), 0.0);
  for (std::size_t i = 1; i < piece.samples.size(); ++i)
    piece.arc_length[i] = piece.arc_length[i - 1] + nurbs::segment_length(piece.curve.curve, piece.samples[i - 1], piece.samples[i]);
  return piece;
}

// The script's file name for messages, whatever the pattern holds.
std::string source_file(const Pattern& pattern) {
  return pattern.courses.empty() ? pattern.name : pattern.courses.front().where.file;
}

// "file:line: " of the course at which the fabric passes `share` of its loops: where a
// fabric too large to make grows past the limit, the line a designer would shorten.
std::string where_it_passes(const Pattern& pattern, double share) {
  if (pattern.courses.empty()) return source_file(pattern) + ":1: ";
  double total = static_cast<double>(pattern.cast_on);
  for (const Course& c : pattern.courses) total += static_cast<double>(c.ops.size());
  double so_far = static_cast<double>(pattern.cast_on);
  const Course* at = &pattern.courses.back();
  for (const Course& c : pattern.courses) {
    so_far += static_cast<double>(c.ops.size());
    if (so_far >= share * total) {
      at = &c;
      break;
    }
  }
  return at->where.file + ":" + std::to_string(std::max(at->where.line, 1)) + ": ";
}

mesh::Mode primitive_mode(View view) {
  switch (view) {
    case View::surface: return mesh::Mode::triangles;
    case View::wireframe: return mesh::Mode::lines;
    case View::centreline: return mesh::Mode::line_strip;
  }
  return mesh::Mode::triangles;
}

mesh::Mesh build_mesh(const Pattern& pattern, const std::vector<CurvePiece>& pieces, const CompileOptions& options) {
  mesh::Mesh out;
  // A material for each yarn that is used, in the pattern's yarn order.
  std::vector<int> material_of(pattern.yarns.size(), -1);
  for (const CurvePiece& p : pieces) material_of[p.path.yarn] = 0;
  for (std::size_t y = 0; y < pattern.yarns.size(); ++y) {
    if (material_of[y] < 0) continue;
    material_of[y] = static_cast<int>(out.materials.size());
    const glm::vec3 colour = linear_rgb(pattern.yarns[y].color);
    out.materials.push_back({pattern.yarns[y].id, colour, colour, 0.5f});
  }
  const mesh::Mode mode = primitive_mode(options.view);
  if (mode == mesh::Mode::line_strip) {
    // glTF has no primitive restart: a line strip per piece.
    for (const CurvePiece& p : pieces) {
      mesh::Primitive prim;
      prim.material = material_of[p.path.yarn];
      prim.mode = mode;
      for (const auto& o : p.frames.origin) {
        prim.indices.push_back(static_cast<std::uint32_t>(prim.positions.size()));
        prim.positions.emplace_back(o);
      }
      out.primitives.push_back(std::move(prim));
    }
    return out;
  }
  auto sides_of = [&](const Yarn& yarn) {
    // A ply is a fraction of the yarn's width: about half the sides do.
    return yarn.section == Section::plied ? std::max(5, (options.sides + 1) / 2) : options.sides;
  };
  auto strand_count = [](const Yarn& yarn) { return yarn.section == Section::plied ? yarn.plies : 1; };
  if (mode == mesh::Mode::triangles) {
    // Every piece's place in its yarn's primitive is known from its sample count: the
    // arrays are sized once and each piece's tubes are written straight into them, in
    // parallel, with the same bytes for any thread count.
    std::vector<std::size_t> vertex_at(pieces.size()), index_at(pieces.size());
    std::vector<std::size_t> vertices(pattern.yarns.size(), 0), indices(pattern.yarns.size(), 0);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const int y = pieces[i].path.yarn;
      const Yarn& yarn = pattern.yarns[y];
      const auto size = sweep::tube_size(pieces[i].samples.size(), sides_of(yarn), static_cast<std::size_t>(strand_count(yarn)));
      vertex_at[i] = vertices[y];
      index_at[i] = indices[y];
      vertices[y] += size.vertices;
      indices[y] += size.indices;
    }
    std::vector<mesh::Primitive> by_yarn(pattern.yarns.size());
    for (std::size_t y = 0; y < by_yarn.size(); ++y) {  // one allocation per array
      by_yarn[y].material = material_of[y];
      by_yarn[y].mode = mode;
      by_yarn[y].positions.resize(vertices[y]);
      by_yarn[y].normals.resize(vertices[y]);
      by_yarn[y].uvs.resize(vertices[y]);
      by_yarn[y].indices.resize(indices[y]);
    }
    parallel_for(pieces.size(), thread_count(options.threads), [&](std::size_t i) {
      const CurvePiece& p = pieces[i];
      const Yarn& yarn = pattern.yarns[p.path.yarn];
      const auto strands = sweep::strands(p.frames, p.arc_length, cross_section(yarn));
      sweep::write_tubes(strands, p.arc_length, sides_of(yarn), by_yarn[p.path.yarn], vertex_at[i], index_at[i]);
    });
    for (auto& prim : by_yarn) {
      if (!prim.indices.empty()) out.primitives.push_back(std::move(prim));
    }
    return out;
  }
  // Wireframes: each piece's lines, then one primitive per yarn, the pieces in order.
  std::vector<mesh::Primitive> lines(pieces.size());
  parallel_for(pieces.size(), thread_count(options.threads), [&](std::size_t i) {
    const CurvePiece& p = pieces[i];
    const Yarn& yarn = pattern.yarns[p.path.yarn];
    lines[i].mode = mode;
    sweep::append_wireframe(sweep::strands(p.frames, p.arc_length, cross_section(yarn)), sides_of(yarn), lines[i]);
  });
  for (std::size_t y = 0; y < pattern.yarns.size(); ++y) {
    mesh::Primitive prim;
    prim.material = material_of[y];
    prim.mode = mode;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (pieces[i].path.yarn != static_cast<int>(y)) continue;
      const auto offset = static_cast<std::uint32_t>(prim.positions.size());
      prim.positions.insert(prim.positions.end(), lines[i].positions.begin(), lines[i].positions.end());
      for (std::uint32_t index : lines[i].indices) prim.indices.push_back(index + offset);
    }
    if (!prim.indices.empty()) out.primitives.push_back(std::move(prim));
  }
  return out;
}

}  // namespace

Fabric compile(const Pattern& pattern, const CompileOptions& options) {
  assert(options.sides >= 3 && options.chord_tolerance > 0.0);
  std::uint64_t loops = static_cast<std::uint64_t>(pattern.cast_on);
  for (const Course& c : pattern.courses) loops += c.ops.size();
  if (loops > max_loops)
    throw CompileError(where_it_passes(pattern, static_cast<double>(max_loops) / static_cast<double>(loops)) + "the fabric has " + std::to_string(loops) +
                       " loops; knitc lays out at most " + std::to_string(max_loops) + " (knitc check and chart take more)");
  // Before sampling, a cautious estimate (half the rings the plain loop needs, about 55
  // at 1% tolerance, scaling as tolerance^-1/2) turns away the hopeless in a moment.
  const double rings_per_loop = 0.5 * 55.0 * std::sqrt(0.01 / options.chord_tolerance);
  if (static_cast<double>(loops) * rings_per_loop * (options.sides + 1) > static_cast<double>(max_vertices))
    throw CompileError(where_it_passes(pattern, 1.0) + std::to_string(loops) + " loops at this quality make a mesh " +
                       "over knitc's limit of " + std::to_string(max_vertices / 1'000'000) +
                       " million vertices; knit a smaller piece, or use --quality draft");
  layout::Layout layout;
  try {
    layout = layout::lay_out(pattern);
  } catch (const std::invalid_argument& e) {  // the runtime checks counts first: a caller's bug
    throw CompileError(where_it_passes(pattern, 1.0) + e.what());
  }
  return compile(pattern, std::move(layout), options);
}

Fabric compile(const Pattern& pattern, layout::Layout layout, const CompileOptions& options) {
  Fabric fabric;
  fabric.layout = std::move(layout);
  auto paths = yarn_paths::trace(fabric.layout, options.loop_model);
  // The mesh's size from the data points' polygons, before any curve is fitted or
  // relaxed: a fabric far past the limit is turned away in a moment, not after a minute.
  double estimate = 0.0;
  for (const auto& piece : paths) {
    const Yarn& yarn = pattern.yarns[piece.yarn];
    const double samples = sweep::estimate_samples(piece.data_points, options.chord_tolerance * yarn.diameter,
                                                   0.5 * yarn.diameter, max_sample_step(yarn));
    estimate += static_cast<double>(strand_count(yarn)) * (samples + 2.0) * (options.sides + 1);
  }
  // (On the library's fabrics the estimate is 0.87 to 1.05 of the count.)
  if (estimate > static_cast<double>(max_vertices))
    throw CompileError(where_it_passes(pattern, static_cast<double>(max_vertices) / estimate) + "the mesh would have about " + std::to_string(static_cast<long long>(estimate / 1e6)) +
                       " million vertices, over knitc's limit of " + std::to_string(max_vertices / 1'000'000) +
                       " million; knit a smaller piece, or use --quality draft");
  if (options.relax) {
    if (options.progress) options.progress("relax", 0.0);
    const auto start = std::chrono::steady_clock::now();
    std::vector<double> diameter;
    for (const Yarn& y : pattern.yarns) diameter.push_back(y.diameter);
    relax::Options ro = options.relaxation;
    ro.threads = options.threads;
    auto relaxed = relax::relax(fabric.layout, relax::refine(std::move(paths), diameter, ro.spacing), diameter, ro);
    paths = std::move(relaxed.pieces);
    fabric.relaxed = true;
    fabric.relaxation = relaxed.stats;
    fabric.relax_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options.progress) options.progress("relax", 1.0);
  }
  fabric.pieces.resize(paths.size());
  std::atomic<std::size_t> traced{0};
  const std::size_t step = std::max<std::size_t>(1, paths.size() / 100);
  parallel_for(paths.size(), thread_count(options.threads), [&](std::size_t i) {
    fabric.pieces[i] = trace_curve(std::move(paths[i]), pattern, options);
    const std::size_t done = ++traced;
    if (options.progress && done % step == 0) options.progress("curves", static_cast<double>(done) / static_cast<double>(paths.size()));
  });
  if (options.progress) options.progress("mesh", 0.0);
  // The mesh's size is known from the samples: refuse what no machine of ours holds (and
  // what 32-bit indices cannot address) before allocating it.
  std::uint64_t vertices = 0;
  for (const CurvePiece& p : fabric.pieces)
    vertices += strand_count(pattern.yarns[p.path.yarn]) * (p.samples.size() + 2) * static_cast<std::uint64_t>(options.sides + 1);
  if (vertices > max_vertices)
    throw CompileError(where_it_passes(pattern, static_cast<double>(max_vertices) / static_cast<double>(vertices)) + "the mesh would have " + std::to_string(vertices / 1'000'000) +
                       " million vertices, over knitc's limit of " + std::to_string(max_vertices / 1'000'000) +
                       " million; knit a smaller piece, or use --quality draft");
  fabric.mesh = build_mesh(pattern, fabric.pieces, options);
  if (options.progress) options.progress("mesh", 1.0);
  return fabric;
}

}  // namespace knitc
