// sss_header_shape <header>...: checks that a public header reads like a spec sheet (ctest
// docs.runtime_header_shape, on sss.h and sss_common.h):
//   - no line is wider than 110 columns;
//   - one declaration per line: a struct field line declares one field, an enum line one enumerator;
//   - every public name has its own documentation comment: a field, an enumerator or a #define by a
//     trailing "/**<" comment on its line or a "/** ... */" block right above it; a function, a
//     typedef and a struct or enum by such a block right above it;
//   - every function that returns an sss_result lists its codes as "@retval" lines (SSS_OK among
//     them), never as one "@return" sentence.
// Prints every problem as "<header>:<line>: <what>" and exits 1 if there is any.
#include <cctype>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace {

constexpr std::size_t kMaxColumns = 110;

struct Line {
  std::string text;
  bool in_comment = false;  // the whole line lies inside a comment
};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

// Marks the lines that lie wholly inside a /* */ comment (a comment's continuation lines).
std::vector<Line> read_lines(const char* path, bool* ok) {
  std::ifstream in(path);
  *ok = in.good();
  std::vector<Line> lines;
  std::string text;
  bool open = false;
  while (std::getline(in, text)) {
    Line line;
    line.text = text;
    const std::string t = trim(text);
    line.in_comment = open || t.rfind("/*", 0) == 0;
    // Track whether a comment stays open past this line (only the last opener and closer matter
    // for the header's style: one comment per line at most).
    const auto opener = text.rfind("/*");
    const auto closer = text.rfind("*/");
    if (opener != std::string::npos && (closer == std::string::npos || closer < opener)) open = true;
    if (closer != std::string::npos && (opener == std::string::npos || closer > opener)) open = false;
    lines.push_back(line);
  }
  return lines;
}

class Checker {
 public:
  Checker(const char* path, std::vector<Line> lines) : path_(path), lines_(std::move(lines)) {}

  int run() {
    for (std::size_t i = 0; i < lines_.size(); ++i) check_line(i);
    return problems_;
  }

 private:
  void problem(std::size_t i, const std::string& what) {
    std::printf("%s:%zu: %s\n", path_, i + 1, what.c_str());
    ++problems_;
  }

  // A "/** ... */" block ends on the line right above line i (blank lines not allowed between).
  bool documented_above(std::size_t i) const {
    if (i == 0) return false;
    std::size_t j = i - 1;
    if (trim(lines_[j].text).find("*/") == std::string::npos) return false;
    while (true) {
      const std::string t = trim(lines_[j].text);
      if (t.rfind("/**", 0) == 0) return t.rfind("/**<", 0) != 0;
      if (!lines_[j].in_comment || j == 0) return false;
      --j;
    }
  }
  // The text of that block (for @retval), or "".
  std::string block_above(std::size_t i) const {
    if (!documented_above(i)) return "";
    std::string text;
    std::size_t j = i - 1;
    while (true) {
      text = lines_[j].text + "\n" + text;
      if (trim(lines_[j].text).rfind("/**", 0) == 0) return text;
      --j;
    }
  }
  static bool trailing_doc(const std::string& text) { return text.find("/**<") != std::string::npos; }
  static bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }
  static bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }
  // The name a "#define NAME ..." line defines, or "" for another line.
  static std::string defined_name(const std::string& code) {
    if (code.empty() || code[0] != '#') return "";
    const std::string rest = trim(code.substr(1));
    if (!starts_with(rest, "define")) return "";
    const std::string after = trim(rest.substr(6));
    std::size_t end = 0;
    while (end < after.size() && identifier_char(after[end])) ++end;
    return after.substr(0, end);
  }
  // The identifier right before the first '(' of a declaration, and the text before it.
  static bool function_name(const std::string& code, std::string* name, std::string* before) {
    if (!starts_with(code, "SSS_API")) return false;
    const std::size_t paren = code.find('(');
    if (paren == std::string::npos) return false;
    std::size_t end = paren;
    while (end > 0 && code[end - 1] == ' ') --end;
    std::size_t begin = end;
    while (begin > 0 && identifier_char(code[begin - 1])) --begin;
    *name = code.substr(begin, end - begin);
    *before = code.substr(0, begin);
    return !name->empty();
  }
  // Enumerators on an enum's line: the comma-separated pieces that start with a name.
  static int enumerators(const std::string& code) {
    int count = 0;
    std::size_t from = 0;
    while (from <= code.size()) {
      const std::size_t comma = code.find(',', from);
      const std::string piece = trim(code.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
      if (!piece.empty() && (std::isalpha(static_cast<unsigned char>(piece[0])) != 0 || piece[0] == '_')) ++count;
      if (comma == std::string::npos) break;
      from = comma + 1;
    }
    return count;
  }
  // The code before any comment on the line.
  static std::string code_of(const std::string& text) {
    const auto c = text.find("/*");
    return trim(c == std::string::npos ? text : text.substr(0, c));
  }

  void check_line(std::size_t i) {
    const std::string& text = lines_[i].text;
    if (text.size() > kMaxColumns) {
      problem(i, "line of " + std::to_string(text.size()) + " columns (at most " + std::to_string(kMaxColumns) + ")");
    }
    if (lines_[i].in_comment) return;
    const std::string code = code_of(text);
    if (code.empty()) return;
    const std::string name = defined_name(code);
    if (!name.empty()) {
      if (name == "SSS_API" || name.find("_H") == name.size() - 2) return;  // export macro, include guard
      if (!trailing_doc(text) && !documented_above(i)) problem(i, "#define " + name + " has no comment of its own");
      return;
    }
    if (code[0] == '#') return;  // other preprocessor lines
    if (code[0] == '}' && code.back() == ';') {
      if (code.find(';') != code.rfind(';')) problem(i, "the struct's closing line declares more");
      scope_ = Scope::none;
      return;
    }
    const bool opens = code.find('{') != std::string::npos;
    if (opens && (starts_with(code, "typedef enum") || starts_with(code, "typedef struct"))) {
      if (!documented_above(i)) problem(i, "a type without a comment of its own above it");
      if (code.find('}') != std::string::npos) problem(i, "a whole enum or struct on one line");
      scope_ = code.find("enum") != std::string::npos ? Scope::enumeration : Scope::structure;
      return;
    }
    if (scope_ == Scope::enumeration) {
      if (enumerators(code) > 1) problem(i, "several enumerators on one line: " + code);
      if (!trailing_doc(text) && !documented_above(i)) problem(i, "enumerator without a comment of its own: " + code);
      return;
    }
    if (scope_ == Scope::structure) {
      // One field: one ';' and no ',' outside brackets (an array's size is in brackets).
      int depth = 0, commas = 0, semicolons = 0;
      for (char c : code) {
        if (c == '[' || c == '(') ++depth;
        if (c == ']' || c == ')') --depth;
        if (c == ',' && depth == 0) ++commas;
        if (c == ';') ++semicolons;
      }
      if (commas > 0 || semicolons > 1) problem(i, "several fields on one line: " + code);
      if (!trailing_doc(text) && !documented_above(i)) problem(i, "field without a comment of its own: " + code);
      return;
    }
    std::string function, returns;
    if (function_name(code, &function, &returns)) {
      if (!documented_above(i)) {
        problem(i, function + "() has no comment of its own above it");
        return;
      }
      const std::string block = block_above(i);
      if (returns.find("sss_result") != std::string::npos) {
        if (block.find("@retval SSS_OK") == std::string::npos) problem(i, function + "(): no \"@retval SSS_OK\"");
        if (block.find("@return") != std::string::npos) problem(i, function + "(): codes in \"@return\", not \"@retval\"");
      }
      return;
    }
    if (starts_with(code, "typedef ")) {
      if (!documented_above(i)) problem(i, "a typedef without a comment of its own above it: " + code);
    }
  }

  enum class Scope { none, enumeration, structure };
  const char* path_;
  std::vector<Line> lines_;
  Scope scope_ = Scope::none;
  int problems_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: sss_header_shape <header>...\n");
    return 2;
  }
  int problems = 0;
  for (int a = 1; a < argc; ++a) {
    bool ok = false;
    std::vector<Line> lines = read_lines(argv[a], &ok);
    if (!ok) {
      std::fprintf(stderr, "%s: cannot read\n", argv[a]);
      return 2;
    }
    problems += Checker(argv[a], std::move(lines)).run();
  }
  if (problems == 0) std::printf("every line within %zu columns, one declaration each, every name documented\n", kMaxColumns);
  return problems == 0 ? 0 : 1;
}
