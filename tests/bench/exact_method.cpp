// The exact 2D reference on the GPU: for every translucent pixel, the surface convolution of the
// irradiance with the full six-Gaussian skin profile over every translucent pixel within the
// profile's cutoff, each source pixel's footprint integrated exactly (a rectangle in its tangent
// plane; the Gaussians factor into erf differences). The same geometry and integral as the CPU
// reference in module/src/math/exact_reference.hpp (double precision), here in fp32 for full-size
// images. Two passes: footprints (positions and tangent frames), then the brute-force N×N sum.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "fullscreen.hpp"
#include "host_gl_util.hpp"
#include "math/skin_profile.hpp"
#include "method.hpp"

using namespace host_gl;

namespace sss_bench {

namespace {

// Footprints: view-space position, and the pixel's surface patch as a rectangle t1·a × t2·b.
const char* const kFootprintShader = R"(#version 330 core
uniform sampler2D u_irradiance;  // alpha > 0: translucent
uniform sampler2D u_distance;
uniform mat4 u_projection;
uniform vec2 u_size;
layout(location = 0) out vec4 o_position;  // xyz, 1 translucent / 0 not
layout(location = 1) out vec4 o_axis1;     // t1, a
layout(location = 2) out vec4 o_axis2;     // t2, b

vec3 position_at(vec2 pixel, float distance) {
  vec2 ndc = 2.0 * (pixel + 0.5) / u_size - 1.0;
  float z = -distance;
  float w = u_projection[2][3] * z + u_projection[3][3];
  return vec3((ndc.x * w - u_projection[2][0] * z - u_projection[3][0]) / u_projection[0][0],
              (ndc.y * w - u_projection[2][1] * z - u_projection[3][1]) / u_projection[1][1], z);
}

// Usable: inside the image, translucent, and in front of the camera (as in surface.hpp).
bool usable(ivec2 p) {
  if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, ivec2(u_size)))) return false;
  if (!(texelFetch(u_irradiance, p, 0).a > 0.0)) return false;
  float z = -texelFetch(u_distance, p, 0).r;
  return u_projection[2][3] * z + u_projection[3][3] > 0.0;
}

// The tangent along `step` by module/src/math/surface.hpp's rule central_where_smooth: a central
// difference where both neighbours are usable and the slope changes by at most one facing-plane
// pixel width, else a one-sided difference towards the neighbour nearer in depth (forward on a
// tie), else the step of a plane facing the camera.
vec3 tangent(ivec2 p, ivec2 step, vec3 centre, float distance, float facing_width) {
  bool forward_ok = usable(p + step), backward_ok = usable(p - step);
  float forward_d = forward_ok ? texelFetch(u_distance, p + step, 0).r : 0.0;
  float backward_d = backward_ok ? texelFetch(u_distance, p - step, 0).r : 0.0;
  if (forward_ok && backward_ok && abs(forward_d - 2.0 * distance + backward_d) <= facing_width) {
    return 0.5 * (position_at(vec2(p + step), forward_d) - position_at(vec2(p - step), backward_d));
  }
  if (forward_ok && (!backward_ok || abs(forward_d - distance) <= abs(backward_d - distance))) {
    return position_at(vec2(p + step), forward_d) - centre;
  }
  if (backward_ok) return centre - position_at(vec2(p - step), backward_d);
  return vec3(vec2(step), 0.0) * facing_width;
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float distance = texelFetch(u_distance, p, 0).r;
  vec3 centre = position_at(vec2(p), distance);
  o_position = vec4(centre, usable(p) ? 1.0 : 0.0);
  float w = u_projection[2][3] * -distance + u_projection[3][3];
  vec3 tx = tangent(p, ivec2(1, 0), centre, distance, abs(2.0 * w / (u_projection[0][0] * u_size.x)));
  vec3 ty = tangent(p, ivec2(0, 1), centre, distance, abs(2.0 * w / (u_projection[1][1] * u_size.y)));
  float area = length(cross(tx, ty));
  float a = length(tx);
  vec3 t1 = tx / a;
  vec3 t2 = ty - dot(ty, t1) * t1;
  float t2_length = length(t2);
  bool degenerate = !(area > 0.0) || !(t2_length > 0.0);
  o_axis1 = vec4(t1, a);
  o_axis2 = degenerate ? vec4(0.0) : vec4(t2 / t2_length, area / a);
}
)";

const char* const kSumShader = R"(#version 330 core
uniform sampler2D u_irradiance;
uniform sampler2D u_position;
uniform sampler2D u_axis1;
uniform sampler2D u_axis2;
uniform mat4 u_projection;
uniform vec2 u_size;
uniform float u_world_per_mm;
uniform float u_cutoff_mm;               // beyond this no term has mass left (CPU-computed)
uniform vec4 u_terms[6];                 // rgb weight, variance mm²
uniform float u_term_cutoff_mm[6];
uniform int u_stride;                    // receivers on this grid only (1: every pixel)
uniform ivec2 u_band;                    // source rows [p.y + x, p.y + y) of this draw
uniform bool u_first_band;
out vec4 o_color;

// erfc with fractional error below 1.2e-7 for x >= 0 (a Chebyshev fit of the continued fraction).
float erfc_positive(float x) {
  float t = 1.0 / (1.0 + 0.5 * x);
  float p = -1.26551223 + t * (1.00002368 + t * (0.37409196 + t * (0.09678418 + t * (-0.18628806 +
            t * (0.27886807 + t * (-1.13520398 + t * (1.48851587 + t * (-0.82215223 + t * 0.17087277))))))));
  return t * exp(-x * x + p);
}
// erf(hi) - erf(lo) for lo <= hi, computed from the tail that avoids cancellation.
float erf_difference(float lo, float hi) {
  if (lo >= 0.0) return erfc_positive(lo) - erfc_positive(hi);
  if (hi <= 0.0) return erfc_positive(-hi) - erfc_positive(-lo);
  return 2.0 - erfc_positive(-lo) - erfc_positive(hi);
}

// One term's contribution from a source footprint (a function, not a loop: see the draw loop in
// run() on why no loop here may run long).
vec3 term(int k, float distance, float u0, float v0, float h2, float a, float b) {
  if (distance > u_term_cutoff_mm[k] + 0.5 * (a + b)) return vec3(0.0);
  float s = sqrt(2.0 * u_terms[k].w);
  float mass = exp(-h2 / (2.0 * u_terms[k].w)) * 0.25 *
               erf_difference((u0 - 0.5 * a) / s, (u0 + 0.5 * a) / s) *
               erf_difference((v0 - 0.5 * b) / s, (v0 + 0.5 * b) / s);
  return u_terms[k].rgb * mass;
}

void main() {
  // With a stride the target is the small grid image: fragment (i, j) is receiver (i, j)·s + s/2.
  ivec2 p = min(ivec2(gl_FragCoord.xy) * u_stride + u_stride / 2, ivec2(u_size) - 1);
  vec4 input_color = texelFetch(u_irradiance, p, 0);
  vec4 receiver = texelFetch(u_position, p, 0);
  // The first draw writes every pixel; later ones add their band of source rows (blending).
  vec4 nothing = u_first_band ? input_color : vec4(0.0);
  if (receiver.w == 0.0) { o_color = nothing; return; }
  // A conservative pixel radius: the cutoff sphere around the receiver, projected.
  float cutoff_world = u_cutoff_mm * u_world_per_mm;
  float w_near = u_projection[2][3] * (receiver.z + cutoff_world) + u_projection[3][3];
  ivec2 radius = ivec2(u_size);
  if (w_near > 0.0) {
    vec2 r = cutoff_world * abs(vec2(u_projection[0][0], u_projection[1][1])) * 0.5 * u_size / w_near + 2.0;
    radius = ivec2(min(r, u_size));
  }
  ivec2 lo = max(p - radius, ivec2(0));
  ivec2 hi = min(p + radius, ivec2(u_size) - 1);
  lo.y = max(lo.y, p.y + u_band.x);
  hi.y = min(hi.y, p.y + u_band.y - 1);
  vec3 sum = vec3(0.0);
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      ivec2 q = ivec2(x, y);
      vec4 source = texelFetch(u_position, q, 0);
      if (source.w == 0.0) continue;
      vec3 delta = (source.xyz - receiver.xyz) / u_world_per_mm;
      vec4 axis1 = texelFetch(u_axis1, q, 0);
      vec4 axis2 = texelFetch(u_axis2, q, 0);
      float a = axis1.w / u_world_per_mm, b = axis2.w / u_world_per_mm;
      float distance2 = dot(delta, delta);
      float reach = u_cutoff_mm + 0.5 * (a + b);
      if (distance2 > reach * reach) continue;
      float u0 = dot(delta, axis1.xyz), v0 = dot(delta, axis2.xyz);
      float h2 = max(0.0, distance2 - u0 * u0 - v0 * v0);
      float distance = sqrt(distance2);
      vec3 weight = term(0, distance, u0, v0, h2, a, b) + term(1, distance, u0, v0, h2, a, b) +
                    term(2, distance, u0, v0, h2, a, b) + term(3, distance, u0, v0, h2, a, b) +
                    term(4, distance, u0, v0, h2, a, b) + term(5, distance, u0, v0, h2, a, b);
      sum += weight * texelFetch(u_irradiance, q, 0).rgb;
    }
  }
  o_color = vec4(sum, u_first_band ? input_color.a : 0.0);
}
)";

// Stride > 1: the grid image back into a full-size output (receivers from the grid, the rest the input).
const char* const kScatterShader = R"(#version 330 core
uniform sampler2D u_irradiance;
uniform sampler2D u_grid;
uniform int u_stride;
out vec4 o_color;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  bool receiver = all(equal(p % u_stride, ivec2(u_stride / 2)));
  o_color = receiver ? texelFetch(u_grid, p / u_stride, 0) : texelFetch(u_irradiance, p, 0);
}
)";

// The radius beyond which a 2D Gaussian of variance v (mm²) has less than `tail` of its mass:
// the mass outside r is exp(-r²/2v).
double tail_radius(double variance, double tail) { return std::sqrt(-2.0 * variance * std::log(tail)); }

class ExactMethod : public Method {
 public:
  ExactMethod(int stride, std::pair<int, int> band)
      : stride_(stride),
        band_(band),
        footprint_(build_fullscreen_program("exact footprints", kFootprintShader)),
        sum_(build_fullscreen_program("exact sum", kSumShader)),
        scatter_(build_fullscreen_program("exact scatter", kScatterShader)) {}
  ~ExactMethod() override {
    glUseProgram(0);  // a deleted program that stays current would be restored by name later
    glDeleteProgram(footprint_);
    glDeleteProgram(sum_);
    glDeleteProgram(scatter_);
    glDeleteTextures(3, targets_);
    glDeleteTextures(1, &grid_);
  }
  std::string name() const override { return "exact-2d"; }
  int taps() const override { return 0; }
  bool follow_surface() const override { return false; }
  int passes() const override { return 2; }

  bool run(const GpuScene& scene, GLuint output, std::string* error) override {
    if (targets_[0] == 0 || width_ != scene.width || height_ != scene.height) {
      glDeleteTextures(3, targets_);
      for (GLuint& t : targets_) t = make_texture(GL_RGBA32F, scene.width, scene.height, GL_RGBA, GL_FLOAT);
      glDeleteTextures(1, &grid_);
      grid_ = stride_ > 1 ? make_texture(GL_RGBA32F, grid_width(scene.width), grid_width(scene.height), GL_RGBA, GL_FLOAT) : 0;
      width_ = scene.width;
      height_ = scene.height;
    }
    const float size[2] = {static_cast<float>(scene.width), static_cast<float>(scene.height)};
    glUseProgram(footprint_);
    glUniform1i(glGetUniformLocation(footprint_, "u_irradiance"), 0);
    glUniform1i(glGetUniformLocation(footprint_, "u_distance"), 1);
    glUniformMatrix4fv(glGetUniformLocation(footprint_, "u_projection"), 1, GL_FALSE, scene.projection.data());
    glUniform2f(glGetUniformLocation(footprint_, "u_size"), size[0], size[1]);
    if (!pass_.bind_targets({targets_[0], targets_[1], targets_[2]}, scene.width, scene.height, error)) return false;
    FullscreenPass::bind_texture(0, scene.irradiance);
    FullscreenPass::bind_texture(1, scene.distance);
    pass_.draw();

    glUseProgram(sum_);
    const char* samplers[4] = {"u_irradiance", "u_position", "u_axis1", "u_axis2"};
    for (int i = 0; i < 4; ++i) glUniform1i(glGetUniformLocation(sum_, samplers[i]), i);
    glUniformMatrix4fv(glGetUniformLocation(sum_, "u_projection"), 1, GL_FALSE, scene.projection.data());
    glUniform2f(glGetUniformLocation(sum_, "u_size"), size[0], size[1]);
    glUniform1f(glGetUniformLocation(sum_, "u_world_per_mm"), scene.world_units_per_mm);
    const auto& terms = sss::math::skin_gaussians();
    float packed[6 * 4];
    float cutoffs[6];
    double widest = 0.0;
    for (std::size_t k = 0; k < terms.size(); ++k) {
      for (std::size_t c = 0; c < 3; ++c) packed[k * 4 + c] = static_cast<float>(terms[k].weight[c]);
      packed[k * 4 + 3] = static_cast<float>(terms[k].variance_mm2);
      cutoffs[k] = static_cast<float>(tail_radius(terms[k].variance_mm2, kTailMass));
      widest = std::max(widest, static_cast<double>(cutoffs[k]));
    }
    glUniform4fv(glGetUniformLocation(sum_, "u_terms"), 6, packed);
    glUniform1fv(glGetUniformLocation(sum_, "u_term_cutoff_mm"), 6, cutoffs);
    glUniform1f(glGetUniformLocation(sum_, "u_cutoff_mm"), static_cast<float>(widest));
    glUniform1i(glGetUniformLocation(sum_, "u_stride"), stride_);
    const bool on_grid = stride_ > 1;
    if (!pass_.bind_targets({on_grid ? grid_ : output}, on_grid ? grid_width(scene.width) : scene.width,
                            on_grid ? grid_width(scene.height) : scene.height, error)) {
      return false;
    }
    FullscreenPass::bind_texture(0, scene.irradiance);
    for (int i = 0; i < 3; ++i) FullscreenPass::bind_texture(static_cast<GLuint>(i + 1), targets_[i]);
    const bool banded = band_.second > band_.first;
    if (banded) {
      glEnable(GL_SCISSOR_TEST);
      glScissor(0, band_.first, scene.width, band_.second - band_.first);
    }
    // llvmpipe stops any shader loop after 65535 iterations (a guard against hangs; a GPU's
    // watchdog does much the same to long draws), which a 1080p close-up's window of 40 000 and
    // more sources per receiver exceeds. So the window's rows are split over several draws of at
    // most kBandRows rows each, added up by blending.
    const int max_radius = max_radius_pixels(scene);
    const GLint band = glGetUniformLocation(sum_, "u_band");
    const GLint first = glGetUniformLocation(sum_, "u_first_band");
    for (int row = -max_radius; row <= max_radius; row += kBandRows) {
      glUniform2i(band, row, std::min(row + kBandRows, max_radius + 1));
      glUniform1i(first, row == -max_radius ? 1 : 0);
      if (row != -max_radius) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
      }
      pass_.draw();
    }
    glDisable(GL_BLEND);
    if (banded) glDisable(GL_SCISSOR_TEST);
    if (!on_grid) return true;
    glUseProgram(scatter_);
    glUniform1i(glGetUniformLocation(scatter_, "u_irradiance"), 0);
    glUniform1i(glGetUniformLocation(scatter_, "u_grid"), 1);
    glUniform1i(glGetUniformLocation(scatter_, "u_stride"), stride_);
    if (!pass_.bind_targets({output}, scene.width, scene.height, error)) return false;
    FullscreenPass::bind_texture(1, grid_);
    pass_.draw();
    return true;
  }

 private:
  // Receivers along an axis of `size` pixels: x = i·s + s/2 < size.
  int grid_width(int size) const { return (size - stride_ / 2 + stride_ - 1) / stride_; }

  // The largest window radius (pixels, rows) any receiver can have: the shader's own bound at the
  // nearest translucent distance.
  static int max_radius_pixels(const GpuScene& scene) {
    const auto& m = scene.projection;
    const double cutoff_world = max_cutoff_mm() * scene.world_units_per_mm;
    const double w_near = -m[11] * (scene.nearest_translucent_distance - cutoff_world) + m[15];
    if (!(w_near > 0.0)) return scene.height;
    const double r = cutoff_world * std::fabs(m[5]) * 0.5 * scene.height / w_near + 2.0;
    return static_cast<int>(std::min(std::ceil(r), static_cast<double>(scene.height)));
  }
  static double max_cutoff_mm() {
    double widest = 0.0;
    for (const auto& t : sss::math::skin_gaussians()) widest = std::max(widest, tail_radius(t.variance_mm2, kTailMass));
    return widest;
  }

 public:

 private:
  // Mass of a term left out beyond its cutoff (the CPU reference uses the same bound).
  static constexpr double kTailMass = 1e-9;
  // Rows of the source window per draw: 64 rows × up to 400 columns stays well under llvmpipe's
  // 65535 loop iterations.
  static constexpr int kBandRows = 64;
  int stride_;
  std::pair<int, int> band_;
  GLuint footprint_, sum_, scatter_;
  GLuint grid_ = 0;
  GLuint targets_[3] = {0, 0, 0};  // positions, axis 1, axis 2
  int width_ = 0, height_ = 0;
  FullscreenPass pass_;
};

}  // namespace

std::unique_ptr<Method> make_exact_method(int receiver_stride, std::pair<int, int> band_rows) {
  if (receiver_stride < 1) throw std::invalid_argument("receiver stride must be >= 1");
  if (receiver_stride > 1 && band_rows.second > band_rows.first) {
    throw std::invalid_argument("a row band is for full-resolution timing: stride must be 1");
  }
  return std::make_unique<ExactMethod>(receiver_stride, band_rows);
}

}  // namespace sss_bench
