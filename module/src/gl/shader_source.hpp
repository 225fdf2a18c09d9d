// Shader sources assembled from parts. A stage's text is the dialect's header piece
// (module/shaders/version_*.glsl), the variant's #define lines, then the stage's own file, in which
// a line `#include "piece.glsl"` stands for that piece of module/shaders (GLSL has no #include in
// core, so the module expands it, from the embedded sources). Each part is numbered with #line, so
// that a driver's error points at the part and its own line, and the driver's log can be rewritten
// with the file names (name_log_sources). No GL here.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace sss::gl {

// A piece's text by its file name ("depth.glsl"); nullptr: no such piece.
using PieceLookup = std::function<const char*(const std::string& name)>;

// The pieces embedded from module/shaders (every file listed in module/CMakeLists.txt).
const char* embedded_piece(const std::string& name);

// What one stage is made of: file names of the dialect header and the stage's own file, and the
// variant's #define lines (may be empty).
struct ShaderRecipe {
  std::string header;   // "version_330.glsl": starts with the #version line
  std::string defines;  // "#define SSS_OUTSIDE 0\n..."
  std::string top;      // "separable_blur.frag"
};

// The numbers the assembler gives the parts: the header 0 (the #version line must come first,
// before any #line), the defines 1, the stage's file 2, then each included piece in the order it is
// first met. Part k's line n is `#line k·kPartLineStride + n k`: source string k, and k again in
// the line number, because Mesa reports source string 0 for an error it places on a grammar rule
// rather than a token (an undeclared identifier: its parser's YYLLOC_DEFAULT sets no source), while
// every driver keeps the line. So "2:20007" is line 7 of the stage's file, and so is Mesa's
// "0:20007". A part has fewer lines than the stride.
inline constexpr int kHeaderSourceString = 0;
inline constexpr int kDefinesSourceString = 1;
inline constexpr int kTopSourceString = 2;
inline constexpr int kPartLineStride = 10000;
// The name the defines go by in a log.
inline constexpr const char* kDefinesName = "<variant defines>";

struct AssembledShader {
  std::string text;                // what glShaderSource gets
  std::vector<std::string> files;  // index: a part's source-string number; value: its file name
};

// Assembles `recipe`: each piece included once (a later #include of the same piece is dropped);
// an #include of an unknown piece, a cyclic one, or one inside an #if group (whose skipped #line
// directives would leave the numbering wrong) is an error. Returns false with
// `error` set ("separable_blur.frag:12: unknown piece \"x.glsl\"").
bool assemble_shader(const ShaderRecipe& recipe, const PieceLookup& lookup, AssembledShader* out,
                     std::string* error);
inline bool assemble_shader(const ShaderRecipe& recipe, AssembledShader* out, std::string* error) {
  return assemble_shader(recipe, embedded_piece, out, error);
}

// A driver's info log with each message's location turned into the part's file name and its own
// line (the part from the line number, see kPartLineStride), as `file:line:`: Mesa's
// "2:20012(3): error: ..." -> "separable_blur.frag:12:3: error: ...", NVIDIA's
// "2(20012) : error C0000: ..." -> "separable_blur.frag:12: error C0000: ...", glslang's and AMD's
// "ERROR: 2:20012: ..." -> "ERROR: separable_blur.frag:12: ...". Lines in no such form, and
// locations outside `files`, stay as they are.
std::string name_log_sources(const std::string& log, const std::vector<std::string>& files);

}  // namespace sss::gl
