// Every GL program the passes use, built on first use (or ahead, by prewarm) and kept until the
// filter is destroyed: the copy, the separable blur (fragment and compute variants), the
// cross-bilateral blur, the MSAA resolve, stencil mark and per-sample write, and the strength
// texture's combine. A program's
// uniform locations are looked up once, when it is linked: its pass kind's struct (one location,
// pass_uniforms.hpp), its tables (one each) and, where the dialect cannot say a sampler's unit in
// the shader (GLSL 330, ES 3.00), its samplers, whose units are set then too (texture_units.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>

#include "frame_plan.hpp"
#include "gl_functions.hpp"
#include "glsl_variant.hpp"
#include "pass_uniforms.hpp"
#include "shader_variants.hpp"

namespace sss::gl {

using Log = std::function<void(int level, const std::string& message)>;

// What a blur pass writes at a pixel that is not blurred (SSS_OUTSIDE), and the blur's switches:
// shader_variants.hpp, which the shaders.glslang test builds every variant from too.
using Outside = BlurOutside;

// The compute path's target image formats: every colour and output format sss_apply_frame accepts.
constexpr int kImageFormats = kComputeImageFormatCount;
int image_format_index(GLint internal_format);  // into kComputeImageFormats; -1: no image format

struct BlurProgram {
  GLuint program = 0;
  UniformLocations fields;  // the blur pass's uniform struct (pass_uniforms.hpp)
  // SSS_FOLLOW_SURFACE 2 without per-pixel profiles: the depth correction is the term's Gaussian,
  // so u_follow_surface is profile mm per world unit (fill_blur_uniforms).
  bool gaussian_depth = false;
  // The kernel's tables, uploaded when the kernel, term or axis changes (footprint_cells.glsl).
  GLint cdf = -1, spacing = -1;
  GLint profile = -1;    // per-pixel profile variants only: each profile's numbers for the pass
  GLint tile_grid = -1;  // fragment programs only: the masked path's rows of tiles (fullscreen.vert)
  bool compute = false;
  // Reads its taps through image unit 0 (SSS_IMAGE_TAPS): bind_packed_inputs binds the source there.
  bool image_taps = false;
  // Which taps the kernel uniforms hold: kernel revision, term and axis (revision 0: none yet).
  std::uint64_t kernel_revision = 0;
  std::size_t uploaded_term = 0;
  int uploaded_axis = -1;
};

struct CbfProgram {
  GLuint program = 0;
  UniformLocations fields;  // the cross-bilateral pass's uniform struct (pass_uniforms.hpp)
  // The kernel's tables: footprint_cells.glsl's cumulative one and its layout's spacing.
  GLint cdf = -1, spacing = -1;
  std::uint64_t kernel_revision = 0;  // of the kernel its uniforms hold (0: none yet)
};

// The module's copy of the colour the passes read (colour_copy.cpp): divided by the albedo, with
// the host's separate strength texture as its alpha.
struct ColourCopyProgram {
  GLuint program = 0;
  UniformLocations fields;  // the copy's uniform struct (pass_uniforms.hpp)
  GLint texturing = -1;  // SSS_ALBEDO 3: each profile's mode
};

struct ResolveProgram {
  GLuint program = 0;
  UniformLocations fields;  // the resolve's uniform struct (pass_uniforms.hpp)
};

struct PassInputsProgram {
  GLuint program = 0;
  UniformLocations fields;  // the inputs' uniform struct (pass_uniforms.hpp)
  GLint tile_grid = -1;
  // Reads the colour through image unit 0 in kComputeImageFormats[color_image] (SSS_COLOR_IMAGE);
  // -1: through the sampler on unit 0.
  int color_image = -1;
  GLint texturing = -1;  // SSS_ALBEDO 3: each profile's mode
};

// The masked path's tile marks (tile_mark.frag): per tile, or per column of tiles.
struct TileMarkProgram {
  GLuint program = 0;
  GLint rect = -1;
  // The tiles' marks read the colour through image unit 0 in kComputeImageFormats[color_image]
  // (SSS_COLOR_IMAGE); -1: through the sampler on unit 0 (and the columns' marks read no colour).
  int color_image = -1;
};

// The tiles debug view (tile_view.frag): one program per vertex stage (TileSpans: the full-screen
// triangle for the marks, then the inputs draw's and the blur passes' bands).
struct TileViewProgram {
  GLuint program = 0;
  GLint rect = -1;       // the marks' draw (the drawn rectangle)
  GLint tile_grid = -1;  // the band draws' (fullscreen.vert)
};

// The half-resolution path's reduction (half_inputs.frag) and upsample (half_upsample.frag).
struct HalfInputsProgram {
  GLuint program = 0;
  UniformLocations fields;  // the reduction's uniform struct (pass_uniforms.hpp)
  GLint depth_factor = -1;  // per profile: 1 / the kernel's reach in world units
  GLint tile_grid = -1;  // the tiles' bands at half size (fullscreen.vert, the inputs' spans)
};
struct HalfUpsampleProgram {
  GLuint program = 0;
  UniformLocations fields;  // the upsample's uniform struct (pass_uniforms.hpp)
  GLint looks = -1;     // per profile: pixels per mm on x and y, depth factor
  GLint tile_grid = -1;  // the tiles' bands (fullscreen.vert, the passes' spans)
};

struct SampleWriteProgram {
  GLuint program = 0;
  UniformLocations fields;  // the write-back's uniform struct (pass_uniforms.hpp)
  bool one_draw = false;    // SSS_SAMPLE_MASK_OUTPUT: gl_SampleMask picks the samples
  int albedo = 0;           // SSS_ALBEDO: the host's multisampled albedo on unit::albedo
};

// Every program builds exactly the variant it is asked for: which variant a frame needs is the
// planner's (frame_plan.hpp). Where the driver refuses a program that another variant stands in
// for (its taps or colour through the image unit, a preset tap count as a constant), the cache
// records the refusal in the Capabilities it was given and logs it once (SSS_LOG_WARNING); the
// caller then plans again and asks for the stand-in.
class ProgramCache {
 public:
  // Builds the copy program and the fragment programs every host uses (written back, follow-surface,
  // hardware depth, culled by depth: the default settings'), so a driver that cannot compile them
  // fails at create. `log` (may be empty) gets a DEBUG note per program built; it and `caps` (the
  // context's capabilities, where refusals are recorded) must outlive the cache.
  sss_result init(const Functions* gl, GlslVariant variant, bool labels, const Log* log, Capabilities* caps,
                  std::string* message);
  void destroy();  // deletes the programs (they must exist in the current context), then forget()s
  void forget();   // drops the names (context lost)

  // SSS_PROFILES of the per-pixel profile variants (ProfileTables::capacity); before init().
  void set_profile_capacity(int profiles) { profile_capacity_ = profiles; }
  GLuint copy() const { return copy_; }
  sss_result blur(const BlurVariant& v, BlurProgram** out, std::string* message);
  // The compute variant of `v` (no per-pixel profiles) for `pass`, writing image format `image_format`.
  sss_result compute(const BlurVariant& v, int image_format, ComputePass pass, BlurProgram** out,
                     std::string* message);
  sss_result cross_bilateral(Outside outside, bool linear_depth, bool normals, int albedo, CbfProgram** out,
                             std::string* message);
  // `write_back`: the variant that also keeps the translucent samples' mean, lowest values and mask.
  // `albedo`: SSS_ALBEDO (0-2, the texturing mode that divides each sample).
  sss_result msaa_resolve(bool linear_depth, bool write_back, int albedo, ResolveProgram** out, std::string* message);
  sss_result stencil_mark(GLuint* out, std::string* message);  // the mask from alpha
  sss_result sample_write(int albedo, SampleWriteProgram** out, std::string* message);
  sss_result colour_copy(const ColourCopyVariant& v, ColourCopyProgram** out, std::string* message);
  // The fragment passes' inputs: colour and view distance (and R8UI indices), strength.
  sss_result pass_inputs(const PassInputsVariant& v, PassInputsProgram** out, std::string* message);
  sss_result half_inputs(const HalfVariant& v, HalfInputsProgram** out, std::string* message);
  sss_result half_upsample(const HalfVariant& v, HalfUpsampleProgram** out, std::string* message);
  // `columns`: the marks of the columns of tiles (SSS_TILE_COLUMNS), else of the tiles.
  // `color_image`: the colour's image format for the tiles' marks (ignored for the columns'), -1 for
  // the sampler.
  sss_result tile_mark(bool columns, int color_image, TileMarkProgram** out, std::string* message);
  // The tiles debug view's program drawn with the vertex stage `spans` (SSS_DEBUG_VIEW_TILES).
  sss_result tile_view(TileSpans spans, TileViewProgram** out, std::string* message);

 private:
  // The compute variants (is_compute_blur_variant): blur_variant_index's leading factor (packed
  // output, profile ids: 6 values) is 0 for them.
  static constexpr int kComputeBlurVariants = kBlurVariantCount / 6;
  static constexpr int kComputeVariantCount = kComputeBlurVariants * kImageFormats * kComputePassCount;
  static constexpr int kCbfVariantCount = 3 * 2 * 2 * 3;  // outside, linear depth, normals, SSS_ALBEDO

  // A program from the full-screen vertex shader (with the tile spans `spans`) and the fragment
  // shader file `fragment` with `defines`, in the context's dialect; 0 with *message ("<what>:
  // <driver log>") on failure.
  GLuint link(const char* fragment, const std::string& defines, const std::string& what, std::string* message,
              TileSpans spans = TileSpans::none);
  void find_blur_uniforms(BlurProgram* p) const;
  // The locations of a pass struct's fields in `program` (pass_uniforms.hpp find_uniforms: at their
  // table's rows where the dialect has explicit uniform locations).
  UniformLocations struct_fields(GLuint program, const UniformStruct& s) const;
  // Sets the sampler uniform `name` of `program` to `unit` where the dialect cannot say it in the
  // shader (GLSL 420 and 430 have layout(binding): no lookup there).
  void set_unit(GLuint program, const char* name, GLuint unit) const;
  // A program the driver refused (`refused`, its log in *message) where another gives the same
  // image: one SSS_LOG_WARNING naming both, with the driver's log from *message; *message then
  // says what was refused (the caller plans again).
  void stand_in(const std::string& refused, const std::string& instead, std::string* message) const;
  // Labels a new program and, where `built` names its kind, notes it (DEBUG) with its dialect
  // (nullptr: the context's).
  void finish(GLuint program, const char* label, const char* built, const char* dialect = nullptr);

  const Functions* gl_ = nullptr;
  GlslVariant variant_ = GlslVariant::glsl330;
  bool labels_ = false;
  int profile_capacity_ = SSS_MAX_PROFILES;
  Capabilities* caps_ = nullptr;
  const Log* log_ = nullptr;
  GLuint copy_ = 0;
  // Fragment variants by blur_variant_index, half_taps and image_taps (std::map: the programs stay
  // put while a frame holds pointers to them, and only the tap counts a host uses get an entry).
  std::map<int, BlurProgram> blur_;
  // By (blur_variant_index, image format, pass) and SSS_ALBEDO; only the variants a host uses.
  std::map<int, BlurProgram> compute_;
  std::array<CbfProgram, kCbfVariantCount> cbf_{};
  std::array<ResolveProgram, 12> resolve_{};  // index: 4 · SSS_ALBEDO + 2 · writes back + host depth is linear
  GLuint stencil_mark_ = 0;
  std::array<SampleWriteProgram, 3> sample_write_{};  // index: SSS_ALBEDO
  std::array<ColourCopyProgram, kColourCopyVariantCount> colour_copy_{};
  std::array<PassInputsProgram, kPassInputsVariantCount> pass_inputs_{};
  std::array<HalfInputsProgram, kHalfVariantCount> half_inputs_{};
  std::array<HalfUpsampleProgram, kHalfVariantCount> half_upsample_{};
  // [0]: the columns' marks; [1 + color_image + 1]: the tiles' (sampler, then each image format).
  std::array<TileMarkProgram, 2 + kPassInputsColorImageFormats> tile_mark_{};
  std::array<TileViewProgram, 3> tile_view_{};  // by TileSpans
};

}  // namespace sss::gl
