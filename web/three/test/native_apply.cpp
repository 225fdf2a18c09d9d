// sss_three_native_apply: the three.js pass's frame filtered again natively, on OpenGL ES 3.0 (EGL
// surfaceless, Mesa llvmpipe), from exactly the inputs the pass gave the library in the browser
// (web/three/test/three_test.py captures them, docs/three.md "Against the native frame"): three's
// colour before the pass, its depth, the pass's profile texture, the projection and every setting.
// Three's scene cannot be rebuilt natively, so the same inputs stand in for the same scene.
//
//   sss_three_native_apply DIR
//
// DIR holds (rows bottom first, as glReadPixels gives them): colour.f32 (W*H*4 floats), depth.f32
// (W*H window depths in [0, 1]), profile.u8 (W*H bytes, profile | object << 4) and params.txt (one
// "name value..." a line: width, height, projection (16, column-major); count and fields (count
// profiles of 16 floats), taps, follow_surface, path, jitter: the arguments the pass gave
// sss3_set_profiles; noise_index, flags; albedo_format: 0, or SRGB8_ALPHA8 with albedo.u8, W*H*4
// bytes, the split's albedo as stored, which the pass handed sss3_apply where a profile's
// texturing is not pre-scatter). The profiles become settings and kernels by the
// WebAssembly's own code (web/three/wasm/profile_fields.cpp). Writes DIR/native.f32 (the filtered
// colour, W*H*4 floats) and prints one JSON object.
#include <GLES3/gl3.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <sss/sss.h>

#include "profile_fields.hpp"
#include "sss_headless.h"

namespace {

using Params = std::map<std::string, std::vector<double>>;

bool read_params(const std::string& path, Params* out) {
  std::ifstream in(path);
  if (!in) return false;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string name;
    if (!(words >> name)) continue;
    double v = 0.0;
    while (words >> v) (*out)[name].push_back(v);
  }
  return true;
}

template <typename T>
bool read_file(const std::string& path, size_t count, std::vector<T>* out) {
  out->resize(count);
  FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) return false;
  const bool ok = std::fread(out->data(), sizeof(T), count, f) == count && std::fgetc(f) == EOF;
  std::fclose(f);
  return ok;
}

GLuint texture(GLenum internal_format, int width, int height, GLenum format, GLenum type, const void* data, GLenum filter) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal_format), width, height, 0, format, type, data);
  // As three makes them: render-target colour linear, depth and the integer profile nearest, no mipmaps.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  return t;
}

int run(const std::string& dir, sss_headless* headless) {
  Params p;
  if (!read_params(dir + "/params.txt", &p)) {
    std::fprintf(stderr, "sss_three_native_apply: cannot read %s/params.txt\n", dir.c_str());
    return 1;
  }
  const auto one = [&p](const char* name) { return p[name].empty() ? 0.0 : p[name][0]; };
  const int width = static_cast<int>(one("width")), height = static_cast<int>(one("height"));
  const int count = static_cast<int>(one("count"));
  if (width <= 0 || height <= 0 || p["projection"].size() != 16 || count < 1 || count > SSS_MAX_PROFILES ||
      p["fields"].size() != static_cast<size_t>(count) * sss_three::kProfileFloats) {
    std::fprintf(stderr, "sss_three_native_apply: params.txt lacks a size, the projection, or count and its fields\n");
    return 1;
  }
  const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height);
  std::vector<float> colour, depth;
  std::vector<uint8_t> profile;
  if (!read_file(dir + "/colour.f32", n * 4, &colour) || !read_file(dir + "/depth.f32", n, &depth) ||
      !read_file(dir + "/profile.u8", n, &profile)) {
    std::fprintf(stderr, "sss_three_native_apply: colour.f32, depth.f32 or profile.u8 missing or of the wrong size\n");
    return 1;
  }
  const auto albedo_format = static_cast<uint32_t>(one("albedo_format"));
  std::vector<uint8_t> albedo;
  if (albedo_format != 0 && (albedo_format != SSS_GL_SRGB8_ALPHA8 || !read_file(dir + "/albedo.u8", n * 4, &albedo))) {
    std::fprintf(stderr, "sss_three_native_apply: albedo_format is not SRGB8_ALPHA8, or albedo.u8 missing or of the wrong size\n");
    return 1;
  }

  sss_create_desc desc{};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = sss_headless_get_proc_address;
  desc.get_proc_address_user = headless;
  sss_context* sss = nullptr;
  sss_result r = sss_create(&desc, &sss);
  if (r != SSS_OK) {
    std::fprintf(stderr, "sss_three_native_apply: sss_create: %s\n", sss_last_error(nullptr));
    return 1;
  }
  // The profiles as sss3_set_profiles (web/three/wasm/sss_three.cpp) makes them from the same floats.
  const std::vector<float> fields(p["fields"].begin(), p["fields"].end());
  sss_settings profiles[SSS_MAX_PROFILES];
  sss_kernel_desc kernels[SSS_MAX_PROFILES];
  r = sss_three::profiles_from_fields(fields.data(), count, static_cast<int>(one("taps")),
                                      static_cast<int>(one("follow_surface")), static_cast<int>(one("path")),
                                      static_cast<float>(one("jitter")), profiles, kernels);
  std::string message;
  if (r != SSS_OK) message = sss_last_error(nullptr);
  if (r == SSS_OK) r = sss_set_profiles(sss, profiles, static_cast<uint32_t>(count));

  // The same values in the same formats, but the depth: three's DEPTH_COMPONENT24 as the float it
  // sampled to, in DEPTH_COMPONENT32F (the library reads both as the same window depth).
  const GLuint colour_tex = texture(GL_RGBA16F, width, height, GL_RGBA, GL_FLOAT, colour.data(), GL_LINEAR);
  const GLuint depth_tex = texture(GL_DEPTH_COMPONENT32F, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data(), GL_NEAREST);
  const GLuint profile_tex = texture(GL_R8UI, width, height, GL_RED_INTEGER, GL_UNSIGNED_BYTE, profile.data(), GL_NEAREST);
  // The split's albedo as the companion target holds it: SRGB8_ALPHA8, nearest (the same bytes).
  const GLuint albedo_tex =
      albedo.empty() ? 0 : texture(GL_SRGB8_ALPHA8, width, height, GL_RGBA, GL_UNSIGNED_BYTE, albedo.data(), GL_NEAREST);
  if (r == SSS_OK) {
    sss_prepare_desc prepare{};
    prepare.struct_size = sizeof prepare;
    prepare.width = width;
    prepare.height = height;
    prepare.color_format = SSS_GL_RGBA16F;
    prepare.depth_format = SSS_GL_DEPTH_COMPONENT32F;
    prepare.profile_format = SSS_GL_R8UI;
    prepare.albedo_format = albedo_format;
    r = sss_prepare(sss, &prepare);
  }
  std::vector<float> projection(p["projection"].begin(), p["projection"].end());
  if (r == SSS_OK) {
    sss_frame frame{};
    frame.struct_size = sizeof frame;
    frame.color_texture = colour_tex;
    frame.color_format = SSS_GL_RGBA16F;
    frame.depth_texture = depth_tex;
    frame.depth_format = SSS_GL_DEPTH_COMPONENT32F;
    frame.profile_texture = profile_tex;
    frame.profile_format = SSS_GL_R8UI;
    frame.texture_width = width;
    frame.texture_height = height;
    frame.projection = projection.data();
    frame.noise_index = static_cast<uint32_t>(one("noise_index"));
    frame.flags = static_cast<uint32_t>(one("flags"));
    frame.albedo_texture = albedo_tex;
    frame.albedo_format = albedo_format;
    r = sss_apply_frame(sss, &frame);  // in place, as the pass filters three's target
  }
  if (r != SSS_OK && message.empty()) message = sss_last_error(sss);
  int status = r == SSS_OK ? 0 : 1;
  if (r == SSS_OK) {
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_tex, 0);
    std::vector<float> out(n * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, out.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    const GLenum error = glGetError();
    FILE* f = std::fopen((dir + "/native.f32").c_str(), "wb");
    const bool written = f != nullptr && std::fwrite(out.data(), sizeof(float), out.size(), f) == out.size();
    if (f != nullptr && std::fclose(f) != 0) status = 1;
    if (!written || error != GL_NO_ERROR) {
      std::fprintf(stderr, "sss_three_native_apply: reading or writing the output failed (GL error 0x%x)\n", error);
      status = 1;
    }
  }
  const GLuint textures[] = {colour_tex, depth_tex, profile_tex, albedo_tex};
  glDeleteTextures(4, textures);
  sss_destroy(sss);
  std::printf("{\"renderer\": \"%s\", \"result\": \"%s\", \"message\": \"%s\"}\n", sss_headless_renderer(headless),
              sss_result_string(r), message.c_str());
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: sss_three_native_apply DIR\n");
    return 2;
  }
  sss_headless_desc desc = {SSS_HEADLESS_EGL_GLES, 3, 0, 0, 0};
  sss_headless* headless = nullptr;
  char err[256] = {};
  if (sss_headless_create(&desc, &headless, err, sizeof err) != 0) {
    std::fprintf(stderr, "sss_three_native_apply: no OpenGL ES 3.0 context: %s\n", err);
    return 1;
  }
  const int status = run(argv[1], headless);
  sss_headless_destroy(headless);
  return status;
}
