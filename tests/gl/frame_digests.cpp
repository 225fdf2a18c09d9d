// sss_frame_digests: a digest of what the library writes for every way a frame can run, for a
// change that must not change any image (a refactoring of the frame's code: docs/development.md).
// Run it on the code before the change and after, on each backend, and compare the files:
//
//   build/release/tests/sss_frame_digests --sss-backend=osmesa | grep ^digest > before-osmesa.txt
//   (the change, a rebuild)
//   build/release/tests/sss_frame_digests --sss-backend=osmesa | grep ^digest | diff before-osmesa.txt -
//
// Each line names a case and gives the FNV-1a hash of the bits the GL read back after its first and
// after its second frame (the second is a steady frame: it asks the GL nothing). It is a tool, not
// a test: the digests depend on the driver and the processor (llvmpipe's vector width), so no file
// of expected values is kept. The cases: every path with each texture layout and switch that
// selects a different variant or step (output, host stencil, region, viewport, depth encodings,
// colour formats, a strength texture, per-pixel profiles, kernel terms, tap counts, jitter,
// follow-surface, each texturing mode over an albedo, a mode per profile), the cross-bilateral
// mode, the MSAA path (with the texturing modes too) and every debug view. A refused frame prints
// its code alone (the message names textures, whose numbers move as cases are added).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "gl_fixture.hpp"
#include "kernel_of.hpp"
#include "multisample_textures.hpp"
#include "synthetic_scene.hpp"

namespace sss_test {
namespace {

constexpr int kW = 96, kH = 64;

enum class Colour { rgba32f, rgba16f, r11f_with_strength };
enum class Depth { depth32f, depth24_stencil8, linear_r32f };

struct DigestCase {
  std::string name;
  sss_settings settings{};
  Colour colour = Colour::rgba32f;
  Depth depth = Depth::depth32f;
  bool output = false;
  bool stencil = false;
  bool region = false;
  std::array<int32_t, 4> region_rect = {10, 6, 60, 40};
  bool viewport = false;
  int samples = 0;       // 0: single-sample; else the MSAA path with this many samples
  GLenum profiles = 0;   // 0, GL_R8UI or GL_R16UI: two profiles, in stripes
  bool normals = false;  // the cross-bilateral mode's normal texture
  uint32_t debug_view = 0;
  uint32_t noise_index = 0;
  // A texturing mode (sss_settings.texturing) over an RGBA16F albedo; with per-pixel profiles the
  // second profile keeps pre-scatter (a mode per pixel).
  uint32_t texturing = SSS_TEXTURING_PRE_SCATTER;
};

// The albedo of a texturing case: 2-pixel cells of three greys per channel (each sample its own on
// the MSAA path's fine grid), never below the module's floor.
std::vector<float> albedo_pattern(int width, int height) {
  std::vector<float> a(static_cast<std::size_t>(width) * height * 4, 1.0f);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const int cell = (x / 2 + 2 * (y / 2)) % 3;
      for (int c = 0; c < 3; ++c) a[(static_cast<std::size_t>(y) * width + x) * 4 + c] = 0.25f + 0.3f * static_cast<float>((cell + c) % 3);
    }
  }
  return a;
}

std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t h = 1469598103934665603ull) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) {
    h ^= p[i];
    h *= 1099511628211ull;
  }
  return h;
}

class FrameDigests : public GlTest {
 protected:
  // The case's frame applied twice on a fresh context; the digest of the target after each.
  std::string digest(const DigestCase& c) {
    if (sss_ != nullptr) sss_destroy(sss_);
    sss_ = create_sss();
    if (sss_ == nullptr) return "no context";
    const int fw = c.samples > 0 ? 2 * kW : kW, fh = c.samples > 0 ? 2 * kH : kH;
    const SyntheticScene scene =
        make_relief_scene(fw, fh, 7u, perspective_matrix(40.0f, static_cast<float>(kW) / kH, 0.1f, 10.0f));
    if (sss_set_settings(sss_, &c.settings) != SSS_OK) return std::string("settings refused: ") + sss_last_error(sss_);
    if (sss_set_camera(sss_, scene.projection.data()) != SSS_OK) return "camera refused";
    sss_frame f = frame_of(0, 0);
    sss_stencil stencil = {0, 1, 0xFF};
    GLuint target = 0;
    if (c.samples > 0) {
      f.color_texture = make_multisample_texture(c.colour == Colour::rgba16f ? GL_RGBA16F : GL_RGBA32F, kW, kH,
                                                 c.samples, scene.color);
      f.depth_texture = c.stencil
                            ? make_multisample_depth_stencil(kW, kH, c.samples, scene.window_depth, scene.stencil)
                            : make_multisample_texture(GL_DEPTH_COMPONENT32F, kW, kH, c.samples, scene.window_depth);
      if (f.color_texture == 0 || f.depth_texture == 0) return "no multisampled textures";
    } else {
      f.color_texture = colour_texture(c, scene);
      f.depth_texture = depth_texture(c, scene);
      if (c.colour == Colour::r11f_with_strength) {
        std::vector<float> alpha(static_cast<std::size_t>(kW) * kH);
        for (std::size_t i = 0; i < alpha.size(); ++i) alpha[i] = scene.color[4 * i + 3];
        f.strength_texture = make_texture(GL_R8, kW, kH, GL_RED, GL_FLOAT, alpha.data());
      }
    }
    if (c.stencil) {
      stencil.depth_stencil_texture = f.depth_texture;
      f.stencil = &stencil;
    }
    if (c.output || c.colour == Colour::r11f_with_strength) {
      f.output_texture = make_rgba32f(kW, kH, std::vector<float>(static_cast<std::size_t>(kW) * kH * 4, -7.0f));
    }
    if (c.profiles != 0) f.profile_texture = profile_texture(c.profiles);
    if (c.texturing != SSS_TEXTURING_PRE_SCATTER) {
      f.albedo_texture = c.samples > 0 ? make_multisample_texture(GL_RGBA16F, kW, kH, c.samples, albedo_pattern(fw, fh))
                                       : make_rgba16f(kW, kH, albedo_pattern(kW, kH));
      if (c.samples > 0) textures_.push_back(f.albedo_texture);
    }
    if (c.normals) f.normal_texture = make_rgba32f(kW, kH, normals());
    if (c.region) {
      f.flags |= SSS_FRAME_REGION;
      for (int i = 0; i < 4; ++i) f.region[i] = c.region_rect[static_cast<std::size_t>(i)];
    }
    if (c.viewport) {
      const int32_t vp[4] = {4, 2, kW - 12, kH - 8};
      std::memcpy(f.viewport, vp, sizeof vp);
    }
    f.debug_view = c.debug_view;
    f.noise_index = c.noise_index;
    if (c.profiles != 0) {
      sss_settings two[2] = {c.settings, c.settings};
      two[1].scale = 2.5f;
      two[1].strength[0] = 0.4f;
      two[1].texturing = SSS_TEXTURING_PRE_SCATTER;
      if (sss_set_profiles(sss_, two, 2) != SSS_OK) return std::string("profiles refused: ") + sss_last_error(sss_);
    }
    if (is_gles()) describe(c, &f);
    target = f.output_texture != 0 ? f.output_texture : f.color_texture;
    std::string line;
    for (int frame = 0; frame < 2; ++frame) {
      const sss_result r = sss_apply_frame(sss_, &f);
      // The code alone: the message names textures, whose numbers move as cases are added.
      if (r != SSS_OK) return line + " refused: " + sss_result_string(r);
      char hex[24];
      std::snprintf(hex, sizeof hex, " %016llx", static_cast<unsigned long long>(read_back(target, c)));
      line += hex;
    }
    sss_stats stats = {};
    stats.struct_size = sizeof stats;
    sss_get_stats(sss_, &stats);
    char tail[64];
    std::snprintf(tail, sizeof tail, " path %u draws %u", stats.last_frame_path, stats.last_frame_passes);
    return line + tail;
  }

  GLuint colour_texture(const DigestCase& c, const SyntheticScene& s) {
    switch (c.colour) {
      case Colour::rgba16f: return make_rgba16f(kW, kH, s.color);
      case Colour::r11f_with_strength: {
        std::vector<float> rgb(static_cast<std::size_t>(kW) * kH * 3);
        for (std::size_t i = 0; i < rgb.size() / 3; ++i) {
          for (std::size_t k = 0; k < 3; ++k) rgb[3 * i + k] = s.color[4 * i + k];
        }
        return make_texture(GL_R11F_G11F_B10F, kW, kH, GL_RGB, GL_FLOAT, rgb.data());
      }
      default: return make_rgba32f(kW, kH, s.color);
    }
  }

  GLuint depth_texture(const DigestCase& c, const SyntheticScene& s) {
    if (c.depth == Depth::linear_r32f) return make_texture(GL_R32F, kW, kH, GL_RED, GL_FLOAT, s.distance.data());
    if (c.depth == Depth::depth24_stencil8 || c.stencil) {
      std::vector<uint32_t> packed(s.window_depth.size());
      for (std::size_t i = 0; i < packed.size(); ++i) {
        const auto d24 = static_cast<uint32_t>(s.window_depth[i] * 16777215.0 + 0.5);
        packed[i] = (d24 << 8) | (s.stencil[i] ? 1u : 0u);
      }
      return make_texture(GL_DEPTH24_STENCIL8, kW, kH, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed.data());
    }
    return make_depth32f(kW, kH, s.window_depth);
  }

  GLuint profile_texture(GLenum format) {
    std::vector<std::uint8_t> v8(static_cast<std::size_t>(kW) * kH);
    std::vector<std::uint16_t> v16(v8.size());
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) {
        const unsigned id = ((x / 12) % 2) | ((y / 16) % 3 == 0 ? 0x20u : 0u);  // profile 0/1, objects 0/2
        v8[static_cast<std::size_t>(y * kW + x)] = static_cast<std::uint8_t>(id);
        v16[static_cast<std::size_t>(y * kW + x)] = static_cast<std::uint16_t>(id);
      }
    }
    return format == GL_R16UI ? make_texture(GL_R16UI, kW, kH, GL_RED_INTEGER, GL_UNSIGNED_SHORT, v16.data())
                              : make_texture(GL_R8UI, kW, kH, GL_RED_INTEGER, GL_UNSIGNED_BYTE, v8.data());
  }

  static std::vector<float> normals() {
    std::vector<float> n(static_cast<std::size_t>(kW) * kH * 4);
    for (int i = 0; i < kW * kH; ++i) {
      const float tilt = static_cast<float>(i % kW) / kW - 0.5f;
      n[4 * static_cast<std::size_t>(i)] = tilt;
      n[4 * static_cast<std::size_t>(i) + 2] = 1.0f;
    }
    return n;
  }

  void describe(const DigestCase& c, sss_frame* f) const {
    f->texture_width = kW;
    f->texture_height = kH;
    f->color_format = c.colour == Colour::rgba16f   ? GL_RGBA16F
                      : c.colour == Colour::rgba32f ? GL_RGBA32F
                                                    : GL_R11F_G11F_B10F;
    f->depth_format = c.depth == Depth::linear_r32f                       ? GL_R32F
                      : (c.depth == Depth::depth24_stencil8 || c.stencil) ? GL_DEPTH24_STENCIL8
                                                                          : GL_DEPTH_COMPONENT32F;
    f->output_format = f->output_texture != 0 ? GL_RGBA32F : 0;
    f->stencil_format = f->stencil != nullptr ? GL_DEPTH24_STENCIL8 : 0;
    f->strength_format = f->strength_texture != 0 ? GL_R8 : 0;
    f->profile_format = f->profile_texture != 0 ? c.profiles : 0;
    f->albedo_format = f->albedo_texture != 0 ? GL_RGBA16F : 0;
    f->normal_format = f->normal_texture != 0 ? GL_RGBA32F : 0;
  }

  std::uint64_t read_back(GLuint target, const DigestCase& c) {
    if (c.samples > 0 && !c.output) {
      std::uint64_t h = 1469598103934665603ull;
      for (const std::vector<float>& sample : read_samples(target, kW, kH, c.samples)) {
        h = fnv1a(sample.data(), sample.size() * sizeof(float), h);
      }
      return h;
    }
    const std::vector<float> rgba = read_rgba(target, kW, kH);
    return fnv1a(rgba.data(), rgba.size() * sizeof(float));
  }
};

sss_settings base_settings() {
  sss_settings s;
  sss_default_settings(&s);
  s.world_units_per_mm = 0.045f;  // as the GL suites run the relief scene: a blur of several pixels
  return s;
}

// What a case changes from the default frame, as bits.
enum Feature : unsigned {
  kHalfColour = 1u << 0,
  kOutput = 1u << 1,
  kStencil = 1u << 2,
  kRegion = 1u << 3,
  kOddRegion = 1u << 4,
  kViewport = 1u << 5,
  kD24S8 = 1u << 6,
  kLinearDepth = 1u << 7,
  kTwoTerms = 1u << 8,
  kTaps9 = 1u << 9,
  kTaps33 = 1u << 10,
  kTaps21 = 1u << 11,
  kJitter = 1u << 12,
  kNoFollowSurface = 1u << 13,
  kStrengthTexture = 1u << 14,
  kProfilesR8 = 1u << 15,
  kProfilesR16 = 1u << 16,
  kIdentity = 1u << 17,
  kAutoHalf = 1u << 18,
  kNormals = 1u << 19,
  kComputePath = 1u << 20,
  kCrossBilateral = 1u << 21,
  kPostScatter = 1u << 22,
  kPreAndPostScatter = 1u << 23,
};

DigestCase make_case(const std::string& name, uint32_t path, unsigned features) {
  DigestCase c;
  c.name = name;
  c.settings = base_settings();
  c.settings.path = (features & kComputePath) != 0 ? static_cast<uint32_t>(SSS_PATH_COMPUTE) : path;
  if ((features & kCrossBilateral) != 0) c.settings.mode = SSS_MODE_CROSS_BILATERAL;
  if ((features & kHalfColour) != 0) c.colour = Colour::rgba16f;
  if ((features & kStrengthTexture) != 0) c.colour = Colour::r11f_with_strength;
  c.output = (features & kOutput) != 0;
  c.stencil = (features & kStencil) != 0;
  c.region = (features & (kRegion | kOddRegion)) != 0;
  if ((features & kOddRegion) != 0) c.region_rect = {11, 7, 57, 41};
  c.viewport = (features & kViewport) != 0;
  if ((features & kD24S8) != 0) c.depth = Depth::depth24_stencil8;
  if ((features & kLinearDepth) != 0) c.depth = Depth::linear_r32f;
  if ((features & kTwoTerms) != 0) {
    kernel_of(c.settings).family = SSS_KERNEL_SVD;
    kernel_of(c.settings).rank = 2;
  }
  if ((features & kTaps9) != 0) c.settings.taps = 9;
  if ((features & kTaps33) != 0) c.settings.taps = 33;
  if ((features & kTaps21) != 0) c.settings.taps = 21;  // no preset: the count as a uniform
  if ((features & kJitter) != 0) {
    c.settings.jitter = 0.5f;
    c.noise_index = 3;
  }
  if ((features & kNoFollowSurface) != 0) c.settings.flags &= ~SSS_FOLLOW_SURFACE;
  if ((features & kProfilesR8) != 0) c.profiles = GL_R8UI;
  if ((features & kProfilesR16) != 0) c.profiles = GL_R16UI;
  if ((features & kIdentity) != 0) c.settings.scale = 0.0f;
  if ((features & kAutoHalf) != 0) c.settings.flags |= SSS_AUTO_HALF_RESOLUTION;
  c.normals = (features & kNormals) != 0;
  if ((features & kPostScatter) != 0) c.texturing = SSS_TEXTURING_POST_SCATTER;
  if ((features & kPreAndPostScatter) != 0) c.texturing = SSS_TEXTURING_PRE_AND_POST_SCATTER;
  c.settings.texturing = c.texturing;
  return c;
}

struct Variation {
  const char* name;
  unsigned features;
};

// Every path with each texture layout and switch.
constexpr Variation kPathVariations[] = {
    {"default", 0},
    {"rgba16f", kHalfColour},
    {"rgba16f output", kHalfColour | kOutput},
    {"output", kOutput},
    {"stencil", kStencil},
    {"stencil output", kStencil | kOutput},
    {"region", kRegion},
    {"region odd output", kOddRegion | kOutput},
    {"viewport output", kViewport | kOutput},
    {"d24s8", kD24S8},
    {"linear depth", kLinearDepth},
    {"two terms", kTwoTerms},
    {"two terms output rgba16f", kTwoTerms | kOutput | kHalfColour},
    {"9 taps", kTaps9},
    {"33 taps", kTaps33},
    {"21 taps", kTaps21},
    {"jitter", kJitter},
    {"no follow-surface", kNoFollowSurface},
    {"strength texture", kStrengthTexture},
    {"profiles r8", kProfilesR8},
    {"profiles r16 output", kProfilesR16 | kOutput},
    {"profiles r8 stencil", kProfilesR8 | kStencil},
    {"identity output", kIdentity | kOutput},
    {"identity in place", kIdentity},
    {"auto half allowed", kAutoHalf},
    {"post-scatter", kPostScatter},
    {"pre- and post-scatter output", kPreAndPostScatter | kOutput},
    {"post-scatter profiles r8", kPostScatter | kProfilesR8},
};
constexpr Variation kCrossBilateralVariations[] = {
    {"default", 0},
    {"output", kOutput},
    {"stencil", kStencil},
    {"stencil output", kStencil | kOutput},
    {"normals", kNormals},
    {"linear depth", kLinearDepth},
    {"compute", kComputePath},
    {"region output", kRegion | kOutput},
    {"post-scatter", kPostScatter},
    {"pre- and post-scatter output", kPreAndPostScatter | kOutput},
};
// The MSAA path: the layouts it takes of the list above (what a multisampled frame refuses, and
// what does not change its plan, left out), the cross-bilateral mode, and the compute path asked for.
constexpr unsigned kMsaaFeatures =
    kHalfColour | kOutput | kStencil | kTwoTerms | kIdentity | kProfilesR8 | kPostScatter | kPreAndPostScatter;
constexpr Variation kMsaaExtras[] = {{"cross-bilateral", kCrossBilateral}, {"compute", kComputePath}};

std::vector<DigestCase> cases() {
  std::vector<DigestCase> out;
  const std::pair<const char*, uint32_t> paths[] = {{"fragment", SSS_PATH_FRAGMENT},
                                                    {"masked", SSS_PATH_FRAGMENT_MASKED},
                                                    {"half", SSS_PATH_HALF_RESOLUTION},
                                                    {"compute", SSS_PATH_COMPUTE},
                                                    {"auto", SSS_PATH_AUTO}};
  for (const auto& [path_name, path] : paths) {
    for (const Variation& v : kPathVariations)
      out.push_back(make_case(std::string(path_name) + " " + v.name, path, v.features));
  }
  for (const Variation& v : kCrossBilateralVariations) {
    out.push_back(make_case(std::string("cross-bilateral ") + v.name, SSS_PATH_FRAGMENT, v.features | kCrossBilateral));
  }
  const auto msaa = [&out](const Variation& v) {
    DigestCase c = make_case(std::string("msaa ") + v.name, SSS_PATH_AUTO, v.features);
    c.samples = 4;
    out.push_back(c);
  };
  for (const Variation& v : kPathVariations) {
    if ((v.features & ~kMsaaFeatures) == 0) msaa(v);
  }
  for (const Variation& v : kMsaaExtras) msaa(v);
  for (uint32_t view = 1; view <= SSS_DEBUG_VIEW_LAST; ++view) {
    for (const uint32_t path : {SSS_PATH_FRAGMENT, SSS_PATH_FRAGMENT_MASKED}) {
      const std::string name =
          "debug view " + std::to_string(view) + (path == SSS_PATH_FRAGMENT ? " fragment" : " masked");
      for (const unsigned profiles : {0u, static_cast<unsigned>(kProfilesR8)}) {
        DigestCase c = make_case(profiles != 0 ? name + " profiles" : name, path, kOutput | profiles);
        c.debug_view = view;
        out.push_back(c);
      }
    }
  }
  return out;
}

TEST_F(FrameDigests, EveryCase) {
  for (const DigestCase& c : cases()) {
    std::printf("digest %s:%s\n", c.name.c_str(), digest(c).c_str());
    std::fflush(stdout);
  }
}

}  // namespace
}  // namespace sss_test
