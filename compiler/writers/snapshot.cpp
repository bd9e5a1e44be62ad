#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

#include "mesh/bounds.hpp"
#include "writers/writers.hpp"

namespace knitc::writers {

namespace {

// FNV-1a, 64 bits: small, stable, no dependency.
struct Fnv1a {
  std::uint64_t state = 0xcbf29ce484222325ull;
  void add(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) {
      state ^= (v >> (8 * i)) & 0xffu;
      state *= 0x100000001b3ull;
    }
  }
};

std::int64_t micrometres(double mm) { return static_cast<std::int64_t>(std::llround(mm * 1000.0)); }

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v == 0.0 ? 0.0 : v);  // no "-0.000"
  return buf;
}

}  // namespace

std::string snapshot(const Pattern& pattern, const Fabric& fabric, const measure::FabricMeasures& m) {
  std::string out = "knitc snapshot 2\n";
  out += "pattern     " + pattern.name + "\n";
  out += "courses     " + std::to_string(fabric.layout.courses) + "\n";
  out += "wales       " + std::to_string(fabric.layout.wales) + "\n";
  out += "loops       " + std::to_string(fabric.layout.loops.size()) + "\n";
  out += "pieces      " + std::to_string(fabric.pieces.size()) + "\n";
  for (std::size_t y = 0; y < pattern.yarns.size(); ++y)
    out += "yarn " + pattern.yarns[y].id + " mm  " + fixed(m.yarn_length[y], 3) + "\n";
  out += "penetration " + fixed(m.deepest_penetration, 3) + " d\n";
  out += "tightest bend " + fixed(m.tightest_bend, 3) + " tube radii\n";
  out += "frame turn  " + fixed(m.largest_frame_turn, 3) + " deg\n";
  // The relaxation's figures, but not its time: a snapshot is the same on every run.
  if (fabric.relaxed)
    out += "relaxation  " + std::to_string(fabric.relaxation.iterations) + " iterations, overlap " +
           fixed(fabric.relaxation.start_overlap, 3) + " -> " + fixed(fabric.relaxation.end_overlap, 3) + " d, length " +
           fixed(100.0 * fabric.relaxation.length_change, 2) + "%\n";
  else
    out += "relaxation  off\n";
  if (fabric.crossings_checked)
    out += "crossings   " + std::to_string(fabric.crossings.kept) + " kept, " +
           std::to_string(measure::passed_through(fabric.crossings)) + " passed through\n";
  std::size_t vertices = 0, elements = 0, triangles = 0;
  // The geometry's hash: every position to 1 micrometre, every index, primitive by primitive.
  Fnv1a hash;
  for (const mesh::Primitive& p : fabric.mesh.primitives) {
    hash.add(static_cast<std::uint64_t>(p.material));
    hash.add(static_cast<std::uint64_t>(p.mode));
    hash.add(p.positions.size());
    for (const auto& v : p.positions) {
      for (int k = 0; k < 3; ++k) hash.add(static_cast<std::uint64_t>(micrometres(v[k])));
    }
    for (std::uint32_t i : p.indices) hash.add(i);
    vertices += p.positions.size();
    elements += p.indices.size();
    if (p.mode == mesh::Mode::triangles) triangles += p.indices.size() / 3;
  }
  // An instanced tile's primitives once and its places: the drawn triangles count each.
  for (const mesh::Instances& group : fabric.mesh.instanced) {
    hash.add(group.translations.size());
    for (const auto& t : group.translations)
      for (int k = 0; k < 3; ++k) hash.add(static_cast<std::uint64_t>(micrometres(t[k])));
    for (const mesh::Primitive& p : group.primitives) {
      hash.add(static_cast<std::uint64_t>(p.material));
      hash.add(p.positions.size());
      for (const auto& v : p.positions)
        for (int k = 0; k < 3; ++k) hash.add(static_cast<std::uint64_t>(micrometres(v[k])));
      for (std::uint32_t i : p.indices) hash.add(i);
      vertices += p.positions.size();
      elements += p.indices.size();
      triangles += group.translations.size() * (p.indices.size() / 3);
    }
  }
  out += "mesh        " + fabric.mesh_choice + "\n";
  out += "density     " + std::to_string(fabric.density.sides) + " sides, tolerance " + fixed(fabric.density.chord_tolerance, 4) +
         " d, " + fabric.density_choice + "\n";
  out += "vertices    " + std::to_string(vertices) + "\n";
  out += "indices     " + std::to_string(elements) + "\n";
  out += "triangles   " + std::to_string(triangles) + "\n";
  if (const mesh::Bounds box = mesh::bounds(fabric.mesh); !box.empty) {
    out += "bounds mm   " + fixed(box.min.x, 3) + " " + fixed(box.min.y, 3) + " " + fixed(box.min.z, 3) + " .. " +
           fixed(box.max.x, 3) + " " + fixed(box.max.y, 3) + " " + fixed(box.max.z, 3) + "\n";
  }
  char h[32];
  std::snprintf(h, sizeof h, "%016llx", static_cast<unsigned long long>(hash.state));
  out += std::string("geometry    fnv1a64 ") + h + "\n";
  // A dyed yarn's colours, as the file holds them (8 bits a channel): where the runs fall.
  Fnv1a colours;
  bool dyed = false;
  for (const mesh::Primitive& p : fabric.mesh.primitives) {
    if (p.colors.empty()) continue;
    dyed = true;
    for (const auto& c : p.colors)
      for (int k = 0; k < 3; ++k) colours.add(static_cast<std::uint64_t>(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255.0f)));
  }
  if (dyed) {
    std::snprintf(h, sizeof h, "%016llx", static_cast<unsigned long long>(colours.state));
    out += std::string("colours     fnv1a64 ") + h + "\n";
  }
  // The baked maps (fibres/bake.hpp), every texel, and the tile each material repeats.
  if (!fabric.mesh.images.empty()) {
    Fnv1a maps;
    for (const mesh::Image& image : fabric.mesh.images) {
      maps.add(static_cast<std::uint64_t>(image.width));
      maps.add(static_cast<std::uint64_t>(image.height));
      for (unsigned char c : image.pixels) maps.add(c);
    }
    for (const mesh::Material& material : fabric.mesh.materials) maps.add(static_cast<std::uint64_t>(micrometres(material.textures.repeat.x)));
    std::snprintf(h, sizeof h, "%016llx", static_cast<unsigned long long>(maps.state));
    out += "textures    " + std::to_string(fabric.mesh.images.size()) + " maps, fnv1a64 " + h + "\n";
  }
  return out;
}

}  // namespace knitc::writers
