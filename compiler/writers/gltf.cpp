// The binary glTF writer. The JSON is small and written with nlohmann-json; the binary
// chunk is written straight from the mesh's arrays (positions scaled to metres on the way
// in blocks), so the mesh is never copied whole: the output costs about what its bytes do.
// (tinygltf reads the files back in the tests.)
#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <deque>

#include <glm/common.hpp>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>
#include <stb/stb_image_write.h>

#include "mesh/bounds.hpp"
#include "mesh/tangents.hpp"
#include "parallel.hpp"
#include "writers/writers.hpp"

namespace knitc::writers {

namespace {

using json = nlohmann::ordered_json;

constexpr float metres_per_mm = 0.001f;
constexpr int gl_float = 5126, gl_unsigned_int = 5125, gl_unsigned_short = 5123, gl_unsigned_byte = 5121, gl_byte = 5120;
constexpr int gl_array_buffer = 34962, gl_element_array_buffer = 34963;

int gltf_mode(mesh::Mode mode) {
  switch (mode) {
    case mesh::Mode::triangles: return 4;
    case mesh::Mode::lines: return 1;
    case mesh::Mode::line_strip: return 3;
  }
  return 4;
}

std::size_t padded(std::size_t n) { return (n + 3) & ~std::size_t{3}; }

// One array of the binary chunk: where it goes and how to write it.
struct Block {
  std::size_t offset = 0, bytes = 0;
  const mesh::Primitive* primitive = nullptr;
  enum class What { positions, normals, uvs, colors, indices, vectors, tangents } what = What::positions;
  // KHR_mesh_quantization: positions as uint16 in the mesh's box (then the node's scale
  // and translation), normals as normalised int8; 4-byte aligned elements.
  bool quantized = false;
  glm::vec3 lo{0.0f}, step{1.0f};  // mm: position = lo + q * step
  std::size_t element = 4;         // bytes per vertex (or per index)
  std::size_t count = 0;
  const std::vector<glm::vec3>* vectors = nullptr;  // What::vectors: floats written as they are (instances' TRS)
  const std::vector<glm::vec4>* tangents = nullptr;  // What::tangents
};

// A block's bytes as the file holds them uncompressed (for meshopt to encode).
std::string raw_bytes(const Block& b);

std::uint16_t quantize_position(float v, float lo, float step) {
  return static_cast<std::uint16_t>(std::clamp(std::lround((v - lo) / step), 0L, 65535L));
}

std::int8_t quantize_normal(float v) { return static_cast<std::int8_t>(std::clamp(std::lround(v * 127.0f), -127L, 127L)); }

void write_quantized(const Block& b, std::ostream& out) {
  const mesh::Primitive& p = *b.primitive;
  std::vector<char> chunk;
  const std::size_t stride = b.what == Block::What::positions ? 8 : 4;
  for (std::size_t first = 0; first < p.positions.size(); first += 4096) {
    const std::size_t n = std::min<std::size_t>(4096, p.positions.size() - first);
    chunk.assign(n * stride, 0);
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < 3; ++k) {
        if (b.what == Block::What::positions) {
          const std::uint16_t q = quantize_position(p.positions[first + i][k], b.lo[k], b.step[k]);
          std::memcpy(&chunk[i * stride + 2 * k], &q, 2);
        } else {
          chunk[i * stride + k] = static_cast<char>(quantize_normal(p.normals[first + i][k]));
        }
      }
    }
    out.write(chunk.data(), static_cast<std::streamsize>(chunk.size()));
  }
}

// COLOR_0 as normalised RGBA bytes (linear, as glTF's vertex colours are): a quarter of
// floats' size, and each element 4-byte aligned.
void write_colors(const mesh::Primitive& p, std::ostream& out) {
  std::array<unsigned char, 4 * 4096> chunk;
  const auto byte = [](float v) { return static_cast<unsigned char>(std::clamp(std::lround(v * 255.0f), 0L, 255L)); };
  for (std::size_t first = 0; first < p.colors.size(); first += 4096) {
    const std::size_t n = std::min<std::size_t>(4096, p.colors.size() - first);
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < 3; ++k) chunk[4 * i + k] = byte(p.colors[first + i][k]);
      chunk[4 * i + 3] = 255;
    }
    out.write(reinterpret_cast<const char*>(chunk.data()), static_cast<std::streamsize>(4 * n));
  }
}

// TANGENT: floats, or normalised int8 (4-byte elements) when quantised.
void write_tangents(const Block& b, std::ostream& out) {
  const std::vector<glm::vec4>& t = *b.tangents;
  if (!b.quantized) {
    out.write(reinterpret_cast<const char*>(t.data()), static_cast<std::streamsize>(b.bytes));
    return;
  }
  std::array<std::int8_t, 4 * 4096> chunk;
  for (std::size_t first = 0; first < t.size(); first += 4096) {
    const std::size_t n = std::min<std::size_t>(4096, t.size() - first);
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 4; ++k) chunk[4 * i + k] = quantize_normal(t[first + i][k]);
    out.write(reinterpret_cast<const char*>(chunk.data()), static_cast<std::streamsize>(4 * n));
  }
}

void write_block(const Block& b, std::ostream& out) {
  if (b.what == Block::What::tangents) {
    write_tangents(b, out);
    return;  // 4 or 16 bytes an element: always padded
  }
  if (b.what == Block::What::vectors) {
    out.write(reinterpret_cast<const char*>(b.vectors->data()), static_cast<std::streamsize>(b.bytes));
    return;  // 12 bytes a vector: always padded
  }
  const mesh::Primitive& p = *b.primitive;
  if (b.quantized && (b.what == Block::What::positions || b.what == Block::What::normals)) {
    write_quantized(b, out);
    return;
  }
  switch (b.what) {
    case Block::What::positions: {
      // In blocks of 4096 vertices: metres, without a copy of the whole array.
      std::array<float, 3 * 4096> chunk;
      for (std::size_t first = 0; first < p.positions.size(); first += 4096) {
        const std::size_t n = std::min<std::size_t>(4096, p.positions.size() - first);
        for (std::size_t i = 0; i < n; ++i) {
          for (int k = 0; k < 3; ++k) chunk[3 * i + k] = p.positions[first + i][k] * metres_per_mm;
        }
        out.write(reinterpret_cast<const char*>(chunk.data()), static_cast<std::streamsize>(n * 3 * sizeof(float)));
      }
      break;
    }
    case Block::What::normals:
      out.write(reinterpret_cast<const char*>(p.normals.data()), static_cast<std::streamsize>(b.bytes));
      break;
    case Block::What::uvs:
      out.write(reinterpret_cast<const char*>(p.uvs.data()), static_cast<std::streamsize>(b.bytes));
      break;
    case Block::What::colors: write_colors(p, out); break;
    case Block::What::indices:
      out.write(reinterpret_cast<const char*>(p.indices.data()), static_cast<std::streamsize>(b.bytes));
      break;
    case Block::What::vectors:
    case Block::What::tangents: break;
  }
  static constexpr char zeros[4] = {};
  out.write(zeros, static_cast<std::streamsize>(padded(b.bytes) - b.bytes));
}

void put_u32(std::ostream& out, std::uint32_t v) {
  const unsigned char b[4] = {static_cast<unsigned char>(v), static_cast<unsigned char>(v >> 8),
                              static_cast<unsigned char>(v >> 16), static_cast<unsigned char>(v >> 24)};
  out.write(reinterpret_cast<const char*>(b), 4);
}

std::string raw_bytes(const Block& b) {
  std::ostringstream out;
  write_block(b, out);
  std::string bytes = std::move(out).str();
  bytes.resize(b.bytes);  // without the padding
  return bytes;
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

// Where every attribute and index array goes in the binary chunk, and the JSON that says so.
struct BinaryLayout {
  json views = json::array(), accessors = json::array(), primitives = json::array();
  std::vector<Block> blocks;
  std::size_t bytes = 0;  // the uncompressed binary's length
  std::deque<std::vector<glm::vec4>> tangents;  // TANGENT of the primitives with a normal map
};

BinaryLayout lay_out_binary(const std::vector<const mesh::Primitive*>& all, const mesh::Mesh& mesh, const GlbOptions& options,
                            glm::vec3 box_lo, glm::vec3 step) {
  BinaryLayout b;
  auto add = [&](const mesh::Primitive& p, Block::What what, std::size_t bytes, int target, json accessor,
                 std::size_t stride = 0) {
    const std::size_t count = accessor["count"].get<std::size_t>();
    b.blocks.push_back({b.bytes, bytes, &p, what, options.quantize, box_lo, step, count == 0 ? 4 : bytes / count, count});
    json view = {{"buffer", 0}, {"byteOffset", b.bytes}, {"byteLength", bytes}, {"target", target}};
    if (stride != 0) view["byteStride"] = stride;
    b.views.push_back(std::move(view));
    accessor["bufferView"] = b.views.size() - 1;
    b.accessors.push_back(std::move(accessor));
    b.bytes += padded(bytes);
    return b.accessors.size() - 1;
  };
  for (const mesh::Primitive* each : all) {
    const mesh::Primitive& p = *each;
    // In metres, exactly as the values written (scaling by a positive factor keeps order).
    const mesh::Bounds pb = mesh::bounds(p);
    std::array<double, 3> lo, hi;
    for (int k = 0; k < 3; ++k) {
      lo[k] = static_cast<double>(pb.min[k] * metres_per_mm);
      hi[k] = static_cast<double>(pb.max[k] * metres_per_mm);
    }
    json prim;
    json attributes;
    if (options.quantize) {
      std::array<int, 3> qlo{65535, 65535, 65535}, qhi{0, 0, 0};
      for (const auto& v : p.positions) {
        for (int k = 0; k < 3; ++k) {
          const int q = quantize_position(v[k], box_lo[k], step[k]);
          qlo[k] = std::min(qlo[k], q);
          qhi[k] = std::max(qhi[k], q);
        }
      }
      attributes["POSITION"] = add(p, Block::What::positions, p.positions.size() * 8, gl_array_buffer,
                                   {{"componentType", gl_unsigned_short}, {"count", p.positions.size()}, {"type", "VEC3"},
                                    {"min", qlo}, {"max", qhi}},
                                   8);
      if (!p.normals.empty())
        attributes["NORMAL"] = add(p, Block::What::normals, p.normals.size() * 4, gl_array_buffer,
                                   {{"componentType", gl_byte}, {"normalized", true}, {"count", p.normals.size()}, {"type", "VEC3"}},
                                   4);
    } else {
      attributes["POSITION"] = add(p, Block::What::positions, p.positions.size() * sizeof(glm::vec3), gl_array_buffer,
                                   {{"componentType", gl_float}, {"count", p.positions.size()}, {"type", "VEC3"},
                                    {"min", lo}, {"max", hi}});
      if (!p.normals.empty())
        attributes["NORMAL"] = add(p, Block::What::normals, p.normals.size() * sizeof(glm::vec3), gl_array_buffer,
                                   {{"componentType", gl_float}, {"count", p.normals.size()}, {"type", "VEC3"}});
    }
    if (!p.uvs.empty())
      attributes["TEXCOORD_0"] = add(p, Block::What::uvs, p.uvs.size() * sizeof(glm::vec2), gl_array_buffer,
                                     {{"componentType", gl_float}, {"count", p.uvs.size()}, {"type", "VEC2"}});
    // A normal map needs the tangent its red channel runs along (mesh/tangents.hpp).
    const bool mapped = p.mode == mesh::Mode::triangles && !p.normals.empty() && !p.uvs.empty() && p.material >= 0 &&
                        static_cast<std::size_t>(p.material) < mesh.materials.size() &&
                        mesh.materials[static_cast<std::size_t>(p.material)].textures.normal >= 0;
    if (mapped) {
      b.tangents.push_back(mesh::vertex_tangents(p));
      const std::size_t element = options.quantize ? 4 : sizeof(glm::vec4);
      json accessor = {{"componentType", options.quantize ? gl_byte : gl_float}, {"count", p.positions.size()}, {"type", "VEC4"}};
      if (options.quantize) accessor["normalized"] = true;
      attributes["TANGENT"] = add(p, Block::What::tangents, p.positions.size() * element, gl_array_buffer, accessor,
                                  options.quantize ? 4 : 0);
      b.blocks.back().tangents = &b.tangents.back();
    }
    if (!p.colors.empty())
      attributes["COLOR_0"] = add(p, Block::What::colors, p.colors.size() * 4, gl_array_buffer,
                                  {{"componentType", gl_unsigned_byte}, {"normalized", true}, {"count", p.colors.size()}, {"type", "VEC4"}},
                                  4);
    prim["attributes"] = std::move(attributes);
    prim["indices"] = add(p, Block::What::indices, p.indices.size() * sizeof(std::uint32_t), gl_element_array_buffer,
                          {{"componentType", gl_unsigned_int}, {"count", p.indices.size()}, {"type", "SCALAR"}});
    prim["material"] = p.material;
    prim["mode"] = gltf_mode(p.mode);
    b.primitives.push_back(std::move(prim));
  }
  return b;
}

// EXT_meshopt_compression: each view's bytes encoded by meshoptimizer into the binary
// chunk (the views then point there); returns the encoded blobs, and their length in
// `binary`.
std::vector<std::string> encode_meshopt(BinaryLayout& layout, std::size_t& binary, int threads) {
  // Each view encoded on its own, in parallel (each blob lands in its slot); then placed.
  std::vector<std::string> encoded(layout.blocks.size());
  std::vector<const char*> modes(layout.blocks.size(), "ATTRIBUTES");
  parallel_for(layout.blocks.size(), thread_count(threads), [&](std::size_t i) {
    const Block& b = layout.blocks[i];
    const std::string raw = raw_bytes(b);
    std::string blob;
    const char*& mode = modes[i];
    if (b.what == Block::What::indices) {
      const auto* indices = reinterpret_cast<const unsigned int*>(raw.data());
      const std::size_t vertices = b.primitive->positions.size();
      if (b.primitive->mode == mesh::Mode::triangles) {
        mode = "TRIANGLES";
        blob.resize(meshopt_encodeIndexBufferBound(b.count, vertices));
        blob.resize(meshopt_encodeIndexBuffer(reinterpret_cast<unsigned char*>(blob.data()), blob.size(), indices, b.count));
      } else {
        mode = "INDICES";
        blob.resize(meshopt_encodeIndexSequenceBound(b.count, vertices));
        blob.resize(meshopt_encodeIndexSequence(reinterpret_cast<unsigned char*>(blob.data()), blob.size(), indices, b.count));
      }
    } else {
      blob.resize(meshopt_encodeVertexBufferBound(b.count, b.element));
      blob.resize(meshopt_encodeVertexBuffer(reinterpret_cast<unsigned char*>(blob.data()), blob.size(), raw.data(), b.count,
                                             b.element));
    }
    encoded[i] = std::move(blob);
  });
  binary = 0;
  for (std::size_t i = 0; i < layout.blocks.size(); ++i) {
    const Block& b = layout.blocks[i];
    const std::string& blob = encoded[i];
    const char* mode = modes[i];
    if (b.what != Block::What::indices) layout.views[i]["byteStride"] = b.element;
    layout.views[i]["buffer"] = 1;
    layout.views[i]["extensions"]["EXT_meshopt_compression"] = {{"buffer", 0},        {"byteOffset", binary},
                                                                {"byteLength", blob.size()}, {"byteStride", b.element},
                                                                {"mode", mode},       {"count", b.count}};
    binary += padded(blob.size());
  }
  return encoded;
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
  if (!plain.empty()) {
    json node = {{"name", "fabric"}, {"mesh", meshes.size()}};
    if (options.quantize) {
      node["translation"] = {box_lo.x * metres_per_mm, box_lo.y * metres_per_mm, box_lo.z * metres_per_mm};
      node["scale"] = {step.x * metres_per_mm, step.y * metres_per_mm, step.z * metres_per_mm};
    }
    meshes.push_back({{"name", "fabric"},
                      {"primitives", json(std::vector<json>(layout.primitives.begin(), layout.primitives.begin() +
                                                                                           static_cast<std::ptrdiff_t>(plain.size())))}});
    nodes.push_back(std::move(node));
  }
  // EXT_mesh_gpu_instancing: the tile's mesh once, a translation per cell (metres); the
  // quantisation's box and step go into each instance's TRS, which applies before the
  // node's (an identity here).
  std::vector<glm::vec3> translations, scales;
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
    meshes.push_back({{"name", "tile"},
                      {"primitives", json(std::vector<json>(layout.primitives.begin() + static_cast<std::ptrdiff_t>(plain.size()),
                                                            layout.primitives.end()))}});
    nodes.push_back({{"name", "tiles"},
                     {"mesh", meshes.size() - 1},
                     {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", std::move(attributes)}}}}}});
  }
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
