#include "stats.hpp"

#include <algorithm>
#include <cstddef>

#include <fmt/core.h>
#include <glm/geometric.hpp>

#include "measure/measure.hpp"
#include "mesh/bounds.hpp"
#include "tiles/tiles.hpp"

namespace {

// The relaxed yarns' pressed sections (relax/press.hpp): how much of the yarn is
// flattened, and how flat.
void print_sections(const knitc::Fabric& fabric) {
  std::size_t points = 0, pressed = 0;
  double sum = 0.0, flattest = 1.0;
  for (const auto& piece : fabric.pieces)
    for (const auto& v : piece.path.pressed) {
      ++points;
      const double aspect = 1.0 - glm::length(v);
      if (aspect >= 0.99) continue;
      ++pressed;
      sum += aspect;
      flattest = std::min(flattest, aspect);
    }
  if (points == 0) return;
  if (pressed == 0) {
    fmt::print(stderr, "sections    round (no yarn pressed)\n");
    return;
  }
  fmt::print(stderr, "sections    {:.0f}% of the yarn pressed flatter than 0.99; mean aspect there {:.2f}, flattest {:.2f}\n",
             100.0 * static_cast<double>(pressed) / static_cast<double>(points), sum / static_cast<double>(pressed), flattest);
}

}  // namespace

void print_stats(const knitc::Pattern& pattern, const knitc::Fabric& fabric, double relax_seconds) {
  std::size_t vertices = 0, elements = 0;
  for (const auto& p : fabric.mesh.primitives) {
    vertices += p.positions.size();
    elements += p.indices.size();
  }
  const knitc::mesh::Bounds box = knitc::mesh::bounds(fabric.mesh);
  const glm::vec3 lo = box.min, hi = box.max;
  std::size_t samples = 0;
  for (const auto& piece : fabric.pieces) samples += piece.samples.size();
  fmt::print(stderr, "pattern     {}\n", pattern.name);
  fmt::print(stderr, "courses     {}\nwales       {}\nloops       {}\n", fabric.layout.courses, fabric.layout.wales,
             fabric.layout.loops.size());
  fmt::print(stderr, "yarn pieces {}\nsamples     {}\nvertices    {}\nindices     {}\n", fabric.pieces.size(), samples,
             vertices, elements);
  const knitc::tiles::Drawn drawn = knitc::tiles::drawn(fabric.mesh);
  fmt::print(stderr, "mesh        {}\n", fabric.mesh_choice);
  if (fabric.instanced)
    fmt::print(stderr, "drawn       {} triangles, {} vertices ({} stored, {} in the tile, placed {} times)\n", drawn.triangles,
               drawn.vertices, drawn.stored_vertices, drawn.stored_vertices - vertices, fabric.mesh.instanced.front().translations.size());
  fmt::print(stderr, "density     {} sides, tolerance {:g} d; {}\n", fabric.density.sides, fabric.density.chord_tolerance,
             fabric.density_choice);
  for (const knitc::mesh::Material& m : fabric.mesh.materials)
    if (m.textures.normal >= 0) {
      const knitc::mesh::Image& image = fabric.mesh.images[static_cast<std::size_t>(m.textures.normal)];
      fmt::print(stderr, "textures    yarn {}: normal, occlusion and colour maps of {} x {}, a tile every {:.2f} mm of yarn\n",
                 m.name, image.width, image.height, m.textures.repeat.x);
    }
  if (!fabric.layout.loops.empty())
    fmt::print(stderr, "per loop    {:.0f} triangles drawn\n", static_cast<double>(drawn.triangles) / static_cast<double>(fabric.layout.loops.size()));
  fmt::print(stderr, "bounds mm   [{:.3f}, {:.3f}, {:.3f}] .. [{:.3f}, {:.3f}, {:.3f}]\n", lo.x, lo.y, lo.z, hi.x, hi.y,
             hi.z);
  const auto m = knitc::measure::measure(pattern, fabric.layout, fabric.pieces);
  for (std::size_t y = 0; y < pattern.yarns.size(); ++y)
    fmt::print(stderr, "yarn {:<7} {:.1f} mm long; free diameter {:.3f} mm, core {:.3f} mm\n", pattern.yarns[y].id,
               m.yarn_length[y], pattern.yarns[y].diameter, pattern.yarns[y].core_diameter);
  fmt::print(stderr, "penetration {:.3f} d (deepest overlap of two yarn tubes; the seed paper's loop overlaps by about 0.85 d)\n",
             m.deepest_penetration);
  fmt::print(stderr, "cores       {:.3f} core d (deepest overlap of two yarn cores, which never compress)\n",
             m.deepest_core_penetration);
  // A coarse density (a fabric seen whole) cuts the yarn's bends by up to its chord error:
  // the overlaps are the written mesh's, not the relaxed curves' (go-newStar.k at 0.5 d:
  // cores 0.658 core d; at --quality normal 0.000).
  if (fabric.density.chord_tolerance > knitc::density(knitc::Quality::draft).chord_tolerance)
    fmt::print(stderr, "            both measured on the mesh's centrelines, which cut the curves' bends by up to {:.2f} d at this density; "
                       "--quality normal measures the curves within 0.01 d\n",
               fabric.density.chord_tolerance);
  fmt::print(stderr, "tightest bend {:.3f} tube radii (smallest radius of curvature over the tube's radius)\n", m.tightest_bend);
  fmt::print(stderr, "frame turn  {:.1f} deg (largest between consecutive sweep frames)\n", m.largest_frame_turn);
  if (const auto shape = knitc::measure::loop_shape(fabric.layout, fabric.pieces); shape.loops > 0)
    fmt::print(stderr, "loop shape  l {:.2f} mm, wale spacing {:.2f} mm, course spacing {:.2f} mm: kc {:.2f}, kw {:.2f}, kc/kw {:.2f} ({} inner loops)\n",
               shape.loop_length, shape.wale_spacing, shape.course_spacing, shape.kc, shape.kw, shape.kc / shape.kw, shape.loops);
  if (const auto shape = knitc::measure::loop_shape(fabric.layout, fabric.pieces); shape.loops > 0)
    fmt::print(stderr, "in the plane {:.2f} mm across a wale, {:.2f} mm up a course; centrelines {:.2f} mm deep\n", shape.wale_pitch,
               shape.course_pitch, shape.depth);
  if (fabric.relaxed) {
    const auto& r = fabric.relaxation;
    fmt::print(stderr, "relaxation  {} iterations, {:.2f} s; cores overlap {:.3f} core d before, {:.3f} after; lengths changed <= {:.2f}%; "
               "pressed shells squeezed {:.0f}% on average\n",
               r.iterations, relax_seconds, r.start_overlap, r.end_overlap, 100.0 * r.length_change, 100.0 * r.compression);
    if (r.repeat_wales > 0 && r.strips > 0)
      fmt::print(stderr,
                 "by repeat   a tile of {} x {} loops relaxed in {} sweeps, tiled; {:.0f}% of the yarn held; the edges' {} bands relaxed as "
                 "strips periodic along them (at most {} sweeps), {:.0f}% of the yarn; the corners in {} sweeps\n",
                 r.repeat_wales, r.repeat_courses, r.repeat_iterations, 100.0 * r.held_share, r.strips, r.strip_iterations,
                 100.0 * r.strip_share, r.iterations);
    else if (r.repeat_wales > 0)
      fmt::print(stderr, "by repeat   a tile of {} x {} loops relaxed in {} sweeps, tiled; {:.0f}% of the yarn held, the rest relaxed in {} sweeps\n",
                 r.repeat_wales, r.repeat_courses, r.repeat_iterations, 100.0 * r.held_share, r.iterations);
    if (r.repeat_wales > 0 && r.morph_sweeps > 0)
      fmt::print(stderr, "by repeat   the edges' relaxation carried the yarn to the tile's places over {} sweeps (jumped there, it "
                 "would lie deeper into itself than laid)\n", r.morph_sweeps);
    if (fabric.tiling_refused)
      fmt::print(stderr, "by repeat   refused: tiled, a yarn passed through another; relaxed whole instead\n");
    print_sections(fabric);
    if (fabric.crossings_checked) {
      const auto& x = fabric.crossings;
      fmt::print(stderr, "crossings   {} kept, {} flipped; {} lost and {} new, of which {} and {} alone where the yarns touched "
                 "(a yarn passed through another), {} and {} by a yarn's end (a tail drawn back or out); {} at one height{}\n",
                 x.kept, x.flipped, x.lost, x.found, x.lost_alone_touching, x.found_alone_touching, x.lost_at_end, x.found_at_end, x.ties,
                 x.copies_left_out ? "; counted where the yarn is not a copy of the tile's or an edge strip's first (the copies cross as it does)" : "");
    }
  } else {
    fmt::print(stderr, "relaxation  off\n");
  }
  if (m.tightest_bend < 1.0)
    fmt::print(stderr, "knitc: warning: a yarn bends tighter than its own radius ({:.2f} tube radii): the tube folds on itself there\n",
               m.tightest_bend);
}

