// The .glb read back by another reader (tinygltf's loader): what the writer meant is what
// a client gets, in metres.
#include <cstring>

#include <gtest/gtest.h>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "support.hpp"
#include "writers/writers.hpp"

namespace knitc {
namespace {

// The file as tinygltf's loader reads it; a failure to load fails the test.
tinygltf::Model load(const std::string& bytes) {
  tinygltf::Model m;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  const bool ok = loader.LoadBinaryFromMemory(&m, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                              static_cast<unsigned int>(bytes.size()));
  EXPECT_TRUE(ok) << err;
  return m;
}

TEST(Gltf, ReadsBackWithTheMeshItWasWrittenFrom) {
  const Pattern p = runtime::run_pattern(
                        "pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { diameter = 1, color = \"#ff0000\" },\n"
                        "  B = { diameter = 1, section = \"plied\", plies = 2 } } }\ncast_on(6)\nrows(2, \"k\")\nyarn \"B\"\nrows(2, \"k\")\n",
                        "t.lua")
                        .pattern;
  const Fabric f = compile(p, CompileOptions{});
  const tinygltf::Model m = load(writers::glb(f.mesh, "knitc test"));
  EXPECT_EQ(m.asset.generator, "knitc test");
  ASSERT_EQ(m.meshes.size(), 1u);
  ASSERT_EQ(m.meshes[0].primitives.size(), 2u);
  ASSERT_EQ(m.materials.size(), 2u);
  EXPECT_NEAR(m.materials[0].pbrMetallicRoughness.baseColorFactor[0], 1.0, 1e-6);  // #ff0000 is linear 1, 0, 0
  EXPECT_NEAR(m.materials[0].pbrMetallicRoughness.baseColorFactor[1], 0.0, 1e-6);
  EXPECT_TRUE(m.materials[0].extensions.count("KHR_materials_sheen"));
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& prim = m.meshes[0].primitives[i];
    const auto& src = f.mesh.primitives[i];
    EXPECT_EQ(prim.mode, TINYGLTF_MODE_TRIANGLES);
    const auto& pos = m.accessors[prim.attributes.at("POSITION")];
    ASSERT_EQ(pos.count, src.positions.size());
    const auto& view = m.bufferViews[pos.bufferView];
    const float* xyz = reinterpret_cast<const float*>(m.buffers[view.buffer].data.data() + view.byteOffset + pos.byteOffset);
    for (std::size_t v = 0; v < src.positions.size(); v += 97) {
      for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(xyz[3 * v + k], src.positions[v][k] * 0.001f);  // metres
    }
    EXPECT_EQ(m.accessors[prim.attributes.at("NORMAL")].count, src.positions.size());
    EXPECT_EQ(m.accessors[prim.attributes.at("TEXCOORD_0")].count, src.positions.size());
    const auto& idx = m.accessors[prim.indices];
    EXPECT_EQ(idx.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    EXPECT_EQ(idx.count, src.indices.size());
    ASSERT_EQ(pos.minValues.size(), 3u);
    for (int k = 0; k < 3; ++k) EXPECT_LT(pos.minValues[k], pos.maxValues[k]);
  }
}

}  // namespace
}  // namespace knitc

namespace knitc {
namespace {

TEST(Gltf, QuantisedPositionsComeBackWithinHalfAStep) {
  const Pattern p = test::jersey(5, 4);
  const Fabric f = compile(p, CompileOptions{});
  const std::string bytes = writers::glb(f.mesh, "knitc test", {true});
  EXPECT_LT(bytes.size(), writers::glb(f.mesh, "knitc test").size() * 4 / 5);
  const tinygltf::Model m = load(bytes);
  ASSERT_EQ(m.extensionsRequired, std::vector<std::string>{"KHR_mesh_quantization"});
  const auto& node = m.nodes[0];
  ASSERT_EQ(node.scale.size(), 3u);
  ASSERT_EQ(node.translation.size(), 3u);
  const auto& prim = m.meshes[0].primitives[0];
  const auto& pos = m.accessors[prim.attributes.at("POSITION")];
  EXPECT_EQ(pos.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  const auto& view = m.bufferViews[pos.bufferView];
  EXPECT_EQ(view.byteStride, 8u);
  const auto* data = m.buffers[0].data.data() + view.byteOffset;
  const auto& src = f.mesh.primitives[0];
  ASSERT_EQ(pos.count, src.positions.size());
  for (std::size_t v = 0; v < src.positions.size(); v += 53) {
    for (int k = 0; k < 3; ++k) {
      std::uint16_t q;
      std::memcpy(&q, data + 8 * v + 2 * k, 2);
      const double metres = node.translation[k] + node.scale[k] * q;
      EXPECT_NEAR(metres, src.positions[v][k] * 0.001, 0.51 * node.scale[k] + 1e-9);
    }
  }
  const auto& normal = m.accessors[prim.attributes.at("NORMAL")];
  EXPECT_EQ(normal.componentType, TINYGLTF_COMPONENT_TYPE_BYTE);
  EXPECT_TRUE(normal.normalized);
}

}  // namespace
}  // namespace knitc

namespace knitc {
namespace {

// A .glb's JSON and binary chunk.
std::pair<nlohmann::json, std::string> chunks(const std::string& glb) {
  auto u32 = [&](std::size_t at) {
    std::uint32_t v;
    std::memcpy(&v, glb.data() + at, 4);
    return v;
  };
  const std::uint32_t json_length = u32(12);
  const auto doc = nlohmann::json::parse(glb.substr(20, json_length));
  const std::size_t bin = 20 + json_length;
  return {doc, glb.substr(bin + 8, u32(bin))};
}

TEST(Gltf, MeshoptViewsDecodeToTheUncompressedBytes) {
  const Pattern p = runtime::run_pattern(
                        "pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { diameter = 1 } } }\ncast_on(6)\nrows(3, \"k\")\n",
                        "t.lua")
                        .pattern;
  for (const View view : {View::surface, View::wireframe}) {
    CompileOptions o;
    o.view = view;
    const Fabric f = compile(p, o);
    const auto [plain_doc, plain] = chunks(writers::glb(f.mesh, "t", {true, false}));
    const auto [doc, packed] = chunks(writers::glb(f.mesh, "t", {true, true}));
    EXPECT_LT(packed.size(), plain.size() / 2);
    EXPECT_EQ(doc["buffers"][1]["byteLength"], plain.size());
    ASSERT_EQ(doc["bufferViews"].size(), plain_doc["bufferViews"].size());
    for (std::size_t i = 0; i < doc["bufferViews"].size(); ++i) {
      const auto& v = doc["bufferViews"][i];
      const auto& ext = v["extensions"]["EXT_meshopt_compression"];
      const std::size_t count = ext["count"], stride = ext["byteStride"];
      const std::size_t at = ext["byteOffset"], length = ext["byteLength"];
      const auto* src = reinterpret_cast<const unsigned char*>(packed.data() + at);
      std::string decoded(count * stride, '\0');
      int rc = -1;
      if (ext["mode"] == "ATTRIBUTES") rc = meshopt_decodeVertexBuffer(decoded.data(), count, stride, src, length);
      else if (ext["mode"] == "TRIANGLES") rc = meshopt_decodeIndexBuffer(decoded.data(), count, stride, src, length);
      else rc = meshopt_decodeIndexSequence(decoded.data(), count, stride, src, length);
      ASSERT_EQ(rc, 0) << "view " << i;
      const std::size_t plain_at = plain_doc["bufferViews"][i]["byteOffset"];
      const std::string expected = plain.substr(plain_at, decoded.size());
      if (ext["mode"] != "TRIANGLES") {
        EXPECT_TRUE(decoded == expected) << "view " << i;
        continue;
      }
      // The index codec keeps every triangle and its winding but may start it at another corner.
      std::size_t same = 0;
      for (std::size_t t = 0; t < count / 3; ++t) {
        std::uint32_t a[3], b[3];
        std::memcpy(a, decoded.data() + 12 * t, 12);
        std::memcpy(b, expected.data() + 12 * t, 12);
        for (int r = 0; r < 3; ++r) same += a[0] == b[r] && a[1] == b[(r + 1) % 3] && a[2] == b[(r + 2) % 3];
      }
      EXPECT_EQ(same, count / 3) << "view " << i;
      EXPECT_EQ(v["byteOffset"], plain_at);
    }
  }
}

}  // namespace
}  // namespace knitc
