// The shader assembler (module/src/gl/shader_source.cpp): #include expanded once each, #line
// numbering that puts every line at its own file's line, errors for unknown, cyclic and
// conditional includes, and the driver's log rewritten with file names.
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "gl/shader_source.hpp"
#include "gl/shader_variants.hpp"

namespace {

using sss::gl::AssembledShader;
using sss::gl::ShaderRecipe;

// Pieces of a test's own, by name.
sss::gl::PieceLookup pieces(std::map<std::string, std::string> files) {
  return [files = std::move(files)](const std::string& name) -> const char* {
    const auto it = files.find(name);
    return it == files.end() ? nullptr : it->second.c_str();
  };
}

const std::map<std::string, std::string> kFiles = {
    {"head.glsl", "#version 330 core\n#define SSS_BINDING(unit)\n"},
    {"top.frag", "a\n#include \"p.glsl\"\nb\n  #  include \"p.glsl\"  \nc\n"},
    {"p.glsl", "p1\n#include \"q.glsl\"\np3\n"},
    {"q.glsl", "q1"},  // no final newline
};

TEST(ShaderSource, ExpandsEachIncludeOnceWithLineDirectives) {
  AssembledShader out;
  std::string error;
  ASSERT_TRUE(sss::gl::assemble_shader(ShaderRecipe{"head.glsl", "#define X 1\n", "top.frag"}, pieces(kFiles), &out,
                                       &error))
      << error;
  EXPECT_EQ(out.text,
            "#version 330 core\n#define SSS_BINDING(unit)\n"
            "#line 10001 1\n#define X 1\n"
            "#line 20001 2\na\n"
            "#line 30001 3\np1\n"
            "#line 40001 4\nq1\n"
            "#line 30003 3\np3\n"
            "#line 20003 2\nb\n"
            "#line 20005 2\nc\n");
  EXPECT_EQ(out.files, (std::vector<std::string>{"head.glsl", "<variant defines>", "top.frag", "p.glsl", "q.glsl"}));
}

TEST(ShaderSource, DefinesWithoutFinalNewlineKeepTheirLine) {
  AssembledShader out;
  ASSERT_TRUE(sss::gl::assemble_shader(ShaderRecipe{"head.glsl", "#define X 1", "q.glsl"}, pieces(kFiles), &out,
                                       nullptr));
  EXPECT_NE(out.text.find("#define X 1\n#line 20001 2\nq1\n"), std::string::npos) << out.text;
}

std::string assembly_error(const std::map<std::string, std::string>& files) {
  AssembledShader out;
  std::string error;
  EXPECT_FALSE(sss::gl::assemble_shader(ShaderRecipe{"head.glsl", "", "top.frag"}, pieces(files), &out, &error));
  return error;
}

TEST(ShaderSource, UnknownIncludeIsAnError) {
  std::map<std::string, std::string> files = kFiles;
  files["top.frag"] = "a\n#include \"nowhere.glsl\"\n";
  EXPECT_EQ(assembly_error(files), "top.frag:2: unknown piece \"nowhere.glsl\"");
}

TEST(ShaderSource, UnknownTopOrHeaderIsAnError) {
  AssembledShader out;
  std::string error;
  EXPECT_FALSE(sss::gl::assemble_shader(ShaderRecipe{"head.glsl", "", "none.frag"}, pieces(kFiles), &out, &error));
  EXPECT_EQ(error, "unknown piece \"none.frag\"");
}

TEST(ShaderSource, CyclicIncludeIsAnError) {
  std::map<std::string, std::string> files = kFiles;
  files["q.glsl"] = "q1\n#include \"p.glsl\"\n";
  EXPECT_EQ(assembly_error(files), "q.glsl:2: #include \"p.glsl\" is cyclic");
}

TEST(ShaderSource, IncludeInsideIfIsAnError) {
  std::map<std::string, std::string> files = kFiles;
  files["top.frag"] = "#if X\n#include \"q.glsl\"\n#endif\n";
  EXPECT_NE(assembly_error(files).find("top.frag:2: #include \"q.glsl\" inside #if"), std::string::npos);
  // After the group closes, an include is fine.
  files["top.frag"] = "#ifdef X\n#endif\n#include \"q.glsl\"\n";
  AssembledShader out;
  EXPECT_TRUE(sss::gl::assemble_shader(ShaderRecipe{"head.glsl", "", "top.frag"}, pieces(files), &out, nullptr));
}

TEST(ShaderSource, MalformedIncludeIsAnError) {
  std::map<std::string, std::string> files = kFiles;
  for (const char* line : {"#include <q.glsl>", "#include \"q.glsl\" x", "#include \"\"", "#include"}) {
    files["top.frag"] = std::string("a\n") + line + "\n";
    EXPECT_NE(assembly_error(files).find("top.frag:2: malformed #include"), std::string::npos) << line;
  }
}

// What a GLSL preprocessor makes of the #line directives: for every other line of `text`, the
// (part, line) its location names, checked against that line of that file.
void expect_every_line_at_home(const AssembledShader& shader, const sss::gl::PieceLookup& lookup) {
  std::istringstream text(shader.text);
  std::string line;
  int source = 0, number = 1;
  while (std::getline(text, line)) {
    int next_line = 0, next_source = 0;
    if (std::sscanf(line.c_str(), "#line %d %d", &next_line, &next_source) == 2) {
      // GLSL 3.30+ and ES 3.00: the line after `#line N` is line N. The part is in both numbers.
      EXPECT_EQ(next_line / sss::gl::kPartLineStride, next_source) << line;
      number = next_line % sss::gl::kPartLineStride;
      source = next_source;
      continue;
    }
    ASSERT_LT(static_cast<std::size_t>(source), shader.files.size());
    const std::string& file = shader.files[static_cast<std::size_t>(source)];
    if (source != sss::gl::kDefinesSourceString) {
      std::istringstream original(lookup(file));
      std::string expected;
      for (int i = 0; i < number; ++i) std::getline(original, expected);
      EXPECT_EQ(line, expected) << file << ':' << number;
    }
    ++number;
  }
}

TEST(ShaderSource, EveryLineOfTheEmbeddedShadersCarriesItsFileAndLine) {
  using namespace sss::gl;
  BlurVariant jittered;
  jittered.jitter = true;
  jittered.follow_surface = 2;
  const std::vector<ShaderRecipe> recipes = {
      stage_recipe(GlslVariant::essl300, "separable_blur.frag", blur_defines(jittered)),
      compute_recipe(compute_blur_defines(jittered, 0, ComputePass::vertical)),
      stage_recipe(GlslVariant::glsl420, "cbf_blur.frag", cbf_defines(BlurOutside::copy_original, false, true)),
      stage_recipe(GlslVariant::glsl330, "msaa_resolve.frag", msaa_resolve_defines(false, true)),
      stage_recipe(GlslVariant::glsl330, "lut_generate.frag", lut_defines(1)),
      vertex_recipe(GlslVariant::glsl330),
  };
  for (const ShaderRecipe& recipe : recipes) {
    AssembledShader out;
    std::string error;
    ASSERT_TRUE(assemble_shader(recipe, &out, &error)) << recipe.top << ": " << error;
    EXPECT_EQ(out.text.find("\n#include"), std::string::npos) << recipe.top;
    expect_every_line_at_home(out, embedded_piece);
  }
}

// The fragment passes (the filter and its debug views, each through blur_pixel.glsl, what a pass
// reads at its pixel) and the compute passes include the same pieces in the same order.
TEST(ShaderSource, TheBlurShadersShareTheirPieces) {
  using namespace sss::gl;
  const std::vector<std::string> shared = {"nearest_half.glsl", "colour_range.glsl",   "depth.glsl",
                                           "jitter.glsl",       "pass_surface.glsl",   "albedo.glsl",
                                           "footprint_taps.glsl", "footprint_cells.glsl"};
  BlurVariant view;
  view.debug_view = SSS_DEBUG_VIEW_TAPS;
  for (const BlurVariant& v : {BlurVariant{}, view}) {
    AssembledShader out;
    ASSERT_TRUE(
        assemble_shader(stage_recipe(GlslVariant::glsl330, blur_fragment_file(v), blur_defines(v)), &out, nullptr));
    std::vector<std::string> pieces(out.files.begin() + 3, out.files.end());
    ASSERT_FALSE(pieces.empty());
    EXPECT_EQ(pieces.front(), "blur_pixel.glsl") << blur_fragment_file(v);
    EXPECT_EQ(std::vector<std::string>(pieces.begin() + 1, pieces.end()), shared) << blur_fragment_file(v);
  }
  AssembledShader out;
  ASSERT_TRUE(assemble_shader(compute_recipe(compute_blur_defines(BlurVariant{}, 1, ComputePass::horizontal_marked)),
                              &out, nullptr));
  EXPECT_EQ(std::vector<std::string>(out.files.begin() + 3, out.files.end()), shared);
}

const std::vector<std::string> kNames = {"version_330.glsl", "<variant defines>", "separable_blur.frag", "depth.glsl"};

TEST(ShaderSource, NamesMesaLogLocations) {
  EXPECT_EQ(sss::gl::name_log_sources("0:12(3): error: syntax error, unexpected ';'\n"
                                      "3:30007(10): warning: unused\n",
                                      kNames),
            "version_330.glsl:12:3: error: syntax error, unexpected ';'\n"
            "depth.glsl:7:10: warning: unused\n");
  // Mesa's source string 0 on an error placed on a rule: the line still names the part.
  EXPECT_EQ(sss::gl::name_log_sources("0:20007(14): error: `undeclared_name' undeclared", kNames),
            "separable_blur.frag:7:14: error: `undeclared_name' undeclared");
}

TEST(ShaderSource, NamesNvidiaLogLocations) {
  EXPECT_EQ(sss::gl::name_log_sources("2(20041) : error C0000: syntax error, unexpected ';' at token \";\"\n"
                                      "3(30009) : warning C7050: \"d\" might be used before being initialized",
                                      kNames),
            "separable_blur.frag:41: error C0000: syntax error, unexpected ';' at token \";\"\n"
            "depth.glsl:9: warning C7050: \"d\" might be used before being initialized");
}

TEST(ShaderSource, NamesGlslangAndAmdLogLocations) {
  EXPECT_EQ(sss::gl::name_log_sources("ERROR: 1:10002: '#error' : injected\nERROR: 1 compilation errors.", kNames),
            "ERROR: <variant defines>:2: '#error' : injected\nERROR: 1 compilation errors.");
  EXPECT_EQ(sss::gl::name_log_sources("WARNING: 2:20005: 'x' : deprecated", kNames),
            "WARNING: separable_blur.frag:5: 'x' : deprecated");
}

TEST(ShaderSource, LeavesOtherLogLinesAlone) {
  for (const char* log : {"9:90012(3): error: no such part", "0:12 no colon after the line",
                          "error: 0:12: not at the start", "", "link error: 0(3) undefined", "12(3)"}) {
    EXPECT_EQ(sss::gl::name_log_sources(log, kNames), log);
  }
}

}  // namespace
