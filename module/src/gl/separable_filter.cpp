#include "separable_filter.hpp"

#include "runners.hpp"

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
  return programs_.init(gl_, variant_, labels_, &log_, message);
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
}

sss_result SeparableFilter::rebuild(std::string* message) {
  const sss_result r = init(gl_, variant_, labels_, message);
  if (r != SSS_OK) destroy();  // what init built before it failed; the arguments stay for the next try
  return r;
}

PathChooser::Choice SeparableFilter::choose_path(const FilterRun& run) {
  // Availability is asked only when a path other than the plain one is.
  const auto compute_ok = [&] { return !run.identity && *compute_unavailable(*gl_, run) == '\0'; };
  PathChooser::Choice choice;
  if (run.debug_view != 0) {  // the views are the fragment passes' (fragment_runner.cpp)
    choice.path = PathChooser::fragment;
    return choice;
  }
  switch (run.path) {
    case SSS_PATH_COMPUTE: {
      const char* refusal = run.identity ? "" : compute_unavailable(*gl_, run);
      choice.path = !run.identity && *refusal == '\0' ? PathChooser::compute : PathChooser::fragment;
      note_refusal(&compute_refusal_, "SSS_PATH_COMPUTE", refusal);
      break;
    }
    case SSS_PATH_FRAGMENT_MASKED:
      choice.path = masked_available(run) ? PathChooser::masked : PathChooser::fragment;
      break;
    case SSS_PATH_HALF_RESOLUTION: {
      const char* refusal = half_resolution_unavailable(run);
      choice.path = *refusal == '\0' ? PathChooser::half : PathChooser::fragment;
      note_refusal(&half_refusal_, "SSS_PATH_HALF_RESOLUTION", refusal);
      break;
    }
    case SSS_PATH_AUTO: {
      const bool half_ok = run.auto_half_resolution && *half_resolution_unavailable(run) == '\0';
      const unsigned available = (compute_ok() ? 1u << PathChooser::compute : 0u) |
                                 (masked_available(run) ? 1u << PathChooser::masked : 0u) |
                                 (half_ok ? 1u << PathChooser::half : 0u);
      if (available != 0) {
        choice = chooser_.choose(run.path_key, available, run.region);
        if (*chooser_.decision() != '\0' && log_) {
          log_(SSS_LOG_INFO, std::string("SSS_PATH_AUTO chose the ") + chooser_.decision());
        }
      }
      break;
    }
    default: break;
  }
  return choice;
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

sss_result SeparableFilter::run(const FilterRun& given, std::string* message) {
  PassContext ctx{*gl_, programs_, targets_, objects_, labels_, measure_ ? &queries_ : nullptr};
  ctx.check_framebuffers = given.verify;
  ctx.profile_tables = &profile_tables_;
  if (given.has_profiles() && !given.identity) {  // before the first draw: it can fail
    const sss_result r = profile_tables_.upload(given, message);
    if (r != SSS_OK) return r;
  }
  // A strength texture: the passes run on the colour with it as alpha (strength_source.cpp); in
  // place with nothing to blur, nothing changes (as without one).
  FilterRun with_strength;
  if (given.strength.name != 0) {
    last_draws_ = 0;
    if (given.identity && given.writes_back()) return SSS_OK;
    const sss_result r = draw_strength_source(ctx, given, message);
    if (r != SSS_OK) return r;
    with_strength = with_strength_source(given, targets_.names());
  }
  const FilterRun& run = given.strength.name != 0 ? with_strength : given;
  if (run.color.multisampled()) {
    const sss_result r = run_msaa(ctx, run, message);
    last_draws_ = ctx.draws;
    if (r == SSS_OK) reported_path_ = SSS_PATH_FRAGMENT;
    return r;
  }
  const PathChooser::Choice choice = choose_path(run);
  const unsigned path = choice.path == PathChooser::compute  ? SSS_PATH_COMPUTE
                        : choice.path == PathChooser::masked ? SSS_PATH_FRAGMENT_MASKED
                        : choice.path == PathChooser::half   ? SSS_PATH_HALF_RESOLUTION
                                                             : SSS_PATH_FRAGMENT;
  // A steady frame's framebuffers are the last run's only if it took the same path (SSS_PATH_AUTO
  // tries each in turn).
  ctx.check_framebuffers = run.verify || path != last_path_;
  chooser_.begin(choice);
  sss_result r = SSS_OK;
  switch (choice.path) {
    case PathChooser::compute: r = run_compute(ctx, run, message); break;
    case PathChooser::masked: r = run_masked(ctx, run, message); break;
    case PathChooser::half: r = run_half_resolution(ctx, run, message); break;
    default: r = run_fragment(ctx, run, message); break;
  }
  chooser_.end();
  last_draws_ = ctx.draws;
  if (r == SSS_OK) last_path_ = reported_path_ = path;
  return r;
}

}  // namespace sss::gl
