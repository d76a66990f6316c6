// Faults around `pond` (issue 8), run against the real executable: each test spawns pond with the
// fault arranged (environment, a mount namespace, a resource limit, a signal) and checks the exit
// code, the one-line message, and that nothing is left under the requested name or as a temporary.
//   exit 2: bad input (the command line, a scene, an output folder that cannot take a file)
//   exit 1: failure at run time (no Vulkan loader or driver, a disk that fills up)
//   exit 130 / 143: stopped by SIGINT / SIGTERM, nothing written
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <thread>
#include <vector>

namespace {
namespace fs = std::filesystem;

struct Result {
  int code = -1;    // exit code, or 128 + signal when killed
  std::string err;  // stderr
};

struct Spawn {
  std::vector<std::string> argv;  // after the program name
  std::string exe = POND_EXE;     // a name without a slash is looked up in PATH
  std::map<std::string, std::string> env;  // added to (or, with an empty value, removed from) ours
  rlim_t file_size_limit = RLIM_INFINITY;  // RLIMIT_FSIZE: a disk that fills up at this size
};

Spawn pond(std::vector<std::string> argv) {
  Spawn s;
  s.argv = std::move(argv);
  return s;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class Faults : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    work_ = fs::path(POND_TEST_WORK_DIR) / info->name();
    fs::remove_all(work_);
    fs::create_directories(work_);
  }

  // Starts pond (argv[0] is added) with stderr to a file; returns the pid.
  pid_t start(const Spawn& s) {
    std::vector<std::string> args = {s.exe};
    args.insert(args.end(), s.argv.begin(), s.argv.end());
    const std::string err_path = (work_ / "stderr").string();
    const pid_t pid = ::fork();
    if (pid == 0) {
      const int fd = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      const int null = ::open("/dev/null", O_WRONLY);
      if (fd < 0 || null < 0) ::_exit(120);
      ::dup2(fd, 2);
      ::dup2(null, 1);
      for (const auto& [k, v] : s.env) v.empty() ? ::unsetenv(k.c_str()) : ::setenv(k.c_str(), v.c_str(), 1);
      if (s.file_size_limit != RLIM_INFINITY) {
        ::signal(SIGXFSZ, SIG_IGN);  // so a write past the limit fails with EFBIG, like a full disk
        const rlimit lim{s.file_size_limit, s.file_size_limit};
        ::setrlimit(RLIMIT_FSIZE, &lim);
      }
      std::vector<char*> argv;
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      ::execvp(argv[0], argv.data());
      ::_exit(121);
    }
    return pid;
  }

  // Waits for pid (at most `limit`: a hang fails the test instead of stalling the suite).
  Result wait(pid_t pid, std::chrono::seconds limit = std::chrono::seconds(300)) {
    Result r;
    int status = 0;
    const auto until = std::chrono::steady_clock::now() + limit;
    while (::waitpid(pid, &status, WNOHANG) == 0) {
      if (std::chrono::steady_clock::now() > until) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, &status, 0);
        ADD_FAILURE() << "pond did not finish within " << limit.count() << " s";
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.err = read_text(work_ / "stderr");
    return r;
  }

  Result run(const Spawn& s) { return wait(start(s)); }

  // True once pid has a handler for `sig` (/proc/PID/status SigCgt): then a signal sent reaches
  // pond's own handling, not the default action. False if the process ended first.
  static bool catches(pid_t pid, int sig) {
    for (int i = 0; i < 30000; ++i) {
      std::ifstream status("/proc/" + std::to_string(pid) + "/status");
      std::string line;
      bool alive = false;
      while (std::getline(status, line)) {
        if (line.rfind("State:", 0) == 0) alive = line.find('Z') == std::string::npos;
        if (line.rfind("SigCgt:", 0) == 0 && alive) {
          const unsigned long long mask = std::stoull(line.substr(7), nullptr, 16);
          if (mask & (1ull << (sig - 1))) return true;
        }
      }
      if (!alive) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  }

  void expect_no_temporaries() {
    for (const auto& e : fs::directory_iterator(work_))
      EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << "left behind: " << e.path();
  }

  void write_sentinel(const fs::path& p) { std::ofstream(p) << "sentinel\n"; }

  fs::path work_;
};

std::size_t lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

#ifdef POND_TEST_WITH_VULKAN
// No Vulkan driver: the loader finds no ICD. The GPU solver fails at run time (exit 1) with a
// message naming Vulkan; the CPU solvers do not need it.
TEST_F(Faults, NoVulkanDriverFailsTheGpuSolverOnly) {
  const std::map<std::string, std::string> no_icd = {{"VK_ICD_FILENAMES", "/nonexistent/icd.json"},
                                                     {"VK_DRIVER_FILES", "/nonexistent/icd.json"}};
  const fs::path out = work_ / "state.npy";
  Spawn s = pond({"simulate", "--solver", "gpu", "--steps", "10", "--out", out.string()});
  s.env = no_icd;
  Result r = run(s);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("Vulkan"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  expect_no_temporaries();
  s.argv[2] = "scalar";
  r = run(s);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out));
}

// No Vulkan loader: libvulkan.so.1 is hidden (an unloadable file bound over it in a private mount
// namespace, which needs root or CAP_SYS_ADMIN: skipped otherwise). pond does not link the loader,
// so it starts; the GPU solver fails with exit 1 and says the CPU solvers work, and they do.
TEST_F(Faults, NoVulkanLoaderFailsTheGpuSolverOnly) {
  std::string loader;
  for (const char* p : {"/usr/lib/x86_64-linux-gnu/libvulkan.so.1", "/lib/x86_64-linux-gnu/libvulkan.so.1",
                        "/usr/lib64/libvulkan.so.1", "/usr/lib/libvulkan.so.1"})
    if (fs::exists(p)) {
      loader = fs::canonical(p).string();
      break;
    }
  if (loader.empty()) GTEST_SKIP() << "no libvulkan.so.1 found to hide";
  if (::geteuid() != 0 || std::system("unshare -m --propagation private true 2>/dev/null") != 0)
    GTEST_SKIP() << "cannot hide the loader: needs root and unshare -m (a private mount namespace)";
  const fs::path fake = work_ / "libvulkan.so.1", out = work_ / "state.npy";
  std::ofstream(fake) << "not a shared library\n";
  auto hidden = [&](const std::string& solver) {
    const std::string script = "mount --bind \"$1\" \"$2\" || exit 125; shift 2; exec \"$@\"";
    Spawn s;
    s.exe = "unshare";
    s.argv = {"-m", "--propagation", "private", "sh", "-c", script, "sh", fake.string(), loader, POND_EXE,
              "simulate", "--solver", solver, "--steps", "10", "--out", out.string()};
    return run(s);
  };
  Result r = hidden("gpu");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("Vulkan is not available"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  r = hidden("scalar");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out));
}
#endif

// An output folder that cannot take a file is bad input, found before the run (exit 2), whoever
// runs it: a path whose "folder" is a file, a read-only folder (chmod 0555, which root ignores), and
// for root a folder of procfs, where access() says writable but no file can be created.
TEST_F(Faults, UnwritableOutputFolderIsBadInput) {
  std::ofstream(work_ / "a_file") << "x\n";
  Result r = run(pond({"simulate", "--steps", "10", "--out", (work_ / "a_file" / "state.npy").string()}));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("a_file"), std::string::npos) << r.err;

  const fs::path ro = work_ / "read_only";
  fs::create_directories(ro);
  fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                          fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
  const fs::path folder = ::geteuid() == 0 ? fs::path("/proc") : ro;  // root writes into a 0555 folder
  r = run(pond({"simulate", "--steps", "10", "--out", (folder / "pond-fault-test.npy").string()}));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("not writable"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(folder / "pond-fault-test.npy"));
  fs::permissions(ro, fs::perms::owner_all);
}

// A full disk as the output device: /dev/full takes the open and refuses the bytes (ENOSPC). Exit
// 1 naming the file and the reason; /dev/full is still the device (never renamed over).
TEST_F(Faults, FullDiskDeviceFailsAtRunTime) {
  if (!fs::is_character_file("/dev/full")) GTEST_SKIP() << "no /dev/full";
  Result r = run(pond({"simulate", "--steps", "10", "--out", "/dev/full"}));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("/dev/full"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

// A disk that fills up while the output is written (RLIMIT_FSIZE of 1 KiB: the write fails with
// EFBIG part-way, as on a full disk). Exit 1; the old file under the requested name is untouched and
// the partial temporary is removed.
TEST_F(Faults, DiskFillingUpKeepsTheOldOutput) {
  const fs::path out = work_ / "state.npy";
  write_sentinel(out);
  Spawn s;
  s.argv = {"simulate", "--steps", "10", "--out", out.string()};
  s.file_size_limit = 1024;
  Result r = run(s);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;
  EXPECT_EQ(read_text(out), "sentinel\n");
  expect_no_temporaries();
}

// SIGINT / SIGTERM during a long `pond simulate`: it stops between chunks of steps, says so in one
// line, exits 128 + the signal, and writes nothing (the old file under the requested name is
// untouched, no temporary file). The signal is sent once pond catches it (/proc/PID/status), so
// the test does not depend on timing.
class Interrupts : public Faults {
 protected:
  void check(int sig, const std::vector<std::string>& extra) {
    const fs::path out = work_ / "state.npy";
    write_sentinel(out);
    Spawn s;
    s.argv = {"simulate", "--steps", "1000000000000", "--out", out.string()};
    s.argv.insert(s.argv.end(), extra.begin(), extra.end());
    const pid_t pid = start(s);
    ASSERT_TRUE(catches(pid, sig)) << "pond ended before catching the signal: " << read_text(work_ / "stderr");
    ::kill(pid, sig);
    const Result r = wait(pid, std::chrono::seconds(120));
    EXPECT_EQ(r.code, 128 + sig) << r.err;
    EXPECT_EQ(lines(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find(std::string("interrupted by ") + (sig == SIGINT ? "SIGINT" : "SIGTERM")),
              std::string::npos) << r.err;
    EXPECT_NE(r.err.find("nothing was written"), std::string::npos) << r.err;
    EXPECT_EQ(read_text(out), "sentinel\n");
    expect_no_temporaries();
  }
};

TEST_F(Interrupts, SigintStopsCpuSimulate) { check(SIGINT, {"--solver", "scalar", "--threads", "1"}); }
TEST_F(Interrupts, SigtermStopsCpuSimulate) { check(SIGTERM, {}); }
#ifdef POND_TEST_WITH_VULKAN
TEST_F(Interrupts, SigintStopsGpuSimulate) { check(SIGINT, {"--solver", "gpu"}); }
#endif

}  // namespace
