#include "composite.hpp"

#include "host_gl_util.hpp"

namespace demo {

namespace {

const char *const kFragmentShader = R"(#version 330 core
uniform sampler2D u_before;
uniform sampler2D u_after;
uniform sampler2D u_specular;
uniform sampler2D u_heat_map;
uniform usampler2D u_profile;  // R8UI: profile | object << 4
uniform int u_mode;         // 0 final, 1 split, 2 heat map, 3 touched, 4 profiles
uniform float u_exposure;
uniform float u_split_x;    // pixels from the left
uniform vec2 u_size;        // output size in pixels
uniform int u_debug_view;   // the sss_debug_view in u_after (0: the filtered image)
uniform vec2 u_view_depth;  // the depth view's nearest and farthest view distance
uniform float u_taps;       // the taps view's top (sss_settings.taps)
out vec4 o_color;

// Narkowicz's fit of the ACES filmic curve (with his 0.6 input scale).
vec3 filmic(vec3 x) {
  x *= 0.6;
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 srgb_encode(vec3 c) {
  vec3 low = c * 12.92;
  vec3 high = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
  return mix(low, high, step(vec3(0.0031308), c));
}

vec3 display(vec3 diffuse, vec3 specular) {
  return srgb_encode(filmic(max(diffuse + specular, vec3(0.0)) * u_exposure));
}

// Flat false colours (no shading, so each profile/object pair is one colour in the PNG): a hue per
// profile, darker for each further object of it; the background and opaque pixels dark grey.
const vec3 kProfileColours[8] = vec3[8](vec3(0.95, 0.55, 0.45), vec3(0.55, 0.75, 0.95), vec3(0.95, 0.85, 0.35),
                                        vec3(0.55, 0.90, 0.50), vec3(0.80, 0.50, 0.90), vec3(0.40, 0.90, 0.85),
                                        vec3(0.95, 0.45, 0.70), vec3(0.85, 0.85, 0.85));
vec3 profile_colour(uint value, float alpha) {
  if (alpha <= 0.0) return vec3(0.12);
  uint profile = value & 15u, object = value >> 4;
  vec3 c = kProfileColours[profile & 7u] * (profile >= 8u ? 0.6 : 1.0);
  return c * (object <= 1u ? 1.0 : 1.0 - 0.22 * float((object - 1u) % 4u));
}

// 0 at 0.01 profile mm per pixel (a 4K close-up's finest) to 1 at 10 (a far crowd), logarithmic.
float footprint_level(float mm) { return clamp((log2(max(mm, 1e-6)) - log2(0.01)) / log2(1000.0), 0.0, 1.0); }

// A debug view (sss.h sss_debug_view) in colours a person reads: each pass's number in its own
// channel (red the horizontal pass, green the vertical one) where the view has two; the pixels the
// passes leave alone ((0, 0, 0, 1) in the view) show the unfiltered frame in dim grey.
vec3 debug_colour(vec4 view, vec3 base) {
  bool alone = view.rgb == vec3(0.0);
  vec3 dim = vec3(0.1 + 0.3 * dot(base, vec3(0.2126, 0.7152, 0.0722)));
  if (u_debug_view == 6) return mix(dim, view.rgb, 0.6);  // tiles: r passes, g inputs, b marked
  if (alone) return dim;
  if (u_debug_view == 5) return profile_colour(uint(view.r) | (uint(view.g) << 4), 1.0);  // kProfiles' hues
  if (u_debug_view == 1) return vec3(1.0, 0.55, 0.1);  // mask
  if (u_debug_view == 2) {  // depth: white at the scene's nearest point, dark at its farthest
    float t = clamp((view.r - u_view_depth.x) / (u_view_depth.y - u_view_depth.x), 0.0, 1.0);
    return vec3(1.0 - 0.85 * t);
  }
  if (u_debug_view == 3) return vec3(footprint_level(view.r), footprint_level(view.g), 0.15);
  return vec3((view.rg - 1.0) / max(u_taps - 1.0, 1.0), 0.15);  // taps: 1 (the centre alone) to u_taps
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  if (u_debug_view != 0 && u_mode != 2 && u_mode != 4) {
    vec4 before = texelFetch(u_before, p, 0);
    vec3 base = display(before.rgb, texelFetch(u_specular, p, 0).rgb);
    o_color = vec4(debug_colour(texelFetch(u_after, p, 0), base), 1.0);
    return;
  }
  if (u_mode == 4) {
    o_color = vec4(profile_colour(texelFetch(u_profile, p, 0).r, texelFetch(u_before, p, 0).a), 1.0);
    return;
  }
  vec3 specular = texelFetch(u_specular, p, 0).rgb;
  if (u_mode == 1) {
    if (abs(gl_FragCoord.x - u_split_x) < 1.0) {  // two pixels wide
      o_color = vec4(1.0);
      return;
    }
    vec3 d = gl_FragCoord.x < u_split_x ? texelFetch(u_before, p, 0).rgb : texelFetch(u_after, p, 0).rgb;
    o_color = vec4(display(d, specular), 1.0);
  } else if (u_mode == 2) {
    o_color = vec4(texture(u_heat_map, gl_FragCoord.xy / u_size).rgb, 1.0);
  } else if (u_mode == 3) {
    vec4 before = texelFetch(u_before, p, 0);
    vec4 after = texelFetch(u_after, p, 0);
    float grey = dot(display(after.rgb, specular), vec3(0.2126, 0.7152, 0.0722));
    vec3 base = vec3(0.15 + 0.45 * grey);
    if (any(notEqual(before, after)))
      o_color = vec4(mix(base, vec3(1.0, 0.45, 0.0), 0.75), 1.0);
    else if (before.a > 0.0)
      o_color = vec4(mix(base, vec3(0.1, 0.35, 1.0), 0.6), 1.0);
    else
      o_color = vec4(base * 0.6, 1.0);
  } else {
    o_color = vec4(display(texelFetch(u_after, p, 0).rgb, specular), 1.0);
  }
}
)";

}  // namespace

const char *view_mode_name(ViewMode mode) {
  switch (mode) {
    case ViewMode::kFinal: return "final";
    case ViewMode::kSplit: return "split";
    case ViewMode::kHeatMap: return "heatmap";
    case ViewMode::kTouched: return "touched";
    case ViewMode::kProfiles: return "profiles";
  }
  return "?";
}

const char *debug_view_legend(int view) {
  switch (view) {
    case 1: return "orange: the pixels the passes change";
    case 2: return "the view distance the passes read: white at the scene's nearest point, dark at its farthest";
    case 3: return "profile mm per pixel step, red the horizontal pass, green the vertical, each from 0.01 (dark) "
                   "to 10 (full) on a log scale; yellow where both are coarse";
    case 4: return "taps read, red the horizontal pass, green the vertical, from 1 (dark) to the settings' taps (full)";
    case 5: return "the profile and object the passes read, in the profiles view's colours";
    case 6: return "16x16 tiles of the masked path: red its blur passes draw, green its inputs draw, blue the tile "
                   "holds a translucent pixel (white: all three)";
    default: return "the filtered image";
  }
}

bool create_composite_pass(CompositePass *pass) {
  pass->program = build_program("composite", kFullscreenVertexShader, kFragmentShader);
  if (pass->program == 0) return false;
  glUseProgram(pass->program);
  glUniform1i(glGetUniformLocation(pass->program, "u_before"), 0);
  glUniform1i(glGetUniformLocation(pass->program, "u_after"), 1);
  glUniform1i(glGetUniformLocation(pass->program, "u_specular"), 2);
  glUniform1i(glGetUniformLocation(pass->program, "u_heat_map"), 3);
  glUniform1i(glGetUniformLocation(pass->program, "u_profile"), 4);
  glUseProgram(0);
  glGenVertexArrays(1, &pass->vao);
  return check_gl("composite pass setup");
}

void run_composite_pass(const CompositePass &pass, const FrameTargets &targets, const CompositeInput &in) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targets.output_framebuffer);
  glViewport(0, 0, targets.width, targets.height);
  glUseProgram(pass.program);
  glUniform1i(glGetUniformLocation(pass.program, "u_mode"), static_cast<GLint>(in.mode));
  glUniform1f(glGetUniformLocation(pass.program, "u_exposure"), in.exposure);
  glUniform1f(glGetUniformLocation(pass.program, "u_split_x"),
              static_cast<float>(static_cast<int>(in.split * static_cast<float>(targets.width))));
  glUniform2f(glGetUniformLocation(pass.program, "u_size"), static_cast<float>(targets.width),
              static_cast<float>(targets.height));
  glUniform1i(glGetUniformLocation(pass.program, "u_debug_view"), in.debug_view);
  glUniform2f(glGetUniformLocation(pass.program, "u_view_depth"), in.view_depth[0], in.view_depth[1]);
  glUniform1f(glGetUniformLocation(pass.program, "u_taps"), static_cast<float>(in.taps));
  const GLuint textures[5] = {in.before, in.after, in.specular, in.heat_map, targets.profile};
  for (GLuint unit = 0; unit < 5; ++unit) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, textures[unit]);
  }
  glBindVertexArray(pass.vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  for (GLuint unit = 5; unit-- > 0;) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  glUseProgram(0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

void destroy_composite_pass(CompositePass *pass) {
  glDeleteProgram(pass->program);
  glDeleteVertexArrays(1, &pass->vao);
  *pass = CompositePass{};
}

std::vector<std::uint8_t> read_output(const FrameTargets &targets) {
  std::vector<std::uint8_t> pixels(static_cast<size_t>(targets.width) * static_cast<size_t>(targets.height) * 4u);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.output_framebuffer);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, targets.width, targets.height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return pixels;
}

}  // namespace demo
