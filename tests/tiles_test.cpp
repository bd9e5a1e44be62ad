// Instanced repeats (compiler/tiles): a relaxed fabric's repeat meshed once and placed,
// meeting its neighbours and the plain edges ring for ring; the policy that picks it; and
// the files: each flattened instance on its tile, read back from what was written.
#include <cmath>
#include <cstring>
#include <unordered_map>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <tiny_gltf.h>

#include "mesh/bounds.hpp"
#include "support.hpp"
#include "tiles/tiles.hpp"
#include "writers/writers.hpp"

namespace knitc {
namespace {

CompileOptions relaxed_options(Instancing instancing) {
  CompileOptions o;
  o.relax = true;
  o.sides = 6;
  o.chord_tolerance = 0.05;
  o.instancing = instancing;
  return o;
}

// The 24 x 28 jersey relaxed by repeat, instanced (on every core): compiled once for the
// tests that read it.
const Pattern& small_jersey() {
  static const Pattern p = test::jersey(24, 28);
  return p;
}
const Fabric& instanced_jersey() {
  static const Fabric f = compile(small_jersey(), relaxed_options(Instancing::instance));
  return f;
}

// Vertices welded where they lie within `tolerance` (mm) of each other: a vertex's weld is
// the first vertex found within reach (a grid of cells the tolerance wide, and their
// neighbours, is searched).
std::vector<std::uint32_t> weld(const std::vector<glm::vec3>& positions, float tolerance) {
  struct Key {
    long x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct Hash {
    std::size_t operator()(const Key& k) const { return std::hash<long>()(k.x * 73856093L ^ k.y * 19349663L ^ k.z * 83492791L); }
  };
  std::unordered_map<Key, std::vector<std::uint32_t>, Hash> grid;
  std::vector<std::uint32_t> out(positions.size());
  for (std::uint32_t i = 0; i < positions.size(); ++i) {
    const glm::vec3& p = positions[i];
    const Key k{std::lround(std::floor(p.x / tolerance)), std::lround(std::floor(p.y / tolerance)), std::lround(std::floor(p.z / tolerance))};
    out[i] = i;
    bool found = false;
    for (long dx = -1; dx <= 1 && !found; ++dx)
      for (long dy = -1; dy <= 1 && !found; ++dy)
        for (long dz = -1; dz <= 1 && !found; ++dz) {
          const auto it = grid.find({k.x + dx, k.y + dy, k.z + dz});
          if (it == grid.end()) continue;
          for (const std::uint32_t j : it->second)
            if (glm::distance(positions[j], p) <= tolerance) {
              out[i] = out[j];
              found = true;
              break;
            }
        }
    grid[k].push_back(i);
  }
  return out;
}

TEST(Tiles, ARelaxedRepeatIsPlacedAcrossTheInteriorAndTheEdgesStayPlain) {
  const Fabric& f = instanced_jersey();
  ASSERT_TRUE(f.instanced) << f.mesh_choice;
  EXPECT_EQ(f.mesh_choice.rfind("instanced (--instance); ", 0), 0u) << f.mesh_choice;
  ASSERT_EQ(f.mesh.instanced.size(), 1u);
  const auto& tiles = f.mesh.instanced[0];
  // The 4 x 4 tile: 24 x 28 loops hold 5 x 6 cells from (2, 2); those held as tiled (the
  // relaxation frees three loops round anything untiled) repeat exactly.
  EXPECT_GE(tiles.translations.size(), 4u);
  EXPECT_EQ(tiles.primitives.size(), 1u);
  EXPECT_FALSE(f.mesh.primitives.empty());
  // Drawn, it spans the box the same fabric meshed whole does (the same curves, cut), and
  // each placed tile is about one period from the next. The rings round the curves turn
  // differently in the two (a tile's seam is set at its cut): where a 6-sided ring of the
  // 1 mm yarn shows a vertex in one and a side in the other, the box differs by
  // r (1 - cos 30 deg) = 0.067 mm.
  const Fabric whole = compile(small_jersey(), relaxed_options(Instancing::automatic));
  ASSERT_FALSE(whole.instanced);
  ASSERT_EQ(whole.pieces.size(), f.pieces.size());
  for (std::size_t i = 0; i < f.pieces.size(); ++i)
    ASSERT_EQ(whole.pieces[i].curve.curve.points, f.pieces[i].curve.curve.points) << "piece " << i;
  const mesh::Bounds box = mesh::bounds(f.mesh), whole_box = mesh::bounds(whole.mesh);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(box.min[k], whole_box.min[k], 0.07);
    EXPECT_NEAR(box.max[k], whole_box.max[k], 0.07);
  }
  std::vector<float> xs;
  for (const auto& t : tiles.translations) xs.push_back(t.x);
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end(), [](float a, float b) { return std::abs(a - b) < 1e-3f; }), xs.end());
  ASSERT_GE(xs.size(), 2u);
  EXPECT_NEAR(xs[1] - xs[0], 4 * 3.94, 0.3);
}

TEST(Tiles, TilesAndEdgesMeetRingForRingWithoutAGap) {
  const Fabric& f = instanced_jersey();
  ASSERT_TRUE(f.instanced);
  const mesh::Mesh flat = tiles::flatten(f.mesh, 0);
  ASSERT_EQ(flat.primitives.size(), 1u);
  const mesh::Primitive& p = flat.primitives[0];
  EXPECT_EQ(p.indices.size() / 3, tiles::drawn(f.mesh).triangles);
  // Welded within a micrometre, the yarn is one closed surface: every edge is shared by
  // exactly two triangles (a gap or a twisted seam at a cut leaves edges used once).
  const auto id = weld(p.positions, 1e-3f);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (std::size_t t = 0; t < p.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      std::uint32_t a = id[p.indices[t + e]], b = id[p.indices[t + (e + 1) % 3]];
      if (a > b) std::swap(a, b);
      ++uses[{a, b}];
    }
  std::size_t open = 0;
  for (const auto& [edge, n] : uses) open += n != 2;
  EXPECT_EQ(open, 0u);
  // Where two vertices meet, they are one ring's (the same normal and texture, u a whole
  // number of mm at a cut) or a ring's and its cap's (normals square to each other).
  std::size_t cuts = 0;
  std::vector<std::uint32_t> first(p.positions.size(), UINT32_MAX);
  for (std::uint32_t v = 0; v < p.positions.size(); ++v) {
    const std::uint32_t w = first[id[v]];
    if (w == UINT32_MAX) {
      first[id[v]] = v;
      continue;
    }
    const float along = glm::dot(p.normals[v], p.normals[w]);
    if (std::abs(along) < 0.2f) continue;  // a cap's rim
    EXPECT_GT(along, 0.999f) << "vertex " << v << " at " << p.positions[v].x << ", " << p.positions[v].y;
    const float dv = std::abs(p.uvs[v].y - p.uvs[w].y);
    EXPECT_TRUE(dv < 1e-4f || std::abs(dv - 1.0f) < 1e-4f);
    if (std::abs(p.uvs[v].x - p.uvs[w].x) > 1e-3f) {
      ++cuts;
      const float frac_v = p.uvs[v].x - std::round(p.uvs[v].x), frac_w = p.uvs[w].x - std::round(p.uvs[w].x);
      EXPECT_NEAR(frac_v, 0.0f, 1e-3f);
      EXPECT_NEAR(frac_w, 0.0f, 1e-3f);
    }
  }
  EXPECT_GT(cuts, 100u);  // the cuts were seen
}

TEST(Tiles, TheSameBytesForAnyThreadCount) {
  CompileOptions one = relaxed_options(Instancing::instance);
  one.threads = 1;
  const Fabric a = compile(small_jersey(), one);
  const Fabric& b = instanced_jersey();  // on every core
  EXPECT_EQ(writers::glb(a.mesh, "t"), writers::glb(b.mesh, "t"));
  // Compressed, each view encoded on its own thread: the same bytes again.
  EXPECT_EQ(writers::glb(a.mesh, "t", {true, true, 1}), writers::glb(b.mesh, "t", {true, true, 2}));
}

TEST(Tiles, ThePolicySaysWhatItChoseAndWhy) {
  // Small: flat, within the size written flat.
  const Fabric small = compile(test::jersey(12, 12), relaxed_options(Instancing::automatic));
  EXPECT_FALSE(small.instanced);
  EXPECT_NE(small.mesh_choice.find("within the 1.0 million knitc writes flat"), std::string::npos) << small.mesh_choice;
  EXPECT_TRUE(small.mesh.instanced.empty());
  // Asked for, but not relaxed: no repeat was tiled, and it says so.
  CompileOptions unrelaxed = relaxed_options(Instancing::instance);
  unrelaxed.relax = false;
  const Fabric plain = compile(small_jersey(), unrelaxed);
  EXPECT_FALSE(plain.instanced);
  EXPECT_NE(plain.mesh_choice.find("not instanced: not relaxed"), std::string::npos) << plain.mesh_choice;
  // In the round: not tiled.
  const Pattern round = runtime::run_pattern(
                            "pattern { gauge = { loop_width = 4, loop_height = 4.2, thickness = 2 }, yarns = { A = { diameter = 1 } }, "
                            "knitting = \"round\" }\ncast_on(16)\nrows(10, \"k\")\n",
                            "round.lua")
                            .pattern;
  const Fabric tube = compile(round, relaxed_options(Instancing::instance));
  EXPECT_FALSE(tube.instanced);
  EXPECT_NE(tube.mesh_choice.find("work in the round is not tiled"), std::string::npos) << tube.mesh_choice;
  // --flatten: every instance written out, the same triangles as drawn instanced.
  const Fabric flat = compile(small_jersey(), relaxed_options(Instancing::flatten));
  EXPECT_TRUE(flat.mesh.instanced.empty());
  EXPECT_EQ(flat.mesh_choice.rfind("flat (--flatten): every instance written out", 0), 0u) << flat.mesh_choice;
  EXPECT_EQ(tiles::drawn(flat.mesh).triangles, tiles::drawn(instanced_jersey().mesh).triangles);
}

TEST(Tiles, TheDensityFollowsHowLargeALoopIsInAFullView) {
  const auto swatch = density_for_view(layout::lay_out(test::jersey(20, 24)));
  EXPECT_EQ(swatch.density.sides, 12);  // a swatch close-up: normal quality
  EXPECT_GT(swatch.loop_pixels, 40.0);
  EXPECT_TRUE(swatch.maps);
  const layout::Layout front_layout = layout::lay_out(test::jersey(150, 250));
  const auto front = density_for_view(front_layout);
  EXPECT_LT(front.loop_pixels, 16.0);  // a sweater front: a loop is a few pixels
  // Taller than wide, it fits its height into the view's 1080 pixels, not its 1920.
  EXPECT_NEAR(front.loop_pixels, 1080.0 * front_layout.loop_width / (front_layout.courses * front_layout.course_spacing), 1e-9);
  EXPECT_EQ(front.density.sides, 3);  // a triangle's chord error, 25% of d, within the 42% along the yarn
  EXPECT_NEAR(front.density.chord_tolerance, 2.0 / front.loop_pixels, 1e-12);
  EXPECT_FALSE(front.maps);  // its plies under a pixel
  const auto middle = density_for_view(layout::lay_out(test::jersey(80, 60)));
  EXPECT_EQ(middle.density.sides, 8);
  EXPECT_TRUE(middle.maps);
  // Between: a loop of 14.8 pixels takes 2/14.8 = 13.5% along the yarn, past a square's
  // 15%, so the ring is a pentagon's (10%).
  const auto between = density_for_view(layout::lay_out(test::jersey(120, 80)));
  ASSERT_GT(between.loop_pixels, 14.5);
  ASSERT_LT(between.loop_pixels, 15.0);
  EXPECT_EQ(between.density.sides, 5);
  // A close-up of a few loops across: the rule for its loop's pixels.
  EXPECT_EQ(density_for_loop_pixels(69.0).density.sides, 12);
  EXPECT_EQ(density_for_loop_pixels(4.76).density.sides, front.density.sides);
}

// Before the layout, a fabric is refused by the fewest vertices it could have. From the
// view, that is at the coarsest density the view can choose, not at the default's 12
// sides: a fabric the view meshes at 4 sides is not turned away as if at normal quality.
TEST(Tiles, TheBoundBeforeTheLayoutTakesTheCoarsestDensityTheViewCanChoose) {
  const Pattern p = test::jersey(150, 120);
  CompileOptions given;  // 12 sides, 1%
  CompileOptions view = given;
  view.density_from_view = true;
  CompileOptions coarsest = given;
  coarsest.sides = coarsest_view_density.sides;
  coarsest.chord_tolerance = coarsest_view_density.chord_tolerance;
  EXPECT_DOUBLE_EQ(least_vertices(p, view), least_vertices(p, coarsest));
  EXPECT_LT(least_vertices(p, view), least_vertices(p, given) / 5.0);
  // Still a lower bound: the fabric as the view meshes it has more.
  const Fabric fabric = compile(p, view);
  EXPECT_EQ(fabric.density.sides, density_for_view(fabric.layout).density.sides);
  EXPECT_GT(static_cast<double>(tiles::drawn(fabric.mesh).vertices), least_vertices(p, view));
}

// The files, as written by the program and read by tinygltf: the instanced file's tile
// placed by its translations is the flattened file's triangles, within a micrometre.
TEST(Tiles, EachFlattenedInstanceLiesOnItsTileInTheFiles) {
  const auto dir = test::glb_dir();
  const std::string script = (test::scratch_dir("tiles") / "jersey.lua").string();
  test::write_text(script, test::jersey_source(24, 28));
  const std::string instanced = (dir / "tiles_instanced.glb").string(), flattened = (dir / "tiles_flattened.glb").string();
  const auto a = test::run_knitc("build '" + script + "' -o '" + instanced + "' --instance --no-compress --quality draft -q");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const auto b = test::run_knitc("build '" + script + "' -o '" + flattened + "' --flatten --quality draft -q");
  ASSERT_EQ(b.exit_code, 0) << b.err;
  // The program's own compressed default for an instanced file goes to the validator too.
  const auto c = test::run_knitc("build '" + script + "' -o '" + (dir / "tiles_compressed.glb").string() + "' --instance -q");
  ASSERT_EQ(c.exit_code, 0) << c.err;
  tinygltf::TinyGLTF loader;
  tinygltf::Model mi, mf;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadBinaryFromFile(&mi, &err, &warn, instanced)) << err;
  ASSERT_TRUE(loader.LoadBinaryFromFile(&mf, &err, &warn, flattened)) << err;
  auto floats = [](const tinygltf::Model& m, int accessor) {
    const auto& acc = m.accessors[static_cast<std::size_t>(accessor)];
    const auto& view = m.bufferViews[static_cast<std::size_t>(acc.bufferView)];
    EXPECT_EQ(acc.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
    std::vector<glm::vec3> out(acc.count);
    std::memcpy(out.data(), m.buffers[0].data.data() + view.byteOffset + acc.byteOffset, acc.count * sizeof(glm::vec3));
    return out;
  };
  ASSERT_EQ(mi.nodes.size(), 2u);
  ASSERT_EQ(mi.extensionsRequired, std::vector<std::string>{"EXT_mesh_gpu_instancing"});
  const auto& ext = mi.nodes[1].extensions.at("EXT_mesh_gpu_instancing");
  const auto translations = floats(mi, ext.Get("attributes").Get("TRANSLATION").GetNumberAsInt());
  // The edges are one instance of their own mesh, in place (one shader program for the
  // whole fabric in a renderer: gltf.cpp).
  ASSERT_TRUE(mi.nodes[0].extensions.count("EXT_mesh_gpu_instancing"));
  const auto edge_place = floats(mi, mi.nodes[0].extensions.at("EXT_mesh_gpu_instancing").Get("attributes").Get("TRANSLATION").GetNumberAsInt());
  ASSERT_EQ(edge_place.size(), 1u);
  EXPECT_EQ(edge_place[0], glm::vec3(0.0f));
  const auto edges = floats(mi, mi.meshes[0].primitives[0].attributes.at("POSITION"));
  const auto tile = floats(mi, mi.meshes[static_cast<std::size_t>(mi.nodes[1].mesh)].primitives[0].attributes.at("POSITION"));
  ASSERT_EQ(mf.meshes.size(), 1u);
  const auto all = floats(mf, mf.meshes[0].primitives[0].attributes.at("POSITION"));
  ASSERT_EQ(all.size(), edges.size() + translations.size() * tile.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < translations.size(); ++k)
    for (std::size_t v = 0; v < tile.size(); ++v)
      worst = std::max(worst, static_cast<double>(glm::distance(all[edges.size() + k * tile.size() + v], tile[v] + translations[k])));
  EXPECT_LT(worst, 1e-6);  // metres
}

TEST(Tiles, TheFlagsAreExclusive) {
  const auto r = test::run_knitc("build patterns/jersey.lua -o /dev/null --flatten --instance");
  EXPECT_EQ(r.exit_code, 2) << r.err;
}

}  // namespace
}  // namespace knitc
