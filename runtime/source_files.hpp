// Reading the text of a pattern or module file. Internal to the runtime.
#pragma once

#include <string>
#include <string_view>

#include "runtime.hpp"

namespace knitc::runtime {

// A file over the size a pattern or module may have. what() is "path:1: ...".
class SourceTooLarge : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The text of the regular file at `path`, at most `max_bytes` long, with a UTF-8 byte
// order mark dropped and a first line starting with '#' blanked (as Lua's loader
// does). Throws FileError if it cannot be read or is not a regular file (a FIFO, a
// device, a folder), SourceTooLarge if it is too long. Never blocks on a FIFO.
std::string read_source(const std::string& path, std::size_t max_bytes = max_source_bytes);

// Why `text`, read from `path`, cannot be a pattern's text, as "path:1: what it is; what
// to give instead": a file whose first bytes name another format (a .glb, as knitc
// writes; an image; a PDF; a zipped document) or that holds a NUL byte. Empty for text.
// (A Lua binary chunk is left to Lua's loader, which refuses it by name.)
std::string not_text(const std::string& path, std::string_view text);

}  // namespace knitc::runtime
