#pragma once
// Where a click lands on the water: the ray through a pixel intersected with the triangles of the
// current (moving) surface, not with the rest plane, so a splash lands where the wave is seen. And
// which body a press grabs (the nearest sphere the ray meets), and where a dragged body goes (the
// ray's point at the body's height).
#include <array>
#include <cstddef>
#include <optional>
#include <span>

#include "lod/camera_budget.h"
#include "sim/model.h"
#include "sim/solver.h"

namespace pond::app::demo {

struct Ray {
  std::array<double, 3> origin, direction;  // direction normalized
};

// The ray from the eye through pixel (x, y) (origin top-left, pixels), matching the renderer's
// perspective: vertical fovy, aspect width/height, up world +y.
Ray pixel_ray(const lod::Camera& camera, double x, double y);

struct SurfaceHit {
  double row = 0, col = 0;   // grid indices (fractional), barycentric in index space
  double distance = 0;       // along the ray, world units
};

// The nearest hit of `ray` with the surface of the displacements `at` (the solver's on the host:
// both triangles of every cell, world units), or nothing when the ray misses the water.
std::optional<SurfaceHit> intersect_surface(const Ray& ray, const sim::WaterModel& model,
                                           const sim::HostDisplacements& at);

struct Sphere {
  std::array<double, 3> centre;  // world units
  double radius = 0;
};

// The index of the nearest sphere `ray` meets in front of its origin, or nothing.
std::optional<std::size_t> pick_sphere(const Ray& ray, std::span<const Sphere> spheres);

// Where `ray` crosses the horizontal plane y = `height` in front of its origin, or nothing (a ray
// parallel to it or pointing away).
std::optional<std::array<double, 3>> intersect_height(const Ray& ray, double height);

}  // namespace pond::app::demo
