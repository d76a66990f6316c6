// Replays every committed fuzz input through its target, in every build (release, and the
// sanitize preset's ASan + UBSan): the seed corpora (corpus/<target>/) and the inputs that once
// crashed a target (regressions/<target>/, each named after the bug it found). A crash, an escaping
// exception other than InputError, or a failed property check fails the test.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "targets.h"

namespace {
namespace fs = std::filesystem;
using Target = int (*)(const std::uint8_t*, std::size_t);

std::vector<fs::path> inputs(const std::string& folder) {
  std::vector<fs::path> files;
  const fs::path dir = fs::path(POND_FUZZ_DIR) / folder;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file() && e.path().filename() != "README.md") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

void replay(const std::string& name, Target target, std::size_t min_corpus) {
  const std::vector<fs::path> corpus = inputs("corpus/" + name);
  EXPECT_GE(corpus.size(), min_corpus) << "the seed corpus of " << name << " went missing";
  std::vector<fs::path> all = corpus;
  for (const fs::path& p : inputs("regressions/" + name)) all.push_back(p);
  for (const fs::path& p : all) {
    SCOPED_TRACE(p.string());
    std::ifstream in(p, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(target(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), 0);
  }
}

TEST(FuzzReplay, Scene) { replay("scene", pond::fuzz::scene, 5); }
TEST(FuzzReplay, Npy) { replay("npy", pond::fuzz::npy, 5); }
TEST(FuzzReplay, Cli) { replay("cli", pond::fuzz::cli, 5); }
TEST(FuzzReplay, Checkpoint) { replay("checkpoint", pond::fuzz::checkpoint, 3); }

}  // namespace
