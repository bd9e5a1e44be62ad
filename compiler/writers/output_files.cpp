#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include "writers/writers.hpp"

namespace knitc::writers {

namespace {

std::string temporary_for(const std::string& path) {
  return path + ".knitc-tmp-" + std::to_string(::getpid());
}

void remove_all(std::span<const OutputFile> files, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) std::remove(temporary_for(files[i].path).c_str());
}

}  // namespace

OutputFile text_file(std::string path, std::string bytes) {
  return {std::move(path), [bytes = std::move(bytes)](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); }};
}

void write_files(std::span<const OutputFile> files) {
  // First every temporary, completely and flushed; only then the renames.
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string tmp = temporary_for(files[i].path);
    bool ok = false;
    std::string why;
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) {
        why = std::strerror(errno);
      } else {
        try {
          files[i].write(out);
          out.flush();
          ok = static_cast<bool>(out);
          if (!ok) why = "write failed (disk full?)";
        } catch (const std::exception& e) {
          why = e.what();
        }
      }
    }
    if (!ok) {
      remove_all(files, i + 1);
      throw std::runtime_error("cannot write " + files[i].path + ": " + why);
    }
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (std::rename(temporary_for(files[i].path).c_str(), files[i].path.c_str()) != 0) {
      const std::string why = std::strerror(errno);
      remove_all(files, files.size());
      throw std::runtime_error("cannot write " + files[i].path + ": " + why);
    }
  }
}

}  // namespace knitc::writers
