#pragma once
// How a scene is looked at (pond render, the demo): the scene file's optional "camera", "view" and
// "lighting" keys, world units, as src/scene validates them.
#include <array>
#include <cstdint>

namespace pond::view {

// A camera's coordinates lie within +-kMaxCameraCoordinate (world units): the squares of the
// distances float32 shaders and view matrices form stay finite (3 * 1e30 < 3.4e38).
inline constexpr double kMaxCameraCoordinate = 1e15;
// The vertical field of view (degrees) of every camera (the scene's, --fovy): past these,
// 1 / tan(fovy / 2) leaves float's range or the view folds over.
inline constexpr double kMinFovyDegrees = 0.01, kMaxFovyDegrees = 179.99;

// "camera": {"eye": [x, y, z], "target": [x, y, z], "fovy": degrees}; absent = a view of the whole
// pond chosen from the grid size.
struct CameraSpec {
  std::array<double, 3> eye{0, 10, 0};
  std::array<double, 3> target{0, 0, 1};
  double fovy_degrees = 45.0;
  bool operator==(const CameraSpec&) const = default;
};

// The picture's optional effects (the scene's "view" keys of the same names; FrameView::effects).
struct Effects {
  bool reflections = true;  // planar reflection of the land and the trees in the water
  bool caustics = true;     // the sun's light focused by the waves on the pool floor
  bool shadows = true;      // the sun's shadows of the trees and the bodies on the land and the water
  bool submerged = true;    // the islands' walls and the bodies under clear water, refracted
  bool foam = true;         // white water where the surface is stirred, drifting and fading
  static constexpr Effects none();  // every one off (below kEffects)
  bool operator==(const Effects&) const = default;
};

// Every effect, one row each: what the scene file, `pond render --profile`, the demo's keys, help
// and panel read, so a new effect is a row here and its pass (docs/architecture.md).
struct EffectEntry {
  const char* key;      // the scene's "view" key; the name --profile prints
  bool Effects::*flag;  // its switch
  const char* demo_key;  // one letter "A".."Z": the demo's toggle
  const char* label;    // the demo panel's checkbox
  const char* meaning;  // the demo help's line
};
inline constexpr EffectEntry kEffects[] = {
    {"reflections", &Effects::reflections, "M", "reflections", "reflections (mirror image) on / off"},
    {"caustics", &Effects::caustics, "K", "caustics", "caustics (focused sunlight on the floor) on / off"},
    {"shadows", &Effects::shadows, "L", "shadows", "shadows (of the trees and bodies) on / off"},
    {"submerged", &Effects::submerged, "U", "under water", "under water (islands' walls, bodies, refracted) on / off"},
    {"foam", &Effects::foam, "F", "foam", "foam (white water where the surface is stirred) on / off"},
};

constexpr Effects Effects::none() {
  Effects off;
  for (const EffectEntry& e : kEffects) off.*e.flag = false;
  return off;
}

// "view": what a rendered frame advances and which effects it draws (the floor and the land are
// the water's: sim::BasinSpec, the scene's "basin").
struct ViewSpec {
  std::int64_t steps_per_frame = 1;  // simulation steps per rendered frame
  double lod_tolerance_px = 1.0;     // LOD screen-space error bound; 0 = the full mesh
  Effects effects;                   // kEffects' keys: true | false
  bool operator==(const ViewSpec&) const = default;
};

// "lighting": the sun and the colours the water shader mixes (linear RGB in [0, 1]).
struct LightingSpec {
  std::array<double, 3> sun{-0.3, 0.38, -0.87};   // direction toward the sun (normalized on use)
  std::array<double, 3> water{0.015, 0.11, 0.13};  // the light deep water scatters back (its colour)
  // Beer-Lambert absorption per world unit of path (a world unit taken as a metre): pure water's
  // absorption coefficients near 640, 550 and 465 nm (Pope and Fry 1997), a clear pool.
  std::array<double, 3> absorption{0.30, 0.057, 0.0094};
  std::array<double, 3> sky{0.28, 0.52, 0.9};      // sky at the zenith (the horizon is lighter)
  std::array<double, 3> ground{0.55, 0.47, 0.33};  // pool floor, shore and islands
  bool operator==(const LightingSpec&) const = default;
};

}  // namespace pond::view
