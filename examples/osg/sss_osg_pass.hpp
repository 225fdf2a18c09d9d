// The library inside OpenSceneGraph: an osg::Camera draw callback that runs sss_apply_frame on the
// textures an RTT camera renders into, on the engine's own GL names and its own projection. This
// file and sss_osg_pass.cpp are the whole integration; the rest of examples/osg is the host that
// shows and tests it.
//
// Hook: the RTT camera's final draw callback (osg::Camera::setFinalDrawCallback). OSG calls it on
// the draw thread with the context current, after the camera's subgraph is drawn and before its
// post-draw callback and any later camera, so the diffuse and depth the camera wrote are complete
// and the composite camera that adds specular reads the result.
//
// What OSG must be told after the call: nothing. osg::State caches the program, the active unit,
// each unit's texture, the modes, the viewport and the vertex array object it applied, and skips
// calls it believes redundant; the library restores every one of those (sss.h's state list), so
// the cache stays true. examples/osg/cache_check.cpp compares the cache with the GL after each call.
// The restore reads the state it saves (glGetIntegerv and friends), which a threaded GL driver
// answers only after catching up. Created with SSS_CREATE_NO_STATE_RESTORE (set_create_flags), the
// library asks the GL nothing in a steady frame and leaves its bindings behind; the callback then
// tells OSG (tell_osg_the_library_drew): a handful of calls that make the GL and the cache agree
// without a query.
#pragma once

#include <sss/sss.h>

#include <osg/Camera>
#include <osg/State>
#include <osg/Texture2D>

#include <cstdint>
#include <string>
#include <utility>

namespace sss_osg {

// What the pass filters: the RTT camera's colour (RGBA16F, alpha = strength) and depth textures,
// into a separate output the composite reads (OSG keeps a texture it samples and one it renders
// into apart, and so do we).
struct PassTextures {
  osg::ref_ptr<osg::Texture2D> diffuse;  // GL_RGBA16F_ARB, the camera's COLOR_BUFFER0
  osg::ref_ptr<osg::Texture2D> depth;    // GL_DEPTH_COMPONENT32F, the camera's DEPTH_BUFFER
  osg::ref_ptr<osg::Texture2D> output;   // GL_RGBA16F_ARB, what the composite samples
  // GL_RGBA16F_ARB, the camera's COLOR_BUFFER2: the linear albedo the diffuse light was multiplied
  // by (sss_frame.albedo_texture), read when the settings' texturing is not pre-scatter; may be null
  // (then only pre-scatter runs).
  osg::ref_ptr<osg::Texture2D> albedo;
};

// The library's GL loader in OSG: osg::getGLExtensionFuncPtr (`user` unused).
void* osg_gl_loader(const char* name, void* user);

// An RGBA16F texture of `width` x `height`, nearest filtering, as the pass's targets need.
osg::ref_ptr<osg::Texture2D> make_half_float_texture(int width, int height);
// A GL_DEPTH_COMPONENT32F texture for the camera's depth.
osg::ref_ptr<osg::Texture2D> make_depth_texture(int width, int height);

// After a call of a library created with SSS_CREATE_NO_STATE_RESTORE: unbinds what OSG does not
// track (the program, the vertex array, the samplers of units 0-6: 6 is the albedo's), makes the active unit the one
// OSG believes in, and resets OSG's cache (osg::State::reset) so that it applies every mode and
// attribute (the textures, the viewport, depth, blending...) afresh. GL calls only, no query. The
// library's framebuffer stays bound: bind yours again if the callback draws more.
void tell_osg_the_library_drew(osg::State& state);

class SssDrawCallback : public osg::Camera::DrawCallback {
 public:
  SssDrawCallback(PassTextures textures, float world_units_per_mm);

  // On: the filter runs each frame; off: the output texture is left as it is (the host's composite
  // reads the diffuse instead).
  void set_enabled(bool on) { enabled_ = on; }
  bool enabled() const { return enabled_; }
  // Settings for the next frame (from sss_default_settings; world_units_per_mm is kept). A texturing
  // other than SSS_TEXTURING_PRE_SCATTER hands the library PassTextures::albedo with each frame.
  void set_settings(const sss_settings& settings);
  // Before the first frame: sss_create_desc.flags (SSS_CREATE_*), and the GL loader (default:
  // OSG's, osg::getGLExtensionFuncPtr; a test may count the library's calls through its own).
  void set_create_flags(std::uint32_t flags) { create_flags_ = flags; }
  void set_loader(sss_get_proc_address_fn load, void* user) {
    load_ = load;
    load_user_ = user;
  }
  void operator()(osg::RenderInfo& info) const override;

  // The last failure's text ("" while every call succeeded) and the number of frames filtered.
  std::string last_error() const { return last_error_; }
  int frames_applied() const { return frames_applied_; }
  // The library's context (created on the first frame; nullptr before). For its stats.
  sss_context* context() const { return context_; }

  // The next call destroys the library's context instead of filtering (it needs the GL context
  // current, which only the draw thread has): ask, then draw one more frame.
  void request_release() { release_requested_ = true; }

 private:
  bool create() const;
  // Creates, prepares and runs the library on this frame's textures (the call's work, apart from
  // telling OSG).
  void filter(osg::State& state) const;
  bool prepare(int width, int height) const;
  // The settings' texturing divides by the albedo, and there is an albedo texture to give.
  bool uses_albedo() const { return settings_.texturing != SSS_TEXTURING_PRE_SCATTER && textures_.albedo.valid(); }

  PassTextures textures_;
  sss_settings settings_{};
  std::uint32_t create_flags_ = 0;
  sss_get_proc_address_fn load_ = nullptr;
  void* load_user_ = nullptr;
  bool enabled_ = true;
  bool release_requested_ = false;
  // DrawCallback::operator() is const; what it changes is the library's per-context state.
  mutable sss_context* context_ = nullptr;
  mutable bool settings_dirty_ = true;
  mutable int prepared_width_ = 0, prepared_height_ = 0;
  mutable std::string last_error_;
  mutable int frames_applied_ = 0;
};

}  // namespace sss_osg
