// Reading a pattern or module file: a regular file only, bounded, read through one
// descriptor (what is checked is what is read). A FIFO would block, /dev/zero never ends.
#include "source_files.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace knitc::runtime {

namespace {

struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_source(const std::string& path, std::size_t max_bytes) {
  // O_NONBLOCK: opening a FIFO for reading must not wait for a writer.
  Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC)};
  if (file.fd < 0) throw FileError("cannot read " + path + ": " + std::strerror(errno));
  struct stat st {};
  if (::fstat(file.fd, &st) != 0) throw FileError("cannot read " + path + ": " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw FileError("cannot read " + path + ": it is a folder, not a file");
  if (!S_ISREG(st.st_mode))
    throw FileError("cannot read " + path + ": it is not a regular file (a pipe, a device or a socket); save the pattern to a file");
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes)
    throw SourceTooLarge(path + ":1: the file is " + std::to_string(static_cast<std::uintmax_t>(st.st_size) >> 10) +
                         " KiB; knitc reads pattern and module files of at most " + std::to_string(max_bytes >> 20) + " MiB");
  std::string text(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t got = 0;
  while (got < text.size()) {
    const ssize_t n = ::read(file.fd, text.data() + got, text.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw FileError("cannot read " + path + ": " + std::strerror(errno));
    if (n == 0) break;  // the file shrank while it was read
    got += static_cast<std::size_t>(n);
  }
  text.resize(got);
  // As Lua's own loader reads a file: a UTF-8 byte order mark dropped, and a first line
  // that starts with '#' (#!/usr/bin/env knitc) left blank, so line numbers stay.
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
  if (!text.empty() && text[0] == '#') text.erase(0, std::min(text.find('\n'), text.size()));
  return text;
}

std::string not_text(const std::string& path, std::string_view text) {
  const std::string give = "give knitc the pattern's text: a .lua script, a .k machine program or a printed pattern in a .txt file";
  auto starts = [&](std::string_view magic) { return text.substr(0, magic.size()) == magic; };
  std::string what;
  // (A text could begin "glTF": a .glb's version, a little-endian 32-bit 1 or 2, follows.)
  if (starts("glTF") && text.size() >= 8 && text.substr(5, 3) == std::string_view("\0\0\0", 3)) what = "the file is a glTF binary (a .glb, as knitc writes), not a pattern; open it in a glTF viewer, or " + give;
  else if (starts("\x89PNG") || starts("\xFF\xD8\xFF") || starts("GIF87a") || starts("GIF89a")) what = "the file is an image, not a pattern; " + give;
  else if (starts("%PDF-")) what = "the file is a PDF, not plain text; copy the pattern's text into a .txt file and give knitc that";
  else if (starts("PK\x03\x04"))
    what = "the file is zipped (a word processor's .docx or .odt, or an archive), not plain text; save the pattern as plain text (.txt) and give knitc that";
  else if (starts("\xFF\xFE") || starts("\xFE\xFF"))  // Windows' "Unicode" text
    what = "the file is UTF-16 text; save it as UTF-8 (plain text) and give knitc that";
  else if (!starts("\x1bLua") && text.find('\0') != std::string_view::npos) what = "the file holds a NUL byte: it is not a text file; " + give;
  return what.empty() ? what : path + ":1: " + what;
}

}  // namespace knitc::runtime
