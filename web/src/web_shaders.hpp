// The web demo's own shaders (GLSL ES 3.00: WebGL2 in the browser, OpenGL ES 3.0 natively), the
// host's side of the frame: a shadow map, the lit head into diffuse and specular targets, and the
// composite after the library has scattered the diffuse.
#pragma once

#include <string>

#include "mesh_vertex_shader.hpp"

namespace web {

// Depth only, from the key light.
inline const char* const kShadowVertex = R"(#version 300 es
layout(location = 0) in vec3 a_position;
uniform mat4 u_light_matrix;
void main() { gl_Position = u_light_matrix * vec4(a_position, 1.0); }
)";

inline const char* const kShadowFragment = R"(#version 300 es
precision mediump float;
void main() {}
)";

// The mesh's vertex stage, shared with the native demo (integration/gltf_mesh/mesh_vertex_shader.hpp).
inline const std::string kLitVertex = gltf_mesh::mesh_vertex_shader("#version 300 es");

// Diffuse (albedo x irradiance, alpha = the scattering strength) and specular (Kelemen and
// Szirmay-Kalos with a Beckmann lobe) to two RGBA16F targets: the library scatters the first only.
inline const char* const kLitFragment = R"(#version 300 es
precision highp float;
precision highp sampler2DShadow;
in vec3 v_position;
in vec3 v_normal;
in vec4 v_tangent;
in vec2 v_texcoord;
uniform sampler2D u_albedo;
uniform sampler2D u_normal_map;
uniform sampler2DShadow u_shadow_map;
uniform mat4 u_light_matrix;
uniform float u_shadow_texel;
uniform vec3 u_light_direction[2];
uniform vec3 u_light_irradiance[2];
uniform vec3 u_eye;
uniform float u_sss_strength;
layout(location = 0) out vec4 o_diffuse;
layout(location = 1) out vec4 o_specular;

float shadow_factor(vec3 p) {
  vec4 clip = u_light_matrix * vec4(p, 1.0);
  vec3 s = clip.xyz / clip.w * 0.5 + 0.5;
  if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) lit += texture(u_shadow_map, vec3(s.xy + vec2(x, y) * u_shadow_texel, s.z));
  return lit / 9.0;
}

float specular_ksk(vec3 n, vec3 l, vec3 v) {
  float n_dot_l = dot(n, l);
  if (n_dot_l <= 0.0) return 0.0;
  vec3 h = l + v;
  vec3 hn = normalize(h);
  float c2 = max(dot(n, hn) * dot(n, hn), 1e-6);
  const float m2 = 0.35 * 0.35;
  float beckmann = exp((c2 - 1.0) / (c2 * m2)) / (m2 * c2 * c2);
  float base = pow(1.0 - max(dot(hn, v), 0.0), 5.0);
  float fresnel = base + 0.028 * (1.0 - base);
  return n_dot_l * 0.18 * max(beckmann * fresnel / dot(h, h), 0.0);
}

void main() {
  vec3 geometric = normalize(v_normal) * (gl_FrontFacing ? 1.0 : -1.0);
  vec3 t = normalize(v_tangent.xyz - geometric * dot(geometric, v_tangent.xyz));
  vec3 b = cross(geometric, t) * (v_tangent.w < 0.0 ? -1.0 : 1.0);
  vec3 m = texture(u_normal_map, v_texcoord).xyz * 2.0 - 1.0;
  m.y = -m.y;  // the head's normal map has its green flipped (docs/demo.md)
  vec3 n = normalize(t * m.x + b * m.y + geometric * max(m.z, 1e-3));
  vec3 v = normalize(u_eye - v_position);
  vec3 irradiance = mix(vec3(0.02, 0.018, 0.016), vec3(0.035, 0.035, 0.04), n.y * 0.5 + 0.5);
  vec3 specular = vec3(0.0);
  for (int i = 0; i < 2; ++i) {
    vec3 l = u_light_direction[i];
    float shadow = 1.0;
    if (i == 0) shadow = dot(geometric, l) > 0.0 ? shadow_factor(v_position + geometric * 0.002) : 0.0;
    irradiance += u_light_irradiance[i] * (max(dot(n, l), 0.0) * shadow);
    specular += u_light_irradiance[i] * (shadow * specular_ksk(n, l, v));
  }
  vec3 albedo = texture(u_albedo, v_texcoord).rgb;
  o_diffuse = vec4(albedo * irradiance, u_sss_strength);
  o_specular = vec4(specular, 0.0);
}
)";

inline const char* const kFullscreenVertex = R"(#version 300 es
out vec2 v_uv;
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  v_uv = p;
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

// Diffuse (scattered left of u_split_x... or not) + specular, Narkowicz's ACES fit, the sRGB curve.
inline const char* const kCompositeFragment = R"(#version 300 es
precision highp float;
in vec2 v_uv;
uniform sampler2D u_before;
uniform sampler2D u_after;
uniform sampler2D u_specular;
uniform float u_split;  // texture x below which the unscattered diffuse is shown
uniform vec3 u_background;
out vec4 o_color;
vec3 srgb(vec3 c) {
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 before = texelFetch(u_before, p, 0);
  vec4 diffuse = v_uv.x < u_split ? before : texelFetch(u_after, p, 0);
  vec3 c = before.a > 0.0 ? diffuse.rgb + texelFetch(u_specular, p, 0).rgb : u_background;
  c *= 1.6;
  c = clamp((c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
  if (abs(v_uv.x - u_split) * float(textureSize(u_after, 0).x) < 0.5) c = vec3(0.8);
  o_color = vec4(srgb(c), 1.0);
}
)";

}  // namespace web
