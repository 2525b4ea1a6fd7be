// The renderer's GLSL 3.30 core programs, as source text (gl_renderer.cpp
// compiles them): lit instanced shapes with a shadow-mapped key light, their
// depth from the light for the shadow map, the inset's faded scene and
// paths, and flat lines (the grid).
#pragma once

namespace elbowsim::shaders {

// Each program is linked from pieces (link_program joins them in order), so
// that the lit and faded programs share their instance inputs and lighting.
inline constexpr const char* kVersion = "#version 330 core\n";

// Per instance: the model matrix (4 vec4), the normal matrix (inverse
// transpose of its linear part, 3 vec3) and a colour.
inline constexpr const char* kInstanceInputs = R"(
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 model0;
layout(location = 3) in vec4 model1;
layout(location = 4) in vec4 model2;
layout(location = 5) in vec4 model3;
layout(location = 6) in vec3 normal0;
layout(location = 7) in vec3 normal1;
layout(location = 8) in vec3 normal2;
layout(location = 9) in vec4 color;
uniform mat4 view_projection;
vec4 placed_position() { return mat4(model0, model1, model2, model3) * vec4(position, 1.0); }
vec3 placed_normal() { return mat3(normal0, normal1, normal2) * normal; }
)";

// Blinn-Phong:
//   c = ambient k + sum over lights of s_i L_i (max(n.l, 0) k + specular max(n.h, 0)^48),
//   h = (l + v)/|l + v|,
// where s_0 is the key light's visibility (from the shadow map, or 1) and
// s_1 = 1. light_term is light i's diffuse and specular terms for the base
// colour k; zero where the light is behind the face.
inline constexpr const char* kLighting = R"(
uniform vec3 eye;
uniform vec3 light_direction[2];
uniform vec3 light_color[2];
uniform float ambient;
uniform float specular;
vec3 light_term(int i, vec3 n, vec3 v, vec3 k) {
  vec3 l = light_direction[i];
  float diffuse = max(dot(n, l), 0.0);
  // (n.h)^48 by squaring: cheaper than pow() on llvmpipe.
  float s1 = max(dot(n, normalize(l + v)), 0.0);
  float s2 = s1 * s1, s4 = s2 * s2, s8 = s4 * s4, s16 = s8 * s8;
  float shine = diffuse > 0.0 ? s16 * s16 * s16 : 0.0;
  return light_color[i] * (diffuse * k + specular * shine);
}
// Everything but the key light: ambient and the fill light.
vec3 unshadowed_light(vec3 n, vec3 v, vec3 k) { return ambient * k + light_term(1, n, v, k); }
)";

// Where a world point (p, normal n) is in the shadow map: the light's view
// is orthographic, so this is affine in the position and interpolates
// exactly across a triangle; the point is moved 1.5 texels along its normal
// (no self-shadowing "acne").
inline constexpr const char* kShadowCoordinate = R"(
uniform mat4 light_view_projection;
uniform float shadow_texel;
vec3 shadow_coordinate(vec3 p, vec3 n) {
  vec4 s = light_view_projection * vec4(p + 1.5 * shadow_texel * normalize(n), 1.0);
  return s.xyz * 0.5 + 0.5;
}
)";

// The key light's visibility from the shadow map, looked up where the
// vertex stage put the point in the light's view (per vertex: per pixel,
// that transform cost 15 % of a video's CPU), with one bilinear depth
// comparison (the four nearest texels compared and blended). In shadow the
// key keeps `shadow_keep` of its light, so shadowed faces keep their form.
inline constexpr const char* kShadowLookup = R"(
in vec3 shadow_coord;
uniform int shadows;
uniform sampler2DShadow shadow_map;
uniform float shadow_keep;
float key_visibility() {
  if (shadows == 0) return 1.0;
  return mix(shadow_keep, 1.0, texture(shadow_map, shadow_coord));
}
)";

// The lit program's vertex stage: world position and normal per vertex,
// lighting per fragment.
inline constexpr const char* kLitVertex = R"(
out vec3 world_position;
out vec3 world_normal;
out vec3 base_color;
out vec3 shadow_coord;
void main() {
  vec4 p = placed_position();
  world_position = p.xyz;
  world_normal = placed_normal();
  base_color = color.rgb;
  gl_Position = view_projection * p;
  shadow_coord = shadow_coordinate(p.xyz, world_normal);
}
)";

// Lighting per fragment.
// No loop and no branch around the shadow lookup: llvmpipe runs every branch
// of a group of fragments under a mask, so a lookup inside a loop over the
// lights would be paid once per light.
inline constexpr const char* kLitFragment = R"(
in vec3 world_position;
in vec3 world_normal;
in vec3 base_color;
out vec4 frag_color;
void main() {
  vec3 n = normalize(world_normal);
  vec3 v = normalize(eye - world_position);
  vec3 c = unshadowed_light(n, v, base_color) + key_visibility() * light_term(0, n, v, base_color);
  frag_color = vec4(min(c, vec3(1.0)), 1.0);
}
)";

// Flat faces (boxes: the tables, the base) lit per vertex. Under
// directional lights the diffuse terms are the same at every point of a
// face, so only the specular terms are interpolated: the renderer draws a
// box this way only where no face of it shows a highlight of half a level
// or more (lighting.hpp, specular_shows), and with the lit program
// otherwise. The key light's part is kept apart for the shadow look-up per
// fragment. Per fragment, the table's lighting was a tenth of a render's CPU.
inline constexpr const char* kFlatFaceVertex = R"(
out vec3 unshadowed;  // ambient and the fill light
out vec3 key_light;   // the key light's part, before its visibility
out vec3 shadow_coord;
void main() {
  vec4 p = placed_position();
  gl_Position = view_projection * p;
  vec3 n = normalize(placed_normal());
  vec3 v = normalize(eye - p.xyz);
  unshadowed = unshadowed_light(n, v, color.rgb);
  key_light = light_term(0, n, v, color.rgb);
  shadow_coord = shadow_coordinate(p.xyz, n);
}
)";

inline constexpr const char* kFlatFaceFragment = R"(
in vec3 unshadowed;
in vec3 key_light;
out vec4 frag_color;
void main() { frag_color = vec4(min(unshadowed + key_visibility() * key_light, vec3(1.0)), 1.0); }
)";

// The inset's faded scene: lit per vertex (Gouraud), no shadows, then mixed
// `fade` of the way toward fade_color. Per fragment it cost a tenth of a
// render's CPU; at 28 % contrast the difference hardly shows (docs/rendering.md,
// "Lighting"). Drawn with kUnlitFragment, which takes base_color as it is.
inline constexpr const char* kFadedVertex = R"(
uniform float fade;
uniform vec3 fade_color;
out vec3 base_color;
void main() {
  vec4 p = placed_position();
  gl_Position = view_projection * p;
  vec3 n = normalize(placed_normal());
  vec3 v = normalize(eye - p.xyz);
  vec3 c = unshadowed_light(n, v, color.rgb) + light_term(0, n, v, color.rgb);
  base_color = mix(min(c, vec3(1.0)), fade_color, fade);
}
)";

// A colour as it is, no lighting: the inset's paths (with kLitVertex, so
// their positions are the lit program's) and its faded scene (kFadedVertex).
inline constexpr const char* kUnlitFragment = R"(
in vec3 base_color;
out vec4 frag_color;
void main() { frag_color = vec4(base_color, 1.0); }
)";

// Depth from the key light, for the shadow map: the same instances, no colour.
inline constexpr const char* kDepthVertex = R"(
void main() {
  gl_Position = view_projection * placed_position();
}
)";

inline constexpr const char* kDepthFragment = R"(
void main() {}
)";

inline constexpr const char* kFlatVertex = R"(
layout(location = 0) in vec3 position;
uniform mat4 view_projection;
void main() { gl_Position = view_projection * vec4(position, 1.0); }
)";

inline constexpr const char* kFlatFragment = R"(
uniform vec3 color;
out vec4 frag_color;
void main() { frag_color = vec4(color, 1.0); }
)";

}  // namespace elbowsim::shaders
