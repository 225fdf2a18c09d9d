// One runner per way of running a frame's passes; SeparableFilter::run picks one. Each takes the
// run's context (pass_setup.hpp) and a validated FilterRun, draws with the caller's StateGuard
// around it, and returns SSS_OK or an error with *message set. Every runner leaves no host texture
// attached to the module's framebuffers.
#pragma once

#include <string>

#include "filter_run.hpp"
#include "pass_setup.hpp"

namespace sss::gl {

// The fragment passes on single-sample images (fragment_runner.cpp): one horizontal and one
// vertical pass per kernel term, behind the host's stencil (or the module's, run.stencil_ready)
// when there is one; the cross-bilateral mode (cbf_runner.cpp) and the identity copy go from here.
sss_result run_fragment(PassContext& ctx, const FilterRun& run, std::string* message);
// The same, with the masked path's tile culling (`tiles`, tile_culling.cpp) where a run has no stencil.
sss_result run_separable(PassContext& ctx, const FilterRun& run, bool tiles, std::string* message);
// What run_fragment (and the cross-bilateral runner) build and allocate before they draw: the
// runners that draw before they call run_fragment (masked, MSAA) call it first, so that no program
// build or allocation fails after the first draw (sss.h: only a GL error the draws raised does);
// sss_prepare makes the same ahead (prewarm.cpp), so the two cannot drift apart.
sss_result prepare_fragment(PassContext& ctx, const FilterRun& run, std::string* message);
sss_result prepare_cross_bilateral(PassContext& ctx, const FilterRun& run, std::string* message);
// What the fragment passes and the half-resolution ones share (fragment_runner.cpp):
// The colour's image format (kComputeImageFormats) for a draw that may read it through image unit
// 0, where it is known complete (FilterRun::color_complete) and single-sample RGBA16F or RGBA32F;
// else -1 (the sampler). Whether the context has image units is the program cache's to check.
int readable_color_image(const FilterRun& run);
// pass_inputs.frag's variant for `run` (it marks the culling depth unless a stencil culls), its draw
// of variant `v` over the drawn rectangle (leaving the depth test on, func ALWAYS, write mask off),
// and one blur pass of `p` reading `source` (pass_inputs.frag's layout) with the strength on its unit.
PassInputsVariant pass_inputs_variant(const FilterRun& run);
// Whether that draw could read the colour of `run` through an image unit, were it complete
// (FilterRun::color_complete): the context has image units, the frame runs the separable passes
// on a single-sample RGBA16F or RGBA32F colour of the host's. Where this is false, the api layer
// does not ask the GL whether the colour is complete.
bool may_read_color_image(const Functions& gl, const FilterRun& run);
sss_result draw_pass_inputs(PassContext& ctx, const FilterRun& run, const PassInputsVariant& v, std::string* message);
void draw_blur(PassContext& ctx, BlurProgram& p, const FilterRun& run, GLuint source, std::size_t term, int axis);
// Nothing to blur: in place nothing changes; a separate output gets the colour copied.
sss_result run_identity(PassContext& ctx, const FilterRun& run, std::string* message);
// The cross-bilateral mode (Mikkelsen 2010) in two fragment passes (cbf_runner.cpp).
sss_result run_cross_bilateral(PassContext& ctx, const FilterRun& run, std::string* message);

// SSS_PATH_FRAGMENT_MASKED (masked_runner.cpp): the fragment passes culled to the translucent
// pixels by the depth their inputs draw marks from alpha, and every draw kept to the bands of tiles
// that hold such pixels (tile_culling.cpp), so the rest of the frame costs two small draws.
bool masked_available(const FilterRun& run);
sss_result run_masked(PassContext& ctx, const FilterRun& run, std::string* message);
// The tile marks' programs and targets (also for sss_prepare), and their draws: the marks, left on
// their units, and ctx.tile_bands and tile_grid set for the span draws; the viewport back on the
// drawn rectangle.
sss_result prepare_tile_culling(PassContext& ctx, const FilterRun& run, std::string* message);
sss_result mark_tiles(PassContext& ctx, const FilterRun& run, std::string* message);
// SSS_DEBUG_VIEW_TILES (tile_view.cpp): the tiles' marks and the masked path's bands, each draw in
// its own channel of the separate output, over the drawn rectangle.
sss_result run_tile_view(PassContext& ctx, const FilterRun& run, std::string* message);
// The paper's stencil culling: the module's stencil buffer set to 1 where `source`'s alpha is
// above 0 (left on horizontal_framebuffer(run)). Draws over the current viewport.
sss_result mark_stencil_from_alpha(PassContext& ctx, const FilterRun& run, GLuint source, std::string* message);
// The mark's program and the module's DEPTH24_STENCIL8 stencil buffer at this size.
sss_result stencil_mark_resources(PassContext& ctx, int width, int height, GLuint* program, std::string* message);

// SSS_PATH_HALF_RESOLUTION (half_runner.cpp; the method: math/half_resolution.hpp): "" when `run`
// can take it, else why not (it then runs the fragment passes). A host stencil culls alongside the
// depth its inputs draw marks from alpha.
const char* half_resolution_unavailable(const FilterRun& run);
sss_result run_half_resolution(PassContext& ctx, const FilterRun& run, std::string* message);
// Every program and target run_half_resolution needs, also for sss_prepare (prewarm.cpp).
sss_result prepare_half_resolution(PassContext& ctx, const FilterRun& run, std::string* message);

// SSS_PATH_COMPUTE (compute_runner.cpp, OpenGL 4.3+): "" when `run` can take it, else why not.
const char* compute_unavailable(const Functions& gl, const FilterRun& run);
sss_result run_compute(PassContext& ctx, const FilterRun& run, std::string* message);
// What run_compute builds and allocates before its first draw (every term's two programs, the
// intermediate, the sum of terms), also for sss_prepare (prewarm.cpp); the host stencil's copy aside.
sss_result prepare_compute(PassContext& ctx, const FilterRun& run, std::string* message);

// Multisampled colour and depth (msaa_runner.cpp): resolve, the fragment passes on the resolved
// images, and, in place, the per-sample write-back.
sss_result run_msaa(PassContext& ctx, const FilterRun& run, std::string* message);
// What run_msaa builds and allocates before its first draw (the resolve): its own programs and
// targets, the stencil buffer, and prepare_fragment's for the passes on the resolved images; also
// what sss_prepare makes ahead for a multisampled frame (prewarm.cpp).
sss_result prepare_msaa(PassContext& ctx, const FilterRun& run, std::string* message);

// A host strength texture (run.strength, strength_source.cpp): the colour with the strength as
// alpha, drawn into the module's copy before the passes, which then run on with_strength_source's
// run. prepare_ builds the program and allocates the copy (sss_prepare too); draw_ draws it over
// the viewport (module targets only: no host texture is written).
sss_result prepare_strength_source(PassContext& ctx, const FilterRun& run, std::string* message);
sss_result draw_strength_source(PassContext& ctx, const FilterRun& run, std::string* message);
// The run the passes take: the copy as the colour and, written back, the host's colour as the
// separate output (so the passes write its rgb alone: R11F_G11F_B10F has no alpha to keep).
FilterRun with_strength_source(const FilterRun& run, const Targets& targets);

}  // namespace sss::gl
