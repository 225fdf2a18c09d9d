// The host thickness inputs of integration/glsl/sss_transmittance.glsl (sss_thickness_baked,
// sss_thickness_from_unit, sss_thickness_combined) and its rules for bad thickness values, on the GL
// against the CPU formula (math::transmittance, the terms the blur's profile gives), on desktop GL
// and on OpenGL ES 3.0 (the include claims GLSL ES 3.00).
//
// Tolerances: thicknesses that only pass through texture fetches and exact scalings (× 4, × 0.25)
// are compared exactly; a UNORM8 texel's decode to 1e-8 world units at a 0.02 maximum (4 float ulps;
// one step of the map is 7.8e-5). Transmitted light against the CPU's: 1e-6 absolute (values <= 1) at
// the GPU's own thickness, as tests/gl/transmittance_test.cpp argues (float exp and products against
// double, measured 6e-8 there); a wrong rule moves these values by 1e-3 or more.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "gl_fixture.hpp"
#include "host_gl_util.hpp"
#include "math/spike_gaussian_profile.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

constexpr float kWidth = 0.012f, kTranslucency = 0.2f;
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNan = std::numeric_limits<float>::quiet_NaN();

// Every test's point sits on a back face looking away from a light straight behind it: dot(L, -N) =
// 1, so the include's direction factor saturate(0.3 + 1) is 1 and the light is the profile alone.
constexpr const char* kShadowMain = R"(
uniform sampler2D u_map;
uniform float u_shrink;
uniform mat4 u_light_view, u_light_projection;
out vec4 o_color;
void main() {
  float thickness = (gl_FragCoord.x - 0.5) * 0.0005;
  vec3 position = vec3(0.1, -0.2, -(2.0 + thickness));
  float t = SSS_TEST_THICKNESS(u_map, u_light_view, u_light_projection, position, vec3(0.0, 0.0, -1.0), u_shrink);
  o_color = vec4(sss_transmittance(t, u_width, u_translucency, vec3(0.0, 0.0, -1.0), vec3(0.0, 0.0, 1.0)), t);
}
)";

// One texel per pixel of a baked thickness map (nearest: the texel's value exactly).
constexpr const char* kBakedMain = R"(
uniform sampler2D u_map;
uniform float u_max;
out vec4 o_color;
void main() {
  vec2 uv = vec2(gl_FragCoord.x / float(textureSize(u_map, 0).x), 0.5);
  float t = sss_thickness_baked(u_map, uv, u_max);
  o_color = vec4(sss_transmittance(t, u_width, u_translucency, vec3(0.0, 0.0, -1.0), vec3(0.0, 0.0, 1.0)), t);
}
)";

// Pixel x is a point 0.004 behind a slab face the light's distance map places at u_map[x] (2.0: the
// slab itself; less: another object in front); its host thickness comes from a per-pixel unit value
// (a vertex attribute's role) × u_max. u_mode: 0 combined, 1 host only, 2 shadow map only.
constexpr const char* kCombinedMain = R"(
uniform sampler2D u_map;
uniform float u_shrink, u_max;
uniform int u_mode;
uniform mat4 u_light_view, u_light_projection;
out vec4 o_color;
void main() {
  vec3 position = vec3(gl_FragCoord.x / float(textureSize(u_map, 0).x) * 2.0 - 1.0, 0.0, -2.004);
  vec3 normal = vec3(0.0, 0.0, -1.0);
  float host = sss_thickness_from_unit(mod(gl_FragCoord.x - 0.5, 2.0) < 0.5 ? 0.1 : 0.6, u_max);
  float shadow = sss_thickness_linear(u_map, u_light_view, u_light_projection, position, normal, u_shrink);
  float t = u_mode == 0 ? sss_thickness_combined(host, shadow) : u_mode == 1 ? host : shadow;
  o_color = vec4(sss_transmittance(t, u_width, u_translucency, normal, vec3(0.0, 0.0, 1.0)), t);
}
)";

// sss_thickness_combined on pairs of raw values (host from u_map, shadow from u_other).
constexpr const char* kPairMain = R"(
uniform sampler2D u_map, u_other;
out vec4 o_color;
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  float t = sss_thickness_combined(texelFetch(u_map, texel, 0).r, texelFetch(u_other, texel, 0).r);
  o_color = vec4(sss_transmittance(t, u_width, u_translucency, vec3(0.0, 0.0, -1.0), vec3(0.0, 0.0, 1.0)), t);
}
)";

std::string read_include() {
  std::ifstream in(SSS_TRANSMITTANCE_GLSL);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class Thickness : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    ASSERT_EQ(sss_profile_transmittance_terms(SSS_PROFILE_SKIN_DEON, terms_, SSS_PROFILE_MAX_TERMS, &count_), SSS_OK);
    cpu_terms_ = sss::math::transmittance_terms(sss::math::spike_gaussian_profile(SSS_PROFILE_SKIN_DEON));
  }
  void TearDown() override {
    for (GLuint p : programs_) glDeleteProgram(p);
    programs_.clear();
    GlTest::TearDown();
  }

  // The include and `main` after this context's #version (GLSL ES 3.00 with highp on egl-gles).
  GLuint program(const std::string& defines, const char* main) {
    const std::string version = is_gles() ? "#version 300 es\n" : "#version 330 core\n";
    const std::string precision =
        is_gles() ? "precision highp float;\nprecision highp int;\nprecision highp sampler2D;\n" : "";
    std::string vertex = kFullscreenVertexShader;
    vertex.replace(0, vertex.find('\n') + 1, version);
    const std::string fragment = version + precision + defines + read_include() +
                                 "uniform float u_width, u_translucency;\n" + main;
    const GLuint p = build_program("thickness test", vertex.c_str(), fragment.c_str());
    EXPECT_NE(p, 0u);
    programs_.push_back(p);
    glUseProgram(p);
    glUniform4fv(glGetUniformLocation(p, "sss_transmittance_terms"), count_, terms_);
    glUniform1i(glGetUniformLocation(p, "sss_transmittance_term_count"), count_);
    glUniform1f(glGetUniformLocation(p, "u_width"), kWidth);
    glUniform1f(glGetUniformLocation(p, "u_translucency"), kTranslucency);
    return p;
  }

  // An orthographic light looking down -Z from the origin, near 0.5, far 10 (the slab at distance 2).
  static void set_light(GLuint p) {
    const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const float projection[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2.0f / 9.5f, 0, 0, 0, -10.5f / 9.5f, 1};
    glUniformMatrix4fv(glGetUniformLocation(p, "u_light_view"), 1, GL_FALSE, identity);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_light_projection"), 1, GL_FALSE, projection);
  }

  // Binds `texture` to unit `unit` as `name` of the current program.
  static void bind(GLuint p, const char* name, int unit, GLuint texture) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, texture);
    glUniform1i(glGetUniformLocation(p, name), unit);
  }

  // One full-screen draw of the current program into a width x 1 RGBA32F row.
  std::vector<float> draw(int width) {
    const GLuint target = make_rgba32f(width, 1, std::vector<float>(static_cast<std::size_t>(width) * 4, -1.0f));
    {
      const DrawTarget on(target, width, 1);
      glDrawArrays(GL_TRIANGLES, 0, 3);
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    }
    glActiveTexture(GL_TEXTURE0);
    return read_rgba(target, width, 1);
  }

  // The light through `thickness` world units (the include's rules, in double): none for NaN or
  // infinity, a negative thickness as 0.
  double expected(double thickness, int channel, double translucency = kTranslucency) const {
    if (!std::isfinite(thickness)) return 0.0;
    return sss::math::transmittance(cpu_terms_, channel, std::max(thickness, 0.0) * 8.25 * (1.0 - translucency) / kWidth);
  }

  // Largest |GPU - CPU| over a row, each pixel at the thickness the GPU wrote into alpha.
  double worst_against_cpu(const std::vector<float>& row) const {
    double worst = 0.0;
    for (std::size_t i = 0; i < row.size(); i += 4) {
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(row[i + c] - expected(row[i + 3], c)));
    }
    return worst;
  }

  float terms_[SSS_PROFILE_MAX_TERMS * 4] = {};
  int32_t count_ = 0;
  std::vector<sss::math::GaussianTerm> cpu_terms_;
  std::vector<GLuint> programs_;
};

// The thickness each pixel's shadow-map lookup found, handed back as a baked map: the same light.
TEST_F(Thickness, ShadowMapThicknessGivenDirectlyGivesTheSameLight) {
  constexpr int kSize = 64;
  for (bool hardware_depth : {true, false}) {
    SCOPED_TRACE(hardware_depth);
    const GLuint shadow = program(std::string("#define SSS_TEST_THICKNESS ") +
                                      (hardware_depth ? "sss_thickness\n" : "sss_thickness_linear\n"),
                                  kShadowMain);
    ASSERT_NE(shadow, 0u);
    set_light(shadow);
    glUniform1f(glGetUniformLocation(shadow, "u_shrink"), 0.001f);
    const GLuint map = hardware_depth ? make_depth32f(16, 16, std::vector<float>(256, 1.5f / 9.5f))
                                      : make_texture(GL_R32F, 16, 16, GL_RED, GL_FLOAT, std::vector<float>(256, 2.0f).data());
    bind(shadow, "u_map", 0, map);
    const std::vector<float> from_shadow = draw(kSize);

    // The map holds 4 × the thickness and says 0.25 is its maximum: both scalings exact in float.
    std::vector<float> baked(kSize);
    for (int x = 0; x < kSize; ++x) baked[static_cast<std::size_t>(x)] = 4.0f * from_shadow[static_cast<std::size_t>(x) * 4 + 3];
    const GLuint direct = program("", kBakedMain);
    ASSERT_NE(direct, 0u);
    glUniform1f(glGetUniformLocation(direct, "u_max"), 0.25f);
    bind(direct, "u_map", 0, make_texture(GL_R32F, kSize, 1, GL_RED, GL_FLOAT, baked.data()));
    const std::vector<float> from_baked = draw(kSize);

    double worst_paths = 0.0;
    for (std::size_t i = 0; i < from_shadow.size(); i += 4) {
      EXPECT_EQ(from_baked[i + 3], from_shadow[i + 3]) << i / 4;
      for (int c = 0; c < 3; ++c) worst_paths = std::max(worst_paths, static_cast<double>(std::fabs(from_baked[i + c] - from_shadow[i + c])));
    }
    // The shadow map saw thicknesses 0.0005·x - shrink: red light through the thin ones, none through 0.03.
    EXPECT_NEAR(from_shadow[10 * 4 + 3], 0.004, 1e-5);
    EXPECT_GT(from_baked[10 * 4], 0.01f);
    EXPECT_LT(from_baked[63 * 4], 1e-4f);
    const double worst_cpu = worst_against_cpu(from_baked);
    std::printf("thickness given directly: largest |baked - shadow path| %.3g, |GPU - CPU| %.3g\n", worst_paths,
                worst_cpu);
    // The same float code on the same thickness: at most a rounding apart (fused or not).
    EXPECT_LE(worst_paths, 1e-7);
    EXPECT_LE(worst_cpu, 1e-6);
  }
}

// A UNORM8 baked map: texel k reads as k/255 × the maximum thickness (world units).
TEST_F(Thickness, BakedTextureReadsAsItsTexelTimesTheMaximum) {
  constexpr int kSize = 256;
  constexpr float kMax = 0.02f;
  std::vector<unsigned char> texels(kSize);
  for (int k = 0; k < kSize; ++k) texels[static_cast<std::size_t>(k)] = static_cast<unsigned char>(k);
  const GLuint p = program("", kBakedMain);
  ASSERT_NE(p, 0u);
  glUniform1f(glGetUniformLocation(p, "u_max"), kMax);
  bind(p, "u_map", 0, make_texture(GL_R8, kSize, 1, GL_RED, GL_UNSIGNED_BYTE, texels.data()));
  const std::vector<float> row = draw(kSize);
  double worst_decode = 0.0;
  for (int k = 0; k < kSize; ++k) {
    worst_decode = std::max(worst_decode, std::fabs(row[static_cast<std::size_t>(k) * 4 + 3] - k / 255.0 * kMax));
  }
  const double worst_cpu = worst_against_cpu(row);
  std::printf("baked UNORM8 map: largest decode error %.3g world units, |GPU - CPU| %.3g\n", worst_decode, worst_cpu);
  EXPECT_LE(worst_decode, 1e-8);
  EXPECT_LE(worst_cpu, 1e-6);
  EXPECT_GT(row[0], 0.5f);               // texel 0: touching surfaces, the profile's full red
  EXPECT_LT(row[255 * 4], row[0] * 1e-3f);  // 20 mm of skin: next to nothing
}

// The combine rule: the larger of the host's and the shadow map's thickness. Where another object
// stands between the light and the part, the host's thin value must not glow.
TEST_F(Thickness, CombinedTakesTheLargerSoAnOccluderBlocksABakedThinPart) {
  constexpr int kSize = 64;
  constexpr float kShrink = 0.001f, kMax = 0.01f;
  std::vector<float> distance(kSize, 2.0f);
  for (int x = kSize / 2; x < kSize; ++x) distance[static_cast<std::size_t>(x)] = 1.5f;  // the occluder
  const GLuint p = program("", kCombinedMain);
  ASSERT_NE(p, 0u);
  set_light(p);
  glUniform1f(glGetUniformLocation(p, "u_shrink"), kShrink);
  glUniform1f(glGetUniformLocation(p, "u_max"), kMax);
  bind(p, "u_map", 0, make_texture(GL_R32F, kSize, 1, GL_RED, GL_FLOAT, distance.data()));
  std::vector<float> rows[3];
  for (int mode = 0; mode < 3; ++mode) {
    glUseProgram(p);
    glUniform1i(glGetUniformLocation(p, "u_mode"), mode);
    rows[mode] = draw(kSize);
  }
  const std::vector<float>& combined = rows[0];
  const std::vector<float>& host = rows[1];
  const std::vector<float>& shadow = rows[2];
  for (int x = 0; x < kSize; ++x) {
    SCOPED_TRACE(x);
    const std::size_t i = static_cast<std::size_t>(x) * 4;
    const double host_t = (x % 2 == 0 ? 0.1 : 0.6) * kMax;          // 1 mm or 6 mm
    const double shadow_t = 2.004 - kShrink - distance[static_cast<std::size_t>(x)];  // 3 mm, or 503 behind the occluder
    EXPECT_NEAR(host[i + 3], host_t, 1e-9);
    EXPECT_NEAR(shadow[i + 3], shadow_t, 1e-5);
    EXPECT_EQ(combined[i + 3], std::max(host[i + 3], shadow[i + 3]));
    if (x >= kSize / 2) {
      EXPECT_GT(host[i], 0.01f);      // the host's map alone glows behind the occluder...
      EXPECT_LT(combined[i], 1e-6f);  // ...the combined thickness does not
    }
  }
  const double worst = std::max(worst_against_cpu(combined), worst_against_cpu(host));
  std::printf("combined thickness: |GPU - CPU| %.3g; red at x = 0, 1 (1, 6 mm host; 3 mm shadow) %.4g %.4g\n", worst,
              combined[0], combined[4]);
  EXPECT_LE(worst, 1e-6);
}

// Bad values: negative counts as 0 (the most light), NaN and infinities give no light and never a
// NaN; through sss_transmittance alone and through the combine rule.
TEST_F(Thickness, NegativeCountsAsZeroNanAndInfinityGiveNoLight) {
  const std::vector<float> values = {0.0f, -0.01f, -kInf, kNan, kInf, std::numeric_limits<float>::max(), 0.003f};
  const int n = static_cast<int>(values.size());
  const GLuint p = program("", kBakedMain);
  ASSERT_NE(p, 0u);
  glUniform1f(glGetUniformLocation(p, "u_max"), 1.0f);
  bind(p, "u_map", 0, make_texture(GL_R32F, n, 1, GL_RED, GL_FLOAT, values.data()));
  for (float translucency : {kTranslucency, 1.0f}) {
    SCOPED_TRACE(translucency);
    glUseProgram(p);
    glUniform1f(glGetUniformLocation(p, "u_translucency"), translucency);
    const std::vector<float> row = draw(n);
    for (int k = 0; k < n; ++k) {
      SCOPED_TRACE(values[static_cast<std::size_t>(k)]);
      const double t = values[static_cast<std::size_t>(k)];
      for (int c = 0; c < 3; ++c) {
        const float got = row[static_cast<std::size_t>(k) * 4 + c];
        ASSERT_TRUE(std::isfinite(got));
        EXPECT_NEAR(got, expected(t, c, translucency), 1e-6);
      }
    }
    // -0.01 lights as touching surfaces; an unknown thickness is black, not the profile's peak.
    EXPECT_EQ(row[4], row[0]);
    EXPECT_EQ(row[3 * 4], 0.0f);
  }

  const std::vector<float> hosts = {kNan, 0.003f, kInf, 0.003f, -1.0f, -1.0f, 0.001f, 0.004f};
  const std::vector<float> shadows = {0.003f, kNan, 0.003f, -kInf, 0.002f, -2.0f, 0.004f, 0.001f};
  const std::vector<double> thickness = {kNan, kNan, kInf, -kInf, 0.002, 0.0, 0.004, 0.004};
  const int m = static_cast<int>(hosts.size());
  const GLuint pairs = program("", kPairMain);
  ASSERT_NE(pairs, 0u);
  bind(pairs, "u_map", 0, make_texture(GL_R32F, m, 1, GL_RED, GL_FLOAT, hosts.data()));
  bind(pairs, "u_other", 1, make_texture(GL_R32F, m, 1, GL_RED, GL_FLOAT, shadows.data()));
  const std::vector<float> row = draw(m);
  for (int k = 0; k < m; ++k) {
    SCOPED_TRACE(k);
    for (int c = 0; c < 3; ++c) {
      const float got = row[static_cast<std::size_t>(k) * 4 + c];
      ASSERT_TRUE(std::isfinite(got));
      EXPECT_NEAR(got, expected(thickness[static_cast<std::size_t>(k)], c), 1e-6);
    }
  }
}

}  // namespace
}  // namespace sss_test
