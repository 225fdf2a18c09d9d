// integration/glsl/sss_transmittance.glsl on the GL against the CPU formula (DESIGN.md §5): a slab
// lit from behind, its back face at known thicknesses from the light's distance map; the
// transmitted light must equal the profile (the same terms the blur uses) at that thickness.
//
// Tolerance 1e-6 absolute (values <= 1) at the GPU's own thickness: float exp, products and division
// on the GPU against double on the CPU, some ten operations of 6e-8 relative each (measured 6.4e-8
// on llvmpipe); a wrong term, scale
// or shrink moves values by 1e-3 or more at these thicknesses. The thickness itself is checked to 1e-5
// world units (its float cancellation is 5e-7).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "gl_fixture.hpp"
#include "host_gl_util.hpp"
#include "math/spike_gaussian_profile.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

std::string read_include() {
  std::ifstream in(SSS_TRANSMITTANCE_GLSL);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// One pixel per thickness: the fragment at x sits on the slab's back face, `thickness(x)` behind
// the front face the light sees at distance 2 (light at the origin looking down -Z, orthographic).
constexpr const char* kFragmentMain = R"(
uniform sampler2D u_map;
uniform float u_width, u_translucency, u_shrink;
uniform mat4 u_light_view, u_light_projection;
out vec4 o_color;
void main() {
  float thickness = (gl_FragCoord.x - 0.5) * 0.002;
  vec3 position = vec3(0.1, -0.2, -(2.0 + thickness));
  vec3 normal = vec3(0.0, 0.0, -1.0);  // the back face looks away from the light
  float t = SSS_TEST_THICKNESS(u_map, u_light_view, u_light_projection, position, normal, u_shrink);
  o_color = vec4(sss_transmittance(t, u_width, u_translucency, normal, vec3(0.0, 0.0, 1.0)), t);
}
)";

using Transmittance = GlTest;

TEST_F(Transmittance, SlabLitFromBehindMatchesTheProfileAtItsThickness) {
  for (uint32_t profile : {uint32_t{SSS_PROFILE_SKIN_DEON}, uint32_t{SSS_PROFILE_MIKKELSEN_2010}}) {
   for (bool hardware_depth : {true, false}) {
    SCOPED_TRACE(profile);
    SCOPED_TRACE(hardware_depth);
    const std::string fragment = std::string("#version 330 core\n#define SSS_TEST_THICKNESS ") +
                                 (hardware_depth ? "sss_thickness" : "sss_thickness_linear") + "\n" +
                                 read_include() + kFragmentMain;
    const GLuint program = build_program("transmittance test", kFullscreenVertexShader, fragment.c_str());
    ASSERT_NE(program, 0u);
    constexpr int kWidth = 64;
    // Orthographic light looking down -Z from the origin, near 0.5, far 10: the front face at
    // distance 2 is window depth (2 - 0.5) / 9.5 in a depth map, or 2 in a distance map.
    const float near_plane = 0.5f, far_plane = 10.0f;
    const std::vector<float> distance_map(16 * 16, 2.0f);
    const std::vector<float> depth_map(16 * 16, (2.0f - near_plane) / (far_plane - near_plane));
    const GLuint map = hardware_depth ? make_depth32f(16, 16, depth_map)
                                      : make_texture(GL_R32F, 16, 16, GL_RED, GL_FLOAT, distance_map.data());
    const GLuint target = make_rgba32f(kWidth, 1, std::vector<float>(kWidth * 4, 0.0f));
    const DrawTarget draw(target, kWidth, 1);
    glUseProgram(program);
    float terms[SSS_PROFILE_MAX_TERMS * 4];
    int32_t count = 0;
    ASSERT_EQ(sss_profile_transmittance_terms(profile, terms, SSS_PROFILE_MAX_TERMS, &count), SSS_OK);
    glUniform4fv(glGetUniformLocation(program, "sss_transmittance_terms"), count, terms);
    glUniform1i(glGetUniformLocation(program, "sss_transmittance_term_count"), count);
    const float width = 0.012f, translucency = 0.2f, shrink = 0.005f;
    glUniform1f(glGetUniformLocation(program, "u_width"), width);
    glUniform1f(glGetUniformLocation(program, "u_translucency"), translucency);
    glUniform1f(glGetUniformLocation(program, "u_shrink"), shrink);
    const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const float projection[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2.0f / (far_plane - near_plane), 0,
                                  0, 0, -(far_plane + near_plane) / (far_plane - near_plane), 1};
    glUniformMatrix4fv(glGetUniformLocation(program, "u_light_view"), 1, GL_FALSE, identity);
    glUniformMatrix4fv(glGetUniformLocation(program, "u_light_projection"), 1, GL_FALSE, projection);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, map);
    glUniform1i(glGetUniformLocation(program, "u_map"), 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    const std::vector<float> out = read_rgba(target, kWidth, 1);
    glDeleteProgram(program);

    const auto cpu_terms = sss::math::transmittance_terms(sss::math::spike_gaussian_profile(profile));
    double worst = 0.0;
    for (int x = 0; x < kWidth; ++x) {
      // The point is pulled `shrink` towards the light: the thickness crossed is that much less.
      const double thickness = std::fabs(x * 0.002 - shrink);
      // 1e-5: float cancellation near distance 2 (ulp 2.4e-7) and, for the depth map, its
      // linearisation (fp32 depth: 6e-8 of the 9.5 range).
      EXPECT_NEAR(out[static_cast<std::size_t>(x) * 4 + 3], thickness, 1e-5);
      // The profile at the thickness the GPU found (checked just above): the thickness is a difference
      // of two distances near 2 (float ulp 2.4e-7) that the scale 8.25·0.8/0.012 = 550 magnifies, so
      // comparing at the exact thickness would measure that cancellation, not the include.
      const double s = out[static_cast<std::size_t>(x) * 4 + 3] * 8.25 * (1.0 - translucency) / width;
      for (int c = 0; c < 3; ++c) {
        const double expected = sss::math::transmittance(cpu_terms, c, s);  // dot(L, -N) = 1: factor 1
        worst = std::max(worst, std::fabs(out[static_cast<std::size_t>(x) * 4 + c] - expected));
      }
    }
    std::printf("transmittance, profile %u: largest |GPU - CPU| %.3g\n", profile, worst);
    EXPECT_LE(worst, 1e-6);
    // Thin parts glow, thick ones do not: red through 0.01 world units of skin, none through 0.1.
    if (profile == SSS_PROFILE_SKIN_DEON) {
      EXPECT_GT(out[5 * 4], 0.01f);
      EXPECT_LT(out[50 * 4], 1e-4f);
    }
    TearDown();
    SetUp();
   }
  }
}

}  // namespace
}  // namespace sss_test
