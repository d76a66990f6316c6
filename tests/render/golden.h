#pragma once
// The golden-image check of the render tests. An image matches its golden when at most
// kGoldenShare of its pixels differ by more than kGoldenLevels (of 255) in some channel.
#include <string>

#include "image_compare.h"

namespace pond::test {

// The size the image tests draw at, goldens included.
inline constexpr int kWidth = 256, kHeight = 160;

inline constexpr int kGoldenLevels = 4;        // channel difference still counted as equal
inline constexpr double kGoldenShare = 0.005;  // share of pixels allowed to differ by more

// Compares `img` with POND_GOLDEN_DIR/<name>.png and records a test failure when it does not
// match. Always writes POND_TEST_OUT_DIR/<name>.actual.png, and <name>.diff.png (red = differs) on
// a mismatch. With POND_REGENERATE_GOLDENS set in the environment it overwrites the golden instead.
void expect_golden(const std::string& name, const Rgba& img);

}  // namespace pond::test
