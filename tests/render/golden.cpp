#include "golden.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "core/png.h"

namespace pond::test {

void expect_golden(const std::string& name, const Rgba& img) {
  const std::filesystem::path golden = std::filesystem::path(POND_GOLDEN_DIR) / (name + ".png");
  const std::filesystem::path out = POND_TEST_OUT_DIR;
  std::filesystem::create_directories(out);
  pond::write_png(out / (name + ".actual.png"), img.width, img.height, img.pixels);
  if (std::getenv("POND_REGENERATE_GOLDENS")) {
    pond::write_png(golden, img.width, img.height, img.pixels);
    std::printf("regenerated %s\n", golden.c_str());
    return;
  }
  const Rgba expected = read_png(golden);
  ASSERT_GT(expected.width, 0) << "missing golden " << golden
                               << "; regenerate: POND_REGENERATE_GOLDENS=1 ctest --test-dir <build> -L image";
  const ImageDiff d = compare(expected, img, kGoldenLevels);
  if (d.share > kGoldenShare) {
    if (d.diff.width) pond::write_png(out / (name + ".diff.png"), d.diff.width, d.diff.height, d.diff.pixels);
    ADD_FAILURE() << name << ": " << 100 * d.share << "% of pixels differ by more than " << kGoldenLevels
                  << " levels (allowed " << 100 * kGoldenShare << "%), max difference " << d.max_difference
                  << "; see " << (out / (name + ".diff.png")) << " and .actual.png";
  }
}

}  // namespace pond::test
