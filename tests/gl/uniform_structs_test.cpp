// Uniforms as one struct per pass kind (issue 47, module/src/gl/pass_uniforms.hpp): every per-draw
// number a program of the module reads is a field of its pass kind's struct, declared from the
// struct's table, so a new uniform touches one table. Asked of the GL itself: after sss_prepare for
// every path, mode, texturing mode, per-pixel profiles and (desktop) MSAA, each program the module
// linked is listed with glGetActiveUniform, and every active uniform outside a uniform block must
// be a sampler or image, a field of one of the structs, a table (an array), or the vertex stage's
// tile spans: a hand-declared scalar (`uniform float u_new;` in a shader) fails it. And the
// lookups: where the dialect has explicit uniform locations (GLSL 4.20 with
// GL_ARB_explicit_uniform_location) no field is looked up by name, one glGetUniformIndices call per
// struct says which fields a program uses, and every glGetUniformLocation is a sampler or a table,
// each once per program; GLSL ES 3.00 has no explicit locations, so there each field is looked up
// once per program.
//   UniformStructs.*  every backend
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "filter_case.hpp"
#include "sss/sss_lut.h"
#include "gl/gl_functions.hpp"
#include "gl/pass_uniforms.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

constexpr int kW = 32, kH = 24;

constexpr const sss::gl::UniformStruct* kStructs[] = {
    &sss::gl::kBlurUniforms,       &sss::gl::kCbfUniforms,        &sss::gl::kInputsUniforms,
    &sss::gl::kColourCopyUniforms, &sss::gl::kResolveUniforms,    &sss::gl::kSampleWriteUniforms,
    &sss::gl::kHalfInputsUniforms, &sss::gl::kUpsampleUniforms,   &sss::gl::kLutUniforms};

// Every field name of every pass kind's struct, from the tables themselves.
std::set<std::string> struct_fields() {
  std::set<std::string> names;
  for (const sss::gl::UniformStruct* s : kStructs) {
    for (std::size_t i = 0; i < s->count; ++i) names.insert(s->fields[i].glsl_name);
  }
  return names;
}

// The name of each struct's one array (the GLSL ES 3.00 form).
std::set<std::string> struct_arrays() {
  std::set<std::string> names;
  for (const sss::gl::UniformStruct* s : kStructs) names.insert(s->glsl_array);
  return names;
}

// Tables (arrays the passes index) and the tile spans' one vec4 of the vertex stage
// (fullscreen.vert), which the tile marks' and the tiles view's u_rect are alike: their programs'
// one number. (u_spacing and u_rect are fields of other pass kinds' structs too.)
const std::set<std::string> kOwn = {"u_cdf",       "u_spacing",      "u_profile",   "u_looks",
                                    "u_texturing", "u_depth_factor", "u_tile_grid", "u_rect"};

bool is_sampler_or_image(GLenum type) {
  switch (type) {
    case GL_SAMPLER_2D: case GL_INT_SAMPLER_2D: case GL_UNSIGNED_INT_SAMPLER_2D: case GL_SAMPLER_2D_SHADOW:
    case GL_SAMPLER_2D_MULTISAMPLE: case GL_INT_SAMPLER_2D_MULTISAMPLE:
    case GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE: case GL_IMAGE_2D: case GL_INT_IMAGE_2D:
    case GL_UNSIGNED_INT_IMAGE_2D:
      return true;
    default: return false;
  }
}

// The uniforms of the module's programs that exist now which are none of the above (a struct's
// field or its one array, a table, a sampler or image), as "program N: name", and the count of
// programs looked at.
std::vector<std::string> loose_uniforms(const std::set<std::string>& fields, const std::set<std::string>& arrays,
                                        int* programs) {
  std::vector<std::string> loose;
  for (GLuint program = 1; program < 4096; ++program) {
    if (glIsProgram(program) != GL_TRUE) continue;
    ++*programs;
    GLint count = 0;
    glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    for (GLuint i = 0; i < static_cast<GLuint>(count); ++i) {
      char name[128] = {};
      GLint size = 0, block = -1;
      GLenum type = 0;
      glGetActiveUniform(program, i, sizeof name, nullptr, &size, &type, name);
      glGetActiveUniformsiv(program, 1, &i, GL_UNIFORM_BLOCK_INDEX, &block);
      std::string n = name;
      if (n.size() > 3 && n.compare(n.size() - 3, 3, "[0]") == 0) n.resize(n.size() - 3);
      if (block >= 0 || is_sampler_or_image(type) || fields.count(n) != 0 || kOwn.count(n) != 0 ||
          arrays.count(n) != 0) {
        continue;
      }
      loose.push_back("program " + std::to_string(program) + ": " + n);
    }
  }
  return loose;
}

// The module's glGetUniformLocation calls (by program, the names in order) and its
// glGetUniformIndices calls (by program, how many), recorded by a loader that wraps the two.
using LocationFn = sss::gl::GLint(SSS_GL_APIENTRY*)(sss::gl::GLuint, const sss::gl::GLchar*);
using IndicesFn = void(SSS_GL_APIENTRY*)(sss::gl::GLuint, sss::gl::GLsizei, const sss::gl::GLchar* const*,
                                         sss::gl::GLuint*);
struct Lookups {
  std::map<GLuint, std::vector<std::string>> located;
  std::map<GLuint, int> indexed;
  LocationFn real_location = nullptr;
  IndicesFn real_indices = nullptr;
  sss_get_proc_address_fn base = nullptr;
};
Lookups g_lookups;

sss::gl::GLint SSS_GL_APIENTRY recorded_location(sss::gl::GLuint program, const sss::gl::GLchar* name) {
  g_lookups.located[program].push_back(name);
  return g_lookups.real_location(program, name);
}

void SSS_GL_APIENTRY recorded_indices(sss::gl::GLuint program, sss::gl::GLsizei count,
                                      const sss::gl::GLchar* const* names, sss::gl::GLuint* indices) {
  ++g_lookups.indexed[program];
  g_lookups.real_indices(program, count, names, indices);
}

void* recording_loader(const char* name, void* user) {
  void* real = g_lookups.base(name, user);
  if (std::strcmp(name, "glGetUniformLocation") == 0) {
    g_lookups.real_location = reinterpret_cast<LocationFn>(real);
    return reinterpret_cast<void*>(&recorded_location);
  }
  if (std::strcmp(name, "glGetUniformIndices") == 0) {
    g_lookups.real_indices = reinterpret_cast<IndicesFn>(real);
    return reinterpret_cast<void*>(&recorded_indices);
  }
  return real;
}

struct Prepared {
  const char* name;
  sss_settings settings;
  std::uint32_t albedo_format = 0, profile_format = 0;
  int samples = 0;
  std::uint32_t output_format = 0;
};

class UniformStructs : public FilterCaseTest {
 protected:
  // Every path, each with post-scatter and with a separate output; per-pixel profiles with
  // pre-and-post-scatter; the half-resolution path; (desktop) MSAA in place and into an output.
  std::vector<Prepared> preparations() const;
  // A fresh context with `c`'s settings, prepared for `c`'s frames.
  void prepare(const Prepared& c, const float* projection);
};

std::vector<Prepared> UniformStructs::preparations() const {
  std::vector<Prepared> cases;
  for (const PathCase& p : kEveryPath) {
    const sss_settings s = path_case_settings(visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f), p.path, p.mode,
                                              p.two_terms);
    cases.push_back({p.name, s});
    Prepared post{p.name, s, SSS_GL_RGBA16F};
    post.settings.texturing = SSS_TEXTURING_POST_SCATTER;
    cases.push_back(post);
    Prepared output{p.name, s};
    output.output_format = SSS_GL_RGBA16F;
    cases.push_back(output);
  }
  Prepared profiles{"per-pixel profiles", visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f)};
  profiles.profile_format = SSS_GL_R8UI;
  profiles.albedo_format = SSS_GL_RGBA16F;
  profiles.settings.texturing = SSS_TEXTURING_PRE_AND_POST_SCATTER;
  cases.push_back(profiles);
  Prepared gaussian{"sum of Gaussians, half resolution", visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f)};
  gaussian.settings.path = SSS_PATH_HALF_RESOLUTION;
  cases.push_back(gaussian);
  if (!is_gles()) {  // the MSAA path is desktop OpenGL only
    Prepared msaa{"MSAA", visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f)};
    msaa.samples = 4;
    cases.push_back(msaa);
    msaa.output_format = SSS_GL_RGBA16F;
    cases.push_back(msaa);
  }
  return cases;
}

void UniformStructs::prepare(const Prepared& c, const float* projection) {
  fresh_sss(c.settings, projection);
  if (c.profile_format != 0) {
    const sss_settings two[2] = {c.settings, c.settings};
    ASSERT_EQ(sss_set_profiles(sss_, two, 2), SSS_OK) << sss_last_error(sss_);
  }
  sss_prepare_desc d = {};
  d.struct_size = sizeof d;
  d.width = kW;
  d.height = kH;
  d.color_format = SSS_GL_RGBA16F;
  d.output_format = c.output_format;
  d.depth_format = SSS_GL_DEPTH_COMPONENT32F;
  d.samples = c.samples;
  d.albedo_format = c.albedo_format;
  d.profile_format = c.profile_format;
  ASSERT_EQ(sss_prepare(sss_, &d), SSS_OK) << sss_last_error(sss_);
}

TEST_F(UniformStructs, EveryProgramReadsItsNumbersFromItsStructOrATable) {
  const std::set<std::string> fields = struct_fields();
  const std::set<std::string> arrays = struct_arrays();
  const SyntheticScene scene = make_relief_scene(kW, kH, 5, perspective_matrix(40.0f, 32.0f / 24.0f, 0.1f, 10.0f));
  const std::vector<Prepared> cases = preparations();
  int programs = 0;
  for (const Prepared& c : cases) {
    SCOPED_TRACE(c.name);
    prepare(c, scene.projection.data());
    if (HasFatalFailure()) return;
    int built = 0;
    const std::vector<std::string> loose = loose_uniforms(fields, arrays, &built);
    programs += built;
    for (const std::string& l : loose) ADD_FAILURE() << "a uniform outside its pass kind's struct: " << l;
  }
  std::printf("%zu preparations, %d programs looked at\n", cases.size(), programs);
  EXPECT_GT(programs, static_cast<int>(cases.size()) * 3) << "too few programs were built for the check to say much";
}

// What the module looked up since the last clear, by kind: struct fields (none may be), struct
// arrays (one per program on GLSL ES 3.00), anything else (samplers, tables); glGetUniformIndices
// calls (one per program with a struct, where locations are explicit).
struct LookupTally {
  int fields = 0, arrays = 0, others = 0, index_calls = 0;
};

void tally_lookups(const std::set<std::string>& fields, const std::set<std::string>& arrays, LookupTally* t) {
  for (const auto& [program, names] : g_lookups.located) {
    std::set<std::string> seen;
    for (const std::string& n : names) {
      EXPECT_TRUE(seen.insert(n).second) << "program " << program << " looked " << n << " up twice";
      const bool field = fields.count(n) != 0 && kOwn.count(n) == 0;
      EXPECT_FALSE(field) << "program " << program << " looked its struct's field " << n << " up";
      (field ? t->fields : arrays.count(n) != 0 ? t->arrays : t->others) += 1;
    }
  }
  for (const auto& [program, calls] : g_lookups.indexed) {
    EXPECT_EQ(calls, 1) << "program " << program << ": one glGetUniformIndices for its struct";
    t->index_calls += calls;
  }
  g_lookups.located.clear();
  g_lookups.indexed.clear();
}

TEST_F(UniformStructs, FieldsAreFoundWithoutALookupEach) {
  const std::set<std::string> fields = struct_fields();
  const std::set<std::string> arrays = struct_arrays();
  const SyntheticScene scene = make_relief_scene(kW, kH, 5, perspective_matrix(40.0f, 32.0f / 24.0f, 0.1f, 10.0f));
  g_lookups = Lookups{};
  g_lookups.base = is_gles() ? es30_get_proc_address : sss_headless_get_proc_address;
  loader_override_ = recording_loader;
  LookupTally tally;
  for (const Prepared& c : preparations()) {
    SCOPED_TRACE(c.name);
    prepare(c, scene.projection.data());
    if (HasFatalFailure()) return;
    tally_lookups(fields, arrays, &tally);
  }
  // The LUT generator, which sss_lut_create_texture links, draws with and deletes each time.
  {
    SCOPED_TRACE("the LUT generator");
    sss_lut_desc desc;
    sss_lut_default_desc(&desc);
    desc.width = 8;
    desc.height = 4;
    for (const int32_t which : {SSS_LUT_DIFFUSE, SSS_LUT_SHADOW}) {
      uint32_t texture = 0;
      ASSERT_EQ(sss_lut_create_texture(sss_, which, &desc, &texture), SSS_OK) << sss_last_error(sss_);
    }
    EXPECT_EQ(g_lookups.located.size(), 2u) << "the two generators' lookups";
    tally_lookups(fields, arrays, &tally);
  }
  sss_stats stats = {};
  stats.struct_size = sizeof stats;
  ASSERT_EQ(sss_get_stats(sss_, &stats), SSS_OK);
  loader_override_ = nullptr;
  std::printf("glGetUniformLocation: %d for struct fields, %d for struct arrays, %d for samplers and tables; "
              "glGetUniformIndices: %d\n", tally.fields, tally.arrays, tally.others, tally.index_calls);
  EXPECT_EQ(tally.fields, 0);
  if (stats.glsl_variant == SSS_GLSL_300_ES) {
    EXPECT_GT(tally.arrays, 0) << "GLSL ES 3.00 declares each struct as one array";
    EXPECT_EQ(tally.index_calls, 0);
  } else {
    EXPECT_EQ(tally.arrays, 0);
    EXPECT_GT(tally.index_calls, 0) << "no program found its fields by index";
  }
}

}  // namespace
}  // namespace sss_test
