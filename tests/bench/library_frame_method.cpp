#include "library_frame_method.hpp"

#include <stdexcept>

using namespace host_gl;

namespace sss_bench {

LibraryFrameMethod::LibraryFrameMethod(const GlLoader& loader) {
  sss_create_desc desc = {};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = loader.get_proc_address;
  desc.get_proc_address_user = loader.user;
  if (sss_create(&desc, &ctx_) != SSS_OK) throw std::runtime_error(sss_last_error(nullptr));
  glGenFramebuffers(2, framebuffers_);
}

LibraryFrameMethod::~LibraryFrameMethod() {
  sss_destroy(ctx_);
  glDeleteFramebuffers(2, framebuffers_);
  if (work_ != 0) glDeleteTextures(1, &work_);
}

std::string LibraryFrameMethod::path_ran() const {
  sss_stats st = {};
  st.struct_size = sizeof st;
  if (sss_get_stats(ctx_, &st) != SSS_OK) return "";
  return st.last_frame_path == SSS_PATH_COMPUTE           ? "compute"
         : st.last_frame_path == SSS_PATH_FRAGMENT_MASKED ? "masked"
         : st.last_frame_path == SSS_PATH_HALF_RESOLUTION ? "half"
                                                          : "fragment";
}

bool LibraryFrameMethod::ensure_work(const GpuScene& scene) {
  if (work_ != 0 && work_width_ == scene.width && work_height_ == scene.height) return false;
  if (work_ == 0) glGenTextures(1, &work_);
  glBindTexture(GL_TEXTURE_2D, work_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, scene.width, scene.height, 0, GL_RGBA, GL_FLOAT, nullptr);
  glBindTexture(GL_TEXTURE_2D, 0);
  work_width_ = scene.width;
  work_height_ = scene.height;
  return true;
}

void LibraryFrameMethod::blit(GLuint from, GLuint to, int width, int height) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffers_[0]);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, from, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffers_[1]);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, to, 0);
  glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace sss_bench
