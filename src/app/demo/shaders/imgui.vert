#version 450
// ImGui's vertices (pixel positions, font atlas uv, sRGB colour) to clip space. Vulkan clip space
// has y down like ImGui's pixels, so the transform is a scale and an offset.
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

void main() {
  out_color = in_color;
  out_uv = in_uv;
  gl_Position = vec4(in_pos * push.scale + push.translate, 0.0, 1.0);
}
