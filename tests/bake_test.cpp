// Baked textures (fibres/bake.hpp): the tile wraps both ways, the plies' crests face out
// and their crevices are occluded, a heather's colours take their shares of the colour map,
// the tangents the normal map needs run along the yarn with the bitangent round it, and
// the .glb carries the maps (read back by tinygltf, written to the validator's folder).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <glm/geometric.hpp>
#include <stb/stb_image.h>
#include <tiny_gltf.h>

#include "fibres/bake.hpp"
#include "mesh/tangents.hpp"
#include "trace.hpp"
#include "support.hpp"
#include "writers/writers.hpp"

namespace knitc {
namespace {

Pattern run(const std::string& yarn, int stitches = 4) {
  return runtime::run_pattern("pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\", " + yarn +
                                  " } }, knitting = \"flat\" }\ncast_on(" + std::to_string(stitches) +
                                  ")\nrow \"k\"\nrow \"p\"\nrow \"k\"\nbind_off()\n",
                              "t.lua")
      .pattern;
}

glm::dvec3 normal_at(const mesh::Image& m, int x, int y) {
  const std::size_t p = 3 * (static_cast<std::size_t>(y) * m.width + x);
  return glm::dvec3(m.pixels[p], m.pixels[p + 1], m.pixels[p + 2]) / 127.5 - 1.0;
}

// The mean step between neighbours across the tile's seam against that inside the tile.
double seam_ratio(const mesh::Image& m, bool along) {
  double seam = 0.0, inside = 0.0;
  const int n = along ? m.height : m.width;
  for (int k = 0; k < n; ++k) {
    const auto at = [&](int i) { return along ? normal_at(m, i, k) : normal_at(m, k, i); };
    const int last = (along ? m.width : m.height) - 1;
    seam += glm::length(at(0) - at(last));
    inside += glm::length(at(1) - at(0));
  }
  return seam / inside;
}

TEST(Bake, TheTileWrapsAlongAndRoundTheYarn) {
  for (const char* yarn : {"", "fibre = \"cotton\"", "section = \"plied\", plies = 3, twist = 30", "fibre = \"mohair\", fibre_twist = 0"}) {
    const fibres::BakedYarn b = fibres::bake(run(yarn).yarns[0]);
    ASSERT_EQ(b.normal.width, fibres::tile_along);
    ASSERT_EQ(b.normal.height, fibres::tile_round);
    EXPECT_LT(seam_ratio(b.normal, true), 2.0) << yarn;   // the last column runs on into the first
    EXPECT_LT(seam_ratio(b.normal, false), 2.0) << yarn;  // and the last row into the first
    EXPECT_GT(b.length, 0.0);
  }
}

TEST(Bake, PliesFaceOutAtTheirCrestsAndTheirCrevicesAreOccluded) {
  // A 2-ply wool (the preset: 15 turns / 10 cm): at u = 0 ply k's crest is at v = k / 2 and
  // the crevices between them at v = 1/4 and 3/4.
  const Yarn yarn = run("").yarns[0];
  const fibres::BakedYarn b = fibres::bake(yarn);
  EXPECT_NEAR(b.length, 100.0 / 15.0, 1e-9);
  // Means along the plies' helix (the plies turn once, against v, over the tile's length),
  // over every column, so the fibres' ridges average out: the normal's tilt round the yarn
  // and the sky seen, on the crests, on the plies' flanks (1/8 turn from a crest) and in
  // the crevices between them (1/4 turn).
  const int h = b.normal.height, w = b.normal.width;
  const auto mean = [&](int offset, bool tilt) {
    double sum = 0.0;
    int n = 0;
    for (int column = 0; column < w; ++column)
      for (int ply = 0; ply < 2; ++ply)
        for (int row = offset - 2; row <= offset + 2; ++row, ++n) {
          const int r = ((row + ply * h / 2 - column * h / w) % h + h) % h;
          sum += tilt ? std::abs(normal_at(b.normal, column, r).y)
                      : b.occlusion.pixels[static_cast<std::size_t>(r) * w + column] / 255.0;
        }
    return sum / n;
  };
  const double crest_tilt = mean(0, true), flank_tilt = 0.5 * (mean(h / 8, true) + mean(-h / 8, true));
  const double crest_open = mean(0, false), crevice_open = mean(h / 4, false);
  std::printf("tilt %.3f crest, %.3f flank; open %.3f crest, %.3f crevice\n", crest_tilt, flank_tilt, crest_open, crevice_open);
  EXPECT_LT(crest_tilt, 0.2);                // the crests face out, the fibres' ridges aside
  EXPECT_GT(flank_tilt, 2.0 * crest_tilt);   // the plies' flanks turn toward each other
  EXPECT_GT(crest_open, 0.9);                // the crests see nearly all the sky
  EXPECT_LT(crevice_open, crest_open - 0.05);
  // The surface fibres: ridges round each ply, as many as the texels allow.
  EXPECT_GE(b.fibres_round, 16);
  EXPECT_EQ(b.fibre_turns, 2);  // 25 turns / 10 cm over 6.7 mm
}

TEST(Bake, AYarnSweptAsPliesHasOnlyItsFibresInTheTile) {
  // Section "plied" draws the plies in the mesh: the tile is one ply's fibres, one fibre turn
  // long, with no crevice (every texel sees most of the sky).
  const fibres::BakedYarn b = fibres::bake(run("section = \"plied\", plies = 2, twist = 20").yarns[0]);
  EXPECT_NEAR(b.length, 100.0 / 25.0, 1e-9);
  int low = 0;
  for (unsigned char o : b.occlusion.pixels) low += o < 200;
  EXPECT_LT(low, static_cast<int>(b.occlusion.pixels.size()) / 50);
}

TEST(Bake, AHeathersColoursTakeTheirSharesOfTheColourMap) {
  const Yarn yarn = run("heather = { {\"#ff0000\", 3}, {\"#0000ff\", 1} }").yarns[0];
  const fibres::BakedYarn b = fibres::bake(yarn);
  int red = 0, blue = 0;
  for (std::size_t p = 0; p < b.colour.pixels.size(); p += 3) {
    red += b.colour.pixels[p] > 150 && b.colour.pixels[p + 2] < 40;
    blue += b.colour.pixels[p + 2] > 150 && b.colour.pixels[p] < 40;
  }
  EXPECT_EQ(red + blue, fibres::tile_along * fibres::tile_round);
  EXPECT_NEAR(static_cast<double>(red) / (red + blue), 0.75, 0.12);  // about 60 fibres drawn
  // A plain yarn's map is grey: each fibre a shade of the material's colour.
  const fibres::BakedYarn plain = fibres::bake(run("").yarns[0]);
  for (std::size_t p = 0; p < plain.colour.pixels.size(); p += 3) {
    ASSERT_EQ(plain.colour.pixels[p], plain.colour.pixels[p + 1]);
    ASSERT_GT(plain.colour.pixels[p], 200);
  }
  // The same bytes every time, for any thread count.
  const fibres::BakedYarn one = fibres::bake(yarn, 1), three = fibres::bake(yarn, 3);
  EXPECT_EQ(one.colour.pixels, b.colour.pixels);
  EXPECT_EQ(one.normal.pixels, three.normal.pixels);
  EXPECT_EQ(one.occlusion.pixels, three.occlusion.pixels);
  EXPECT_EQ(one.colour.pixels, three.colour.pixels);
}

TEST(Bake, TangentsRunAlongTheYarnAndTheBitangentRoundIt) {
  Pattern pattern = run("");
  CompileOptions options;
  options.textures = true;
  const Fabric fabric = compile(pattern, options);
  ASSERT_EQ(fabric.mesh.materials.size(), 1u);
  ASSERT_GE(fabric.mesh.materials[0].textures.normal, 0);
  const mesh::Primitive& p = fabric.mesh.primitives.at(0);
  const std::vector<glm::vec4> t = mesh::vertex_tangents(p);
  // Ring vertices: each ring is sides + 1 vertices; compare with the next ring (along u)
  // and the next vertex of the ring (along v). On the inside of a bend tighter than the
  // yarn's radius the tube folds over itself, and there the tangent follows the folded
  // triangles: a few per cent of the vertices of this tight swatch.
  const int stride = options.sides + 1;
  int checked = 0, along_ok = 0, round_ok = 0;
  for (std::size_t v = 0; v + stride < p.positions.size(); ++v) {
    if (v % stride == static_cast<std::size_t>(options.sides)) continue;
    if (p.uvs[v + stride].x <= p.uvs[v].x || p.uvs[v + 1].y <= p.uvs[v].y) continue;  // another strand or a cap
    const glm::vec3 along = glm::normalize(p.positions[v + stride] - p.positions[v]);
    const glm::vec3 round = glm::normalize(p.positions[v + 1] - p.positions[v]);
    const glm::vec3 n = p.normals[v], tangent(t[v]);
    ASSERT_NEAR(glm::length(tangent), 1.0f, 1e-4f);
    ASSERT_NEAR(glm::dot(tangent, n), 0.0f, 1e-4f);
    along_ok += glm::dot(tangent, along) > 0.9f;
    round_ok += glm::dot(glm::cross(n, tangent) * t[v].w, round) > 0.8f;
    ++checked;
  }
  EXPECT_GT(checked, 10000);
  EXPECT_GT(along_ok, 0.97 * checked);
  EXPECT_GT(round_ok, 0.97 * checked);
}

TEST(Bake, TheGlbCarriesTheMapsAndTheTangents) {
  CompileOptions options;
  options.textures = true;
  options.relax = true;
  const Fabric fabric = compile(run("heather = { {\"#8a2b2b\", 2}, {\"#d9c8a9\", 1} }", 6), options);
  EXPECT_TRUE(fabric.mesh.primitives.at(0).colors.empty());  // the heather is in the colour map
  EXPECT_EQ(fabric.mesh.materials.at(0).base_color, glm::vec3(1.0f));
  for (const bool compress : {false, true}) {
    writers::GlbOptions glb;
    glb.quantize = glb.meshopt = compress;
    const std::string bytes = writers::glb(fabric.mesh, "knitc test", glb);
    std::filesystem::create_directories(KNITC_GLB_DIR);
    std::ofstream(std::string(KNITC_GLB_DIR) + (compress ? "/baked_compressed.glb" : "/baked.glb"), std::ios::binary) << bytes;
    if (compress) continue;  // tinygltf reads no meshopt; the validator checks that file
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
                                            static_cast<unsigned>(bytes.size())))
        << error;
    ASSERT_EQ(model.images.size(), 3u);
    for (const tinygltf::Image& image : model.images) {
      EXPECT_EQ(image.width, fibres::tile_along);
      EXPECT_EQ(image.height, fibres::tile_round);
      EXPECT_EQ(image.mimeType, "image/png");
    }
    const tinygltf::Material& m = model.materials.at(0);
    EXPECT_GE(m.normalTexture.index, 0);
    EXPECT_GE(m.occlusionTexture.index, 0);
    EXPECT_GE(m.pbrMetallicRoughness.baseColorTexture.index, 0);
    const auto& transform = m.normalTexture.extensions.at("KHR_texture_transform").Get("scale");
    EXPECT_NEAR(transform.Get(0).GetNumberAsDouble(), 1.0 / fabric.mesh.materials[0].textures.repeat.x, 1e-6);
    EXPECT_TRUE(model.meshes.at(0).primitives.at(0).attributes.count("TANGENT"));
    EXPECT_FALSE(model.meshes.at(0).primitives.at(0).attributes.count("COLOR_0"));
  }
}

// The traced preview reads the maps too: a red and blue heather shows red and blue pixels
// only through its colour map, and the normal and occlusion maps change a plain yarn's.
TEST(Bake, TheTracedPreviewDrawsTheMaps) {
  CompileOptions options;
  options.textures = true;
  const Fabric heather = compile(run("heather = { {\"#c0282d\", 1}, {\"#2848c0\", 1} }", 6), options);
  render::TraceOptions trace;
  trace.width = 240, trace.height = 180, trace.samples = 4, trace.close_up = 8.0;
  const auto hues = [&](const mesh::Mesh& m) {
    const std::string png = render::traced_png(m, trace);
    int w = 0, h = 0, channels = 0;
    stbi_uc* px = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(png.data()), static_cast<int>(png.size()), &w, &h, &channels, 3);
    EXPECT_NE(px, nullptr);
    std::array<int, 2> out{0, 0};
    for (int i = 0; px != nullptr && i < w * h; ++i) {
      const int r = px[3 * i], b = px[3 * i + 2];
      out[0] += r > b + 40, out[1] += b > r + 40;
    }
    stbi_image_free(px);
    return out;
  };
  const std::array<int, 2> with = hues(heather.mesh);
  mesh::Mesh bare = heather.mesh;
  for (mesh::Material& m : bare.materials) m.textures = {};
  const std::array<int, 2> without = hues(bare);
  EXPECT_GT(with[0], 240 * 180 / 20);
  EXPECT_GT(with[1], 240 * 180 / 20);
  EXPECT_EQ(without[0] + without[1], 0);  // a white material and no vertex colours

  const Fabric plain = compile(run("", 6), options);
  mesh::Mesh flat = plain.mesh;
  for (mesh::Material& m : flat.materials) m.textures = {};
  EXPECT_NE(render::traced_png(plain.mesh, trace), render::traced_png(flat, trace));
}

// Seen whole, a fabric whose loops span a few pixels shows its plies under a pixel: the
// programs write it as plain tubes, unless --textures on (or a density) is asked for.
TEST(Bake, AFabricSeenWholeAtAFewPixelsALoopHasNoMapsUnlessAsked) {
  const auto dir = test::scratch_dir("bake");
  const std::string script = (dir / "wide.lua").string(), out = (dir / "wide.glb").string();
  test::write_text(script, test::jersey_source(130, 90));
  const auto stats = [&](const std::string& extra) {
    const auto r = test::run_knitc("build '" + script + "' -o '" + out + "' --relax off --stats " + extra);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.err;
  };
  const std::string plain = stats("");
  EXPECT_NE(plain.find("no baked maps"), std::string::npos) << plain;
  EXPECT_EQ(plain.find("\ntextures "), std::string::npos) << plain;
  EXPECT_NE(stats("--textures on").find("\ntextures "), std::string::npos);
  EXPECT_NE(stats("--quality draft").find("\ntextures "), std::string::npos);
}

}  // namespace
}  // namespace knitc
