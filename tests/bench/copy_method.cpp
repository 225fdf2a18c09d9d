// The yardstick: two full-screen passes that only copy (irradiance -> temporary -> output). Every
// time in the results is also given as a ratio to this one, measured in the same run, so numbers
// from different machines can be compared. Where compute shaders run (GL 4.3+), the same two
// copies as compute dispatches ("copy-compute"): on a GPU whose few graphics-capable units shade
// fragments (an H100 has 2 of its 66 TPCs for graphics), that is the memory-bound limit the
// compute path is measured against.
#include "fullscreen.hpp"
#include "host_gl_util.hpp"
#include "method.hpp"

#include <stdexcept>

using namespace host_gl;

namespace sss_bench {

namespace {

const char* const kCopyShader = R"(#version 330 core
uniform sampler2D u_source;
out vec4 o_color;
void main() { o_color = texelFetch(u_source, ivec2(gl_FragCoord.xy), 0); }
)";

// What both copies share: the program, a temporary of the scene's size, and what they report.
class TwoPassCopy : public Method {
 public:
  TwoPassCopy(GLuint program, GLint temporary_format) : program_(program), temporary_format_(temporary_format) {
    if (program_ == 0) throw std::runtime_error("a copy program did not build");
  }
  ~TwoPassCopy() override {
    glUseProgram(0);  // a deleted program that stays current would be restored by name later
    glDeleteProgram(program_);
    glDeleteTextures(1, &temporary_);
  }
  int taps() const override { return 1; }
  bool follow_surface() const override { return false; }
  int passes() const override { return 2; }

 protected:
  // The temporary for this scene's size, (re)made when the size changes.
  GLuint temporary(const GpuScene& scene) {
    if (temporary_ == 0 || width_ != scene.width || height_ != scene.height) {
      glDeleteTextures(1, &temporary_);
      temporary_ = temporary_format_ == GL_RGBA16F
                       ? make_texture(GL_RGBA16F, scene.width, scene.height, GL_RGBA, GL_HALF_FLOAT)
                       : make_texture(temporary_format_, scene.width, scene.height, GL_RGBA, GL_FLOAT);
      width_ = scene.width;
      height_ = scene.height;
    }
    return temporary_;
  }
  const GLuint program_;

 private:
  const GLint temporary_format_;
  GLuint temporary_ = 0;
  int width_ = 0, height_ = 0;
};

class CopyMethod : public TwoPassCopy {
 public:
  CopyMethod() : TwoPassCopy(build_fullscreen_program("copy", kCopyShader), GL_RGBA16F) {
    glUseProgram(program_);
    glUniform1i(glGetUniformLocation(program_, "u_source"), 0);
    glUseProgram(0);
  }
  std::string name() const override { return "copy"; }

  bool run(const GpuScene& scene, GLuint output, std::string* error) override {
    const GLuint middle = temporary(scene);
    glUseProgram(program_);
    if (!pass_.bind_targets({middle}, scene.width, scene.height, error)) return false;
    FullscreenPass::bind_texture(0, scene.irradiance);
    pass_.draw();
    if (!pass_.bind_targets({output}, scene.width, scene.height, error)) return false;
    FullscreenPass::bind_texture(0, middle);
    pass_.draw();
    return true;
  }

 private:
  FullscreenPass pass_;
};

const char* const kComputeCopyShader = R"(#version 430 core
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0) uniform sampler2D u_source;
layout(binding = 0, rgba32f) uniform writeonly image2D u_target;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, textureSize(u_source, 0)))) return;
  imageStore(u_target, p, texelFetch(u_source, p, 0));
}
)";

class ComputeCopyMethod : public TwoPassCopy {
 public:
  ComputeCopyMethod() : TwoPassCopy(build_compute_program("copy-compute", kComputeCopyShader), GL_RGBA32F) {}
  std::string name() const override { return "copy-compute"; }

  bool run(const GpuScene& scene, GLuint output, std::string* /*error*/) override {
    const GLuint middle = temporary(scene);
    glUseProgram(program_);
    const GLuint groups_x = static_cast<GLuint>((scene.width + 15) / 16);
    const GLuint groups_y = static_cast<GLuint>((scene.height + 15) / 16);
    FullscreenPass::bind_texture(0, scene.irradiance);
    glBindImageTexture(0, middle, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(groups_x, groups_y, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    FullscreenPass::bind_texture(0, middle);
    glBindImageTexture(0, output, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(groups_x, groups_y, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    return true;
  }
};

}  // namespace

std::unique_ptr<Method> make_copy_method() { return std::make_unique<CopyMethod>(); }

std::unique_ptr<Method> make_compute_copy_method() {
  return has_compute_shaders() ? std::make_unique<ComputeCopyMethod>() : nullptr;
}

}  // namespace sss_bench
