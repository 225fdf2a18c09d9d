// The established baseline: d'Eon's six-Gaussian skin profile as a sum of Gaussian blurs in screen
// space (Jimenez et al. 2009/2010, the paper's [JG10]). Each level convolves the previous one with
// the variance difference (Gaussians compose by adding variances), horizontally then vertically:
// 12 one-dimensional passes; the vertical pass of each level also adds weight_i · level_i into an
// accumulator through constant-colour blending, and a last pass puts the accumulator on the
// translucent pixels. Per-pixel footprint, strength in alpha and follow-surface test are the same
// as the library's separable filter, so the two differ only in the kernel.
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "fullscreen.hpp"
#include "host_gl_util.hpp"
#include "math/skin_profile.hpp"
#include "method.hpp"

using namespace host_gl;

namespace sss_bench {

namespace {

constexpr int kMaxTaps = 65;
// Each level's 1D Gaussian is cut at ±3 standard deviations (99.7 % of its mass).
constexpr double kSigmaRange = 3.0;
// Follow-surface reach in profile millimetres: the separable filter's for more than 20 taps.
constexpr float kReachMm = 3.0f;

const char* const kBlurShader = R"(#version 330 core
uniform sampler2D u_source;
uniform sampler2D u_distance;
uniform vec2 u_axis;
uniform float u_pixels_per_mm;   // at clip w = 1, strength 1, along u_axis
uniform float u_inverse_reach;   // 1 / follow-surface reach in world units; 0: off
uniform vec2 u_w_terms;          // clip w = x * distance + y
uniform vec2 u_kernel[65];       // weight, offset in mm
uniform int u_tap_count;
layout(location = 0) out vec4 o_level;
layout(location = 1) out vec4 o_accumulate;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 centre = texelFetch(u_source, pixel, 0);
  if (!(centre.a > 0.0)) { o_level = centre; o_accumulate = vec4(0.0); return; }
  float distance = texelFetch(u_distance, pixel, 0).r;
  float step_pixels = u_pixels_per_mm * centre.a / (u_w_terms.x * distance + u_w_terms.y);
  vec2 size = vec2(textureSize(u_source, 0));
  float follow = u_inverse_reach / centre.a;
  vec3 sum = vec3(0.0);
  for (int i = 0; i < u_tap_count; ++i) {
    vec2 position = clamp(gl_FragCoord.xy + u_axis * (u_kernel[i].y * step_pixels), vec2(0.5), size - 0.5);
    vec2 uv = position / size;
    vec3 tap = texture(u_source, uv).rgb;
    float s = follow * abs(distance - texture(u_distance, uv).r);
    if (!(s < 1.0)) s = 1.0;
    sum += u_kernel[i].x * mix(tap, centre.rgb, s);
  }
  o_level = vec4(sum, centre.a);
  o_accumulate = vec4(sum, 0.0);
}
)";

const char* const kComposeShader = R"(#version 330 core
uniform sampler2D u_input;
uniform sampler2D u_accumulated;
out vec4 o_color;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 input_color = texelFetch(u_input, pixel, 0);
  o_color = input_color.a > 0.0 ? vec4(texelFetch(u_accumulated, pixel, 0).rgb, input_color.a) : input_color;
}
)";

// Taps of a 1D Gaussian of standard deviation sigma (mm): evenly spaced over ±3 sigma, each weight
// the Gaussian's mass over the tap's interval, normalised.
std::vector<std::array<float, 2>> gaussian_taps(int taps, double sigma) {
  std::vector<std::array<float, 2>> kernel(static_cast<std::size_t>(taps));
  const double range = kSigmaRange * sigma;
  const double spacing = taps > 1 ? 2.0 * range / (taps - 1) : 0.0;
  double total = 0.0;
  for (int i = 0; i < taps; ++i) {
    const double x = taps > 1 ? -range + spacing * i : 0.0;
    const double lo = i == 0 ? -range : x - 0.5 * spacing;
    const double hi = i == taps - 1 ? range : x + 0.5 * spacing;
    const double mass = taps > 1 ? std::erf(hi / (sigma * std::sqrt(2.0))) - std::erf(lo / (sigma * std::sqrt(2.0))) : 1.0;
    kernel[static_cast<std::size_t>(i)] = {static_cast<float>(mass), static_cast<float>(x)};
    total += mass;
  }
  for (auto& tap : kernel) tap[0] = static_cast<float>(tap[0] / total);
  return kernel;
}

class SumOfGaussiansMethod : public Method {
 public:
  SumOfGaussiansMethod(int taps, bool follow)
      : taps_(taps),
        follow_(follow),
        blur_(build_fullscreen_program("sum-of-gaussians blur", kBlurShader)),
        compose_(build_fullscreen_program("sum-of-gaussians compose", kComposeShader)) {
    glGenSamplers(1, &linear_);
    glSamplerParameteri(linear_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(linear_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(linear_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(linear_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    const auto& terms = sss::math::skin_gaussians();
    double previous = 0.0;
    for (std::size_t i = 0; i < terms.size(); ++i) {
      levels_[i] = gaussian_taps(taps, std::sqrt(terms[i].variance_mm2 - previous));
      previous = terms[i].variance_mm2;
    }
  }
  ~SumOfGaussiansMethod() override {
    glUseProgram(0);  // a deleted program that stays current would be restored by name later
    glDeleteProgram(blur_);
    glDeleteProgram(compose_);
    glDeleteSamplers(1, &linear_);
    glDeleteTextures(static_cast<GLsizei>(targets_.size()), targets_.data());
  }

  std::string name() const override { return "sum-of-gaussians"; }
  int taps() const override { return taps_; }
  bool follow_surface() const override { return follow_; }
  int passes() const override { return 2 * static_cast<int>(levels_.size()) + 1; }

  bool run(const GpuScene& scene, GLuint output, std::string* error) override {
    ensure_targets(scene.width, scene.height);
    const GLuint level_a = targets_[0], level_b = targets_[1], horizontal = targets_[2], accumulated = targets_[3];
    const float world_per_mm = scene.world_units_per_mm;
    const auto& m = scene.projection;
    glUseProgram(blur_);
    glUniform1i(glGetUniformLocation(blur_, "u_source"), 0);
    glUniform1i(glGetUniformLocation(blur_, "u_distance"), 1);
    glUniform1f(glGetUniformLocation(blur_, "u_inverse_reach"), follow_ ? 1.0f / (kReachMm * world_per_mm) : 0.0f);
    glUniform2f(glGetUniformLocation(blur_, "u_w_terms"), -m[11], m[15]);
    glUniform1i(glGetUniformLocation(blur_, "u_tap_count"), taps_);
    const GLint axis = glGetUniformLocation(blur_, "u_axis");
    const GLint pixels_per_mm = glGetUniformLocation(blur_, "u_pixels_per_mm");
    const GLint kernel = glGetUniformLocation(blur_, "u_kernel");
    const float ppm_x = std::fabs(m[0]) * 0.5f * static_cast<float>(scene.width) * world_per_mm;
    const float ppm_y = std::fabs(m[5]) * 0.5f * static_cast<float>(scene.height) * world_per_mm;
    FullscreenPass::bind_texture(1, scene.distance);
    glBindSampler(0, linear_);
    glBindSampler(1, linear_);

    if (!pass_.bind_targets({horizontal, accumulated}, scene.width, scene.height, error)) return false;
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 1, zero);
    const auto& terms = sss::math::skin_gaussians();
    GLuint source = scene.irradiance;
    GLuint destination = level_a;
    for (std::size_t i = 0; i < levels_.size(); ++i) {
      glUniform2fv(kernel, taps_, levels_[i][0].data());
      // Horizontal: previous level -> temporary.
      if (!pass_.bind_targets({horizontal}, scene.width, scene.height, error)) return false;
      glUniform2f(axis, 1.0f, 0.0f);
      glUniform1f(pixels_per_mm, ppm_x);
      FullscreenPass::bind_texture(0, source);
      pass_.draw();
      // Vertical: temporary -> this level, and weight_i · level into the accumulator.
      if (!pass_.bind_targets({destination, accumulated}, scene.width, scene.height, error)) return false;
      glUniform2f(axis, 0.0f, 1.0f);
      glUniform1f(pixels_per_mm, ppm_y);
      FullscreenPass::bind_texture(0, horizontal);
      glEnablei(GL_BLEND, 1);
      glBlendEquation(GL_FUNC_ADD);
      glBlendFunc(GL_CONSTANT_COLOR, GL_ONE);
      glBlendColor(static_cast<float>(terms[i].weight[0]), static_cast<float>(terms[i].weight[1]),
                   static_cast<float>(terms[i].weight[2]), 0.0f);
      pass_.draw();
      glDisablei(GL_BLEND, 1);
      source = destination;
      destination = destination == level_a ? level_b : level_a;
    }
    glBindSampler(0, 0);
    glBindSampler(1, 0);
    glUseProgram(compose_);
    glUniform1i(glGetUniformLocation(compose_, "u_input"), 0);
    glUniform1i(glGetUniformLocation(compose_, "u_accumulated"), 1);
    if (!pass_.bind_targets({output}, scene.width, scene.height, error)) return false;
    FullscreenPass::bind_texture(0, scene.irradiance);
    FullscreenPass::bind_texture(1, accumulated);
    pass_.draw();
    return true;
  }

 private:
  void ensure_targets(int width, int height) {
    if (targets_[0] != 0 && width == width_ && height == height_) return;
    glDeleteTextures(static_cast<GLsizei>(targets_.size()), targets_.data());
    for (GLuint& t : targets_) t = make_texture(GL_RGBA16F, width, height, GL_RGBA, GL_HALF_FLOAT);
    width_ = width;
    height_ = height;
  }

  int taps_;
  bool follow_;
  GLuint blur_, compose_;
  GLuint linear_ = 0;
  std::array<std::vector<std::array<float, 2>>, 6> levels_;
  std::array<GLuint, 4> targets_{};  // level A, level B, horizontal temporary, accumulator
  int width_ = 0, height_ = 0;
  FullscreenPass pass_;
};

}  // namespace

std::unique_ptr<Method> make_sum_of_gaussians_method(int taps, bool follow_surface) {
  if (taps < 1 || taps > kMaxTaps) throw std::invalid_argument("sum-of-gaussians taps must be in [1, 65]");
  return std::make_unique<SumOfGaussiansMethod>(taps, follow_surface);
}

}  // namespace sss_bench
