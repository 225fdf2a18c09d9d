// integration/glsl/sss_back_transmittance.glsl (Mikkelsen's back-facing irradiance gather) on the
// GL against the same 16-tap sum on the CPU: a front plane facing the camera with a back face a
// known thickness behind it. Also: back faces whose tangent planes do not oppose the front's give
// nothing (the sqrt(max(0, -n_t·n_o)) penalty), and thicker slabs transmit less.
//
// Tolerance 1e-5 relative: the GPU and the CPU run the same float formula (tap positions floored
// alike; the scene is uniform so a tap moved to the next texel would change r by one pixel,
// 1.1 mm, and the sum by far more than that); exp and the products differ by float ulps.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "gl_fixture.hpp"
#include "host_gl_util.hpp"
#include "synthetic_scene.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

std::string read_file(const char* path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

constexpr const char* kMain = R"(
uniform sampler2D u_back, u_back_normal;
uniform mat4 u_projection;
uniform vec4 u_viewport;
uniform float u_width, u_r_max;
out vec4 o_color;
void main() {
  vec3 x_o = sss_view_point(gl_FragCoord.xy, 1.0, u_projection, u_viewport);  // the front plane at distance 1
  o_color = vec4(sss_back_transmittance(u_back, u_back_normal, gl_FragCoord.xy, x_o, vec3(0.0, 0.0, 1.0),
                                        u_projection, u_viewport, u_width, u_r_max), 1.0);
}
)";

constexpr int kSize = 32;
constexpr float kWidth = 0.03f, kRMax = 4.5f;

struct Slab {
  float thickness;                  // world units between the front plane and the back face
  std::array<float, 3> back_normal;  // view space
};

// The CPU sum, in float like the shader.
std::array<float, 3> cpu_sum(const sss::math::Matrix4& m, const std::vector<float>& terms, int count, const Slab& s,
                             int px, int py) {
  auto view_point = [&](float x, float y, float distance) {
    const float nx = x / kSize * 2.0f - 1.0f, ny = y / kSize * 2.0f - 1.0f;
    const float z = -distance, w = m[11] * z + m[15];
    return std::array<float, 3>{(nx * w - m[8] * z - m[12]) / m[0], (ny * w - m[9] * z - m[13]) / m[5], z};
  };
  const float cx = static_cast<float>(px) + 0.5f, cy = static_cast<float>(py) + 0.5f;
  const auto xo = view_point(cx, cy, 1.0f);
  const float world_per_mm = kWidth * (2.0f / 3.0f);
  const float w = m[11] * xo[2] + m[15];
  const float hx = m[0] * 0.5f * kSize * (kRMax * world_per_mm) / w, hy = m[5] * 0.5f * kSize * (kRMax * world_per_mm) / w;
  const float area = 3.14159265359f * kRMax * kRMax / 16.0f;
  const float facing = std::sqrt(std::max(0.0f, -s.back_normal[2]));  // n_o = (0, 0, 1)
  std::array<float, 3> sum = {0.0f, 0.0f, 0.0f};
  for (int i = 0; i < 16; ++i) {
    const float radius = std::sqrt((static_cast<float>(i) + 0.5f) / 16.0f);
    const float angle = static_cast<float>(i) * 2.39996322973f;
    const int tx = static_cast<int>(std::clamp(std::floor(cx + hx * radius * std::cos(angle)), 0.0f, kSize - 1.0f));
    const int ty = static_cast<int>(std::clamp(std::floor(cy + hy * radius * std::sin(angle)), 0.0f, kSize - 1.0f));
    const auto xt = view_point(static_cast<float>(tx) + 0.5f, static_cast<float>(ty) + 0.5f, 1.0f + s.thickness);
    const float dx = xt[0] - xo[0], dy = xt[1] - xo[1], dz = xt[2] - xo[2];
    const float r = std::sqrt(dx * dx + dy * dy + dz * dz) / world_per_mm;
    for (int k = 0; k < count; ++k) {
      const float v = terms[static_cast<std::size_t>(k) * 4];
      const float g = std::exp(-r * r / (2.0f * v)) / (6.28318530718f * v);
      const float back[3] = {1.0f, 0.5f, 0.25f};
      for (int c = 0; c < 3; ++c) {
        sum[static_cast<std::size_t>(c)] += back[c] * terms[static_cast<std::size_t>(k) * 4 + 1 + c] * g * area * facing;
      }
    }
  }
  return sum;
}

class BackTransmittance : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    ASSERT_EQ(sss_profile_transmittance_terms(SSS_PROFILE_MIKKELSEN_2010, terms_.data(), SSS_PROFILE_MAX_TERMS, &count_),
              SSS_OK);
    const std::string fragment = "#version 330 core\n" + read_file(SSS_TRANSMITTANCE_GLSL) +
                                 read_file(SSS_BACK_TRANSMITTANCE_GLSL) + kMain;
    program_ = build_program("back transmittance test", kFullscreenVertexShader, fragment.c_str());
    ASSERT_NE(program_, 0u);
  }
  void TearDown() override {
    glDeleteProgram(program_);
    GlTest::TearDown();
  }

  // The gather over a back-face buffer of the slab's normal whose every texel holds `distance`.
  std::vector<float> render(float distance, const std::array<float, 3>& back_normal) {
    std::vector<float> back(kSize * kSize * 4), normals(kSize * kSize * 4);
    for (int i = 0; i < kSize * kSize; ++i) {
      const float values[4] = {1.0f, 0.5f, 0.25f, distance};
      for (int c = 0; c < 4; ++c) back[static_cast<std::size_t>(i) * 4 + c] = values[c];
      for (int c = 0; c < 3; ++c) normals[static_cast<std::size_t>(i) * 4 + c] = back_normal[static_cast<std::size_t>(c)];
    }
    const GLuint back_texture = make_rgba32f(kSize, kSize, back);
    const GLuint normal_texture = make_rgba32f(kSize, kSize, normals);
    const GLuint target = make_rgba32f(kSize, kSize, std::vector<float>(kSize * kSize * 4, 0.0f));
    const DrawTarget draw(target, kSize, kSize);
    glUseProgram(program_);
    glUniform4fv(glGetUniformLocation(program_, "sss_transmittance_terms"), count_, terms_.data());
    glUniform1i(glGetUniformLocation(program_, "sss_transmittance_term_count"), count_);
    glUniformMatrix4fv(glGetUniformLocation(program_, "u_projection"), 1, GL_FALSE, projection_.data());
    glUniform4f(glGetUniformLocation(program_, "u_viewport"), 0.0f, 0.0f, kSize, kSize);
    glUniform1f(glGetUniformLocation(program_, "u_width"), kWidth);
    glUniform1f(glGetUniformLocation(program_, "u_r_max"), kRMax);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, back_texture);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, normal_texture);
    glUniform1i(glGetUniformLocation(program_, "u_back"), 0);
    glUniform1i(glGetUniformLocation(program_, "u_back_normal"), 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    return read_rgba(target, kSize, kSize);
  }
  std::vector<float> render(const Slab& s) { return render(1.0f + s.thickness, s.back_normal); }

  const sss::math::Matrix4 projection_ = perspective_matrix(40.0f, 1.0f, 0.1f, 10.0f);
  std::vector<float> terms_ = std::vector<float>(SSS_PROFILE_MAX_TERMS * 4, 0.0f);
  int32_t count_ = 0;
  GLuint program_ = 0;
};

TEST_F(BackTransmittance, GatherMatchesTheCpuSumAndOnlyOpposingBackFacesTransmit) {
  const Slab thin{0.04f, {0.0f, 0.0f, -1.0f}};    // 2 mm of profile behind, facing away: opposing planes
  const Slab thick{0.08f, {0.0f, 0.0f, -1.0f}};   // 4 mm
  const Slab same_way{0.04f, {0.0f, 0.0f, 1.0f}};  // a back surface turned towards the camera: no transmission
  const std::vector<float> a = render(thin), b = render(thick), c = render(same_way);
  float worst = 0.0f;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * kSize + x) * 4;
      const auto expected = cpu_sum(projection_, terms_, count_, thin, x, y);
      for (int ch = 0; ch < 3; ++ch) {
        worst = std::max(worst, std::fabs(a[i + ch] - expected[static_cast<std::size_t>(ch)]) /
                                    std::max(1e-6f, expected[static_cast<std::size_t>(ch)]));
        EXPECT_GT(a[i + ch], 0.0f);
        EXPECT_LT(b[i + ch], a[i + ch]);  // thicker: less light through
        EXPECT_EQ(c[i + ch], 0.0f);
      }
    }
  }
  std::printf("back transmittance: largest relative |GPU - CPU| %.3g, centre red %.4g (2 mm) %.4g (4 mm)\n", worst,
              a[(16 * kSize + 16) * 4], b[(16 * kSize + 16) * 4]);
  EXPECT_LE(worst, 1e-5f);
}

// A back-face distance that is not a positive finite number adds nothing, as sss_transmittance
// gives no light for a NaN or infinite thickness: an infinite one would otherwise turn the
// view-space point into inf - inf = NaN and the pixel (and the blur after it) NaN.
TEST_F(BackTransmittance, BackDistancesThatAreNotPositiveFiniteAddNothing) {
  for (float distance : {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(),
                         -std::numeric_limits<float>::infinity(), -1.0f, 0.0f}) {
    SCOPED_TRACE(distance);
    const std::vector<float> out = render(distance, {0.0f, 0.0f, -1.0f});
    for (std::size_t i = 0; i < out.size(); i += 4) {
      for (int c = 0; c < 3; ++c) ASSERT_EQ(out[i + static_cast<std::size_t>(c)], 0.0f) << i / 4;
    }
  }
}

}  // namespace
}  // namespace sss_test
