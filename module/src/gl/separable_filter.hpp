// The two full-screen passes on the GPU and the GL objects they own: programs (one per variant,
// built on first use), the RGBA16F intermediate, the stencil copy, framebuffers, sampler and VAO.
// Multisampled inputs add a resolve pass in front and, writing back, a per-sample write after
// (separable_filter_msaa.cpp). Callers validate their inputs first (api layer) and wrap the call
// in a StateGuard.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "../math/cbf_constants.hpp"
#include "../math/cbf_kernel.hpp"
#include "../math/filter_constants.hpp"
#include "../math/pass_kernel.hpp"
#include "../math/separable_kernel.hpp"
#include "gl_functions.hpp"
#include "glsl_variant.hpp"
#include "pass_queries.hpp"
#include "path_chooser.hpp"
#include "shader_constants.hpp"
#include "shader_variants.hpp"
#include "texture_query.hpp"

namespace sss::gl {

struct StencilInput {
  TextureInfo texture;  // the host's depth-stencil texture
  GLuint ref = 0, mask = 0;
};

// How the MSAA resolve turns a pixel's sample depths into one view distance (sss.h
// SSS_MSAA_DEPTH_*): the paper's average of the samples' linear depths, or the alternatives the
// benchmark compares it with.
enum class DepthResolve : int { average = 0, sample0 = 1, nearest = 2, farthest = 3 };

struct FilterRun {
  TextureInfo color;                       // multisampled: the MSAA path (depth has the same samples)
  TextureInfo depth;
  TextureInfo output;                      // name 0: write back into color
  TextureInfo normals;                     // name 0: none (cross-bilateral mode reconstructs from depth)
  const StencilInput* stencil = nullptr;   // nullptr: mask from alpha alone
  std::array<int, 4> viewport = {0, 0, 0, 0};
  // Where the passes draw and their taps stay (constants.clamp_*): the viewport, or the host's
  // region of translucent pixels (SSS_FRAME_REGION; region true). With a separate output the rest of
  // the viewport gets the colour copied first.
  std::array<int, 4> draw_rect = {0, 0, 0, 0};
  bool region = false;
  const math::PassKernel* kernel = nullptr;  // one pair of passes per term
  std::uint64_t kernel_revision = 0;       // changes whenever the kernel does
  math::PassConstants constants;
  bool follow_surface = false;
  bool identity = false;                   // nothing to blur: only copy into a separate output
  std::uint64_t frame = 0;                 // 1-based number of this frame (for the measurements)
  // The cross-bilateral mode (Mikkelsen 2010) instead of the separable kernel.
  bool cross_bilateral = false;
  const math::CbfKernel* cbf_kernel = nullptr;
  std::uint64_t cbf_kernel_revision = 0;
  math::CbfConstants cbf;
  // MSAA path only: the host depth's encoding for the resolve (`constants` then describe the
  // resolved linear distance the passes read), and how sample depths combine.
  math::PassConstants resolve_constants;
  DepthResolve depth_resolve = DepthResolve::average;
  bool stencil_ready = false;              // internal: the stencil buffer already holds the mask
  // sss.h SSS_PATH_*: the compute path is taken (SSS_PATH_COMPUTE), or chosen by timing
  // (SSS_PATH_AUTO, per path_key: the frame's configuration), when compute_unavailable() is "";
  // otherwise (and always on OpenGL ES or before GL 4.3) the fragment passes run.
  unsigned path = SSS_PATH_FRAGMENT;
  std::uint64_t path_key = 0;
};

class SeparableFilter {
 public:
  // The compute path's target image formats (RGBA16F, RGBA32F: every colour and output format).
  static constexpr int kImageFormats = kComputeImageFormatCount;
  // Builds the objects that do not depend on frame size and the most common program variants, so a
  // broken driver fails at create. Returns SSS_OK or an error with `message` set.
  sss_result init(const Functions* gl, GlslVariant variant, bool labels, std::string* message);
  GlslVariant variant() const { return variant_; }
  // Measurements for sss_get_stats; call before init(). Off by default: no query objects exist.
  void enable_measurements(bool es_timer_extension) {
    measure_ = true;
    es_timer_extension_ = es_timer_extension;
  }
  // Mesa's software rasterisers (their GL_TIME_ELAPSED covers one tile); call before init().
  void set_software_renderer(bool software_renderer) { software_renderer_ = software_renderer; }
  const PassQueries& queries() const { return queries_; }
  // Full-screen draws of the last run() (blur passes and copies; MSAA: also the resolve, the
  // stencil mark and one per-sample write per sample).
  int last_draws() const { return last_draws_; }
  // Where DEBUG notes go (a program variant built on first use, the intermediate reallocated).
  void set_log(std::function<void(int level, const std::string& message)> log) { log_ = std::move(log); }
  // Deletes the objects (they must exist in the current context: see objects_present), then
  // forget()s them.
  void destroy();
  sss_result run(const FilterRun& run, std::string* message);
  // Whether run() can take the compute path for `run`: "" when it can, else why not (no GL 4.3,
  // stencil, multisampled, several terms, the cross-bilateral mode).
  const char* compute_unavailable(const FilterRun& run) const;
  // Whether it can take the masked fragment path: the separable mode, single-sample, no host stencil.
  bool masked_available(const FilterRun& run) const {
    return !run.color.multisampled() && !run.cross_bilateral && run.stencil == nullptr && !run.identity;
  }
  // sss.h SSS_PATH_FRAGMENT, _FRAGMENT_MASKED or _COMPUTE: how the last successful run() ran.
  unsigned last_run_path() const { return last_path_; }

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
  bool needs_rebuild() const { return gl_ != nullptr && vertex_array_ == 0; }
  sss_result rebuild(std::string* message);

 private:
  // The blur's compile-time switches, and their #defines (shader_variants.hpp).
  using Outside = BlurOutside;
  using BlurVariant = gl::BlurVariant;
  struct BlurProgram {
    GLuint program = 0;
    GLint source = -1, depth = -1, original = -1, accumulated = -1, jitter_from = -1, inv_two_variance = -1,
          axis = -1, pixels_per_mm = -1, follow_surface = -1, ndc_from_depth = -1, depth_terms = -1, clamp = -1,
          cdf = -1, footprint = -1, spacing = -1, half_taps = -1, round_to_half = -1;
    GLint rect = -1;  // compute programs only
    bool compute = false;
    // Which taps the kernel uniforms hold: kernel revision, term and axis (revision 0: none yet).
    std::uint64_t kernel_revision = 0;
    std::size_t uploaded_term = 0;
    int uploaded_axis = -1;
  };
  static constexpr int kVariantCount = kBlurVariantCount;
  // Compute variants: a fragment variant's index (SSS_ACCUMULATE never set there: one term only) ×
  // the target's image format (kImageFormats).
  static constexpr int kComputeVariantCount = kVariantCount * kImageFormats;
  struct CbfProgram {
    GLuint program = 0;
    GLint source = -1, depth = -1, original = -1, kernel = -1, tap_count = -1, axis = -1, pixels_per_mm = -1,
          ndc_from_depth = -1, depth_terms = -1, clamp = -1, xy_terms = -1, xy_offset = -1, viewport = -1,
          world_per_mm = -1, orthographic = -1, spike_blend = -1, inv_two_variance = -1, normals = -1,
          round_to_half = -1;
    std::uint64_t kernel_revision = 0;
  };
  static constexpr int kCbfVariantCount = 3 * 2 * 2;

  sss_result blur_program(const BlurVariant& v, BlurProgram** out, std::string* message);
  // The variant of term `term`'s pass on `axis` (0 horizontal, 1 vertical) writing `outside`.
  BlurVariant blur_variant(const FilterRun& run, std::size_t term, int axis, Outside outside) const;
  sss_result run_identity(const FilterRun& run, std::string* message);
  // Compute path (separable_filter_compute.cpp).
  sss_result compute_program(const BlurVariant& v, int image_format, BlurProgram** out, std::string* message);
  sss_result run_compute(const FilterRun& run, std::string* message);
  void dispatch_blur(BlurProgram& program, const FilterRun& run, GLuint source, int axis);
  // The kernel and per-frame uniforms of a blur pass (fragment or compute program).
  void set_blur_uniforms(BlurProgram& program, const FilterRun& run, std::size_t term, int axis);
  void find_blur_uniforms(BlurProgram* program) const;
  // The pass input and the host's depth on their units, with the module's samplers.
  void bind_blur_inputs(GLuint source, GLuint depth);
  sss_result cbf_program(Outside outside, bool linear_depth, bool normals, CbfProgram** out, std::string* message);
  // Whether the pass of term `term` on `axis` writes a half-float target, so that the shader rounds
  // what it writes to nearest (module/shaders/nearest_half.glsl, u_round_to_half) whatever rounding
  // the driver's conversion does: horizontal passes write the RGBA16F intermediate, vertical ones the
  // sum of terms (RGBA32F; RGBA16F on ES) or, the last, the host's colour or output.
  bool writes_half_float(const FilterRun& run, std::size_t term, int axis) const;
  // The sum of the kernel's terms: RGBA32F keeps up to six terms at float precision, but OpenGL ES
  // may not render to it (GL_EXT_color_buffer_float), while every ES context the module accepts
  // renders RGBA16F.
  bool accumulators_are_half() const { return gl_->api.es; }
  sss_result run_cbf(const FilterRun& run, std::string* message);
  sss_result ensure_masked_source(GLint format, int width, int height, std::string* message);
  void draw_cbf(CbfProgram& program, const FilterRun& run, GLuint source, int axis);
  sss_result run_single(const FilterRun& run, std::string* message);
  // With a region and a separate output: the viewport's colour into the output (bound as the draw
  // framebuffer), so the pixels the region leaves out hold their input.
  void copy_outside_region(const FilterRun& run);

  // MSAA path (separable_filter_msaa.cpp).
  struct ResolveProgram {
    GLuint program = 0;
    GLint samples = -1, depth_mode = -1, ndc_from_depth = -1, depth_terms = -1;
  };
  struct MsaaObjects {
    std::array<ResolveProgram, 2> resolve{};  // index: host depth is linear
    GLuint mask_program = 0;
    GLuint write_program = 0;
    GLint write_sample = -1, write_samples = -1;
    GLuint resolve_framebuffer = 0, read_framebuffer = 0, copy_framebuffer = 0, write_framebuffer = 0;
    // Single-sample targets: resolved colour (host's format), resolved view distance (R32F), and
    // the blurred result when writing back into the host's samples.
    GLuint resolved_color = 0, resolved_distance = 0, blurred = 0;
    GLint color_format = 0;
    int width = 0, height = 0;
    bool has_blurred = false;
    // A copy of the host's colour samples (the write-back pass reads it: never the attached texture).
    GLuint sample_copy = 0;
    GLint copy_format = 0;
    int copy_width = 0, copy_height = 0, copy_samples = 0;
    GLboolean copy_fixed = 1;
  };
  sss_result run_msaa(const FilterRun& run, std::string* message);
  sss_result msaa_programs(bool linear_depth, bool need_mask, bool need_write, ResolveProgram** resolve,
                           std::string* message);
  sss_result ensure_msaa_framebuffers();
  sss_result ensure_msaa_targets(GLint color_format, int width, int height, bool need_blurred, std::string* message);
  sss_result ensure_sample_copy(const TextureInfo& color, std::string* message);
  sss_result ensure_mask_program(std::string* message);
  sss_result mark_stencil_from_alpha(GLuint source, int width, int height, std::string* message);
  // SSS_PATH_FRAGMENT_MASKED: the fragment passes behind a stencil marked from the colour's alpha.
  sss_result run_masked(const FilterRun& run, std::string* message);
  sss_result write_samples(const FilterRun& run, std::string* message);
  void destroy_msaa();
  sss_result ensure_intermediate(int width, int height, std::string* message);
  // A colour texture the module owns, (re)allocated at this size and format; false with *message set.
  sss_result allocate_target(GLuint* texture, GLenum internal_format, GLenum type, int width, int height,
                             const char* what, std::string* message);
  sss_result ensure_accumulators(int width, int height, std::string* message);
  sss_result ensure_stencil_buffer(GLint format, int width, int height, std::string* message);
  sss_result copy_stencil(const StencilInput& stencil, int width, int height, std::string* message);
  sss_result check_framebuffer(const char* which, std::string* message);
  void draw_blur(BlurProgram& program, const FilterRun& run, GLuint source, std::size_t term, int axis);
  void draw_copy(GLuint source);
  void set_stencil_test(const StencilInput* stencil, GLenum func);

  void note(const std::string& message) const {
    if (log_) log_(SSS_LOG_DEBUG, message);
  }

  const Functions* gl_ = nullptr;
  std::function<void(int, const std::string&)> log_;
  bool measure_ = false, es_timer_extension_ = false, software_renderer_ = false;
  PassQueries queries_;
  int last_draws_ = 0;
  GlslVariant variant_ = GlslVariant::glsl330;
  bool labels_ = false;
  std::array<BlurProgram, kVariantCount> blur_programs_{};
  std::array<BlurProgram, kComputeVariantCount> compute_programs_{};
  unsigned last_path_ = SSS_PATH_FRAGMENT;
  PathChooser chooser_;
  GLuint copy_program_ = 0;
  GLuint vertex_array_ = 0, sampler_ = 0, depth_sampler_ = 0;
  GLfloat sampler_tag_ = 0.0f;  // maximum LOD that marks this instance's sampler
  GLuint intermediate_ = 0;
  int intermediate_width_ = 0, intermediate_height_ = 0;
  GLuint stencil_buffer_ = 0;
  GLint stencil_format_ = 0;
  int stencil_width_ = 0, stencil_height_ = 0;
  GLuint intermediate_framebuffer_ = 0, output_framebuffer_ = 0, stencil_source_framebuffer_ = 0;
  // Kernels of several terms: the running sum of the earlier terms' vertical passes, ping-ponged
  // between two targets (RGBA32F; RGBA16F on OpenGL ES, where RGBA32F may not be renderable).
  std::array<GLuint, 2> accumulators_{};
  int accumulator_width_ = 0, accumulator_height_ = 0;
  GLuint accumulator_framebuffer_ = 0;
  // Cross-bilateral mode: its programs, and (with a stencil) an RGBA32F copy of the colour whose
  // alpha is 0 outside the stencil, so the horizontal pass can tell those neighbours apart.
  std::array<CbfProgram, kCbfVariantCount> cbf_programs_{};
  GLuint masked_source_ = 0, masked_framebuffer_ = 0;
  GLint masked_format_ = 0;
  int masked_width_ = 0, masked_height_ = 0;
  MsaaObjects msaa_;
};

}  // namespace sss::gl
