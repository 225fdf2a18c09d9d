// A real client after sss_apply in the same frame: Dear ImGui's OpenGL3 backend (Debian's
// libimgui) draws a window into the host's framebuffer. Its pixels must be identical with and
// without the SSS pass before it, so the module left nothing behind that a typical client
// depends on. ImGui's backend loads GL through libGL.so.1 (glvnd), which dispatches to an EGL
// context but not to OSMesa's own library: the test runs on EGL and skips elsewhere.
#include <gtest/gtest.h>
#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>

#include <cstring>
#include <vector>

#include "filter_case.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

constexpr int kWidth = 160, kHeight = 120;

class ImGuiClient : public FilterCaseTest {
 protected:
  // One frame: optionally SSS on a scene texture, then ImGui into `target`; returns its pixels.
  std::vector<float> frame(bool with_sss, GLuint target, GLuint scene_color, GLuint scene_depth) {
    if (with_sss) {
      const sss_stencil stencil = {scene_depth, 1, 0xFF};
      EXPECT_EQ(sss_apply(sss_, scene_color, scene_depth, &stencil), SSS_OK) << sss_last_error(sss_);
    }
    GLuint framebuffer = 0;
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
    glViewport(0, 0, kWidth, kHeight);
    glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(kWidth), static_cast<float>(kHeight));
    io.DeltaTime = 1.0f / 60.0f;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(8, 8));
    ImGui::SetNextWindowSize(ImVec2(140, 90));
    ImGui::Begin("sss");
    ImGui::Text("subsurface scattering");
    static float width = 0.5f;
    ImGui::SliderFloat("width", &width, 0.0f, 1.0f);
    ImGui::End();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    return read_rgba(target, kWidth, kHeight);
  }
};

TEST_F(ImGuiClient, DrawsTheSamePixelsAfterSssApply) {
  if (test_backend() == SSS_HEADLESS_OSMESA) GTEST_SKIP() << "ImGui's loader reaches GL through glvnd (EGL) only";
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the directory the test runs in
  ASSERT_TRUE(ImGui_ImplOpenGL3_Init("#version 330 core"));
  const SyntheticScene scene = make_relief_scene(kWidth, kHeight, 3, perspective_matrix(40.0f, 4.0f / 3.0f, 0.1f, 10.0f));
  const GLuint color = make_rgba16f(kWidth, kHeight, scene.color);
  std::vector<uint32_t> packed(scene.window_depth.size());
  for (std::size_t i = 0; i < packed.size(); ++i) {
    packed[i] = (static_cast<uint32_t>(scene.window_depth[i] * 16777215.0) << 8) | scene.stencil[i];
  }
  const GLuint depth = make_texture(GL_DEPTH24_STENCIL8, kWidth, kHeight, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed.data());
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
  ASSERT_EQ(sss_set_camera(sss_, scene.projection.data()), SSS_OK);
  const GLuint target_plain = make_texture(GL_RGBA8, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  const GLuint target_sss = make_texture(GL_RGBA8, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);

  frame(false, target_plain, color, depth);  // ImGui builds its font atlas and programs here
  const std::vector<float> plain = frame(false, target_plain, color, depth);
  const std::vector<float> after_sss = frame(true, target_sss, color, depth);
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext();

  int drawn = 0;
  for (std::size_t i = 0; i < plain.size(); i += 4) drawn += plain[i] != plain[0] || plain[i + 2] != plain[2];
  EXPECT_GT(drawn, 500) << "ImGui drew nothing: the comparison would prove nothing";
  EXPECT_EQ(0, std::memcmp(plain.data(), after_sss.data(), plain.size() * sizeof(float)));
}

}  // namespace
}  // namespace sss_test
