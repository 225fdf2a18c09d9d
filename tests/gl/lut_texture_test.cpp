// sss_lut_create_texture: the GPU generator against the CPU one (every texel, both LUTs, both shadow
// filters, each format), the cache, and bad input. Runs on both headless backends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gl_fixture.hpp"
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
  // RGBA8: the fragment output's float-to-unorm conversion rounds within one step of 1/255.
  desc.format = SSS_LUT_FORMAT_RGBA8;
  EXPECT_LE(max_difference(SSS_LUT_DIFFUSE, desc), kFp32Tolerance + 1.0 / 255.0);
  // RGBA8 from the CPU: rounded to nearest on the host, half a step.
  desc.flags = SSS_LUT_CPU;
  EXPECT_LE(max_difference(SSS_LUT_SHADOW, desc), 0.5 / 255.0 + 1e-6);
  // RGBA32F from the CPU: exactly the fill.
  desc.format = SSS_LUT_FORMAT_RGBA32F;
  EXPECT_EQ(max_difference(SSS_LUT_SHADOW, desc), 0.0);
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

}  // namespace
}  // namespace sss_test
