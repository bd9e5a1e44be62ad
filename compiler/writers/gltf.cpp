// The binary glTF writer. The JSON is small and written with nlohmann-json; the binary
// chunk is written straight from the mesh's arrays (glb_binary.hpp), so the mesh is never
// copied whole: the output costs about what its bytes do. (tinygltf reads the files back
// in the tests.)
#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <glm/common.hpp>
#include <nlohmann/json.hpp>
#include <stb/stb_image_write.h>

#include "mesh/bounds.hpp"
#include "writers/glb_binary.hpp"
#include "writers/writers.hpp"

namespace knitc::writers {

namespace {

using namespace binary;

void put_u32(std::ostream& out, std::uint32_t v) {
  const unsigned char b[4] = {static_cast<unsigned char>(v), static_cast<unsigned char>(v >> 8),
                              static_cast<unsigned char>(v >> 16), static_cast<unsigned char>(v >> 24)};
  out.write(reinterpret_cast<const char*>(b), 4);
}

// A material's map: its texture (one per image, in order), read through TEXCOORD_0 scaled
// to the tile by KHR_texture_transform.
json texture_info(int image, const mesh::Textures& t) {
  return {{"index", image},
          {"extensions", {{"KHR_texture_transform", {{"scale", {1.0 / t.repeat.x, 1.0 / t.repeat.y}}}}}}};
}

// The materials: base colour, not metallic, and the sheen of fibres; a baked yarn's maps.
json materials_json(const mesh::Mesh& mesh) {
  json materials = json::array();
  for (const mesh::Material& m : mesh.materials) {
    json pbr = {{"baseColorFactor", {m.base_color.r, m.base_color.g, m.base_color.b, 1.0}},
                {"metallicFactor", 0.0},  // yarn is a dielectric
                {"roughnessFactor", 0.85}};
    const mesh::Textures& t = m.textures;
    if (t.colour >= 0) pbr["baseColorTexture"] = texture_info(t.colour, t);
    json material = {{"name", m.name}, {"pbrMetallicRoughness", std::move(pbr)}};
    if (t.normal >= 0) material["normalTexture"] = texture_info(t.normal, t);
    if (t.occlusion >= 0) material["occlusionTexture"] = texture_info(t.occlusion, t);
    // Fibres scatter light at grazing angles: the soft rim of cloth.
    material["extensions"] = {{"KHR_materials_sheen",
                               {{"sheenColorFactor", {m.sheen_color.r, m.sheen_color.g, m.sheen_color.b}},
                                {"sheenRoughnessFactor", m.sheen_roughness}}}};
    materials.push_back(std::move(material));
  }
  return materials;
}

// The images as PNG files (stb), each a texture repeated both ways, mipmapped.
std::vector<std::string> encode_images(const mesh::Mesh& mesh) {
  std::vector<std::string> out;
  for (const mesh::Image& image : mesh.images) {
    if (image.width < 1 || image.height < 1 || (image.channels != 1 && image.channels != 3) ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) *
                                   static_cast<std::size_t>(image.channels))
      throw std::runtime_error("glTF: an image's size does not match its pixels");
    std::string png;
    const auto append = [](void* context, void* data, int size) {
      static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
    };
    if (!stbi_write_png_to_func(append, &png, image.width, image.height, image.channels, image.pixels.data(),
                                image.width * image.channels))
      throw std::runtime_error("glTF: cannot encode a texture as PNG");
    out.push_back(std::move(png));
  }
  return out;
}

// The .glb container: header, the JSON chunk (padded with spaces), the binary chunk.
void write_chunks(std::ostream& out, std::string text, std::size_t binary, const BinaryLayout& layout,
                  const std::vector<std::string>& encoded, bool meshopt, const std::vector<std::string>& pngs) {
  text.resize(padded(text.size()), ' ');
  const std::size_t total = 12 + 8 + text.size() + 8 + binary;
  if (total > std::numeric_limits<std::uint32_t>::max())
    throw std::runtime_error("the mesh is over the 4 GiB a .glb can hold; knit a smaller piece or use --quality draft");
  out.write("glTF", 4);
  put_u32(out, 2);
  put_u32(out, static_cast<std::uint32_t>(total));
  put_u32(out, static_cast<std::uint32_t>(text.size()));
  put_u32(out, 0x4E4F534Au);  // JSON
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  put_u32(out, static_cast<std::uint32_t>(binary));
  put_u32(out, 0x004E4942u);  // BIN
  static constexpr char zeros[4] = {};
  if (meshopt) {
    for (const std::string& blob : encoded) {
      out.write(blob.data(), static_cast<std::streamsize>(blob.size()));
      out.write(zeros, static_cast<std::streamsize>(padded(blob.size()) - blob.size()));
    }
  } else {
    for (const Block& b : layout.blocks) write_block(b, out);
  }
  for (const std::string& png : pngs) {
    out.write(png.data(), static_cast<std::streamsize>(png.size()));
    out.write(zeros, static_cast<std::streamsize>(padded(png.size()) - png.size()));
  }
}

}  // namespace

void write_glb(const mesh::Mesh& mesh, const std::string& generator, std::ostream& out, const GlbOptions& options) {
  static_assert(sizeof(glm::vec3) == 3 * sizeof(float) && sizeof(glm::vec2) == 2 * sizeof(float));
  std::vector<const mesh::Primitive*> plain, tile;
  for (const auto& p : mesh.primitives) plain.push_back(&p);
  const mesh::Instances* instances = nullptr;
  for (const auto& group : mesh.instanced)
    if (!group.primitives.empty() && !group.translations.empty()) {
      if (instances != nullptr) throw std::runtime_error("the writer takes one group of instances");
      instances = &group;
      for (const auto& p : group.primitives) tile.push_back(&p);
    }
  if (plain.empty() && tile.empty()) throw std::runtime_error("glTF needs at least one primitive; the mesh is empty");
  // The extensions, in the order earlier files listed them.
  json used = json::array(), required = json::array();
  if (!mesh.materials.empty()) used.push_back("KHR_materials_sheen");
  if (!mesh.images.empty()) used.push_back("KHR_texture_transform");
  if (instances != nullptr) {
    used.push_back("EXT_mesh_gpu_instancing");
    required.push_back("EXT_mesh_gpu_instancing");
  }
  if (options.quantize) {
    used.push_back("KHR_mesh_quantization");
    required.push_back("KHR_mesh_quantization");
  }
  if (options.meshopt) {
    used.push_back("EXT_meshopt_compression");
    required.push_back("EXT_meshopt_compression");
  }
  // The quantisation grid: the box of every stored position (the tile's in its own frame)
  // in 65535 steps of its longest side, the same step on every axis: a uniform scale
  // leaves the normals and tangents stored as they are (a non-uniform one would bend them).
  mesh::Bounds box;
  for (const auto* p : plain)
    for (const auto& v : p->positions) box.add(v);
  for (const auto* p : tile)
    for (const auto& v : p->positions) box.add(v);
  const glm::vec3 box_lo = box.min, box_hi = box.max;
  const glm::vec3 extent = box_hi - box_lo;
  const glm::vec3 step(std::max({extent.x / 65535.0f, extent.y / 65535.0f, extent.z / 65535.0f, 1e-6f}));
  std::vector<const mesh::Primitive*> all = plain;
  all.insert(all.end(), tile.begin(), tile.end());
  BinaryLayout layout = lay_out_binary(all, mesh, options, box_lo, step);
  json nodes = json::array(), meshes = json::array();
  json plain_node;
  if (!plain.empty()) {
    plain_node = {{"name", "fabric"}, {"mesh", meshes.size()}};
    if (options.quantize) {
      plain_node["translation"] = {box_lo.x * metres_per_mm, box_lo.y * metres_per_mm, box_lo.z * metres_per_mm};
      plain_node["scale"] = {step.x * metres_per_mm, step.y * metres_per_mm, step.z * metres_per_mm};
    }
    meshes.push_back({{"name", "fabric"},
                      {"primitives", json(std::vector<json>(layout.primitives.begin(), layout.primitives.begin() +
                                                                                           static_cast<std::ptrdiff_t>(plain.size())))}});
  }
  // EXT_mesh_gpu_instancing: the tile's mesh once, a translation per cell (metres); the
  // quantisation's box and step go into each instance's TRS, which applies before the
  // node's (an identity here).
  std::vector<glm::vec3> translations, scales, edge_translation, edge_scale;
  if (instances != nullptr) {
    for (const glm::vec3& t : instances->translations)
      translations.push_back((options.quantize ? t + box_lo : t) * metres_per_mm);
    if (options.quantize) scales.assign(translations.size(), step * metres_per_mm);
    auto add_vectors = [&](const std::vector<glm::vec3>& v) {
      const std::size_t bytes = v.size() * sizeof(glm::vec3);
      layout.blocks.push_back({layout.bytes, bytes, nullptr, Block::What::vectors, false, box_lo, step, 12, v.size(), &v});
      layout.views.push_back({{"buffer", 0}, {"byteOffset", layout.bytes}, {"byteLength", bytes}});
      glm::vec3 lo = v.front(), hi = v.front();
      for (const auto& x : v) {
        lo = glm::min(lo, x);
        hi = glm::max(hi, x);
      }
      layout.accessors.push_back({{"bufferView", layout.views.size() - 1},
                                  {"componentType", gl_float},
                                  {"count", v.size()},
                                  {"type", "VEC3"},
                                  {"min", {lo.x, lo.y, lo.z}},
                                  {"max", {hi.x, hi.y, hi.z}}});
      layout.bytes += padded(bytes);
      return layout.accessors.size() - 1;
    };
    json attributes = {{"TRANSLATION", add_vectors(translations)}};
    if (options.quantize) attributes["SCALE"] = add_vectors(scales);
    // The edges too are one instance of their mesh, its TRS in the instance: a renderer
    // then draws the whole fabric with one shader program (three.js makes another for a
    // mesh not instanced: in headless Chromium's software GL the front's first frame took
    // 0.94 of its time with one). A reader without the extension (it is required here
    // anyway) would draw the edges alike.
    if (!plain.empty()) {
      edge_translation.push_back(options.quantize ? box_lo * metres_per_mm : glm::vec3(0.0f));
      json edge = {{"TRANSLATION", add_vectors(edge_translation)}};
      if (options.quantize) {
        edge_scale.push_back(step * metres_per_mm);
        edge["SCALE"] = add_vectors(edge_scale);
      }
      plain_node.erase("translation");
      plain_node.erase("scale");
      plain_node["extensions"] = {{"EXT_mesh_gpu_instancing", {{"attributes", std::move(edge)}}}};
      nodes.push_back(std::move(plain_node));
    }
    meshes.push_back({{"name", "tile"},
                      {"primitives", json(std::vector<json>(layout.primitives.begin() + static_cast<std::ptrdiff_t>(plain.size()),
                                                            layout.primitives.end()))}});
    nodes.push_back({{"name", "tiles"},
                     {"mesh", meshes.size() - 1},
                     {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", std::move(attributes)}}}}}});
  }
  if (instances == nullptr && !plain.empty()) nodes.push_back(std::move(plain_node));
  std::vector<std::string> encoded;
  std::size_t binary = layout.bytes;
  if (options.meshopt) encoded = encode_meshopt(layout, binary, options.threads);
  // The textures' PNGs after the arrays (or their encoding), in the first buffer, as they are.
  const std::vector<std::string> pngs = encode_images(mesh);
  json images = json::array(), textures = json::array();
  for (const std::string& png : pngs) {
    layout.views.push_back({{"buffer", 0}, {"byteOffset", binary}, {"byteLength", png.size()}});
    images.push_back({{"bufferView", layout.views.size() - 1}, {"mimeType", "image/png"}});
    textures.push_back({{"sampler", 0}, {"source", images.size() - 1}});
    binary += padded(png.size());
  }
  json buffers = json::array({{{"byteLength", binary}}});
  // The uncompressed layout stays as a fallback buffer with no data.
  if (options.meshopt)
    buffers.push_back({{"byteLength", layout.bytes}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
  json doc;
  doc["asset"] = {{"version", "2.0"}, {"generator", generator}};
  if (!required.empty()) doc["extensionsRequired"] = std::move(required);
  if (!used.empty()) doc["extensionsUsed"] = std::move(used);
  json scene_nodes = json::array();
  for (std::size_t i = 0; i < nodes.size(); ++i) scene_nodes.push_back(i);
  doc["scene"] = 0;
  doc["scenes"] = json::array({{{"nodes", std::move(scene_nodes)}}});
  doc["nodes"] = std::move(nodes);
  if (json materials = materials_json(mesh); !materials.empty()) doc["materials"] = std::move(materials);
  if (!pngs.empty()) {
    // Linear filtering, mipmapped, repeated: the tile wraps along the yarn and round it.
    doc["samplers"] = json::array({{{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}}});
    doc["images"] = std::move(images);
    doc["textures"] = std::move(textures);
  }
  doc["meshes"] = std::move(meshes);
  doc["accessors"] = std::move(layout.accessors);
  doc["buffers"] = std::move(buffers);
  doc["bufferViews"] = std::move(layout.views);
  write_chunks(out, doc.dump(), binary, layout, encoded, options.meshopt, pngs);
}

std::string glb(const mesh::Mesh& mesh, const std::string& generator, const GlbOptions& options) {
  std::ostringstream out;
  write_glb(mesh, generator, out, options);
  return std::move(out).str();
}

}  // namespace knitc::writers
