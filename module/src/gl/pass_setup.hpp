// What every runner shares: the context of one run (the GL, the programs, the targets, the
// vertex array and samplers, the measurements, the draw count) and the steps every path takes the
// same way: the pass state and viewport, the stencil copy and test, attaching and checking the
// pass targets, binding inputs, the copy draw, and the measurement of a frame's passes.
#pragma once

#include <array>
#include <string>

#include "filter_run.hpp"
#include "gl_functions.hpp"
#include "pass_queries.hpp"
#include "profile_tables.hpp"
#include "program_cache.hpp"
#include "target_pool.hpp"

namespace sss::gl {

// The objects that do not depend on a frame's size: the full-screen triangle's vertex array and
// the three samplers. The colour sampler's maximum LOD carries a tag unique to this instance in the
// process, which tells a context holding the module's objects from one that does not
// (SeparableFilter::objects_present).
struct PassObjects {
  GLuint vertex_array = 0;
  GLuint sampler = 0;        // bilinear, clamped, no depth comparison
  GLuint depth_sampler = 0;  // the same, GL_NEAREST on ES (a depth texture is incomplete otherwise)
  GLuint nearest_sampler = 0;  // GL_NEAREST everywhere: integer textures (the profile indices)
  GLfloat sampler_tag = 0.0f;

  void create(const Functions& gl, bool labels);
  void destroy(const Functions& gl);  // then the names are 0
  bool present(const Functions& gl) const;
};

struct PassContext {
  const Functions& gl;
  ProgramCache& programs;
  TargetPool& targets;
  const PassObjects& objects;
  bool labels;
  PassQueries* queries;  // nullptr: this run is not measured
  int draws = 0;         // full-screen draws and dispatches so far
  // glCheckFramebufferStatus on each framebuffer the run attaches (SeparableFilter::run decides:
  // off only where an earlier successful run checked the same attachments).
  bool check_framebuffers = true;
  ProfileTables* profile_tables = nullptr;  // the per-pixel profiles' uniform buffer
  // The masked path's tile culling (tile_culling.cpp), while its draws run: the bands of tiles over
  // the drawn rectangle (0: the draws cover it with one triangle) and the programs' u_tile_grid.
  int tile_bands = 0;
  std::array<GLfloat, 4> tile_grid{};
};

// The measurement of one frame's passes (sss_get_stats): every call is a no-op when the run is not
// measured or the ring of query slots is full.
class FrameMeasurement {
 public:
  FrameMeasurement(PassQueries* queries, std::uint64_t frame)
      : queries_(queries != nullptr && queries->begin_frame(frame) ? queries : nullptr) {}
  void begin(PassQueries::Pass pass) {
    if (queries_ != nullptr) queries_->begin_pass(pass);
  }
  void end(PassQueries::Pass pass) {
    if (queries_ != nullptr) queries_->end_pass(pass);
  }
  void begin_pixels() {
    if (queries_ != nullptr) queries_->begin_pixels();
  }
  void end_pixels() {
    if (queries_ != nullptr) queries_->end_pixels();
  }
  void end_frame() {
    if (queries_ != nullptr) queries_->end_frame();
  }

 private:
  PassQueries* queries_;
};

// The fixed-function state of the passes (set_pass_state), the vertex array and the viewport.
void begin_passes(PassContext& ctx, const std::array<int, 4>& rect);
sss_result check_framebuffer(const Functions& gl, const char* which, std::string* message);
// The same, or SSS_OK without asking where the run does not check (ctx.check_framebuffers).
sss_result check_framebuffer(const PassContext& ctx, const char* which, std::string* message);
// The framebuffer the horizontal pass of `run` draws into, which the stencil goes on: the packed
// intermediate's (separable fragment passes) or the intermediate's (cross-bilateral mode).
GLuint horizontal_framebuffer(const PassContext& ctx, const FilterRun& run);
// The host's depth-stencil into the module's stencil buffer, which is left on `framebuffer` (0:
// horizontal_framebuffer(run); the compute path's mark: the intermediate's).
sss_result copy_stencil(PassContext& ctx, const FilterRun& run, const StencilInput& stencil, std::string* message,
                        GLuint framebuffer = 0);
// Only the pixels whose stencil compares `func` to the host's reference pass (no stencil: all).
void set_stencil_test(const Functions& gl, const StencilInput* stencil, GLenum func);
// Puts `stencil_buffer` (0: none) on `framebuffer` (a horizontal_framebuffer) and checks it
// (`which` names the step in the message).
sss_result attach_stencil(PassContext& ctx, GLuint framebuffer, GLuint stencil_buffer, std::string* message,
                          const char* which = "horizontal pass");
// Puts the host's colour (in place) or output and `stencil_buffer` on the output framebuffer and
// checks it; with a region and a separate output, copies the viewport's colour there first, so
// the pixels the region leaves out hold their input.
sss_result attach_output(PassContext& ctx, const FilterRun& run, GLuint stencil_buffer, std::string* message);
// Takes the host's texture off the output framebuffer: never keep one attached, its storage would
// outlive the host's glDeleteTextures.
void detach_output(PassContext& ctx);
void bind_texture(PassContext& ctx, GLuint unit, GLuint texture, GLuint sampler);
// The host's colour on the original unit for a pass into a separate output; none writing back
// (the host's colour is then the target, and a texture must not be read and written at once).
void bind_original(PassContext& ctx, const FilterRun& run);
// A texturing mode's albedo (module/shaders/albedo.glsl) on its unit, where it stays for the frame
// (the pass that writes the target reads it there too), and for SSS_ALBEDO 3 (`albedo`) each
// profile's mode into the program in use (`texturing`, its table's location), with the host's
// indices on their unit. (Whether the quotient is rounded to half float is in the program's struct.)
void bind_albedo(PassContext& ctx, const FilterRun& run, int albedo, GLint texturing);
void draw_copy(PassContext& ctx, GLuint source);
// The bound program's draw over the viewport: one triangle, or with the masked path's tile culling
// on (ctx.tile_bands) its bands of tiles, `tile_grid` (the program's u_tile_grid) set first.
void draw_cover(PassContext& ctx, GLint tile_grid);
// With a region and a separate output: the viewport's colour into the bound draw framebuffer.
void copy_outside_region(PassContext& ctx, const FilterRun& run);

}  // namespace sss::gl
