#version 460
// Land shading: the ground colour, grassy on the flat tops, diffuse sun plus sky ambient, darker
// where the walls go down towards the (wet) floor.
#extension GL_GOOGLE_include_directive : require

#include "shared/water_render.h"
#include "shared/water_shading.h"

layout(std140, set = 0, binding = POND_RENDER_BINDING_FRAME) uniform Frame { WaterFrame f; };

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec3 in_normal;
layout(location = 0) out vec4 out_color;

void main() {
  const vec3 n = normalize(in_normal);
  const float diffuse = max(dot(n, f.sun.xyz), 0.0);
  const float top = smoothstep(0.7, 0.95, n.y);
  const vec3 grass = vec3(0.12, 0.2, 0.07);
  vec3 albedo = mix(f.ground.rgb, grass, top);
  const float wet = clamp(-in_world.y / max(f.pool.y, 1e-3) + 0.3, 0.0, 1.0);  // darker below the rim top
  albedo *= 1.0 - 0.45 * wet * (1.0 - top);
  const vec3 ambient = f.sky.rgb * (0.25 + 0.15 * n.y);
  out_color = finish_color(albedo * (ambient + 0.85 * diffuse * vec3(1.0, 0.96, 0.9)));
}
