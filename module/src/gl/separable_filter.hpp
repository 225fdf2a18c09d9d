// The GPU side of one sss_context: the objects it owns in the host's GL context and the choice of
// how each frame's passes run. The work is split by job:
//   program_cache.hpp  every program variant, built on first use or at create
//   target_pool.hpp    the render targets and framebuffers, reallocated when a frame's size changes
//   profile_tables.hpp the per-pixel profiles' kernel tables (a uniform buffer)
//   pass_setup.hpp     what every path shares (vertex array, samplers, attachments, measurements)
//   frame_plan.hpp     the frame's decisions as a value: path, variants, targets, ordered steps
//   plan_steps.hpp     the steps a plan runs, each in the file of its concept, and prepare_plan
//   path_chooser.hpp   SSS_PATH_AUTO's timing of the paths
// Callers validate their inputs first (api layer) and wrap run() in a StateGuard (state_guard.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>

#include "filter_run.hpp"
#include "frame_plan.hpp"
#include "gl_functions.hpp"
#include "glsl_variant.hpp"
#include "pass_queries.hpp"
#include "pass_setup.hpp"
#include "path_chooser.hpp"
#include "program_cache.hpp"
#include "target_pool.hpp"

namespace sss::gl {

// A texture name that stands for "given" in the FilterRun of SeparableFilter::prewarm, and the
// colour's own (never the output's: a colour copied and written back is the passes' output, apart
// from a separate one).
inline constexpr GLuint kPrewarmPlaceholder = 0xFFFFFFFFu;
inline constexpr GLuint kPrewarmColourPlaceholder = 0xFFFFFFFDu;

struct PlanPrograms;

class SeparableFilter {
 public:
  // Builds the objects that do not depend on frame size and the most common program variants, so a
  // broken driver fails at create. Returns SSS_OK or an error with `message` set.
  sss_result init(const Functions* gl, GlslVariant variant, bool labels, std::string* message);
  GlslVariant variant() const { return variant_; }
  // How many per-pixel profiles the passes can hold (sss_set_profiles' limit; known after init()).
  int profile_capacity() const { return profile_tables_.capacity(); }
  // Measurements for sss_get_stats; call before init(). Off by default: no query objects exist.
  void enable_measurements(bool es_timer_extension) {
    measure_ = true;
    es_timer_extension_ = es_timer_extension;
  }
  // Mesa's software rasterisers (their GL_TIME_ELAPSED covers one tile); call before init().
  void set_software_renderer(bool software_renderer) { software_renderer_ = software_renderer; }
  const PassQueries& queries() const { return queries_; }
  // The storage of its targets and buffers now (gpu_memory.hpp).
  std::uint64_t gpu_memory_bytes() const { return targets_.memory_bytes() + profile_tables_.memory_bytes(); }
  // Full-screen draws of the last run() (blur passes and copies; MSAA: also the resolve, the
  // stencil mark and one per-sample write per sample).
  int last_draws() const { return last_draws_; }
  // Where DEBUG notes go (a program variant built on first use, a target reallocated).
  void set_log(std::function<void(int level, const std::string& message)> log) { log_ = std::move(log); }
  // Deletes the objects (they must exist in the current context: see objects_present), then
  // forget()s them.
  void destroy();
  sss_result run(const FilterRun& given, std::string* message);
  // Builds every program and allocates every target a frame like `run` can need, on each path
  // run.path lets it take (prewarm.cpp), so that run() on such a frame builds and allocates
  // nothing (sss_prepare). `run` describes the frame's textures by format, size and sample count;
  // their names are 0 or, where FilterRun tells a texture's presence by its name (a separate
  // output, the normals), kPrewarmPlaceholder, and the colour's kPrewarmColourPlaceholder: nothing
  // is bound or drawn. run.identity and run.target_complete are ignored (the blur is prepared all
  // the same, and with the compute path the fragment passes an incomplete target would take).
  sss_result prewarm(const FilterRun& run, std::string* message);
  // sss.h SSS_PATH_FRAGMENT, _FRAGMENT_MASKED or _COMPUTE: how the last successful run() ran.
  // (An MSAA frame resolves, then runs the fragment passes: SSS_PATH_FRAGMENT.)
  unsigned last_run_path() const { return reported_path_; }
  // What the context can run and what its driver refused (the planner's input; known after init()).
  const Capabilities& capabilities() const { return caps_; }

  // Context loss. The objects live in the GL context that init() ran in. When that context was
  // lost or destroyed and the host made a new one current (or made another, unrelated one current)
  // the names mean nothing there, or name the host's own objects: using or deleting them would
  // draw into, detach from or delete the host's objects. objects_present() tells whether the
  // current context holds the module's objects (the vertex array, the three framebuffers and the
  // copy program exist, and the sampler carries this instance's tag in its unused maximum LOD);
  // forget() drops every name without deleting anything; rebuild() runs init() again with the
  // same arguments, in the current context.
  bool objects_present() const;
  void forget();
  bool needs_rebuild() const { return gl_ != nullptr && objects_.vertex_array == 0; }
  sss_result rebuild(std::string* message);

 private:
  // The path a frame takes: the one asked for, the one SSS_PATH_AUTO's timing chose, or the plain
  // fragment passes where the one asked for cannot run this frame (plan_executor.cpp).
  PathChooser::Choice choose_path(const FilterRun& run);
  // The frame's plan into last_plan_ (the last frame's again where nothing it depends on changed),
  // prepared: everything it names built and allocated (plan_executor.cpp).
  sss_result plan(PassContext& ctx, const FilterRun& host, const FilterRun& passes, unsigned path,
                  PlanPrograms* programs, std::string* message);
  // plan_frame on `path`, then prepare_plan; planned again after a refusal the program cache
  // recorded in caps_ (plan_executor.cpp).
  sss_result plan_and_prepare(PassContext& ctx, const FilterRun& host, const FilterRun& passes, unsigned path,
                              FramePlan* plan, PlanPrograms* programs, std::string* message);
  // Logs (INFO) why SSS_PATH_COMPUTE gives way to the fragment path, when the reason changes.
  // Logs why a path asked for cannot run the frame (INFO), when the reason changes.
  void note_refusal(const char** last, const char* path, const char* reason);

  const Functions* gl_ = nullptr;
  Log log_;
  bool measure_ = false, es_timer_extension_ = false, software_renderer_ = false;
  GlslVariant variant_ = GlslVariant::glsl330;
  bool labels_ = false;
  PassObjects objects_;
  ProgramCache programs_;
  TargetPool targets_;
  ProfileTables profile_tables_;
  PassQueries queries_;
  PathChooser chooser_;
  int last_draws_ = 0;
  unsigned last_path_ = SSS_PATH_FRAGMENT;  // the last single-sample run's (its framebuffers were checked)
  unsigned reported_path_ = SSS_PATH_FRAGMENT;  // the last successful run's, MSAA included
  const char* compute_refusal_ = "";  // path_unavailable()'s last answer for SSS_PATH_COMPUTE
  const char* half_refusal_ = "";     // its last answer for SSS_PATH_HALF_RESOLUTION
  Capabilities caps_;
  FramePlan last_plan_;  // the last frame's plan (SSS_LOG_DEBUG prints a plan when it changes)
  FramePlan next_plan_;  // where a frame plans, before it is compared with the last
  // What a steady frame must share with the last one to run its plan again: the path, the drawn
  // rectangle (not part of a steady frame's description) and the driver's refusals.
  struct PlanKey {
    unsigned path = SSS_PATH_FRAGMENT;
    std::array<int, 4> draw_rect{};
    std::size_t refusals = 0;
  };
  PlanKey plan_key_;
  bool plan_cached_ = false;
};

}  // namespace sss::gl
