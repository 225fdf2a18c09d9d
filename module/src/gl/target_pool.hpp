// The render targets the module owns, the framebuffers that draw into them or attach the host's
// textures, and the sizes and formats each was allocated at: a target is (re)allocated only when a
// frame needs it at another size or format. Every ensure_* call returns SSS_OK, or
// SSS_ERROR_OUT_OF_MEMORY / SSS_ERROR_GL with *message saying what failed at which size (and the
// target is then forgotten, so the next frame allocates it again).
#pragma once

#include <array>
#include <cstdint>
#include <vector>
#include <string>

#include "gl_functions.hpp"
#include "gpu_memory.hpp"
#include "program_cache.hpp"
#include "texture_query.hpp"

namespace sss::gl {

// The names, read by the runners; only TargetPool creates, allocates and deletes them.
struct Targets {
  // Created at init. The horizontal pass draws into `intermediate_framebuffer`, the last vertical
  // pass into `output_framebuffer` (the host's colour or output attached for the frame only);
  // `stencil_source_framebuffer` reads the host's depth-stencil for the copy; the vertical passes
  // of all terms but the last draw into `accumulator_framebuffer`.
  GLuint intermediate_framebuffer = 0, output_framebuffer = 0, stencil_source_framebuffer = 0,
         accumulator_framebuffer = 0;
  GLuint intermediate = 0;             // the horizontal pass's result: RGBA16F, or RGBA32F for RGBA32F colour
  std::array<GLuint, 2> accumulators{};  // the sum of the kernel's earlier terms, ping-ponged
  // The stencil copy (host's format), the MSAA path's mask marked from alpha, or the fragment
  // passes' culling depth (DEPTH24_STENCIL8, marked by their inputs draw).
  GLuint stencil_buffer = 0;
  // Cross-bilateral mode with a stencil: the colour with alpha 0 outside it (host's format).
  GLuint masked_source = 0, masked_framebuffer = 0;
  // MSAA path: the resolve's colour (host's format) and view distance (R32F); writing back, the
  // blurred result and what the resolve keeps of each pixel's translucent samples for the write:
  // their mean and count (RGBA32F) and their smallest values and mask (RGBA32UI).
  GLuint resolve_framebuffer = 0, sample_write_framebuffer = 0;
  GLuint resolved_color = 0, resolved_distance = 0, blurred = 0, translucent_mean = 0, translucent_lowest = 0;
  // A texturing mode into a separate output: the samples' mean A_post (RGBA32F; translucent_mean
  // then holds the undivided mean colour).
  GLuint resolved_albedo = 0;
  // A strength texture: the colour with that strength as alpha (RGBA16F; RGBA32F for RGBA32F colour).
  GLuint colour_copy = 0, colour_copy_framebuffer = 0;
  // The separable fragment passes (pass_inputs.frag): per pixel the colour's and view distance's
  // bits (RGBA32UI pass_taps), the strength's (R32UI pass_strength), and the horizontal pass's
  // result in the same layout (RGBA32UI pass_intermediate). pass_inputs_framebuffer draws all three
  // (and the culling depth, stencil_buffer, attached per run); pass_intermediate_framebuffer is the
  // horizontal pass's (with stencil_buffer: the culling).
  GLuint pass_taps = 0, pass_strength = 0, pass_intermediate = 0;
  GLuint pass_inputs_framebuffer = 0, pass_intermediate_framebuffer = 0;
  // The half-resolution path, at half size: half_inputs.frag's texels (RGBA32UI half_taps, R32UI
  // half_strength, and the horizontal pass's target filled alike: half_intermediate), the vertical
  // pass's result (half_result: the intermediate format), and every profile's two pass tables
  // (RGBA32F half_tables, kFootprintEntries + 1 texels a row). half_inputs_framebuffer draws the
  // three inputs; half_intermediate_framebuffer and half_result_framebuffer are the two passes'.
  // half_depth (DEPTH24_STENCIL8, on all three) holds the reduction's culling marks.
  GLuint half_taps = 0, half_strength = 0, half_intermediate = 0, half_result = 0, half_tables = 0, half_depth = 0;
  GLuint half_inputs_framebuffer = 0, half_intermediate_framebuffer = 0, half_result_framebuffer = 0;
  // The masked path's tile culling (tile_culling.cpp): per 16x16 tile of the frame whether it holds
  // a translucent pixel (R8 tiles), and per column of tiles whether any of its tiles does (R8
  // tile_columns, one row); each drawn by its own framebuffer.
  GLuint tiles = 0, tile_columns = 0, tiles_framebuffer = 0, tile_columns_framebuffer = 0;
};

class TargetPool {
 public:
  // Makes the four framebuffers every path uses (the rest come on first use).
  void init(const Functions* gl, bool labels, const Log* log);
  void destroy();  // deletes every object (they must exist in the current context), then forget()s
  void forget();   // drops the names (context lost)
  const Targets& names() const { return t_; }
  // The storage its textures and renderbuffers hold now (gpu_memory.hpp).
  std::uint64_t memory_bytes() const { return memory_.total(); }

  // `format`: intermediate_format (pass_setup.hpp) of the frame: RGBA16F, or RGBA32F for RGBA32F colour.
  sss_result ensure_intermediate(GLint format, int width, int height, std::string* message);
  // `half`: RGBA16F (OpenGL ES, where RGBA32F may not be renderable), else RGBA32F.
  sss_result ensure_accumulators(int width, int height, bool half, std::string* message);
  sss_result ensure_stencil_buffer(GLint format, int width, int height, std::string* message);
  sss_result ensure_masked_source(GLint format, int width, int height, std::string* message);
  void ensure_msaa_framebuffers();
  // `write_back`: also the blurred result and the translucent samples' targets (the resolve's
  // attachments 2 and 3); `albedo` (a texturing mode): those and resolved_albedo (attachment 7).
  sss_result ensure_msaa_targets(GLint color_format, int width, int height, bool write_back, bool albedo,
                                 std::string* message);
  // `format`: RGBA16F or RGBA32F.
  sss_result ensure_colour_copy(GLint format, int width, int height, std::string* message);
  // The fragment passes' inputs (pass_taps, pass_strength, pass_intermediate) as colour attachments
  // 4-6 of resolve_framebuffer, which the MSAA resolve writes: attached once, again only after
  // either was (re)made. Leaves resolve_framebuffer bound where it attaches.
  void attach_resolve_inputs();
  // The three pass_* targets and their framebuffers at this size.
  sss_result ensure_pass_targets(int width, int height, std::string* message);
  // The half_* targets (not the tables) and their framebuffers for a full-size frame of this size;
  // `result_format` RGBA16F or RGBA32F (the frame's intermediate format).
  sss_result ensure_half_targets(int width, int height, GLint result_format, std::string* message);
  // tiles and tile_columns for a frame of this size (math::kTileSize pixels a tile), and their
  // framebuffers.
  sss_result ensure_tile_targets(int width, int height, std::string* message);
  // Whether half_tables holds the kernels of `revision` (then a steady frame builds no texels).
  bool half_tables_hold(std::uint64_t revision) const {
    return t_.half_tables != 0 && half_tables_revision_ == revision;
  }
  // half_tables (re)specified with `rows` rows of `texels` (RGBA floats) for kernel `revision`.
  sss_result upload_half_tables(std::uint64_t revision, int rows, const std::vector<float>& texels,
                                std::string* message);

 private:
  sss_result ensure_resolved_albedo(int width, int height, std::string* message);
  // Creates *framebuffer (labelled `label`) when it is 0; nothing attached yet.
  void ensure_framebuffer(GLuint* framebuffer, const char* label);
  // `texture` as colour attachment 0 of `framebuffer` (left bound as the draw framebuffer).
  void attach_colour(GLuint framebuffer, GLuint texture);
  // pass_inputs.frag's three targets (or the half-size ones): where their names live.
  struct PackedInputs {
    GLuint *taps, *strength, *intermediate;
  };
  // The three, (re)allocated at this size (`size` prefixes their labels: "" or "half-size "), and
  // attached as colour attachments 0-2 of `framebuffer` with three draw buffers.
  sss_result allocate_inputs(const PackedInputs& inputs, int width, int height, const char* size, std::string* message);
  void attach_inputs(GLuint framebuffer, const PackedInputs& inputs);
  // A colour texture the module owns, (re)allocated at this size and format.
  sss_result allocate_target(GLuint* texture, GLenum internal_format, GLenum type, int width, int height,
                             const char* what, std::string* message, GLenum pixel_format = RGBA);
  void note(const std::string& text) const;
  // (Re)specifies a single-sample texture with one level and no data (left bound on unit 0, no
  // unpack buffer), and records its storage in memory_.
  void specify_2d(GLuint texture, GLint format, GLenum pixel_format, GLenum type, int width, int height);

  const Functions* gl_ = nullptr;
  bool labels_ = false;
  const Log* log_ = nullptr;
  Targets t_;
  GpuMemory memory_;
  GLint intermediate_format_ = 0;
  int intermediate_width_ = 0, intermediate_height_ = 0;
  bool accumulator_half_ = false;
  int accumulator_width_ = 0, accumulator_height_ = 0;
  GLint stencil_format_ = 0;
  int stencil_width_ = 0, stencil_height_ = 0;
  GLint masked_format_ = 0;
  int masked_width_ = 0, masked_height_ = 0;
  GLint msaa_color_format_ = 0;
  int msaa_width_ = 0, msaa_height_ = 0;
  bool has_write_back_targets_ = false;
  bool has_resolved_albedo_ = false;
  GLint strength_format_ = 0;
  int strength_width_ = 0, strength_height_ = 0;
  int pass_width_ = 0, pass_height_ = 0;
  bool resolve_inputs_attached_ = false;
  int half_width_ = 0, half_height_ = 0;
  GLint half_result_format_ = 0;
  std::uint64_t half_tables_revision_ = 0;
  int tiles_across_ = 0, tiles_down_ = 0;
};

}  // namespace sss::gl
