#pragma once
// The golden-image check of the render tests. An image matches its golden when at most
// kGoldenShare of its pixels differ by more than kGoldenLevels (of 255) in some channel.
#include <cstddef>
#include <string>

#include "image_compare.h"

namespace pond::test {

// The size the image tests draw at, goldens included.
inline constexpr int kWidth = 256, kHeight = 160;

inline constexpr int kGoldenLevels = 4;        // channel difference still counted as equal
inline constexpr double kGoldenShare = 0.005;  // share of pixels allowed to differ by more

// What POND_REGENERATE_GOLDENS asks for: unset or empty, compare; "1", regenerate; any other
// value is a mistake (a "0" or "false" meant to compare must not rewrite the goldens): invalid.
enum class GoldenMode { compare, regenerate, invalid };
GoldenMode golden_mode(const char* value);

// Compares `img` with POND_GOLDEN_DIR/<name>.png and records a test failure when it does not
// match. Always writes POND_TEST_OUT_DIR/<name>.actual.png, and <name>.diff.png (red = differs) on
// a mismatch. With POND_REGENERATE_GOLDENS=1 in the environment it overwrites the golden instead;
// with any other non-empty value it fails and writes nothing.
void expect_golden(const std::string& name, const Rgba& img);

// An effect's pair of goldens, with it on and off, each checked as above; and where they differ
// (the effect's footprint: pixels of the two goldens more than kFootprintLevels apart, at least
// `min_footprint` of them) each picture matches its own golden to within kGoldenLevels on all
// but kFootprintShare of those pixels. The whole-picture tolerance alone would pass an effect that
// vanished if its footprint is under kGoldenShare of the picture (a trunk's shadow: 0.43 %).
inline constexpr int kFootprintLevels = 16;
inline constexpr double kFootprintShare = 0.05;
void expect_golden_pair(const std::string& on_name, const Rgba& on, const std::string& off_name, const Rgba& off,
                        std::size_t min_footprint = 50);

}  // namespace pond::test
