#include "golden.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

#include "core/png.h"

namespace pond::test {

namespace {

std::filesystem::path golden_path(const std::string& name) {
  return std::filesystem::path(POND_GOLDEN_DIR) / (name + ".png");
}

// The share of `pixels` (indices) where a and b differ by more than `levels` in some channel.
double share_differing(const Rgba& a, const Rgba& b, const std::vector<std::size_t>& pixels, int levels) {
  std::size_t differing = 0;
  for (std::size_t p : pixels) {
    int most = 0;
    for (int c = 0; c < 3; ++c) most = std::max(most, std::abs(a.pixels[p * 4 + c] - b.pixels[p * 4 + c]));
    differing += most > levels;
  }
  return pixels.empty() ? 0.0 : static_cast<double>(differing) / static_cast<double>(pixels.size());
}

}  // namespace

GoldenMode golden_mode(const char* value) {
  if (!value || !*value) return GoldenMode::compare;
  return std::strcmp(value, "1") == 0 ? GoldenMode::regenerate : GoldenMode::invalid;
}

void expect_golden(const std::string& name, const Rgba& img) {
  const std::filesystem::path golden = golden_path(name);
  const std::filesystem::path out = POND_TEST_OUT_DIR;
  const char* regenerate = std::getenv("POND_REGENERATE_GOLDENS");
  const GoldenMode mode = golden_mode(regenerate);
  if (mode == GoldenMode::invalid) {
    ADD_FAILURE() << "POND_REGENERATE_GOLDENS=" << regenerate
                  << ": set it to 1 to regenerate the goldens, or leave it unset to compare";
    return;
  }
  std::filesystem::create_directories(out);
  pond::write_png(out / (name + ".actual.png"), img.width, img.height, img.pixels);
  if (mode == GoldenMode::regenerate) {
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

void expect_golden_pair(const std::string& on_name, const Rgba& on, const std::string& off_name, const Rgba& off,
                        std::size_t min_footprint) {
  expect_golden(on_name, on);
  expect_golden(off_name, off);
  if (golden_mode(std::getenv("POND_REGENERATE_GOLDENS")) != GoldenMode::compare) return;
  const Rgba golden_on = read_png(golden_path(on_name)), golden_off = read_png(golden_path(off_name));
  if (golden_on.width != on.width || golden_on.height != on.height || golden_off.width != on.width ||
      golden_off.height != on.height || off.width != on.width || off.height != on.height)
    return;  // expect_golden has failed already
  std::vector<std::size_t> footprint;
  const std::size_t pixels = static_cast<std::size_t>(on.width) * static_cast<std::size_t>(on.height);
  for (std::size_t p = 0; p < pixels; ++p) {
    int most = 0;
    for (int c = 0; c < 3; ++c) most = std::max(most, std::abs(golden_on.pixels[p * 4 + c] - golden_off.pixels[p * 4 + c]));
    if (most > kFootprintLevels) footprint.push_back(p);
  }
  ASSERT_GE(footprint.size(), min_footprint) << on_name << " and " << off_name << " differ in too few pixels to tell apart";
  const double on_share = share_differing(on, golden_on, footprint, kGoldenLevels);
  const double off_share = share_differing(off, golden_off, footprint, kGoldenLevels);
  std::printf("%s / %s: footprint %zu pixels, %.2f%% / %.2f%% of them differ from their goldens\n", on_name.c_str(),
              off_name.c_str(), footprint.size(), 100 * on_share, 100 * off_share);
  EXPECT_LE(on_share, kFootprintShare) << on_name << " differs from its golden where " << off_name << " does";
  EXPECT_LE(off_share, kFootprintShare) << off_name << " differs from its golden where " << on_name << " does";
}

}  // namespace pond::test
