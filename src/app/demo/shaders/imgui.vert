#version 450
// ImGui's vertices (pixel positions, font atlas uv, sRGB colour) to clip space. Vulkan clip space
// has y down like ImGui's pixels, so the transform is a scale and an offset.
//
// ImGui's colours are sRGB values meant for a UNORM target. Into an sRGB image (the swapchain
// format the water needs) they are linearized here, so the store's encoding gives them back. Per
// vertex, not per pixel: the atlas is white (GetTexDataAsRGBA32 puts the glyph coverage in alpha
// only), so the colour of a pixel is the vertex colour, and llvmpipe would otherwise run pow() on
// every pixel of the panel.
layout(location = 0) in vec2 in_pos;
layout(location = 1) in vec2 in_uv;
layout(location = 2) in vec4 in_color;

layout(push_constant) uniform Push {
  vec2 scale;
  vec2 translate;
  uint srgb_target;
} push;

layout(location = 0) out vec4 out_color;
layout(location = 1) out vec2 out_uv;

vec3 srgb_to_linear(vec3 c) {
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

void main() {
  out_color = push.srgb_target != 0u ? vec4(srgb_to_linear(in_color.rgb), in_color.a) : in_color;
  out_uv = in_uv;
  gl_Position = vec4(in_pos * push.scale + push.translate, 0.0, 1.0);
}
