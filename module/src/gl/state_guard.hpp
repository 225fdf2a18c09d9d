// Saves, on construction, every GL state the module may change (the list in sss.h) and restores it
// on destruction. Disabled (a no-op) when the host opted out with SSS_CREATE_NO_STATE_RESTORE.
// Each saved value is a query (a round trip that stalls a threaded driver), so a caller that knows
// a part of the list cannot change during the call leaves it out of the Scope: what is not changed
// needs no restore.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>

#include "gl_functions.hpp"

namespace sss::gl {

// Groups of restores in ~StateGuard. In the tests' build of the library (sss_state_guard_hook,
// compiled with SSS_STATE_GUARD_TEST_HOOK) a hook, restore_skip_mask_for_tests, can skip any of
// them, so the state harness can show that it notices each single missing restore
// (tests/gl/state_fuzz_test.cpp). The shipped library has no hook: every group is restored.
namespace restore_group {
enum : uint32_t {
  stencil = 1u << 0,          // both faces: func, ref, masks, ops
  color_mask = 1u << 1,
  polygon_mode = 1u << 2,     // desktop
  clip_distances = 1u << 3,   // desktop
  desktop_enables = 1u << 4,  // FRAMEBUFFER_SRGB, DEPTH_CLAMP, COLOR_LOGIC_OP; MULTISAMPLE (in the multisample scope)
  sample_mask_enable = 1u << 5,
  enables = 1u << 6,          // kCapabilities
  viewport = 1u << 7,
  sample_mask_value = 1u << 8,   // set by the MSAA write-back only
  texture_units = 1u << 9,       // 2D and 2D-multisample bindings and samplers of units 0-6
  active_texture = 1u << 10,
  unpack_buffer = 1u << 11,
  renderbuffer = 1u << 12,
  read_framebuffer = 1u << 13,
  draw_framebuffer = 1u << 14,
  vertex_array = 1u << 15,
  program = 1u << 16,
  image_unit = 1u << 17,         // image units 0 and 1 (the compute path's target, the fragment taps and strength), GL 4.3+
  uniform_buffer = 1u << 18,     // uniform buffer binding 0 and the generic one (per-pixel profiles)
  pack_state = 1u << 19,         // pack buffer, alignment, row length, skips (debug checks' readback)
  depth = 1u << 20,              // depth func, write mask and range (the fragment passes' culling)
  blend_function = 1u << 21,     // blend factors and equations (draw buffer 0's): the MSAA write-back only
  all = (1u << 22) - 1u
};
}  // namespace restore_group
#ifdef SSS_STATE_GUARD_TEST_HOOK
std::atomic<uint32_t>& restore_skip_mask_for_tests();  // 0: restore everything
#endif

// Texture units the module binds: 0 pass source, 1 depth, 2 original colour, 3 normals, 4 profile
// indices, 5 the masked path's tile marks, 6 the albedo.
constexpr int kUnitCount = 7;

// The parts of the list a call may change; everything else is saved always. The default is all.
struct GuardScope {
  bool image_unit = true;    // image units 0 and 1: the compute path's target, the fragment passes' taps
                             // and strength (GL 4.3+)
  bool stencil = true;       // stencil func, ref, masks and ops: a stencil mask (the host's, the
                             // masked path's or the MSAA path's)
  bool multisample = true;   // GL_TEXTURE_BINDING_2D_MULTISAMPLE of units 0-3 (and 6: an MSAA albedo),
                             // GL_SAMPLE_MASK_VALUE, GL_MULTISAMPLE and the blend function: the MSAA path, and the texture
                             // query's probe of a texture's target
  bool unit3 = true;         // texture unit 3: the normals, the sum of several kernel terms
  bool profiles = true;      // texture unit 4 and uniform buffer binding 0: per-pixel profiles
  bool tiles = true;         // texture unit 5: the masked path's tile marks (tile_culling.cpp)
  bool albedo = true;        // texture unit 6: the host's albedo (a texturing mode)
  bool pack = false;         // the pack state: the debug checks read the profile indices back
  bool depth = true;         // depth func, write mask and range: the fragment passes' culling
                             // (pass_inputs.frag marks translucent pixels in the module's depth)
};

class StateGuard {
 public:
  using Scope = GuardScope;
  StateGuard(const Functions& gl, bool enabled, const Scope& scope = Scope{});
  ~StateGuard();
  StateGuard(const StateGuard&) = delete;
  StateGuard& operator=(const StateGuard&) = delete;

 private:
  struct StencilFace {
    GLint func, ref, value_mask, fail, depth_fail, depth_pass, write_mask;
  };
  static constexpr int kClipDistances = 8;
  // Enables that exist on every API (GL 3.3, ES 3.0).
  static constexpr std::array<GLenum, 9> kCapabilities = {
      SCISSOR_TEST,       DEPTH_TEST,        STENCIL_TEST,    BLEND, CULL_FACE,
      RASTERIZER_DISCARD, SAMPLE_ALPHA_TO_COVERAGE, SAMPLE_COVERAGE, POLYGON_OFFSET_FILL};
  // Desktop GL only; the passes switch them off.
  static constexpr std::array<GLenum, 3> kDesktopCapabilities = {FRAMEBUFFER_SRGB, DEPTH_CLAMP, COLOR_LOGIC_OP};

  void save_stencil_face(GLenum func, GLenum ref, GLenum value_mask, GLenum fail, GLenum depth_fail,
                         GLenum depth_pass, GLenum write_mask, StencilFace* face) const;
  void restore_stencil_face(GLenum face_enum, const StencilFace& face) const;
  void restore_uniform_buffer() const;
  void restore_image_units() const;
  static constexpr std::array<GLenum, 4> kPackParameters = {PACK_ALIGNMENT, PACK_ROW_LENGTH, PACK_SKIP_ROWS,
                                                              PACK_SKIP_PIXELS};
  // The units saved: 0-2 always, 3 and 4 as the scope says (4 implies 3: the list grew so), 5 for the tiles.
  bool saves_unit(int unit) const {
    return unit < 3 || (unit == 3 && (scope_.unit3 || scope_.profiles)) || (unit == 4 && scope_.profiles) ||
           (unit == 5 && scope_.tiles) || (unit == 6 && scope_.albedo);
  }
  // GL_SAMPLE_MASK_VALUE, GL_MULTISAMPLE and the blend function: set by the desktop MSAA write-back
  // only (never on ES).
  bool msaa_write_back_in_scope() const { return scope_.multisample && gl_.has_msaa_path(); }

  const Functions& gl_;
  bool enabled_;
  Scope scope_;
  GLint program_ = 0, vertex_array_ = 0, draw_framebuffer_ = 0, read_framebuffer_ = 0, renderbuffer_ = 0;
  GLint active_texture_ = 0, unpack_buffer_ = 0;
  std::array<GLint, kUnitCount> textures_{}, samplers_{};
  std::array<GLint, kUnitCount> multisample_textures_{};  // GL 3.2+ / ES 3.1+ only
  GLint sample_mask_value_ = -1;  // GL_SAMPLE_MASK_VALUE, word 0 (the desktop MSAA write-back sets it)
  GLboolean multisample_ = 1;     // the GL_MULTISAMPLE enable (the desktop MSAA write-back switches it on)
  // GL_BLEND_SRC_RGB, _DST_RGB, _SRC_ALPHA, _DST_ALPHA, _EQUATION_RGB, _EQUATION_ALPHA: the MSAA
  // write-back blends its change into the host's samples. Draw buffer 0's; restored on every buffer.
  static constexpr std::array<GLenum, 6> kBlendParameters = {BLEND_SRC_RGB, BLEND_DST_RGB, BLEND_SRC_ALPHA,
                                                               BLEND_DST_ALPHA, BLEND_EQUATION_RGB, BLEND_EQUATION_ALPHA};
  std::array<GLint, 6> blend_{};
  std::array<GLint, 4> viewport_{};
  std::array<GLboolean, kCapabilities.size()> capabilities_{};
  std::array<GLboolean, kDesktopCapabilities.size()> desktop_capabilities_{};
  GLboolean sample_mask_ = 0;  // the GL_SAMPLE_MASK enable
  std::array<GLboolean, kClipDistances> clip_distances_{};
  std::array<GLboolean, 4> color_mask_{};
  std::array<GLint, 2> polygon_mode_{};
  StencilFace front_{}, back_{};
  // Image units 0 and 1 (GL 4.3+: has_compute): the compute path binds its target to 0, the fragment
  // passes their taps' texture to 0 and their strength's to 1.
  struct ImageUnit {
    GLint name = 0, level = 0, layer = 0, access = 0, format = 0;
    GLboolean layered = 0;
  };
  static constexpr GLuint kImageUnits = 2;
  std::array<ImageUnit, kImageUnits> image_units_{};
  // Uniform buffer binding point 0 (name, range) and the generic GL_UNIFORM_BUFFER binding.
  GLint uniform_buffer_ = 0, uniform_buffer0_ = 0;
  std::int64_t uniform_buffer0_start_ = 0, uniform_buffer0_size_ = 0;
  // GL_PIXEL_PACK_BUFFER binding, then alignment, row length, skip rows, skip pixels.
  GLint pack_buffer_ = 0;
  std::array<GLint, 4> pack_{};
  // Depth func, write mask and range.
  GLint depth_func_ = 0;
  GLboolean depth_mask_ = 1;
  std::array<GLfloat, 2> depth_range_{};
};

// Sets the fixed-function state the passes need (after a StateGuard saved it): everything that
// could drop or alter a full-screen triangle's fragments is switched off. (GL_MULTISAMPLE, which
// acts on multisampled targets alone, is the MSAA write-back's to switch on.)
void set_pass_state(const Functions& gl);

}  // namespace sss::gl
