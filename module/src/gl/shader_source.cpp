#include "shader_source.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <utility>

#include "embedded_shaders.hpp"

namespace sss::gl {

const char* embedded_piece(const std::string& name) {
  for (const shaders::File& f : shaders::files) {
    if (name == f.name) return f.text;
  }
  return nullptr;
}

namespace {

// The `#line` directive that makes the next line part `number`'s line `line` (kPartLineStride).
std::string line_directive(int number, int line) {
  return "#line " + std::to_string(number * kPartLineStride + line) + ' ' + std::to_string(number) + '\n';
}

std::size_t skip_blanks(const std::string& s, std::size_t i) {
  while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
  return i;
}

// The directive word of a preprocessor line ("include", "if", ...), or "" for any other line.
std::string directive(const std::string& line, std::size_t* after) {
  std::size_t i = skip_blanks(line, 0);
  if (i >= line.size() || line[i] != '#') return "";
  i = skip_blanks(line, i + 1);
  const std::size_t start = i;
  while (i < line.size() && std::isalpha(static_cast<unsigned char>(line[i]))) ++i;
  *after = i;
  return line.substr(start, i - start);
}

// The piece named by `#include "name"` (the rest of the line after the word); false when the line
// is no such form.
bool include_target(const std::string& line, std::size_t after, std::string* name) {
  std::size_t i = skip_blanks(line, after);
  if (i >= line.size() || line[i] != '"') return false;
  const std::size_t close = line.find('"', i + 1);
  if (close == std::string::npos || close == i + 1) return false;
  *name = line.substr(i + 1, close - i - 1);
  return skip_blanks(line, close + 1) == line.size();
}

class Assembler {
 public:
  Assembler(const PieceLookup& lookup, AssembledShader* out) : lookup_(lookup), out_(out) {}

  // Appends `text` (part number `number`, file `name`) with its includes expanded.
  bool expand(const std::string& name, const char* text, int number) {
    open_.push_back(name);
    int line_number = 0, depth = 0;
    for (const char* p = text; *p != '\0';) {
      const char* end = std::strchr(p, '\n');
      const std::size_t length = end != nullptr ? static_cast<std::size_t>(end - p) : std::strlen(p);
      const std::string line(p, length);
      p += length + (end != nullptr ? 1 : 0);
      if (++line_number == kPartLineStride) return fail(name + ": too long for the #line numbering (kPartLineStride)");
      std::size_t after = 0;
      const std::string word = directive(line, &after);
      if (word == "if" || word == "ifdef" || word == "ifndef") ++depth;
      if (word == "endif") --depth;
      if (word != "include") {
        out_->text += line;
        out_->text += '\n';
        continue;
      }
      if (!include(name, line_number, line, after, depth)) return false;
      out_->text += line_directive(number, line_number + 1);
    }
    open_.pop_back();
    return true;
  }

  std::string error;

 private:
  bool fail(std::string message) {
    error = std::move(message);
    return false;
  }

  // One `#include` line of `name` at `line_number`: the piece (its own #line first), or nothing
  // when it is in already. The caller resumes the includer's numbering after it.
  bool include(const std::string& name, int line_number, const std::string& line, std::size_t after, int depth) {
    const std::string where = name + ':' + std::to_string(line_number) + ": ";
    std::string piece;
    if (!include_target(line, after, &piece)) return fail(where + "malformed #include (want #include \"piece.glsl\")");
    // In a skipped #if group the driver would skip the #line directives too, and every line number
    // after it would be off.
    if (depth != 0) return fail(where + "#include \"" + piece + "\" inside #if: include pieces at the top level");
    if (std::find(open_.begin(), open_.end(), piece) != open_.end()) {
      return fail(where + "#include \"" + piece + "\" is cyclic");
    }
    // Once each: the caller's #line takes the directive's place.
    if (std::find(out_->files.begin(), out_->files.end(), piece) != out_->files.end()) return true;
    const char* text = lookup_(piece);
    if (text == nullptr) return fail(where + "unknown piece \"" + piece + "\"");
    const int number = static_cast<int>(out_->files.size());
    out_->files.push_back(piece);
    out_->text += line_directive(number, 1);
    return expand(piece, text, number);
  }

  const PieceLookup& lookup_;
  AssembledShader* out_;
  std::vector<std::string> open_;  // the pieces being expanded, outermost first
};

}  // namespace

bool assemble_shader(const ShaderRecipe& recipe, const PieceLookup& lookup, AssembledShader* out,
                     std::string* error) {
  *out = AssembledShader{};
  out->files = {recipe.header, kDefinesName, recipe.top};
  const char* header = lookup(recipe.header);
  const char* top = lookup(recipe.top);
  if (header == nullptr || top == nullptr) {
    if (error) *error = "unknown piece \"" + (header == nullptr ? recipe.header : recipe.top) + "\"";
    return false;
  }
  Assembler assembler(lookup, out);
  // The header keeps source string 0 and line 1 (no #line may come before #version).
  bool ok = assembler.expand(recipe.header, header, kHeaderSourceString);
  if (ok) {
    out->text += line_directive(kDefinesSourceString, 1) + recipe.defines;
    if (!recipe.defines.empty() && recipe.defines.back() != '\n') out->text += '\n';
    out->text += line_directive(kTopSourceString, 1);
    ok = assembler.expand(recipe.top, top, kTopSourceString);
  }
  if (!ok && error) *error = assembler.error;
  return ok;
}

namespace {

// Reads the decimal number at `i`; false when there is none.
bool number_at(const std::string& s, std::size_t* i, unsigned long* value) {
  const std::size_t start = *i;
  unsigned long v = 0;
  while (*i < s.size() && std::isdigit(static_cast<unsigned char>(s[*i])) && *i - start < 9) {
    v = v * 10 + static_cast<unsigned long>(s[*i] - '0');
    ++*i;
  }
  *value = v;
  return *i > start;
}

// `line` with the location at `at` named, or "" when there is no location there. Forms:
// "S:L(C):" (Mesa), "S:L:" (glslang, AMD), "S(L) :" (NVIDIA). The part is the line's (S may be 0
// where it should not be: kPartLineStride).
std::string name_location(const std::string& line, std::size_t at, const std::vector<std::string>& files) {
  std::size_t i = at;
  unsigned long source = 0, line_number = 0, column = 0;
  if (!number_at(line, &i, &source) || i >= line.size()) return "";
  std::string column_text;
  if (line[i] == ':') {
    ++i;
    if (!number_at(line, &i, &line_number)) return "";
    if (i < line.size() && line[i] == '(') {  // Mesa's column
      ++i;
      if (!number_at(line, &i, &column) || i >= line.size() || line[i] != ')') return "";
      ++i;
      column_text = ':' + std::to_string(column);
    }
  } else if (line[i] == '(') {
    ++i;
    if (!number_at(line, &i, &line_number) || i >= line.size() || line[i] != ')') return "";
    i = skip_blanks(line, i + 1);
  } else {
    return "";
  }
  const unsigned long stride = static_cast<unsigned long>(kPartLineStride);
  const unsigned long part = line_number / stride;
  if (i >= line.size() || line[i] != ':' || part >= files.size()) return "";
  return line.substr(0, at) + files[part] + ':' + std::to_string(line_number % stride) + column_text + line.substr(i);
}

}  // namespace

std::string name_log_sources(const std::string& log, const std::vector<std::string>& files) {
  std::string out;
  std::size_t start = 0;
  while (start < log.size()) {
    std::size_t end = log.find('\n', start);
    if (end == std::string::npos) end = log.size();
    const std::string line = log.substr(start, end - start);
    std::string named = name_location(line, 0, files);
    for (const char* prefix : {"ERROR: ", "WARNING: "}) {
      const std::size_t length = std::strlen(prefix);
      if (named.empty() && line.compare(0, length, prefix) == 0) named = name_location(line, length, files);
    }
    out += named.empty() ? line : named;
    if (end < log.size()) out += '\n';
    start = end + 1;
  }
  return out;
}

}  // namespace sss::gl
