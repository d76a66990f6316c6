// Replays every committed fuzz input through its target, in every build (release, and the
// sanitize preset's ASan + UBSan): the seed corpora (corpus/<target>/) and the inputs that once
// crashed a target (regressions/<target>/, each named after the bug it found). A crash, an escaping
// exception other than InputError, or a broken property (the target's checks of what the code
// under test must keep, targets.h) fails the test, naming the input and the property.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
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

struct PropertyBroken : std::runtime_error {
  using std::runtime_error::runtime_error;
};

[[noreturn]] void throw_property(const char* what) { throw PropertyBroken(what); }

// One input through a target: it must return 0 and break no property.
void replay_one(Target target, const std::string& bytes) {
  pond::fuzz::set_property_handler(throw_property);
  try {
    EXPECT_EQ(target(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), 0);
  } catch (const PropertyBroken& e) {
    ADD_FAILURE() << "property broken: " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "an exception escaped the target: " << e.what();
  }
  pond::fuzz::set_property_handler(nullptr);
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
    replay_one(target, bytes);
  }
}

// The replay fails on a broken property, and goes on to the next input.
int breaks_a_property(const std::uint8_t*, std::size_t size) {
  if (size == 1) pond::fuzz::property_failed("the test's own broken property");
  return 0;
}
TEST(FuzzReplay, ABrokenPropertyFailsTheReplay) {
  EXPECT_NONFATAL_FAILURE(replay_one(breaks_a_property, "x"), "property broken: the test's own broken property");
  replay_one(breaks_a_property, "xy");
}

TEST(FuzzReplay, Scene) { replay("scene", pond::fuzz::scene, 5); }
TEST(FuzzReplay, Npy) { replay("npy", pond::fuzz::npy, 5); }
TEST(FuzzReplay, Cli) { replay("cli", pond::fuzz::cli, 5); }
TEST(FuzzReplay, Checkpoint) { replay("checkpoint", pond::fuzz::checkpoint, 3); }

}  // namespace
