#include "separable_filter.hpp"


namespace sss::gl {

sss_result SeparableFilter::init(const Functions* gl, GlslVariant variant, bool labels, std::string* message) {
  gl_ = gl;
  variant_ = variant;
  labels_ = labels;
  const Functions& f = *gl_;
  objects_.create(f, labels_);
  targets_.init(gl_, labels_, &log_);
  if (measure_) queries_.init(gl_, es_timer_extension_, software_renderer_);
  // SSS_PATH_AUTO times the paths only where GL_TIME_ELAPSED is whole and readable without an
  // extension: desktop GL, not a software rasteriser, with counter bits.
  GLint bits = 0;
  if (!software_renderer_ && !gl_->api.es) f.GetQueryiv(TIME_ELAPSED, QUERY_COUNTER_BITS, &bits);
  chooser_.init(gl_, bits > 0);
  profile_tables_.init(gl_, labels_);
  programs_.set_profile_capacity(profile_tables_.capacity());
  caps_ = Capabilities{};
  caps_.es = gl_->api.es;
  caps_.compute = gl_->has_compute;
  caps_.image_loads = variant_ == GlslVariant::glsl420 && gl_->has_compute;
  return programs_.init(gl_, variant_, labels_, &log_, &caps_, message);
}

void SeparableFilter::destroy() {
  if (gl_ == nullptr) return;
  programs_.destroy();
  targets_.destroy();
  profile_tables_.destroy();
  objects_.destroy(*gl_);
  queries_.destroy();
  chooser_.destroy();
  forget();
}

bool SeparableFilter::objects_present() const {
  if (gl_ == nullptr || !objects_.present(*gl_)) return false;
  const Functions& f = *gl_;
  const Targets& t = targets_.names();
  return f.IsFramebuffer(t.intermediate_framebuffer) && f.IsFramebuffer(t.output_framebuffer) &&
         f.IsFramebuffer(t.stencil_source_framebuffer) && f.IsProgram(programs_.copy());
}

void SeparableFilter::forget() {
  objects_ = PassObjects{};
  programs_.forget();
  targets_.forget();
  profile_tables_.forget();
  queries_ = PassQueries{};
  chooser_ = PathChooser{};
  last_draws_ = 0;
  last_path_ = reported_path_ = SSS_PATH_FRAGMENT;
  last_plan_ = FramePlan{};
  plan_cached_ = false;
}

sss_result SeparableFilter::rebuild(std::string* message) {
  const sss_result r = init(gl_, variant_, labels_, message);
  if (r != SSS_OK) destroy();  // what init built before it failed; the arguments stay for the next try
  return r;
}

void SeparableFilter::note_refusal(const char** last, const char* path, const char* reason) {
  // The reasons are string literals: a new one is a different pointer. Logged when it changes, not
  // every frame.
  if (reason == *last) return;
  *last = reason;
  if (*reason != '\0' && log_) {
    log_(SSS_LOG_INFO, std::string(path) + ": the frame takes the fragment path: " + reason);
  }
}

}  // namespace sss::gl
