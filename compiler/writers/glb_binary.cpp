// The binary chunk of a .glb (glb_binary.hpp): each array written straight from the mesh's
// arrays, in blocks of 4096 elements, so the mesh is never copied whole.
#include "writers/glb_binary.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <sstream>

#include <meshoptimizer.h>

#include "mesh/bounds.hpp"
#include "mesh/tangents.hpp"
#include "parallel.hpp"

namespace knitc::writers::binary {

namespace {

int gltf_mode(mesh::Mode mode) {
  switch (mode) {
    case mesh::Mode::triangles: return 4;
    case mesh::Mode::lines: return 1;
    case mesh::Mode::line_strip: return 3;
  }
  return 4;
}

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

}  // namespace

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

namespace {

std::string raw_bytes(const Block& b) {
  std::ostringstream out;
  write_block(b, out);
  std::string bytes = std::move(out).str();
  bytes.resize(b.bytes);  // without the padding
  return bytes;
}

}  // namespace

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

}  // namespace knitc::writers::binary
