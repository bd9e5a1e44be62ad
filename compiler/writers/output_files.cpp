#include <cerrno>
#include <cstdio>
#include <cstring>
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

void write_files(std::span<const OutputFile> files) {
  // First every temporary, completely and flushed; only then the renames.
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string tmp = temporary_for(files[i].path);
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    bool ok = f != nullptr;
    const int open_errno = errno;
    if (ok) ok = std::fwrite(files[i].bytes.data(), 1, files[i].bytes.size(), f) == files[i].bytes.size();
    if (f != nullptr && std::fclose(f) != 0) ok = false;
    if (!ok) {
      const std::string why = std::strerror(f == nullptr ? open_errno : errno);
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
