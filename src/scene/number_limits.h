#pragma once
// The ranges of a scene's numbers: where the arithmetic each feeds stays finite and meaningful, in
// the units it is used in (docs/hardening.md). The solver and the picture compute in float32 (7
// digits, at most 3.4e38), in grid units (world / spacing):
//  - a physics value lies within [1e-6, 1e6] of its unit (or is 0 where 0 means none), so that
//    the products the solver's constants are (c dt / m, g dt / h, ...) stay normal floats;
//  - a length or a coordinate lies within 1e6 grid spacings (a positive length, such as a
//    perturbation's radius, at least 1e-3), so positions and their squares stay far inside
//    float's range;
//  - an angle lies within one turn either way, while a degree is still far above its rounding.
#include <optional>
#include <string>

namespace pond::scene {

inline constexpr double kMinScale = 1e-6, kMaxScale = 1e6;
inline constexpr double kMaxSpacings = 1e6;
inline constexpr double kMinLengthSpacings = 1e-3;
inline constexpr double kMaxDegrees = 360.0;
// A body's float constants (shared::BodyConstants: mass ratios, drag rate) at most this large, so
// that a product of two stays finite.
inline constexpr double kMaxBodyConstant = 1e18;

// "is X, outside [LO, HI]UNIT" when `value` is not in [lo, hi] (X with the digits that show why:
// core/text.h number_outside), else nothing.
std::optional<std::string> outside(double value, double lo, double hi, const std::string& unit = "");

}  // namespace pond::scene
