// Faults around the command line: files that must not be clobbered or lost, outputs
// all or nothing, inputs that are not files, bad values, and the exit codes for each
// (1 the pattern, 2 misuse, 3 a file that could not be read or written).
#include <csignal>
#include <thread>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "support.hpp"
#include "writers/writers.hpp"

namespace knitc {
namespace {

namespace fs = std::filesystem;

std::string shell(const fs::path& p) { return "'" + p.string() + "'"; }

std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

const std::string jersey = "patterns/jersey.lua";

// Runs knitc with its standard output sent to `to` (a path, for the shell).
test::CommandResult run_to(const std::string& args, const std::string& to) {
  const auto dir = test::scratch_dir("redirected");
  const std::string command = std::string("cd '") + KNITC_SOURCE_DIR + "' && '" + KNITC_BINARY + "' " + args + " >" + to +
                              " 2>'" + (dir / "err").string() + "'";
  const int status = std::system(command.c_str());
  test::CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = test::read_text(dir / "err");
  fs::remove_all(dir);
  return r;
}

TEST(CliFaults, OutputsNamingOneFileAreRefusedAndNothingIsWritten) {
  const fs::path dir = test::scratch_dir("same-file");
  fs::create_directories(dir / "sub");
  test::write_text(dir / "x.glb", "old");
  for (const std::string& other : {(dir / "sub/../x.glb").string(), (dir / "./x.glb").string(), (dir / "link.glb").string()}) {
    if (other.find("link") != std::string::npos) fs::create_symlink(dir / "x.glb", dir / "link.glb");
    const auto r = test::run_knitc("build " + jersey + " --relax off -q -o " + shell(dir / "x.glb") + " --centreline " + shell(other));
    EXPECT_EQ(r.exit_code, 2) << other << ": " << r.err;
    EXPECT_NE(r.err.find("are the same file"), std::string::npos) << r.err;
    EXPECT_EQ(test::read_text(dir / "x.glb"), "old");
  }
  fs::remove_all(dir);
}

TEST(CliFaults, AFailingSecondOutputLeavesTheFirstAsItWas) {
  const fs::path dir = test::scratch_dir("second-fails");
  test::write_text(dir / "x.glb", "old");
  fs::create_directories(dir / "folder.json");
  for (const fs::path& bad : {dir / "folder.json", dir / "no/such/dir/x.json"}) {
    const auto r = test::run_knitc("build " + jersey + " --relax off -q -o " + shell(dir / "x.glb") + " --centreline " + shell(bad));
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_EQ(r.err.rfind("knitc: cannot write " + bad.string() + ": ", 0), 0u) << r.err;
    EXPECT_EQ(test::read_text(dir / "x.glb"), "old");
    EXPECT_EQ(listing(dir), (std::vector<std::string>{"folder.json", "x.glb"}));
  }
  fs::remove_all(dir);
}

// The renames come last; if one of them fails, the ones before it are undone.
TEST(CliFaults, AFailedRenamePutsBackTheFilesRenamedBeforeIt) {
  const fs::path dir = test::scratch_dir("rename-fails");
  test::write_text(dir / "a.txt", "old a");
  const std::vector<writers::OutputFile> files = {
      writers::text_file((dir / "a.txt").string(), "new a"),
      {(dir / "b.txt").string(), [&](std::ostream& out) {
         // While b's temporary is written, b's name becomes a folder with a file in it:
         // a's rename will succeed and b's will fail.
         fs::create_directories(dir / "b.txt" / "inside");
         out << "new b";
       }}};
  EXPECT_THROW(writers::write_files(files), writers::OutputError);
  EXPECT_EQ(test::read_text(dir / "a.txt"), "old a");
  EXPECT_EQ(listing(dir), (std::vector<std::string>{"a.txt", "b.txt"}));
  fs::remove_all(dir);
}

TEST(CliFaults, AWriterThatFailsLeavesNothing) {
  const fs::path dir = test::scratch_dir("writer-fails");
  test::write_text(dir / "a.txt", "old a");
  const std::vector<writers::OutputFile> files = {
      writers::text_file((dir / "a.txt").string(), "new a"),
      {(dir / "b.txt").string(), [](std::ostream&) { throw std::runtime_error("no more"); }}};
  EXPECT_THROW(writers::write_files(files), writers::OutputError);
  EXPECT_EQ(test::read_text(dir / "a.txt"), "old a");
  EXPECT_EQ(listing(dir), std::vector<std::string>{"a.txt"});
  fs::remove_all(dir);
}

// The old temporary name was the target's plus ".knitc-tmp-" and the pid, opened with
// truncation: a symlink planted there redirected the write.
TEST(CliFaults, APlantedSymlinkAtTheOldTemporaryNameRedirectsNothing) {
  const fs::path dir = test::scratch_dir("planted");
  test::write_text(dir / "victim", "precious");
  const fs::path target = dir / "x.txt";
  fs::create_symlink(dir / "victim", target.string() + ".knitc-tmp-" + std::to_string(::getpid()));
  writers::write_files(std::vector<writers::OutputFile>{writers::text_file(target.string(), "output")});
  EXPECT_EQ(test::read_text(dir / "victim"), "precious");
  EXPECT_EQ(test::read_text(target), "output");
  fs::remove_all(dir);
}

// knitc bench wrote to /tmp/knitc-bench-PID.glb, a name anyone could plant a link at.
TEST(CliFaults, BenchWritesInAFolderOfItsOwn) {
  const fs::path tmp = test::scratch_dir("bench-tmp");
  test::write_text(tmp / "victim", "precious");
  int gate[2];
  ASSERT_EQ(::pipe(gate), 0);
  const pid_t pid = ::fork();
  if (pid == 0) {  // waits until the parent has planted the link at its pid's name
    char go = 0;
    ::close(gate[1]);
    if (::read(gate[0], &go, 1) != 1) ::_exit(126);
    ::setenv("TMPDIR", tmp.c_str(), 1);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::dup2(null, 2);
    ::execl(KNITC_BINARY, KNITC_BINARY, "bench", "--swatch", "3x3", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(gate[0]);
  fs::create_symlink(tmp / "victim", tmp / ("knitc-bench-" + std::to_string(pid) + ".glb"));
  ASSERT_EQ(::write(gate[1], "g", 1), 1);
  ::close(gate[1]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  EXPECT_EQ(test::read_text(tmp / "victim"), "precious");
  EXPECT_EQ(listing(tmp), (std::vector<std::string>{"knitc-bench-" + std::to_string(pid) + ".glb", "victim"}));
  fs::remove_all(tmp);
}

TEST(CliFaults, DevicesAndFifosAreWrittenInPlaceNotReplaced) {
  const auto r = test::run_knitc("build " + jersey + " --relax off -q -o /dev/null");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));  // still the device (as root it was replaced by a file)

  const fs::path dir = test::scratch_dir("fifo");
  const fs::path fifo = dir / "out.glb";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  std::string got;
  std::thread reader([&] { got = test::read_text(fifo); });
  const auto w = test::run_knitc("build " + jersey + " --relax off -q -o " + shell(fifo));
  reader.join();
  EXPECT_EQ(w.exit_code, 0) << w.err;
  EXPECT_EQ(got.substr(0, 4), "glTF");
  ASSERT_EQ(::stat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_EQ(listing(dir), std::vector<std::string>{"out.glb"});
  fs::remove_all(dir);
}

TEST(CliFaults, ATargetKeepsItsModeAndAReadOnlyOneIsRefused) {
  const fs::path dir = test::scratch_dir("modes");
  test::write_text(dir / "private.glb", "old");
  fs::permissions(dir / "private.glb", fs::perms::owner_read | fs::perms::owner_write);
  ASSERT_EQ(test::run_knitc("build " + jersey + " --relax off -q -o " + shell(dir / "private.glb")).exit_code, 0);
  EXPECT_EQ(fs::status(dir / "private.glb").permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
  EXPECT_EQ(test::read_text(dir / "private.glb").substr(0, 4), "glTF");

  const mode_t mask = ::umask(0);
  ::umask(mask);
  ASSERT_EQ(test::run_knitc("build " + jersey + " --relax off -q -o " + shell(dir / "new.glb")).exit_code, 0);
  EXPECT_EQ(static_cast<mode_t>(fs::status(dir / "new.glb").permissions() & fs::perms::all), 0666 & ~mask);

  test::write_text(dir / "locked.glb", "old");
  fs::permissions(dir / "locked.glb", fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  const auto r = test::run_knitc("build " + jersey + " --relax off -q -o " + shell(dir / "locked.glb"));
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("it is read-only"), std::string::npos) << r.err;
  EXPECT_EQ(test::read_text(dir / "locked.glb"), "old");
  EXPECT_EQ(listing(dir), (std::vector<std::string>{"locked.glb", "new.glb", "private.glb"}));
  fs::remove_all(dir);
}

TEST(CliFaults, AFullDiskIsAnIoErrorForEveryOutput) {
  for (const std::string& args : {"snapshot " + jersey, "chart " + jersey, "build " + jersey + " --relax off -q -o /dev/full",
                                  "snapshot " + jersey + " -o /dev/full", "build " + jersey + " --relax off -q -o -",
                                  std::string("reference")}) {
    const auto r = run_to(args, "/dev/full");
    EXPECT_EQ(r.exit_code, 3) << args << ": " << r.err;
    EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << args << ": " << r.err;
  }
}

// A bad argument is quoted in the usage error: escaped, like every other message.
TEST(CliFaults, MisuseMessagesAreFitForATerminal) {
  const auto r = test::run_knitc(std::string("build ") + jersey + " -o x.glb --quality \"$(printf '\\033]0;pwned\\007\\033[2J')\"");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\\x1b"), std::string::npos) << r.err;
}

TEST(CliFaults, DashIsStandardOutputAndLongNamesWork) {
  const fs::path dir = test::scratch_dir("dash");
  const auto r = run_to("build " + jersey + " --relax off -q -o -", shell(dir / "piped.glb"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::read_text(dir / "piped.glb").substr(0, 4), "glTF");
  EXPECT_FALSE(fs::exists(fs::path(KNITC_SOURCE_DIR) / "-"));
  const auto snap = test::run_knitc("snapshot " + jersey + " --relax off -o -");
  EXPECT_EQ(snap.exit_code, 0);
  EXPECT_EQ(snap.out.rfind("knitc snapshot", 0), 0u);
  // 250 characters: legal on every file system knitc meets; the temporary's name is short.
  const fs::path long_name = dir / (std::string(246, 'a') + ".glb");
  const auto l = test::run_knitc("build " + jersey + " --relax off -q -o " + shell(long_name));
  EXPECT_EQ(l.exit_code, 0) << l.err;
  EXPECT_TRUE(fs::exists(long_name));
  fs::remove_all(dir);
}

TEST(CliFaults, PatternsThatAreNotFilesAreRefusedAtOnce) {
  const fs::path dir = test::scratch_dir("inputs");
  ASSERT_EQ(::mkfifo((dir / "fifo.lua").c_str(), 0644), 0);
  test::write_text(dir / "huge.lua", "-- " + std::string(5u << 20, 'x') + "\n");
  const std::pair<std::string, std::string> cases[] = {
      {"/dev/zero", "not a regular file"},
      {(dir / "fifo.lua").string(), "not a regular file"},  // would block for ever on open
      {dir.string(), "it is a folder"},
      {(dir / "none.lua").string(), "No such file or directory"},
  };
  for (const auto& [path, message] : cases) {
    const auto r = test::run_knitc("check " + shell(path));
    EXPECT_EQ(r.exit_code, 3) << path << ": " << r.err;
    EXPECT_EQ(r.err.rfind("knitc: cannot read " + path + ": ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  }
  const auto huge = test::run_knitc("check " + shell(dir / "huge.lua"));
  EXPECT_EQ(huge.exit_code, 1);
  EXPECT_EQ(huge.err.rfind((dir / "huge.lua").string() + ":1: the file is 5120 KiB", 0), 0u) << huge.err;
  fs::remove_all(dir);
}

TEST(CliFaults, ModulesAreReadOnlyFromInsideTheirFolders) {
  const fs::path dir = test::scratch_dir("module-links");
  fs::create_directories(dir / "lib");
  fs::create_directories(dir / "outside");
  test::write_text(dir / "outside" / "evil.lua", "return {}\n");
  test::write_text(dir / "lib" / "good.lua", "return { n = 1 }\n");
  fs::create_symlink(dir / "outside" / "evil.lua", dir / "lib" / "evil.lua");
  fs::create_symlink(dir / "lib" / "good.lua", dir / "lib" / "alias.lua");  // a link inside: fine
  const std::string header = "pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\" } } }\ncast_on(4)\n";
  test::write_text(dir / "p.lua", header + "local g = require \"alias\"\nrequire \"evil\"\nrows(2, \"k\")\n");
  const auto r = test::run_knitc("check " + shell(dir / "p.lua"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("p.lua:4: module \"evil\" is "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("outside"), std::string::npos) << r.err;

  // A lib/ folder that is itself a link elsewhere is not the pattern's own.
  const fs::path other = test::scratch_dir("module-links-2");
  fs::create_directory_symlink(dir / "outside", other / "lib");
  test::write_text(other / "p.lua", header + "require \"evil\"\nrows(2, \"k\")\n");
  const auto s = test::run_knitc("check " + shell(other / "p.lua"));
  EXPECT_EQ(s.exit_code, 1);
  EXPECT_NE(s.err.find("p.lua:3: module \"evil\" is "), std::string::npos) << s.err;
  fs::remove_all(dir);
  fs::remove_all(other);
}

// SIGTERM (or Ctrl-C) while the .glb is written: the temporary goes with the process.
TEST(CliFaults, AnInterruptedWriteLeavesNoTemporary) {
  const fs::path dir = test::scratch_dir("interrupted");
  test::write_text(dir / "big.lua", "pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\" } } }\n"
                                    "cast_on(60)\nrows(60, \"k\")\n");
  test::write_text(dir / "out.glb", "old");
  for (const int sig : {SIGTERM, SIGINT}) {
    const pid_t pid = ::fork();
    if (pid == 0) {
      const int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, 2);
      ::execl(KNITC_BINARY, KNITC_BINARY, "build", (dir / "big.lua").c_str(), "-q", "--relax", "off", "-o",
              (dir / "out.glb").c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    // Wait for the temporary to appear, then interrupt.
    bool seen = false;
    for (int i = 0; i < 200000 && !seen; ++i) {
      for (const auto& name : listing(dir)) seen = seen || name.rfind(".knitc-", 0) == 0;
      if (!seen) std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    ::kill(pid, sig);
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(seen) << "the build finished before its temporary was seen";
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << status;
    EXPECT_EQ(listing(dir), (std::vector<std::string>{"big.lua", "out.glb"}));
    EXPECT_EQ(test::read_text(dir / "out.glb"), "old");
  }
  fs::remove_all(dir);
}

TEST(CliFaults, AFabricTooLargeToMeshIsRefusedBeforeItIsMeshed) {
  const fs::path dir = test::scratch_dir("estimate");
  test::write_text(dir / "big.lua", "pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\" } } }\n"
                                    "cast_on(1000)\nrows(500, \"k\")\n");
  const auto start = std::chrono::steady_clock::now();
  const auto r = test::run_knitc("build " + shell(dir / "big.lua") + " --quality draft -o " + shell(dir / "x.glb"));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind((dir / "big.lua").string() + ":3: the mesh would have about", 0), 0u) << r.err;
  // Fitting and meshing it first took 49 s and 2.2 GB to find that out; the estimate
  // takes 2.8 s and 0.5 GB. The peak memory tells them apart on any machine (the time
  // is only a guard against the old way).
  rusage children{};
  ::getrusage(RUSAGE_CHILDREN, &children);
#ifndef KNITC_SANITIZED
  EXPECT_LT(children.ru_maxrss, 1024L * 1024);  // KiB: under 1 GiB
#endif
  EXPECT_LT(seconds, 40.0);
  EXPECT_FALSE(fs::exists(dir / "x.glb"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace knitc
