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

using DispatchComputeFn = void (*)(GLuint, GLuint, GLuint);
using MemoryBarrierFn = void (*)(GLbitfield);

class ComputeCopyMethod : public Method {
 public:
  ComputeCopyMethod(DispatchComputeFn dispatch, MemoryBarrierFn barrier)
      : dispatch_(dispatch), barrier_(barrier), program_(build_compute_program("copy-compute", kComputeCopyShader)) {
    if (program_ == 0) throw std::runtime_error("the compute copy program did not build");
  }
  ~ComputeCopyMethod() override {
    glUseProgram(0);
    glDeleteProgram(program_);
    glDeleteTextures(1, &temporary_);
  }
  std::string name() const override { return "copy-compute"; }
  int taps() const override { return 1; }
  bool follow_surface() const override { return false; }
  int passes() const override { return 2; }

  bool run(const GpuScene& scene, GLuint output, std::string* /*error*/) override {
    if (temporary_ == 0 || width_ != scene.width || height_ != scene.height) {
      glDeleteTextures(1, &temporary_);
      temporary_ = make_texture(GL_RGBA32F, scene.width, scene.height, GL_RGBA, GL_FLOAT);
      width_ = scene.width;
      height_ = scene.height;
    }
    glUseProgram(program_);
    const GLuint groups_x = static_cast<GLuint>((scene.width + 15) / 16);
    const GLuint groups_y = static_cast<GLuint>((scene.height + 15) / 16);
    FullscreenPass::bind_texture(0, scene.irradiance);
    glBindImageTexture(0, temporary_, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatch_(groups_x, groups_y, 1);
    barrier_(GL_TEXTURE_FETCH_BARRIER_BIT);
    FullscreenPass::bind_texture(0, temporary_);
    glBindImageTexture(0, output, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatch_(groups_x, groups_y, 1);
    barrier_(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    return true;
  }

 private:
  DispatchComputeFn dispatch_;
  MemoryBarrierFn barrier_;
  GLuint program_ = 0;
  GLuint temporary_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace

std::unique_ptr<Method> make_copy_method() { return std::make_unique<CopyMethod>(); }

std::unique_ptr<Method> make_compute_copy_method(const GlLoader& loader) {
  if (!has_compute_shaders()) return nullptr;
  const auto dispatch = reinterpret_cast<DispatchComputeFn>(loader.get_proc_address("glDispatchCompute", loader.user));
  const auto barrier = reinterpret_cast<MemoryBarrierFn>(loader.get_proc_address("glMemoryBarrier", loader.user));
  if (dispatch == nullptr || barrier == nullptr) return nullptr;
  return std::make_unique<ComputeCopyMethod>(dispatch, barrier);
}

}  // namespace sss_bench
