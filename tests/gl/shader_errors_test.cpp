// A compile error in an assembled shader names the file and line it is on, on the driver itself:
// the #line numbering of shader_source.cpp (GLSL 3.30+ and ES 3.00: the line after `#line N` is
// line N) and the log rewriting of gl::build_program. The errors are injected through test-only
// pieces given to the same assembler, so nothing of it ships in the library.
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>

#include "gl/program.hpp"
#include "gl/shader_variants.hpp"
#include "gl_fixture.hpp"

namespace {

namespace gl = sss::gl;

class ShaderErrors : public sss_test::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (HasFatalFailure()) return;
    gl::Api api;
    api.es = is_gles();
    api.major = 3;
    api.minor = api.es ? 0 : 3;  // the context GlTest makes
    std::string missing;
    ASSERT_TRUE(gl::load_functions(sss_headless_get_proc_address, headless_, api, &functions_, &missing)) << missing;
    dialect_ = gl::choose_glsl_variant(api, false);  // a 3.3 context: GLSL 3.30 either way
  }

  // Builds `top` (with `defines`) as a fragment stage after the full-screen vertex stage, the pieces
  // looked up in `test_pieces` first; returns the log of the failure it must be.
  std::string build_error(const std::string& top, const std::string& defines,
                          const std::map<std::string, std::string>& test_pieces) {
    const gl::PieceLookup lookup = [&test_pieces](const std::string& name) -> const char* {
      const auto it = test_pieces.find(name);
      return it != test_pieces.end() ? it->second.c_str() : gl::embedded_piece(name);
    };
    gl::AssembledShader vertex, fragment;
    std::string log;
    EXPECT_TRUE(gl::assemble_shader(gl::vertex_recipe(dialect_), lookup, &vertex, &log)) << log;
    EXPECT_TRUE(gl::assemble_shader(gl::stage_recipe(dialect_, top.c_str(), defines), lookup, &fragment, &log)) << log;
    const gl::GLuint program = gl::build_program(functions_, vertex, fragment, &log);
    EXPECT_EQ(program, 0u) << "the injected error compiled";
    if (program != 0) functions_.DeleteProgram(program);
    return log;
  }

  gl::Functions functions_;
  gl::GlslVariant dialect_ = gl::GlslVariant::glsl330;
};

// `text` with `inserted` put in as line `line` (1-based).
std::string insert_line(const std::string& text, int line, const std::string& inserted) {
  std::istringstream in(text);
  std::string out, l;
  for (int i = 1; std::getline(in, l); ++i) {
    if (i == line) out += inserted + '\n';
    out += l + '\n';
  }
  return out;
}

// The 1-based line of `text` that starts with `prefix`, or 0.
int line_of(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  std::string l;
  for (int i = 1; std::getline(in, l); ++i) {
    if (l.compare(0, prefix.size(), prefix) == 0) return i;
  }
  return 0;
}

TEST_F(ShaderErrors, AnErrorInAnIncludedPieceNamesThePieceAndItsLine) {
  // depth.glsl, included third by the blur (after the header, the defines and nearest_half.glsl),
  // with a syntax error as the first line of view_distance's body.
  const std::string depth = gl::embedded_piece("depth.glsl");
  const int line = line_of(depth, "float view_distance(") + 1;
  ASSERT_GT(line, 1);
  gl::BlurVariant variant;
  variant.follow_surface = 1;
  variant.jitter = true;
  const std::string log = build_error("separable_blur.frag", gl::blur_defines(variant),
                                      {{"depth.glsl", insert_line(depth, line, "  float broken = ;")}});
  EXPECT_NE(log.find("fragment shader: "), std::string::npos) << log;
  EXPECT_NE(log.find("depth.glsl:" + std::to_string(line) + ':'), std::string::npos) << log;
}

TEST_F(ShaderErrors, AnErrorAfterIncludesNamesTheTopFileAndItsLine) {
  // The includes' #line directives resume the top file's numbering after each piece.
  const std::string top =
      "// a test-only stage\n"                      // 1
      "#include \"nearest_half.glsl\"\n"            // 2
      "#include \"depth.glsl\"\n"                   // 3
      "out vec4 o_color;\n"                         // 4
      "void main() {\n"                             // 5
      "  o_color = vec4(view_distance(0.5));\n"     // 6
      "  o_color.x = undeclared_name;\n"            // 7
      "}\n";
  const std::string log =
      build_error("broken_stage.frag", "#define SSS_LINEAR_DEPTH 0\n", {{"broken_stage.frag", top}});
  EXPECT_NE(log.find("broken_stage.frag:7:"), std::string::npos) << log;
}

TEST_F(ShaderErrors, AnErrorInTheDefinesNamesThemAndTheirLine) {
  const std::string log = build_error("copy.frag", "#define SSS_A 1\n#define SSS_B = = ;\nint sss_c = SSS_B\n", {});
  EXPECT_NE(log.find("<variant defines>:3:"), std::string::npos) << log;
}

}  // namespace
