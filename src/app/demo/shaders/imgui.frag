#version 450
// The vertex colour (already in the target's space, see imgui.vert) times the font atlas.
layout(set = 0, binding = 0) uniform sampler2D font_atlas;

layout(location = 0) in vec4 in_color;
layout(location = 1) in vec2 in_uv;
layout(location = 0) out vec4 out_color;

void main() { out_color = in_color * texture(font_atlas, in_uv); }
