// sss_lut_create_texture: the GPU generator against the CPU one (every texel, both LUTs, both shadow
// filters, each format), the cache, the measured materials, and bad input. Runs on both headless
// backends and on OpenGL ES (egl-gles: the generator in GLSL ES 3.00).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <fstream>
#include <sstream>

#include "gl_fixture.hpp"
#include "host_gl_util.hpp"
#include "sss/sss_lut.h"

using namespace host_gl;

namespace sss_test {
namespace {

class LutTexture : public GlTest {
 protected:
  std::vector<float> cpu(int32_t which, const sss_lut_desc& desc) {
    std::vector<float> out(4u * static_cast<std::size_t>(desc.width) * static_cast<std::size_t>(desc.height));
    const sss_result r = which == SSS_LUT_DIFFUSE ? sss_lut_diffuse_fill(&desc, out.data(), out.size())
                                                  : sss_lut_shadow_fill(&desc, out.data(), out.size());
    EXPECT_EQ(r, SSS_OK) << sss_last_error(nullptr);
    return out;
  }
  // Largest |GPU texture - CPU fill| over every texel and channel.
  double max_difference(int32_t which, const sss_lut_desc& desc) {
    uint32_t texture = 0;
    EXPECT_EQ(sss_lut_create_texture(sss_, which, &desc, &texture), SSS_OK) << sss_last_error(sss_);
    const std::vector<float> gpu = read_rgba(texture, desc.width, desc.height);
    const std::vector<float> reference = cpu(which, desc);
    double worst = 0.0;
    std::size_t at = 0;
    for (std::size_t i = 0; i < gpu.size(); ++i) {
      EXPECT_TRUE(std::isfinite(gpu[i])) << i;
      const double d = std::fabs(static_cast<double>(gpu[i]) - reference[i]);
      if (d > worst) {
        worst = d;
        at = i;
      }
    }
    RecordProperty("max_difference", std::to_string(worst));
    std::printf("LUT %d format %d flags %u filter %d: max |GPU - CPU| = %.3g at texel (%zu, %zu) channel %zu\n", which,
                desc.format, desc.flags, desc.shadow_filter, worst, at / 4 % static_cast<std::size_t>(desc.width),
                at / 4 / static_cast<std::size_t>(desc.width), at % 4);
    return worst;
  }
};

// The GPU runs the CPU's quadrature in fp32 (~200 terms summed: ~1e-6 relative). The larger share
// is the driver's transcendentals: llvmpipe evaluates cos, sin and exp by short polynomials good
// to ~1e-4 absolute (the largest difference measured on this LUT is 1.5e-4, diffuse, blue, N·L 0.31,
// r = 16 mm); 5e-4 keeps a 3x margin, while a lost panel or kink moves values by 1e-2 or more.
// The Gaussian penumbra adds its inverse: the shader bisects an erf approximation (|error| < 1.5e-7),
// and near s = 0 and 1 the inverse is steep (dt/ds = σ/φ(4.75) ≈ 4.5e4), which can move the position
// by ~7e-3 penumbra widths there: up to ~1e-3 in value where the blurred penumbra is steepest.
constexpr double kFp32Tolerance = 5e-4;
constexpr double kGaussianPenumbraTolerance = 2e-3;

TEST_F(LutTexture, GpuGeneratorMatchesCpuGenerator) {
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  sss_lut_desc desc;
  sss_lut_default_desc(&desc);
  desc.width = 33;
  desc.height = 17;
  desc.format = SSS_LUT_FORMAT_RGBA32F;
  EXPECT_LE(max_difference(SSS_LUT_DIFFUSE, desc), kFp32Tolerance);
  desc.curvature_max = 20.0f;  // out to r = 0.05 mm: the ring-mean end
  EXPECT_LE(max_difference(SSS_LUT_DIFFUSE, desc), kFp32Tolerance);
  EXPECT_LE(max_difference(SSS_LUT_SHADOW, desc), kFp32Tolerance);
  desc.shadow_filter = SSS_LUT_SHADOW_GAUSSIAN;
  EXPECT_LE(max_difference(SSS_LUT_SHADOW, desc), kGaussianPenumbraTolerance);
}

TEST_F(LutTexture, FormatsHoldTheValuesToTheirPrecision) {
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  sss_lut_desc desc;
  sss_lut_default_desc(&desc);
  desc.width = 16;
  desc.height = 8;
  // RGBA16F: half rounding is 2^-11 relative (values <= 1) on top of the fp32 difference.
  desc.format = SSS_LUT_FORMAT_RGBA16F;
  EXPECT_LE(max_difference(SSS_LUT_DIFFUSE, desc), kFp32Tolerance + std::ldexp(1.0, -11));
  // RGBA32F from the CPU: exactly the fill.
  desc.format = SSS_LUT_FORMAT_RGBA32F;
  desc.flags = SSS_LUT_CPU;
  EXPECT_EQ(max_difference(SSS_LUT_SHADOW, desc), 0.0);
  // ES reads an RGBA8 attachment back only as unsigned bytes (read_rgba reads floats): desktop only.
  if (is_gles()) return;
  desc.flags = 0;
  // RGBA8: the fragment output's float-to-unorm conversion rounds within one step of 1/255.
  desc.format = SSS_LUT_FORMAT_RGBA8;
  EXPECT_LE(max_difference(SSS_LUT_DIFFUSE, desc), kFp32Tolerance + 1.0 / 255.0);
  // RGBA8 from the CPU: rounded to nearest on the host, half a step.
  desc.flags = SSS_LUT_CPU;
  EXPECT_LE(max_difference(SSS_LUT_SHADOW, desc), 0.5 / 255.0 + 1e-6);
}

TEST_F(LutTexture, MeasuredMaterialsAreGeneratedOnTheCpu) {
  // A dipole is no sum of Gaussians: the texture is the CPU fill uploaded (exactly, in RGBA32F),
  // for the asked profile (it differs from skin's), and cached like any other.
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  sss_lut_desc desc;
  sss_lut_default_desc(&desc);
  desc.width = 16;
  desc.height = 8;
  desc.format = SSS_LUT_FORMAT_RGBA32F;
  for (int32_t material : {SSS_PROFILE_MARBLE, SSS_PROFILE_KETCHUP}) {
    desc.profile = material;
    EXPECT_EQ(max_difference(SSS_LUT_DIFFUSE, desc), 0.0) << sss_profile_name(material);
    EXPECT_EQ(max_difference(SSS_LUT_SHADOW, desc), 0.0) << sss_profile_name(material);
  }
  EXPECT_EQ(sss_lut_generation_count(sss_), 4u);
  uint32_t marble = 0, skin = 0;
  desc.profile = SSS_PROFILE_MARBLE;
  ASSERT_EQ(sss_lut_create_texture(sss_, SSS_LUT_DIFFUSE, &desc, &marble), SSS_OK);
  EXPECT_EQ(sss_lut_generation_count(sss_), 4u);  // cached
  desc.profile = SSS_PROFILE_SKIN_DEON;
  ASSERT_EQ(sss_lut_create_texture(sss_, SSS_LUT_DIFFUSE, &desc, &skin), SSS_OK);
  EXPECT_NE(marble, skin);
  EXPECT_NE(read_rgba(marble, desc.width, desc.height), read_rgba(skin, desc.width, desc.height));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(LutTexture, SameInputsGiveTheCachedTextureWithoutGenerating) {
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  sss_lut_desc desc;
  sss_lut_default_desc(&desc);
  desc.width = 8;
  desc.height = 8;
  EXPECT_EQ(sss_lut_generation_count(sss_), 0u);
  uint32_t a = 0, b = 0, c = 0, d = 0;
  ASSERT_EQ(sss_lut_create_texture(sss_, SSS_LUT_DIFFUSE, &desc, &a), SSS_OK);
  EXPECT_EQ(sss_lut_generation_count(sss_), 1u);
  ASSERT_EQ(sss_lut_create_texture(sss_, SSS_LUT_DIFFUSE, &desc, &b), SSS_OK);
  EXPECT_EQ(a, b);
  EXPECT_EQ(sss_lut_generation_count(sss_), 1u);
  desc.threads = 3;  // how it is computed is not an input of the values: still cached
  ASSERT_EQ(sss_lut_create_texture(sss_, SSS_LUT_DIFFUSE, &desc, &b), SSS_OK);
  EXPECT_EQ(a, b);
  EXPECT_EQ(sss_lut_generation_count(sss_), 1u);
  desc.curvature_max = 0.5f;
  ASSERT_EQ(sss_lut_create_texture(sss_, SSS_LUT_DIFFUSE, &desc, &c), SSS_OK);
  EXPECT_NE(c, a);
  EXPECT_EQ(sss_lut_generation_count(sss_), 2u);
  ASSERT_EQ(sss_lut_create_texture(sss_, SSS_LUT_SHADOW, &desc, &d), SSS_OK);
  EXPECT_EQ(sss_lut_generation_count(sss_), 3u);
  desc.flags = SSS_LUT_CPU;  // CPU data cached too: a second format re-uploads, never regenerates
  ASSERT_EQ(sss_lut_create_texture(sss_, SSS_LUT_SHADOW, &desc, &d), SSS_OK);
  EXPECT_EQ(sss_lut_generation_count(sss_), 4u);
  desc.format = SSS_LUT_FORMAT_RGBA8;
  ASSERT_EQ(sss_lut_create_texture(sss_, SSS_LUT_SHADOW, &desc, &d), SSS_OK);
  EXPECT_EQ(sss_lut_generation_count(sss_), 4u);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(LutTexture, BadInputFailsWithNothingLeftBehind) {
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  sss_lut_desc desc;
  sss_lut_default_desc(&desc);
  uint32_t texture = 77;
  EXPECT_EQ(sss_lut_create_texture(sss_, 2, &desc, &texture), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(texture, 0u);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("which = 2"), std::string::npos) << sss_last_error(sss_);
  desc.format = 9;
  EXPECT_EQ(sss_lut_create_texture(sss_, SSS_LUT_DIFFUSE, &desc, &texture), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sss_last_error(sss_)).find("desc->format = 9"), std::string::npos) << sss_last_error(sss_);
  desc.format = SSS_LUT_FORMAT_RGBA16F;
  desc.curvature_max = -1.0f;
  EXPECT_EQ(sss_lut_create_texture(sss_, SSS_LUT_DIFFUSE, &desc, &texture), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sss_lut_create_texture(sss_, SSS_LUT_DIFFUSE, &desc, nullptr), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sss_lut_create_texture(nullptr, SSS_LUT_DIFFUSE, &desc, &texture), SSS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sss_lut_generation_count(sss_), 0u);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// The host include (integration/preintegrated/sss_preintegrated.glsl) run on the GL: a pass whose
// pixel (x, y) asks sss_skin_diffuse / sss_skin_shadow for the values the LUT's texel (x, y) stands
// for must read that texel back (the include's texel-centre mapping of the endpoint-inclusive grid),
// per channel; and a value between two texels must read their linear blend.
TEST_F(LutTexture, HostIncludeReadsTheGridTheFillFunctionsDescribe) {
  // The test's own pass is GLSL 330 (the include itself is validated in GLSL ES 3.00 by shaders.glslang).
  if (is_gles()) GTEST_SKIP() << "desktop GL test harness";
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  std::ifstream file(SSS_PREINTEGRATED_GLSL);
  ASSERT_TRUE(file.good()) << SSS_PREINTEGRATED_GLSL;
  std::stringstream include;
  include << file.rdbuf();
  sss_lut_desc desc;
  sss_lut_default_desc(&desc);
  desc.width = 17;
  desc.height = 9;
  desc.format = SSS_LUT_FORMAT_RGBA32F;
  desc.flags = SSS_LUT_CPU;  // exactly the fill's values
  uint32_t diffuse = 0, shadow = 0;
  ASSERT_EQ(sss_lut_create_texture(sss_, SSS_LUT_DIFFUSE, &desc, &diffuse), SSS_OK);
  ASSERT_EQ(sss_lut_create_texture(sss_, SSS_LUT_SHADOW, &desc, &shadow), SSS_OK);
  const std::string fragment = std::string("#version 330 core\n") + include.str() + R"(
uniform sampler2D u_diffuse;
uniform sampler2D u_shadow;
uniform vec2 u_curvature_range;
uniform vec2 u_penumbra_range;
uniform float u_half_step;  // 0: texel centres; 0.5: halfway to the next column
layout(location = 0) out vec4 o_diffuse;
layout(location = 1) out vec4 o_shadow;
void main() {
  vec2 size = vec2(textureSize(u_diffuse, 0));
  vec2 u = (floor(gl_FragCoord.xy) + vec2(u_half_step, 0.0)) / (size - 1.0);
  float curvature = mix(u_curvature_range.x, u_curvature_range.y, u.y);
  float ndotl = u.x * 2.0 - 1.0;
  o_diffuse = vec4(sss_skin_diffuse(u_diffuse, u_curvature_range, curvature, vec3(ndotl)), 1.0);
  o_shadow = vec4(sss_skin_shadow(u_shadow, u_penumbra_range, u.x, mix(u_penumbra_range.x, u_penumbra_range.y, u.y)), 1.0);
}
)";
  const GLuint program = host_gl::build_program("include test", host_gl::kFullscreenVertexShader, fragment.c_str());
  ASSERT_NE(program, 0u);
  const GLuint out_diffuse = make_texture(GL_RGBA32F, desc.width, desc.height, GL_RGBA, GL_FLOAT, nullptr);
  const GLuint out_shadow = make_texture(GL_RGBA32F, desc.width, desc.height, GL_RGBA, GL_FLOAT, nullptr);
  GLuint framebuffer = 0, vao = 0;
  glGenFramebuffers(1, &framebuffer);
  glGenVertexArrays(1, &vao);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, out_diffuse, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, out_shadow, 0);
  const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, buffers);
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
  glViewport(0, 0, desc.width, desc.height);
  glUseProgram(program);
  glUniform1i(glGetUniformLocation(program, "u_diffuse"), 0);
  glUniform1i(glGetUniformLocation(program, "u_shadow"), 1);
  glUniform2f(glGetUniformLocation(program, "u_curvature_range"), desc.curvature_min, desc.curvature_max);
  glUniform2f(glGetUniformLocation(program, "u_penumbra_range"), desc.penumbra_min, desc.penumbra_max);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, diffuse);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, shadow);
  glActiveTexture(GL_TEXTURE0);
  glBindVertexArray(vao);
  const std::vector<float> cpu_diffuse = cpu(SSS_LUT_DIFFUSE, desc), cpu_shadow = cpu(SSS_LUT_SHADOW, desc);
  for (float half : {0.0f, 0.5f}) {
    glUniform1f(glGetUniformLocation(program, "u_half_step"), half);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    const std::vector<float> got_diffuse = read_rgba(out_diffuse, desc.width, desc.height);
    const std::vector<float> got_shadow = read_rgba(out_shadow, desc.width, desc.height);
    for (int y = 0; y < desc.height; ++y) {
      for (int x = 0; x + (half > 0.0f ? 1 : 0) < desc.width; ++x) {
        for (int c = 0; c < 3; ++c) {
          const std::size_t i = 4u * static_cast<std::size_t>(y * desc.width + x) + static_cast<std::size_t>(c);
          const float next_d = half > 0.0f ? cpu_diffuse[i + 4] : cpu_diffuse[i];
          const float next_s = half > 0.0f ? cpu_shadow[i + 4] : cpu_shadow[i];
          // Texel centres are exact; halfway the blend is the mean. The filtering unit's weights
          // are 8-bit fractions on llvmpipe (1/256 of the step between the two texels) plus fp32
          // coordinate rounding: 1e-5 absolute at centres, 1/256 of the neighbours' difference halfway.
          const double tol_d = 1e-5 + std::fabs(next_d - cpu_diffuse[i]) / 256.0;
          const double tol_s = 1e-5 + std::fabs(next_s - cpu_shadow[i]) / 256.0;
          EXPECT_NEAR(got_diffuse[i], 0.5f * half * 2.0f * (next_d - cpu_diffuse[i]) + cpu_diffuse[i], tol_d)
              << "diffuse x " << x << " y " << y << " c " << c << " half " << half;
          EXPECT_NEAR(got_shadow[i], 0.5f * half * 2.0f * (next_s - cpu_shadow[i]) + cpu_shadow[i], tol_s)
              << "shadow x " << x << " y " << y << " c " << c << " half " << half;
        }
      }
    }
  }
  glBindVertexArray(0);
  glDeleteVertexArrays(1, &vao);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &framebuffer);
  glUseProgram(0);
  glDeleteProgram(program);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace sss_test
