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

}  // namespace knitc::runtime
