// The yardstick: two full-screen passes that only copy (irradiance -> temporary -> output). Every
// time in the results is also given as a ratio to this one, measured in the same run, so numbers
// from different machines can be compared.
#include "fullscreen.hpp"
#include "host_gl_util.hpp"
#include "method.hpp"

using namespace host_gl;

namespace sss_bench {

namespace {

const char* const kCopyShader = R"(#version 330 core
uniform sampler2D u_source;
out vec4 o_color;
void main() { o_color = texelFetch(u_source, ivec2(gl_FragCoord.xy), 0); }
)";

class CopyMethod : public Method {
 public:
  CopyMethod() : program_(build_fullscreen_program("copy", kCopyShader)) {}
  ~CopyMethod() override {
    glUseProgram(0);  // a deleted program that stays current would be restored by name later
    glDeleteProgram(program_);
    glDeleteTextures(1, &temporary_);
  }
  std::string name() const override { return "copy"; }
  int taps() const override { return 1; }
  bool follow_surface() const override { return false; }
  int passes() const override { return 2; }

  bool run(const GpuScene& scene, GLuint output, std::string* error) override {
    if (temporary_ == 0 || width_ != scene.width || height_ != scene.height) {
      glDeleteTextures(1, &temporary_);
      temporary_ = make_texture(GL_RGBA16F, scene.width, scene.height, GL_RGBA, GL_HALF_FLOAT);
      width_ = scene.width;
      height_ = scene.height;
    }
    glUseProgram(program_);
    glUniform1i(glGetUniformLocation(program_, "u_source"), 0);
    if (!pass_.bind_targets({temporary_}, scene.width, scene.height, error)) return false;
    FullscreenPass::bind_texture(0, scene.irradiance);
    pass_.draw();
    if (!pass_.bind_targets({output}, scene.width, scene.height, error)) return false;
    FullscreenPass::bind_texture(0, temporary_);
    pass_.draw();
    return true;
  }

 private:
  GLuint program_;
  FullscreenPass pass_;
  GLuint temporary_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace

std::unique_ptr<Method> make_copy_method() { return std::make_unique<CopyMethod>(); }

}  // namespace sss_bench
