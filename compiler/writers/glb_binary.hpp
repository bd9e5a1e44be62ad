// The binary chunk of a .glb: where each attribute and index array goes (its view and
// accessor), and how each is written from the mesh's arrays (as floats, or quantised for
// KHR_mesh_quantization, or encoded by meshoptimizer). Internal to writers/: gltf.cpp
// writes the container and the scene around it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <ostream>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include "mesh/mesh.hpp"
#include "writers/writers.hpp"

namespace knitc::writers::binary {

using json = nlohmann::ordered_json;

constexpr float metres_per_mm = 0.001f;
constexpr int gl_float = 5126, gl_unsigned_int = 5125, gl_unsigned_short = 5123, gl_unsigned_byte = 5121, gl_byte = 5120;
constexpr int gl_array_buffer = 34962, gl_element_array_buffer = 34963;

// The padding to a 4-byte boundary every view and chunk ends on.
inline std::size_t padded(std::size_t n) { return (n + 3) & ~std::size_t{3}; }

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

// Writes a block's bytes as the file holds them (floats in metres, or quantised), padded.
void write_block(const Block& b, std::ostream& out);

// Where every attribute and index array goes in the binary chunk, and the JSON that says so.
struct BinaryLayout {
  json views = json::array(), accessors = json::array(), primitives = json::array();
  std::vector<Block> blocks;
  std::size_t bytes = 0;  // the uncompressed binary's length
  std::deque<std::vector<glm::vec4>> tangents;  // TANGENT of the primitives with a normal map
};

// The views, accessors and primitives of `all` (the plain primitives, then the tile's),
// positions quantised to the grid from `box_lo` in steps of `step` (mm) when
// options.quantize; a normal-mapped primitive gets its TANGENT.
BinaryLayout lay_out_binary(const std::vector<const mesh::Primitive*>& all, const mesh::Mesh& mesh, const GlbOptions& options,
                            glm::vec3 box_lo, glm::vec3 step);

// EXT_meshopt_compression: each view's bytes encoded by meshoptimizer into the binary
// chunk (the views then point there); returns the encoded blobs, and their length in
// `binary`. The same bytes for any thread count.
std::vector<std::string> encode_meshopt(BinaryLayout& layout, std::size_t& binary, int threads);

}  // namespace knitc::writers::binary
