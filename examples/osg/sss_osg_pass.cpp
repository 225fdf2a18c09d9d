#include "sss_osg_pass.hpp"

#include <osg/GL>
#include <osg/GLExtensions>
#include <osg/RenderInfo>
#include <osg/State>

#include <cstdio>

namespace sss_osg {

void* osg_gl_loader(const char* name, void* /*user*/) { return osg::getGLExtensionFuncPtr(name); }

namespace {
// The pass's textures are read with texelFetch only, in the library and in the composite: nearest,
// clamped, no mipmaps (complete as they are).
osg::ref_ptr<osg::Texture2D> texel_texture(int width, int height, GLint internal_format, GLenum format, GLenum type) {
  osg::ref_ptr<osg::Texture2D> t = new osg::Texture2D;
  t->setTextureSize(width, height);
  t->setInternalFormat(internal_format);
  t->setSourceFormat(format);
  t->setSourceType(type);
  t->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
  t->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
  t->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_EDGE);
  t->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_EDGE);
  return t;
}
}  // namespace

osg::ref_ptr<osg::Texture2D> make_half_float_texture(int width, int height) {
  return texel_texture(width, height, GL_RGBA16F_ARB, GL_RGBA, GL_HALF_FLOAT);
}

osg::ref_ptr<osg::Texture2D> make_depth_texture(int width, int height) {
  return texel_texture(width, height, GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT);
}

void tell_osg_the_library_drew(osg::State& state) {
  osg::GLExtensions* gl = state.get<osg::GLExtensions>();
  // The GL's program and vertex array become 0, and so does OSG's belief.
  gl->glUseProgram(0);
  state.setLastAppliedProgramObject(nullptr);
  gl->glBindVertexArray(0);
  state.setCurrentVertexArrayObject(0);
  // OSG binds no sampler objects; the library's on units 0-5 (and 6 in a frame with an albedo)
  // would override OSG's textures' own filtering.
  for (GLuint unit = 0; unit < 7; ++unit) gl->glBindSampler(unit, 0);
  gl->glActiveTexture(GL_TEXTURE0 + state.getActiveTextureUnit());  // OSG's belief, made true
  // Every mode and attribute (each unit's texture, the viewport, depth, blending...) forgotten, so
  // that OSG applies each afresh when next needed. Measured: dirtyAllModes() and dirtyAllAttributes()
  // do not do that (OSG then skips a mode or a texture it believes already set, and the next
  // camera's frame comes out wrong); reset() does.
  state.reset();
}

SssDrawCallback::SssDrawCallback(PassTextures textures, float world_units_per_mm) : textures_(std::move(textures)) {
  sss_default_settings(&settings_);
  settings_.world_units_per_mm = world_units_per_mm;
}

void SssDrawCallback::set_settings(const sss_settings& settings) {
  const float world_units_per_mm = settings_.world_units_per_mm;
  settings_ = settings;
  settings_.world_units_per_mm = world_units_per_mm;
  settings_dirty_ = true;
}

bool SssDrawCallback::create() const {
  sss_create_desc desc{};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = load_ != nullptr ? load_ : osg_gl_loader;
  desc.get_proc_address_user = load_user_;
  desc.flags = create_flags_;
  if (sss_create(&desc, &context_) != SSS_OK) {
    last_error_ = std::string("sss_create: ") + sss_last_error(nullptr);
    context_ = nullptr;
    return false;
  }
  return true;
}

bool SssDrawCallback::prepare(int width, int height) const {
  // The frames' shape, once per size or settings: the programs and targets are built here and
  // not inside a frame (no hitch when the window is resized).
  if (!settings_dirty_ && width == prepared_width_ && height == prepared_height_) return true;
  if (settings_dirty_ && sss_set_settings(context_, &settings_) != SSS_OK) {
    last_error_ = std::string("sss_set_settings: ") + sss_last_error(context_);
    return false;
  }
  settings_dirty_ = false;
  sss_prepare_desc prepare{};
  prepare.struct_size = sizeof prepare;
  prepare.width = width;
  prepare.height = height;
  prepare.color_format = SSS_GL_RGBA16F;
  prepare.output_format = SSS_GL_RGBA16F;
  prepare.depth_format = SSS_GL_DEPTH_COMPONENT32F;
  prepare.albedo_format = uses_albedo() ? SSS_GL_RGBA16F : 0u;
  if (sss_prepare(context_, &prepare) != SSS_OK) {
    last_error_ = std::string("sss_prepare: ") + sss_last_error(context_);
    return false;
  }
  prepared_width_ = width;
  prepared_height_ = height;
  return true;
}

void SssDrawCallback::operator()(osg::RenderInfo& info) const {
  if (release_requested_) {
    sss_destroy(context_);  // deletes the library's objects; binds nothing of OSG's (sss.h)
    context_ = nullptr;
    prepared_width_ = prepared_height_ = 0;
    settings_dirty_ = true;
    return;
  }
  if (!enabled_) return;
  osg::State& state = *info.getState();
  filter(state);
  // Without its restore the library leaves its bindings after sss_create and sss_prepare too, and
  // after a failed frame whatever those left: OSG is told after any call of this callback.
  if ((create_flags_ & SSS_CREATE_NO_STATE_RESTORE) != 0 && context_ != nullptr) tell_osg_the_library_drew(state);
}

void SssDrawCallback::filter(osg::State& state) const {
  if (context_ == nullptr && !create()) return;
  const unsigned id = state.getContextID();
  // The output is only sampled by the composite, later in the frame: on the first frame OSG has not
  // made its GL texture yet. Applied through osg::State, so that the cache knows what is bound.
  if (textures_.output->getTextureObject(id) == nullptr) state.applyTextureAttribute(0, textures_.output.get());
  const osg::Texture::TextureObject* diffuse = textures_.diffuse->getTextureObject(id);
  const osg::Texture::TextureObject* depth = textures_.depth->getTextureObject(id);
  const osg::Texture::TextureObject* output = textures_.output->getTextureObject(id);
  if (diffuse == nullptr || depth == nullptr || output == nullptr) {
    last_error_ = "the camera's textures have no GL object yet (is the callback on the camera that renders them?)";
    return;
  }
  const int width = textures_.diffuse->getTextureWidth(), height = textures_.diffuse->getTextureHeight();
  if (!prepare(width, height)) return;
  // The projection OSG applied for this camera: with near and far computed per frame (OSG's
  // default) it is not the camera's own matrix. osg::Matrixd's memory order is OpenGL's.
  float projection[16];
  const osg::Matrixd::value_type* m = state.getProjectionMatrix().ptr();
  for (int i = 0; i < 16; ++i) projection[i] = static_cast<float>(m[i]);
  sss_frame frame{};
  frame.struct_size = sizeof frame;
  frame.color_texture = diffuse->id();
  frame.color_format = SSS_GL_RGBA16F;
  frame.depth_texture = depth->id();
  frame.depth_format = SSS_GL_DEPTH_COMPONENT32F;
  frame.output_texture = output->id();
  frame.output_format = SSS_GL_RGBA16F;
  frame.texture_width = width;
  frame.texture_height = height;
  frame.projection = projection;
  if (uses_albedo()) {
    // The G-buffer's albedo, which the lit pass wrote beside the diffuse: made by OSG with the camera.
    const osg::Texture::TextureObject* albedo = textures_.albedo->getTextureObject(id);
    if (albedo == nullptr) {
      last_error_ = "the albedo texture has no GL object yet (is it attached to the camera that renders the diffuse?)";
      return;
    }
    frame.albedo_texture = albedo->id();
    frame.albedo_format = SSS_GL_RGBA16F;
  }
  if (sss_apply_frame(context_, &frame) != SSS_OK) {
    // A failed call draws nothing and leaves the state as it found it, restore or not (sss.h).
    last_error_ = std::string("sss_apply_frame: ") + sss_last_error(context_);
    std::fprintf(stderr, "sss_osg: %s\n", last_error_.c_str());
    return;
  }
  last_error_.clear();
  ++frames_applied_;
}

}  // namespace sss_osg
