// Output files written all or nothing: every file to a temporary beside its target,
// then the renames, undone if one fails. The temporaries have unpredictable names made
// with O_EXCL (a planted symlink cannot redirect them), take the target's mode, and are
// removed if the process is interrupted.
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "writers/writers.hpp"

namespace knitc::writers {

namespace {

namespace fs = std::filesystem;

// ---- temporaries a signal handler can remove (async-signal-safe: fixed storage, unlink)

constexpr int max_temporaries = 16;
char temporary_paths[max_temporaries][PATH_MAX];
std::atomic<bool> temporary_used[max_temporaries];

int register_temporary(const std::string& path) {
  if (path.size() >= PATH_MAX) return -1;
  for (int i = 0; i < max_temporaries; ++i) {
    bool expected = false;
    if (temporary_used[i].compare_exchange_strong(expected, true)) {
      std::memcpy(temporary_paths[i], path.c_str(), path.size() + 1);
      return i;
    }
  }
  return -1;
}

void forget_temporary(int slot) {
  if (slot >= 0) temporary_used[slot].store(false);
}

extern "C" void remove_temporaries_and_die(int sig) {
  for (int i = 0; i < max_temporaries; ++i) {
    if (temporary_used[i].load()) ::unlink(temporary_paths[i]);
  }
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

constexpr int cleanup_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

// Holds the cleanup signals off while files are renamed into place: a Ctrl-C then comes
// after, when the outputs are whole, not between two renames.
class SignalsHeld {
 public:
  SignalsHeld() {
    sigset_t set;
    sigemptyset(&set);
    for (int s : cleanup_signals) sigaddset(&set, s);
    ::pthread_sigmask(SIG_BLOCK, &set, &before_);
  }
  ~SignalsHeld() { ::pthread_sigmask(SIG_SETMASK, &before_, nullptr); }

 private:
  sigset_t before_;
};

std::string why(int error) { return std::strerror(error); }

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
  throw OutputError("cannot write " + (path == "-" ? std::string("standard output") : path) + ": " + reason);
}

// ---- writing to a descriptor through an ostream

class DescriptorBuffer : public std::streambuf {
 public:
  explicit DescriptorBuffer(int fd) : fd_(fd), buffer_(1u << 20) { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (n >= static_cast<std::streamsize>(buffer_.size())) {  // large blocks go straight out
      if (!drain() || !write_all(s, static_cast<std::size_t>(n))) return 0;
      return n;
    }
    return std::streambuf::xsputn(s, n);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool write_all(const char* s, std::size_t n) {
    while (n > 0) {
      const ssize_t w = ::write(fd_, s, n);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) {
        error_ = w < 0 ? errno : EIO;
        return false;
      }
      s += w;
      n -= static_cast<std::size_t>(w);
    }
    return true;
  }
  bool drain() {
    if (error_ != 0) return false;
    const bool ok = write_all(pbase(), static_cast<std::size_t>(pptr() - pbase()));
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return ok;
  }

  int fd_;
  std::vector<char> buffer_;
  int error_ = 0;
};

// Runs a file's writer into fd; the error text, or "" when all of it was written.
std::string write_to(int fd, const OutputFile& file) {
  DescriptorBuffer buffer(fd);
  std::ostream out(&buffer);
  try {
    file.write(out);
    out.flush();
  } catch (const std::exception& e) {
    return e.what();
  }
  if (buffer.error() != 0) return why(buffer.error());
  if (!out) return "write failed";
  return "";
}

// ---- the targets

struct Target {
  const OutputFile* file = nullptr;
  bool to_stdout = false;
  bool special = false;  // an existing device or FIFO: written in place, never replaced
  bool existed = false;
  std::string real;      // the file that is replaced (a symlink's target)
  struct stat st {};
  std::string temporary;
  int temporary_slot = -1;
  std::string backup;    // a second name for the old file while the renames run
  bool renamed = false;
};

mode_t process_umask() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return mask;
}

std::string random_name(const std::string& dir, const char* stem) {
  static std::random_device device;
  static const char letters[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  std::string name = dir + "/" + stem;
  for (int i = 0; i < 10; ++i) name += letters[device() % 36];
  return name;
}

// Decides how a target is written, before anything is.
void resolve(Target& t) {
  const std::string& path = t.file->path;
  if (path == "-") {
    t.to_stdout = true;
    return;
  }
  if (path.empty()) fail(path, "no file name");
  if (::stat(path.c_str(), &t.st) == 0) {
    t.existed = true;
    if (S_ISDIR(t.st.st_mode)) fail(path, "it is a folder");
    if (!S_ISREG(t.st.st_mode)) {  // /dev/null, a FIFO: written as it is, never replaced by a file
      t.special = true;
      t.real = path;
      return;
    }
    if (::access(path.c_str(), W_OK) != 0 || (t.st.st_mode & 0222) == 0) fail(path, "it is read-only");
    std::error_code ec;
    t.real = fs::canonical(path, ec).string();  // through symlinks: the link stays a link
    if (ec) t.real = path;
  } else if (errno == ENOENT) {
    t.real = path;
  } else {
    fail(path, why(errno));
  }
}

// Writes the target's temporary, fully.
void write_temporary(Target& t, mode_t umask_bits) {
  const fs::path real(t.real);
  const std::string dir = real.has_parent_path() ? real.parent_path().string() : std::string(".");
  std::string name = dir + "/.knitc-XXXXXX";
  int fd = -1;
  {
    SignalsHeld held;  // a signal between making the file and registering it would leave it
    fd = ::mkostemp(name.data(), O_CLOEXEC);
    if (fd < 0) fail(t.file->path, why(errno));
    t.temporary = name;
    t.temporary_slot = register_temporary(name);
  }
  const mode_t mode = t.existed ? (t.st.st_mode & 07777) : (0666 & ~umask_bits);
  ::fchmod(fd, mode);
  if (t.existed && ::geteuid() == 0) (void)!::fchown(fd, t.st.st_uid, t.st.st_gid);
  std::string error = write_to(fd, *t.file);
  if (::close(fd) != 0 && error.empty()) error = why(errno);
  if (!error.empty()) fail(t.file->path, error);
}

void write_in_place(Target& t) {
  if (t.to_stdout) {
    if (const std::string error = write_to(STDOUT_FILENO, *t.file); !error.empty()) fail("-", error);
    return;
  }
  const int fd = ::open(t.real.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) fail(t.file->path, why(errno));
  std::string error = write_to(fd, *t.file);
  if (::close(fd) != 0 && error.empty()) error = why(errno);
  if (!error.empty()) fail(t.file->path, error);
}

void remove_temporaries(std::vector<Target>& targets) {
  for (Target& t : targets) {
    if (!t.temporary.empty()) ::unlink(t.temporary.c_str());
    forget_temporary(t.temporary_slot);
    t.temporary.clear();
    t.temporary_slot = -1;
  }
}

// Puts back what the renames before a failure replaced.
void undo_renames(std::vector<Target>& targets) {
  for (auto it = targets.rbegin(); it != targets.rend(); ++it) {
    if (!it->renamed) continue;
    if (!it->backup.empty()) {
      ::rename(it->backup.c_str(), it->real.c_str());
      it->backup.clear();
    } else if (!it->existed) {
      ::unlink(it->real.c_str());
    }
  }
}

void commit(std::vector<Target>& targets) {
  SignalsHeld held;
  for (Target& t : targets) {
    if (t.temporary.empty()) continue;
    const std::string dir = fs::path(t.real).has_parent_path() ? fs::path(t.real).parent_path().string() : ".";
    if (t.existed) {  // keep the old file under a second name until every rename is done
      for (int attempt = 0; attempt < 8 && t.backup.empty(); ++attempt) {
        const std::string name = random_name(dir, ".knitc-old-");
        if (::link(t.real.c_str(), name.c_str()) == 0) t.backup = name;
        else if (errno != EEXIST) break;  // no hard links here: this one cannot be put back
      }
    }
    if (::rename(t.temporary.c_str(), t.real.c_str()) != 0) {
      const int error = errno;
      undo_renames(targets);
      for (Target& b : targets) {
        if (!b.backup.empty()) ::unlink(b.backup.c_str());
      }
      remove_temporaries(targets);
      fail(t.file->path, why(error));
    }
    t.renamed = true;
    forget_temporary(t.temporary_slot);
    t.temporary_slot = -1;
    t.temporary.clear();
  }
  for (Target& t : targets) {
    if (!t.backup.empty()) ::unlink(t.backup.c_str());
  }
}

}  // namespace

OutputFile text_file(std::string path, std::string bytes) {
  return {std::move(path), [bytes = std::move(bytes)](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); }};
}

void write_files(std::span<const OutputFile> files) {
  std::vector<Target> targets(files.size());
  for (std::size_t i = 0; i < files.size(); ++i) {
    targets[i].file = &files[i];
    resolve(targets[i]);
  }
  const mode_t umask_bits = process_umask();
  try {
    for (Target& t : targets) {
      if (!t.to_stdout && !t.special) write_temporary(t, umask_bits);
    }
    // Streams and devices next: they cannot be taken back, so only once every file is
    // ready; then the renames.
    for (Target& t : targets) {
      if (t.to_stdout || t.special) write_in_place(t);
    }
  } catch (...) {
    remove_temporaries(targets);
    throw;
  }
  commit(targets);
}

void remove_temporaries_on_signals() {
  for (int s : cleanup_signals) {
    struct sigaction action {};
    action.sa_handler = remove_temporaries_and_die;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    ::sigaction(s, &action, nullptr);
  }
}

std::string file_identity(const std::string& path) {
  if (path == "-") return "-";
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) return "inode " + std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino);
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return "path " + (ec ? path : p.lexically_normal().string());
}

}  // namespace knitc::writers
