// Output paths judged by what they name (core/output_paths.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "core/errors.h"
#include "core/output_paths.h"

namespace pond {
namespace {
namespace fs = std::filesystem;

class OutputPaths : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pond-output-paths-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "sub");
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(OutputPaths, NotYetWrittenFilesAreComparedByFolderAndName) {
  EXPECT_TRUE(same_file(dir_ / "a.npy", dir_ / "." / "a.npy"));
  EXPECT_TRUE(same_file(dir_ / "a.npy", dir_ / "sub" / ".." / "a.npy"));
  EXPECT_FALSE(same_file(dir_ / "a.npy", dir_ / "sub" / "a.npy"));
  EXPECT_FALSE(same_file(dir_ / "a.npy", dir_ / "b.npy"));
  fs::create_directory_symlink(dir_ / "sub", dir_ / "link");
  EXPECT_TRUE(same_file(dir_ / "sub" / "x.npy", dir_ / "link" / "x.npy"));
}

TEST_F(OutputPaths, ExistingFilesAreComparedByWhatTheyAre) {
  std::ofstream(dir_ / "real.npy") << "x";
  fs::create_symlink(dir_ / "real.npy", dir_ / "alias.npy");
  fs::create_hard_link(dir_ / "real.npy", dir_ / "hard.npy");
  EXPECT_TRUE(same_file(dir_ / "real.npy", dir_ / "alias.npy"));
  EXPECT_TRUE(same_file(dir_ / "hard.npy", dir_ / "alias.npy"));
  EXPECT_FALSE(same_file(dir_ / "real.npy", dir_ / "other.npy"));
}

TEST_F(OutputPaths, TheFirstPairNamingOneFileIsRefused) {
  EXPECT_NO_THROW(check_distinct_outputs({{"--out", dir_ / "a"}, {"--bodies-out", ""}, {"--x", dir_ / "b"}}));
  try {
    check_distinct_outputs({{"--out", dir_ / "a"}, {"--x", dir_ / "b"}, {"--bodies-out", dir_ / "sub/../a"}});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--bodies-out"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("names the same file as --out"), std::string::npos) << e.what();
  }
}

TEST_F(OutputPaths, NamesLongerThanTheFolderTakesAreRefused) {
  const long name_max = ::pathconf(dir_.c_str(), _PC_NAME_MAX);
  ASSERT_GT(name_max, static_cast<long>(kTemporaryNameRoom));
  const std::size_t fits = static_cast<std::size_t>(name_max) - kTemporaryNameRoom;
  EXPECT_NO_THROW(check_name_length(dir_ / std::string(fits, 'x'), dir_));
  EXPECT_THROW(check_name_length(dir_ / std::string(fits + 1, 'x'), dir_), InputError);
}

}  // namespace
}  // namespace pond
