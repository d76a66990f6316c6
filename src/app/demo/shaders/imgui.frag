#version 450
// ImGui's colours are sRGB values meant for a UNORM target. Into an sRGB image (the swapchain
// format the water needs) they are linearized first, so the store's encoding gives them back.
layout(set = 0, binding = 0) uniform sampler2D font_atlas;

layout(push_constant) uniform Push {
  vec2 scale;
  vec2 translate;
  uint srgb_target;
} push;

layout(location = 0) in vec4 in_color;
layout(location = 1) in vec2 in_uv;
layout(location = 0) out vec4 out_color;

vec3 srgb_to_linear(vec3 c) {
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

void main() {
  vec4 c = in_color * texture(font_atlas, in_uv);
  if (push.srgb_target != 0u) c.rgb = srgb_to_linear(c.rgb);
  out_color = c;
}
