// A floating body against the land (shared/bodies.h, step 2, after the pairs), grid units: the
// pond's walls (the rim, continued upward, so no ball leaves the pond), the floor and the land
// cells (islands, as row runs) up to the land's top. Each contact pushes the body out along its
// normal, then answers with restitution POND_RESTITUTION_LAND and Coulomb friction
// POND_FRICTION_LAND (contact_response, which the pairs share).
#ifndef POND_BODY_LAND_H
#define POND_BODY_LAND_H

#include "shared/bodies.h"

#define POND_MIN_DISTANCE2 1e-12  // below this squared distance a contact has no direction

// The land's row runs (shared/bodies.h): a parameter in C++, the shader's `land` buffer in GLSL.
#ifdef __cplusplus
#define POND_LAND_PARAM const uint *land,
namespace pond::shared {
#else
#define POND_LAND_PARAM
#endif

// The velocity response of a contact with unit normal n (from the other side toward b) whose other
// side has infinite mass and no velocity: no normal velocity into it, a bounce of `restitution`
// above bounce_speed, Coulomb friction on the tangential velocity.
POND_BODY_FN void contact_response(POND_INOUT(BodyState) b, float nx, float ny, float nz, float restitution,
                                   float friction, float bounce_speed) {
  POND_PRECISE float vn = b.vx * nx;
  POND_PRECISE float t = b.vy * ny;
  vn = vn + t;
  t = b.vz * nz;
  vn = vn + t;
  if (!(vn < 0.0f)) return;
  POND_PRECISE float e = -vn > bounce_speed ? restitution : 0.0f;
  POND_PRECISE float jn = 1.0f + e;
  jn = jn * vn;
  jn = -jn;  // the normal impulse per unit mass, > 0
  POND_PRECISE float tx = nx * vn;
  tx = b.vx - tx;
  POND_PRECISE float ty = ny * vn;
  ty = b.vy - ty;
  POND_PRECISE float tz = nz * vn;
  tz = b.vz - tz;
  POND_PRECISE float t2 = tx * tx;
  t = ty * ty;
  t2 = t2 + t;
  t = tz * tz;
  t2 = t2 + t;
  POND_PRECISE float keep = 1.0f;  // the share of the tangential velocity friction leaves
  if (t2 > POND_MIN_DISTANCE2) {
    POND_PRECISE float inv_vt = rsqrt_exact(t2, kRsqrtStepsExact);
    POND_PRECISE float stop = friction * jn;
    stop = stop * inv_vt;
    keep = 1.0f - stop;
    keep = keep > 0.0f ? keep : 0.0f;
  }
  POND_PRECISE float vn_after = vn + jn;
  t = tx * keep; POND_PRECISE float u = nx * vn_after; t = t + u; b.vx = t;
  t = ty * keep; u = ny * vn_after; t = t + u; b.vy = t;
  t = tz * keep; u = nz * vn_after; t = t + u; b.vz = t;
}

// Pushes b out of the land by `depth` along the unit normal n, then its velocity response.
POND_BODY_FN void land_contact(POND_INOUT(BodyState) b, float nx, float ny, float nz, float depth, float bounce_speed) {
  POND_PRECISE float t;
  t = nx * depth; t = b.x + t; b.x = t;
  t = ny * depth; t = b.y + t; b.y = t;
  t = nz * depth; t = b.z + t; b.z = t;
  contact_response(b, nx, ny, nz, POND_RESTITUTION_LAND, POND_FRICTION_LAND, bounce_speed);
}

// b against a column of land [x0, x1] x [z0, z1] up to `top` (it reaches down past the floor).
// True when they touched.
POND_BODY_FN bool box_contact(POND_INOUT(BodyState) b, BodyConstants c, float x0, float x1, float z0, float z1,
                              float top, float bounce_speed) {
  POND_PRECISE float px = b.x > x0 ? (b.x < x1 ? b.x : x1) : x0;
  POND_PRECISE float py = b.y < top ? b.y : top;
  POND_PRECISE float pz = b.z > z0 ? (b.z < z1 ? b.z : z1) : z0;
  POND_PRECISE float dx = b.x - px;
  POND_PRECISE float dy = b.y - py;
  POND_PRECISE float dz = b.z - pz;
  POND_PRECISE float d2 = dx * dx;
  POND_PRECISE float t = dy * dy;
  d2 = d2 + t;
  t = dz * dz;
  d2 = d2 + t;
  if (!(d2 < c.radius2)) return false;
  if (d2 > POND_MIN_DISTANCE2) {
    POND_PRECISE float inv_d = rsqrt_exact(d2, kRsqrtStepsExact);
    POND_PRECISE float d = d2 * inv_d;
    POND_PRECISE float depth = c.radius - d;
    POND_PRECISE float nx = dx * inv_d;
    POND_PRECISE float ny = dy * inv_d;
    POND_PRECISE float nz = dz * inv_d;
    land_contact(b, nx, ny, nz, depth, bounce_speed);
  } else {  // the centre inside the land: out through its top
    POND_PRECISE float depth = top - b.y;
    depth = depth + c.radius;
    land_contact(b, 0.0f, 1.0f, 0.0f, depth, bounce_speed);
  }
  return true;
}

// A floating body against the pond's walls, its floor and the land cells near it. True when it
// touched any.
POND_BODY_FN bool collide_land(POND_LAND_PARAM POND_INOUT(BodyState) b, BodyConstants c, ContactPush p) {
  bool touched = false;
  const float r = c.radius;
  POND_PRECISE float lim = p.rim_x - r;
  if (b.x < r) { land_contact(b, 1.0f, 0.0f, 0.0f, r - b.x, p.bounce_speed); touched = true; }
  if (b.x > lim) { land_contact(b, -1.0f, 0.0f, 0.0f, b.x - lim, p.bounce_speed); touched = true; }
  lim = p.rim_z - r;
  if (b.z < r) { land_contact(b, 0.0f, 0.0f, 1.0f, r - b.z, p.bounce_speed); touched = true; }
  if (b.z > lim) { land_contact(b, 0.0f, 0.0f, -1.0f, b.z - lim, p.bounce_speed); touched = true; }
  lim = p.floor_y + r;
  if (b.y < lim) { land_contact(b, 0.0f, 1.0f, 0.0f, lim - b.y, p.bounce_speed); touched = true; }
  POND_PRECISE float bottom = b.y - r;
  if (!(bottom < p.land_y)) return touched;
  const int last_row = int(land[0]) - 1;
  const uint runs = POND_LAND_HEADER(land[0]);
  POND_PRECISE float lo = b.x - r;
  POND_PRECISE float hi = b.x + r;
  POND_PRECISE float zlo = b.z - r;
  POND_PRECISE float zhi = b.z + r;
  const int i0 = clip_index(floor(zlo), last_row), i1 = clip_index(floor(zhi), last_row);
  for (int i = i0; i <= i1; ++i)
    for (uint k = land[1 + i]; k < land[2 + i]; ++k) {
      const float x0 = float(land[runs + 2u * k]), x1 = float(land[runs + 2u * k + 1u]);
      if (x1 < lo) continue;
      if (x0 > hi) break;
      if (box_contact(b, c, x0, x1, float(i), float(i + 1), p.land_y, p.bounce_speed)) touched = true;
    }
  return touched;
}

#ifdef __cplusplus
}  // namespace pond::shared
#endif
#endif
