// sss_shader_variants <folder>: writes every shader stage the module can build, each assembled as
// the module assembles it (gl::assemble_shader on the recipes of gl/shader_variants.hpp, with the
// sizes of gl/shader_constants.hpp), for the shaders.glslang test (cmake/SssValidateShaders.cmake)
// to validate offline with glslangValidator. The variants are enumerated here, and only here; their
// switches and numbers come from the module.
//
// Each stage goes to <dialect>_<program>.<vert|frag|comp> (glslangValidator takes the stage from
// the extension and the profile from #version), and the names of its parts, one per line in the
// order of their numbers, to the same name + ".parts".
// sss_shader_variants --name-log <stage file>: the validator's log (stdin) with its locations named
// by the module's own gl::name_log_sources, from the stage's .parts.
// sss_shader_variants --tap-fetches: the texture fetches and image loads one tap of a preprocessed blur stage
// (stdin, glslangValidator -E) makes: those in sss_fetch_tap's body and in the bodies of the
// functions it calls (for the shaders.tap_fetches test, cmake/SssCountTapFetches.cmake).
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "gl/shader_constants.hpp"
#include "gl/shader_variants.hpp"
#include "sss/sss.h"

namespace {

namespace gl = sss::gl;

struct Writer {
  std::string folder;
  int written = 0;
  bool ok = true;
  // Every name written: two variants under one name would leave one of them unvalidated (the
  // second overwrites the first), as a new switch missing from its file name once did.
  std::set<std::string> names;

  void write(const std::string& name, const gl::ShaderRecipe& recipe) {
    if (!names.insert(name).second) {
      std::fprintf(stderr, "%s: a second variant under this name (its switches are not all in the name)\n",
                   name.c_str());
      ok = false;
      return;
    }
    gl::AssembledShader shader;
    std::string error;
    if (!gl::assemble_shader(recipe, &shader, &error)) {
      std::fprintf(stderr, "%s: %s\n", name.c_str(), error.c_str());
      ok = false;
      return;
    }
    std::ofstream text(folder + '/' + name);
    text << shader.text;
    std::ofstream parts(folder + '/' + name + ".parts");
    for (const std::string& file : shader.files) parts << file << '\n';
    if (!text || !parts) {
      std::fprintf(stderr, "%s: cannot write into %s\n", name.c_str(), folder.c_str());
      ok = false;
      return;
    }
    ++written;
  }
};

const char* dialect_prefix(gl::GlslVariant v) {
  switch (v) {
    case gl::GlslVariant::glsl420: return "420";
    case gl::GlslVariant::essl300: return "es300";
    case gl::GlslVariant::glsl330: break;
  }
  return "330";
}

std::string blur_name(const gl::BlurVariant& v) {
  char name[64];
  std::snprintf(name, sizeof name, "o%d_f%d_l%d_j%d_p%d_k%d", static_cast<int>(v.outside), v.follow_surface,
                v.linear_depth ? 1 : 0, v.jitter ? 1 : 0, v.profile_ids, v.packed_output ? 1 : 0);
  return name;
}

// The fragment-path programs of one dialect (each with the full-screen vertex stage, written once).
void write_dialect(Writer* out, gl::GlslVariant dialect) {
  const std::string d = std::string(dialect_prefix(dialect)) + '_';
  out->write(d + "fullscreen.vert", gl::vertex_recipe(dialect));
  // The masked path's: the vertex stage with its bands of tiles (the passes', the inputs'), the marks.
  out->write(d + "fullscreen_spans_passes.vert", gl::vertex_recipe(dialect, gl::TileSpans::passes));
  out->write(d + "fullscreen_spans_inputs.vert", gl::vertex_recipe(dialect, gl::TileSpans::inputs));
  for (const bool columns : {false, true}) {
    out->write(d + (columns ? "tile_mark_columns.frag" : "tile_mark.frag"),
               gl::stage_recipe(dialect, "tile_mark.frag", gl::tile_mark_defines(columns)));
  }
  // The tiles' marks reading the colour through the image unit (GLSL 4.20, as the inputs below).
  for (int image = 0; dialect == gl::GlslVariant::glsl420 && image < gl::kPassInputsColorImageFormats; ++image) {
    out->write(d + "tile_mark_" + gl::kComputeImageFormats[image].qualifier + ".frag",
               gl::stage_recipe(dialect, "tile_mark.frag", gl::tile_mark_defines(false, image)));
  }
  // The tiles debug view's fragment stages: the marks' (with the full-screen vertex stage) and the
  // band draws' (with the two band vertex stages above).
  out->write(d + "tile_view.frag", gl::stage_recipe(dialect, "tile_view.frag"));
  out->write(d + "tile_view_bands.frag", gl::stage_recipe(dialect, "tile_view.frag", "#define SSS_TILE_VIEW_BANDS 1\n"));
  out->write(d + "copy.frag", gl::stage_recipe(dialect, "copy.frag"));
  // The colour copy: every switch (the strength texture, each texturing mode, the index formats
  // that pick a profile's mode).
  for (int i = 0; i < gl::kColourCopyVariantCount; ++i) {
    const gl::ColourCopyVariant v = gl::colour_copy_variant_at(i);
    if (v.profile_ids != 0 && v.albedo != 3) continue;
    out->write(d + "colour_copy_s" + std::to_string(v.strength_texture ? 1 : 0) + "_a" + std::to_string(v.albedo) +
                   "_p" + std::to_string(v.profile_ids) + ".frag",
               gl::stage_recipe(dialect, "colour_copy.frag", gl::colour_copy_defines(v)));
  }
  // The texturing modes' last passes (SSS_ALBEDO): the vertical pass into the target, written back
  // and into a separate output, with each profile variant (3: per profile only with profiles).
  for (int albedo = 1; albedo <= 3; ++albedo) {
    for (int profile_ids = albedo == 3 ? 1 : 0; profile_ids < 3; ++profile_ids) {
      for (const gl::BlurOutside outside : {gl::BlurOutside::discard, gl::BlurOutside::copy_original}) {
        gl::BlurVariant v;
        v.follow_surface = 1;
        v.profile_ids = profile_ids;
        v.outside = outside;
        v.accumulate = profile_ids == 0;  // a kernel of several terms (one profile)
        v.albedo = albedo;
        out->write(d + "blur_albedo" + std::to_string(albedo) + "_" + blur_name(v) + ".frag",
                   gl::stage_recipe(dialect, gl::blur_fragment_file(v), gl::blur_defines(v)));
      }
    }
  }
  for (int albedo = 1; albedo <= 2; ++albedo) {
    for (int profile_ids = 0; profile_ids < 2; ++profile_ids) {
      const gl::HalfVariant v{profile_ids, albedo};
      out->write(d + "half_upsample_p" + std::to_string(profile_ids) + "_albedo" + std::to_string(albedo) + ".frag",
                 gl::stage_recipe(dialect, "half_upsample.frag", gl::half_upsample_defines(v)));
    }
    out->write(d + "cbf_o2_albedo" + std::to_string(albedo) + ".frag",
               gl::stage_recipe(dialect, "cbf_blur.frag", gl::cbf_defines(gl::BlurOutside::copy_original, false, false, albedo)));
  }
  // The inputs: every switch set with the colour read through the sampler; GLSL 4.20 also through
  // the image unit in each image format (what a GL 4.3+ context builds for a complete colour).
  for (int i = 0; i < gl::kPassInputsVariantCount; ++i) {
    const gl::PassInputsVariant v = gl::pass_inputs_variant_at(i);
    if (v.color_image >= 0 && dialect != gl::GlslVariant::glsl420) continue;
    if (v.albedo == 3 && v.profile_ids == 0) continue;  // a mode per profile needs the profiles
    out->write(d + "pass_inputs_l" + std::to_string(v.linear_depth ? 1 : 0) + "_p" + std::to_string(v.profile_ids) +
                   "_m" + std::to_string(v.mark_depth ? 1 : 0) +
                   (v.color_image >= 0 ? std::string("_") + gl::kComputeImageFormats[v.color_image].qualifier : "") +
                   "_a" + std::to_string(v.albedo) + ".frag",
               gl::stage_recipe(dialect, "pass_inputs.frag", gl::pass_inputs_defines(v)));
  }
  for (int i = 0; i < gl::kHalfVariantCount; ++i) {
    const gl::HalfVariant v = gl::half_variant_at(i);
    if (v.albedo != 0) continue;  // below, with the texturing modes' passes
    const std::string suffix = "_p" + std::to_string(v.profile_ids) + ".frag";
    out->write(d + "half_inputs" + suffix, gl::stage_recipe(dialect, "half_inputs.frag", gl::half_inputs_defines(v)));
    out->write(d + "half_upsample" + suffix,
               gl::stage_recipe(dialect, "half_upsample.frag", gl::half_upsample_defines(v)));
  }
  // Every switch set with the tap count as a uniform (any count but the presets'); the presets'
  // constant counts (the loop and spacing differ, the rest does not) on the written-back pair of
  // the default's switches, with and without jitter. GLSL 4.20: every one with its taps read
  // through the image unit (what a GL 4.3+ context builds, ProgramCache::blur), and the default pair
  // also through the sampler (a GL 4.2 context; the other dialects always read them so).
  for (int i = 0; i < gl::kBlurVariantCount; ++i) {
    gl::BlurVariant v = gl::blur_variant_at(i);
    if (!gl::is_fragment_blur_variant(v)) continue;
    const bool default_pair = v.follow_surface == 1 && v.profile_ids == 0 && !v.accumulate &&
                              (v.outside == gl::BlurOutside::discard || v.packed_output);
    const bool glsl420 = dialect == gl::GlslVariant::glsl420;
    for (const bool image_taps : {false, true}) {
      if (image_taps ? !glsl420 : glsl420 && !default_pair) continue;
      v.image_taps = image_taps;
      for (const int half_taps : {0, SSS_TAPS_LOW / 2, SSS_TAPS_MEDIUM / 2, SSS_TAPS_HIGH / 2}) {
        if (half_taps != 0 && !default_pair) continue;
        v.half_taps = half_taps;
        out->write(d + "blur_" + blur_name(v) + "_a" + (v.accumulate ? "1" : "0") + "_t" + std::to_string(half_taps) +
                       (image_taps ? "_i" : "") + ".frag",
                   gl::stage_recipe(dialect, gl::blur_fragment_file(v), gl::blur_defines(v)));
      }
    }
  }
  // The debug views the passes write (SSS_DEBUG_VIEW 1..5 and 7): the fragment passes' pair a view
  // runs (the horizontal pass packed, the vertical one into a separate output), with each per-pixel
  // profile variant, and the albedo view's vertical pass with each SSS_ALBEDO. The tiles view has
  // its own program, with each of its vertex stages below.
  for (const int view : {1, 2, 3, 4, 5, static_cast<int>(SSS_DEBUG_VIEW_ALBEDO)}) {
    for (int profile_ids = 0; profile_ids < 3; ++profile_ids) {
      for (const bool packed : {true, false}) {
        for (int albedo = 0; albedo <= (view == SSS_DEBUG_VIEW_ALBEDO && !packed ? 3 : 0); ++albedo) {
          if (albedo == 3 && profile_ids == 0) continue;  // per profile: only with profiles
          gl::BlurVariant v;
          v.follow_surface = 1;
          v.profile_ids = profile_ids;
          v.packed_output = packed;
          v.outside = packed ? gl::BlurOutside::write_centre : gl::BlurOutside::copy_original;
          v.debug_view = view;
          v.albedo = albedo;
          out->write(d + "blur_debug" + std::to_string(view) + "_albedo" + std::to_string(albedo) + "_" +
                         blur_name(v) + ".frag",
                     gl::stage_recipe(dialect, gl::blur_fragment_file(v), gl::blur_defines(v)));
        }
      }
    }
  }
  for (int outside = 0; outside < 3; ++outside) {
    for (int linear = 0; linear < 2; ++linear) {
      for (int normals = 0; normals < 2; ++normals) {
        const std::string defines = gl::cbf_defines(static_cast<gl::BlurOutside>(outside), linear != 0, normals != 0);
        out->write(d + "cbf_o" + std::to_string(outside) + "_l" + std::to_string(linear) + "_n" +
                       std::to_string(normals) + ".frag",
                   gl::stage_recipe(dialect, "cbf_blur.frag", defines));
      }
    }
  }
  if (gl::has_msaa_shaders(dialect)) {
    // SSS_ALBEDO 1 and 2 (a texturing mode over a multisampled albedo) add "_a1", "_a2".
    for (int albedo = 0; albedo < 3; ++albedo) {
      const std::string a = albedo == 0 ? "" : "_a" + std::to_string(albedo);
      for (int linear = 0; linear < 2; ++linear) {
        for (int write_back = 0; write_back < 2; ++write_back) {
          out->write(d + "msaa_resolve_l" + std::to_string(linear) + "_w" + std::to_string(write_back) + a + ".frag",
                     gl::stage_recipe(dialect, "msaa_resolve.frag",
                                      gl::msaa_resolve_defines(linear != 0, write_back != 0, albedo)));
        }
      }
      out->write(d + "msaa_write" + a + ".frag",
                 gl::stage_recipe(dialect, "msaa_write.frag", gl::msaa_write_defines(dialect, albedo)));
    }
    out->write(d + "msaa_mask.frag", gl::stage_recipe(dialect, "msaa_mask.frag"));
  }
  for (int kind = 0; kind < 2; ++kind) {
    out->write(d + "lut_generate_k" + std::to_string(kind) + ".frag",
               gl::stage_recipe(dialect, "lut_generate.frag", gl::lut_defines(kind)));
  }
}

// The compute path's blur (GLSL 4.30): every variant but per-pixel profiles × every target image
// format × its passes (the horizontal ones never accumulate).
void write_compute(Writer* out) {
  const char* const pass_names[gl::kComputePassCount] = {"h", "hm", "v"};
  for (int i = 0; i < gl::kBlurVariantCount; ++i) {
    const gl::BlurVariant v = gl::blur_variant_at(i);
    if (!gl::is_compute_blur_variant(v)) continue;  // per-pixel profiles run on the fragment passes
    for (int pass = 0; pass < gl::kComputePassCount; ++pass) {
      if (v.accumulate && pass != static_cast<int>(gl::ComputePass::vertical)) continue;
      for (int format = 0; format < gl::kComputeImageFormatCount; ++format) {
        out->write("430_blur_compute_" + blur_name(v) + "_a" + (v.accumulate ? "1_" : "0_") + pass_names[pass] + '_' +
                       gl::kComputeImageFormats[format].qualifier + ".comp",
                   gl::compute_recipe(gl::compute_blur_defines(v, format, static_cast<gl::ComputePass>(pass))));
      }
    }
  }
  // The texturing modes' last vertical pass (SSS_ALBEDO 1 and 2), written back and into an output.
  for (int albedo = 1; albedo <= 2; ++albedo) {
    for (const gl::BlurOutside outside : {gl::BlurOutside::discard, gl::BlurOutside::copy_original}) {
      gl::BlurVariant v;
      v.follow_surface = 1;
      v.outside = outside;
      v.albedo = albedo;
      out->write("430_blur_compute_albedo" + std::to_string(albedo) + "_" + blur_name(v) + "_v_rgba16f.comp",
                 gl::compute_recipe(gl::compute_blur_defines(v, 0, gl::ComputePass::vertical)));
    }
  }
  // Tiles of several lines (SSS_LINES > 1, several pixels per invocation), which the shader keeps
  // for hardware that prefers them (shader_constants.hpp), on the default's switches.
  constexpr gl::ComputeTile lines{128, 8, 56};
  static_assert(gl::compute_shared_bytes(lines) <= 32768);
  for (int pass = 0; pass < gl::kComputePassCount; ++pass) {
    gl::BlurVariant v;
    v.follow_surface = 1;
    v.outside = pass == static_cast<int>(gl::ComputePass::vertical) ? gl::BlurOutside::discard
                                                                    : gl::BlurOutside::write_centre;
    out->write(std::string("430_blur_compute_lines8_") + pass_names[pass] + ".comp",
               gl::compute_recipe(gl::compute_blur_defines(v, 0, static_cast<gl::ComputePass>(pass), &lines)));
  }
}

// Prints stdin with the locations named after `stage`'s parts.
int name_log(const std::string& stage) {
  std::ifstream parts(stage + ".parts");
  std::vector<std::string> files;
  for (std::string line; std::getline(parts, line);) files.push_back(line);
  std::ostringstream log;
  log << std::cin.rdbuf();
  std::cout << gl::name_log_sources(log.str(), files);
  return files.empty() ? 1 : 0;
}

// The body of function `name` in `text` (between its definition's braces), or "" where it is not defined.
std::string function_body(const std::string& text, const std::string& name) {
  for (std::size_t at = text.find(name + '('); at != std::string::npos; at = text.find(name + '(', at + 1)) {
    const std::size_t close = text.find(')', at);
    const std::size_t open = text.find_first_not_of(" \t\n", close + 1);
    if (close == std::string::npos || open == std::string::npos || text[open] != '{') continue;  // a call
    int depth = 0;
    for (std::size_t i = open; i < text.size(); ++i) {
      if (text[i] == '{') ++depth;
      if (text[i] == '}' && --depth == 0) return text.substr(open, i - open + 1);
    }
  }
  return "";
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Fetches (texelFetch, texture) of sss_fetch_tap, following the calls it makes one level down into
// the stage's own sss_* functions.
int tap_fetches() {
  std::ostringstream in;
  in << std::cin.rdbuf();
  const std::string text = in.str();
  const std::string body = function_body(text, "sss_fetch_tap");
  if (body.empty()) return -1;
  const auto fetches = [](const std::string& b) {
    return count(b, "texelFetch(") + count(b, "texture(") + count(b, "imageLoad(");
  };
  int n = fetches(body);
  for (std::size_t at = body.find("sss_"); at != std::string::npos; at = body.find("sss_", at + 1)) {
    const std::size_t end = body.find('(', at);
    if (end == std::string::npos) break;
    const std::string callee = body.substr(at, end - at);
    if (callee.find_first_of(" ,;=.)") != std::string::npos || callee == "sss_fetch_tap") continue;
    n += fetches(function_body(text, callee));
  }
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "--name-log") == 0) return name_log(argv[2]);
  if (argc == 2 && std::strcmp(argv[1], "--tap-fetches") == 0) {
    const int n = tap_fetches();
    std::printf("%d\n", n);
    return n < 0 ? 1 : 0;
  }
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <folder> | --name-log <stage file>\n", argv[0]);
    return 2;
  }
  Writer out;
  out.folder = argv[1];
  for (gl::GlslVariant dialect : {gl::GlslVariant::glsl330, gl::GlslVariant::glsl420, gl::GlslVariant::essl300}) {
    write_dialect(&out, dialect);
  }
  write_compute(&out);
  std::printf("%d shader stages written to %s\n", out.written, out.folder.c_str());
  return out.ok ? 0 : 1;
}
