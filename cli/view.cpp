#include "view.hpp"
#include "sources.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <map>
#include <new>
#include <sstream>
#include <thread>

#include <fmt/core.h>

#include "view/info.hpp"
#include "view/server.hpp"
#include "writers/writers.hpp"

extern char** environ;

namespace knitc::cli {

namespace {

// What a file was when last seen: a change to any of these is an edit.
struct Seen {
  bool exists = false;
  std::int64_t modified_ns = 0;
  std::int64_t size = 0;
  std::uint64_t inode = 0;
  bool operator==(const Seen&) const = default;
};

Seen seen(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return {};
  return {true, static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1'000'000'000 + st.st_mtim.tv_nsec, static_cast<std::int64_t>(st.st_size),
          static_cast<std::uint64_t>(st.st_ino)};
}

struct Build {
  view::Published published;
  std::vector<std::string> files;  // what to watch
};

std::string lines(const std::vector<std::string>& texts) {
  std::string out;
  for (const auto& t : texts) out += runtime::printable(t, 1000) + "\n";
  return out;
}

Build build(const ViewOptions& o) {
  Build b;
  b.files = {o.pattern};
  try {
    const runtime::RunResult r = cli::read_pattern(o.pattern, o.printed, o.run);
    if (!r.files.empty()) b.files = r.files;
    b.published.warnings = lines(r.warnings);
    const Fabric fabric = compile(r.pattern, o.compile);
    const bool small = fabric.instanced;  // compressed as knitc build does by default
    b.published.glb = writers::glb(fabric.mesh, "knitc " KNITC_VERSION, {small, small, o.compile.threads});
    b.published.info = view::fabric_info(r.pattern, fabric);
  } catch (const runtime::PatternError& e) {
    if (!e.files.empty()) b.files = e.files;
    b.published.warnings = lines(e.warnings);
    b.published.error = e.what();
  } catch (const runtime::FileError& e) {
    b.published.error = std::string("knitc: ") + e.what();
  } catch (const CompileError& e) {
    b.published.error = runtime::printable(e.what(), 4000);
  } catch (const std::bad_alloc&) {
    b.published.error = "knitc: out of memory building the fabric; knit a smaller piece or use --quality draft";
  }
  b.published.glb.shrink_to_fit();
  return b;
}

// Opens `url` in the desktop's browser, if there is a desktop and xdg-open; quietly not
// otherwise (the address is printed).
void open_in_browser(const std::string& url) {
  if (std::getenv("DISPLAY") == nullptr && std::getenv("WAYLAND_DISPLAY") == nullptr) return;
  pid_t pid = 0;
  char* argv[] = {const_cast<char*>("xdg-open"), const_cast<char*>(url.c_str()), nullptr};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  if (posix_spawnp(&pid, "xdg-open", &actions, nullptr, argv, environ) == 0) {
    std::thread([pid] { waitpid(pid, nullptr, 0); }).detach();  // reaped, never waited on here
  }
  posix_spawn_file_actions_destroy(&actions);
}

}  // namespace

int view(const ViewOptions& o) {
  // The signals that stop the view are taken here, by sigtimedwait between looks at the
  // files, on this thread only: every thread started from now on (the server's) inherits
  // the mask, so none of them is interrupted mid-request.
  sigset_t stops;
  sigemptyset(&stops);
  sigaddset(&stops, SIGINT);
  sigaddset(&stops, SIGTERM);
  sigaddset(&stops, SIGHUP);
  pthread_sigmask(SIG_BLOCK, &stops, nullptr);

  std::unique_ptr<view::Server> server;
  try {
    server = std::make_unique<view::Server>(o.port);
  } catch (const std::exception& e) {
    fmt::print(stderr, "knitc: {}\n", e.what());
    return 2;
  }
  Build current = build(o);
  server->publish(current.published);
  if (!current.published.error.empty()) fmt::print(stderr, "{}\n", current.published.error);
  std::thread serving([&] { server->run(); });
  server->wait_until_serving();
  fmt::print("knitc: viewing {} at {} (Ctrl-C stops)\n", runtime::printable(o.pattern, 500), server->address());
  std::fflush(stdout);
  if (o.open) open_in_browser(server->address());

  std::map<std::string, Seen> watched;
  auto look = [&] {
    std::map<std::string, Seen> now;
    for (const auto& f : current.files) now[f] = seen(f);
    return now;
  };
  watched = look();
  for (;;) {
    const timespec wait{0, 50'000'000};  // a twentieth of a second between looks
    siginfo_t info;
    if (sigtimedwait(&stops, &info, &wait) > 0) break;
    if (look() == watched) continue;
    // An editor may save in steps (truncate, then write): wait for the file to settle.
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const auto t0 = std::chrono::steady_clock::now();
    current = build(o);
    watched = look();
    server->publish(current.published);
    if (!o.quiet) {
      if (current.published.error.empty())
        fmt::print(stderr, "knitc: rebuilt in {:.2f} s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      else
        fmt::print(stderr, "{}\n", current.published.error);
    }
  }
  server->stop();
  serving.join();
  if (!o.quiet) fmt::print(stderr, "knitc: stopped\n");
  return 0;
}

}  // namespace knitc::cli
