#include <algorithm>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <tiny_gltf.h>

#include "writers/writers.hpp"

namespace knitc::writers {

namespace {

constexpr float metres_per_mm = 0.001f;

int gltf_mode(mesh::Mode mode) {
  switch (mode) {
    case mesh::Mode::triangles: return TINYGLTF_MODE_TRIANGLES;
    case mesh::Mode::lines: return TINYGLTF_MODE_LINE;
    case mesh::Mode::line_strip: return TINYGLTF_MODE_LINE_STRIP;
  }
  return TINYGLTF_MODE_TRIANGLES;
}

// Appends bytes to the single buffer as a buffer view of its own; returns the view.
int add_view(tinygltf::Model& m, const void* data, std::size_t bytes, int target) {
  auto& buffer = m.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = bytes;
  view.target = target;
  const auto* p = static_cast<const unsigned char*>(data);
  buffer.insert(buffer.end(), p, p + bytes);
  buffer.resize((buffer.size() + 3) & ~std::size_t{3}, 0);  // keep every view 4-aligned
  m.bufferViews.push_back(view);
  return static_cast<int>(m.bufferViews.size()) - 1;
}

int add_accessor(tinygltf::Model& m, int view, int component, std::size_t count, int type) {
  tinygltf::Accessor a;
  a.bufferView = view;
  a.componentType = component;
  a.count = count;
  a.type = type;
  m.accessors.push_back(a);
  return static_cast<int>(m.accessors.size()) - 1;
}

// Positions go straight into the buffer, converted to metres on the way.
int add_positions(tinygltf::Model& m, const mesh::Primitive& p, std::vector<double>& lo, std::vector<double>& hi) {
  auto& buffer = m.buffers[0].data;
  const std::size_t offset = buffer.size(), bytes = p.positions.size() * 3 * sizeof(float);
  buffer.resize((offset + bytes + 3) & ~std::size_t{3}, 0);
  float* xyz = reinterpret_cast<float*>(buffer.data() + offset);
  lo.assign(3, std::numeric_limits<double>::infinity());
  hi.assign(3, -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < p.positions.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const float v = p.positions[i][k] * metres_per_mm;
      xyz[3 * i + k] = v;
      lo[k] = std::min(lo[k], static_cast<double>(v));
      hi[k] = std::max(hi[k], static_cast<double>(v));
    }
  }
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = offset;
  view.byteLength = bytes;
  view.target = TINYGLTF_TARGET_ARRAY_BUFFER;
  m.bufferViews.push_back(view);
  return static_cast<int>(m.bufferViews.size()) - 1;
}

void add_primitive(tinygltf::Model& m, const mesh::Primitive& p) {
  std::vector<double> lo, hi;
  tinygltf::Primitive prim;
  prim.mode = gltf_mode(p.mode);
  prim.material = p.material;
  const int pos_view = add_positions(m, p, lo, hi);
  const int pos = add_accessor(m, pos_view, TINYGLTF_COMPONENT_TYPE_FLOAT, p.positions.size(), TINYGLTF_TYPE_VEC3);
  m.accessors[pos].minValues = lo;
  m.accessors[pos].maxValues = hi;
  prim.attributes["POSITION"] = pos;
  if (!p.normals.empty()) {
    const int view = add_view(m, p.normals.data(), p.normals.size() * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
    prim.attributes["NORMAL"] = add_accessor(m, view, TINYGLTF_COMPONENT_TYPE_FLOAT, p.normals.size(), TINYGLTF_TYPE_VEC3);
  }
  if (!p.uvs.empty()) {
    static_assert(sizeof(glm::vec2) == 2 * sizeof(float));
    const int view = add_view(m, p.uvs.data(), p.uvs.size() * sizeof(glm::vec2), TINYGLTF_TARGET_ARRAY_BUFFER);
    prim.attributes["TEXCOORD_0"] = add_accessor(m, view, TINYGLTF_COMPONENT_TYPE_FLOAT, p.uvs.size(), TINYGLTF_TYPE_VEC2);
  }
  const int index_view = add_view(m, p.indices.data(), p.indices.size() * sizeof(std::uint32_t),
                                  TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  prim.indices = add_accessor(m, index_view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, p.indices.size(), TINYGLTF_TYPE_SCALAR);
  m.meshes[0].primitives.push_back(prim);
}

}  // namespace

void write_glb(const mesh::Mesh& mesh, const std::string& generator, std::ostream& out) {
  static_assert(sizeof(glm::vec3) == 3 * sizeof(float));
  if (mesh.primitives.empty()) throw std::runtime_error("glTF needs at least one primitive; the mesh is empty");
  tinygltf::Model m;
  m.asset.version = "2.0";
  m.asset.generator = generator;
  m.buffers.resize(1);
  // The buffer's size is known: one allocation, each array written once into it.
  std::size_t bytes = 0;
  for (const mesh::Primitive& p : mesh.primitives) {
    bytes += p.positions.size() * sizeof(glm::vec3) + p.normals.size() * sizeof(glm::vec3) +
             p.uvs.size() * sizeof(glm::vec2) + p.indices.size() * sizeof(std::uint32_t) + 16;
  }
  m.buffers[0].data.reserve(bytes);
  if (!mesh.materials.empty()) m.extensionsUsed.push_back("KHR_materials_sheen");
  for (const mesh::Material& mat : mesh.materials) {
    tinygltf::Material g;
    g.name = mat.name;
    g.pbrMetallicRoughness.baseColorFactor = {mat.base_color.r, mat.base_color.g, mat.base_color.b, 1.0};
    g.pbrMetallicRoughness.metallicFactor = 0.0;  // yarn is a dielectric
    g.pbrMetallicRoughness.roughnessFactor = 0.85;
    // Fibres scatter light at grazing angles: the soft rim of cloth.
    tinygltf::Value::Object sheen;
    sheen["sheenColorFactor"] = tinygltf::Value(tinygltf::Value::Array{
        tinygltf::Value(static_cast<double>(mat.sheen_color.r)), tinygltf::Value(static_cast<double>(mat.sheen_color.g)),
        tinygltf::Value(static_cast<double>(mat.sheen_color.b))});
    sheen["sheenRoughnessFactor"] = tinygltf::Value(static_cast<double>(mat.sheen_roughness));
    g.extensions["KHR_materials_sheen"] = tinygltf::Value(sheen);
    m.materials.push_back(g);
  }
  m.meshes.resize(1);
  m.meshes[0].name = "fabric";
  for (const mesh::Primitive& p : mesh.primitives) add_primitive(m, p);
  tinygltf::Node node;
  node.name = "fabric";
  node.mesh = 0;
  m.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  m.scenes.push_back(scene);
  m.defaultScene = 0;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&m, out, false, true)) throw std::runtime_error("glTF serialisation failed");
}

std::string glb(const mesh::Mesh& mesh, const std::string& generator) {
  std::ostringstream out;
  write_glb(mesh, generator, out);
  return std::move(out).str();
}

}  // namespace knitc::writers
