// Writers: the mesh and the centrelines as bytes, and files written all or nothing.
// They know the mesh and plain geometry, not how it was made.
#pragma once

#include <functional>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "compile.hpp"
#include "measure/measure.hpp"
#include "mesh/mesh.hpp"

namespace knitc::writers {

// A binary glTF 2.0 (.glb) of the mesh: metres (positions scaled from mm), +Y up, one
// mesh with a primitive per mesh primitive, one material per mesh material (base colour,
// not metallic), uint32 indices, POSITION with min and max, NORMAL where present.
// `generator` goes to asset.generator. Throws std::runtime_error if serialisation fails.
// A material's maps (mesh::Textures) are PNG images in the binary chunk, each a texture
// read through TEXCOORD_0 with KHR_texture_transform's scale; a primitive whose material has
// a normal map gets its TANGENT (mesh/tangents.hpp).
// With quantize (KHR_mesh_quantization, a required extension): positions as uint16 on a
// grid of the mesh's box in 65535 steps of its longest side, the same step on every axis
// (the node's uniform scale and translation map it back to metres; about 1.2 micrometres on
// an 8 cm swatch), normals and tangents as normalised int8.
// With meshopt (EXT_meshopt_compression, required): every buffer view encoded by
// meshoptimizer, the uncompressed layout kept as a fallback buffer without data.
struct GlbOptions {
  bool quantize = false;
  bool meshopt = false;
  int threads = 0;  // meshopt encodes the views on up to this many threads (0: every core); the same bytes for any
};
void write_glb(const mesh::Mesh& mesh, const std::string& generator, std::ostream& out, const GlbOptions& options = {});
std::string glb(const mesh::Mesh& mesh, const std::string& generator, const GlbOptions& options = {});

// The centreline JSON (units mm), rounded to 1e-6 mm:
// {"units":"mm","loop_model":..., "yarns":[{"id","color","free_diameter","core_diameter",
//  "points","pieces"}], "loops":[{"course","wale","stitch","yarn","file","line","data_points","samples",
//  "points"}]}
// A yarn's "points" are the samples of all its pieces, piece after piece; "pieces" gives
// each piece as [first point index, point count]. A loop's "data_points" are the points
// its stretch of curve passes through and its "samples" that stretch, both in the mesh's
// space (in the round, wrapped onto the tube) and in the yarn's working order; its
// "points" are that stretch as [first, last] indices into its yarn's points; its "file"
// and "line" the script line of the row that made it ("" and 0 for the cast-on's and a
// bind-off's loops).
std::string centreline_json(const Pattern& pattern, const Fabric& fabric, yarn_paths::LoopModel model);

// A short, stable, diff-friendly summary of a compiled fabric for snapshot tests: counts,
// each yarn's length (0.001 mm) and the sanity figures from `measures` (the measuring
// stage's, for this fabric), the bounds (0.001 mm) and a 64-bit FNV-1a hash of every
// position quantised to 1 micrometre and every index. The same for any thread count.
std::string snapshot(const Pattern& pattern, const Fabric& fabric, const measure::FabricMeasures& measures);

struct OutputFile {
  std::string path;                          // "-" is standard output
  std::function<void(std::ostream&)> write;  // writes the file's whole content
};

// A file whose content is already in memory.
OutputFile text_file(std::string path, std::string bytes);

// An output that could not be written. Nothing was replaced (standard output and
// devices excepted: what they were sent cannot be taken back).
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes the files all or nothing. Each regular file goes to a temporary beside it
// (".knitc-" and a random suffix, made with O_EXCL, with the old file's mode or
// 0666 & ~umask) and only when every temporary is whole, and standard output and any
// device or FIFO target (written in place, never replaced) have been written, are they
// renamed into place; a failed rename puts back the files already renamed. A symlink
// target is written through (the link stays); a folder or a read-only file is refused.
// Throws OutputError naming the path, after removing the temporaries.
void write_files(std::span<const OutputFile> files);

// Installs handlers for SIGINT, SIGTERM, SIGHUP and SIGQUIT that remove the
// temporaries being written, then end the process as the signal would have.
void remove_temporaries_on_signals();

// What a path names, for telling whether two paths are one file: the device and inode
// of an existing file, else its absolute path with symlinks and ".." resolved.
std::string file_identity(const std::string& path);

}  // namespace knitc::writers
