// sss_docs names: every public name of <sss/sss.h> and the headers it includes (functions, types,
// struct fields, enumerators, macros) is written as code in docs/integration.md (ctest
// docs.guide_names); a field counts as `struct.field`, or as a field in a paragraph, table or code
// block that names its struct. Why: a name added to the header and not to the guide is an API a
// host finds only by reading the header, and the guide is where a host starts.
// sss_docs names-selftest: the header parser on a packed and a one-declaration-a-line layout of one
// small header, and the guide's rules on a small guide (ctest docs.guide_names_parser). Why: a
// parser that misses names after the header is reformatted would make the check pass by finding
// less.
#include "sss_docs_names.hpp"

#include <cctype>
#include <chrono>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "sss_docs_text.hpp"

namespace sss_docs {
namespace {

// One public name of the header: a function, a type, a struct's field, an enumerator or a macro.
struct PublicName {
  std::string name;   // the identifier
  std::string kind;   // "function", "type", "field", "enumerator", "macro", "variable"
  std::string owner;  // a field's struct (its typedef name, else its tag); empty otherwise
  std::string where;  // file:line
  std::string display() const { return owner.empty() ? name : owner + "." + name; }
};

struct Token {
  std::string text;
  int line = 0;
  bool identifier() const {
    return !text.empty() && (std::isalpha(static_cast<unsigned char>(text[0])) || text[0] == '_');
  }
};

// The text with its comments blanked out (newlines kept, so that line numbers hold); string and
// character literals are kept whole.
std::string without_comments(const std::string& text) {
  std::string out = text;
  for (std::size_t i = 0; i < out.size();) {
    const char c = out[i];
    if (c == '"' || c == '\'') {
      for (++i; i < out.size() && out[i] != c && out[i] != '\n'; ++i) {
        if (out[i] == '\\') ++i;
      }
      ++i;
    } else if (c == '/' && i + 1 < out.size() && out[i + 1] == '*') {
      const std::size_t end = out.find("*/", i + 2);
      const std::size_t stop = end == std::string::npos ? out.size() : end + 2;
      for (std::size_t j = i; j < stop; ++j) {
        if (out[j] != '\n') out[j] = ' ';
      }
      i = stop;
    } else if (c == '/' && i + 1 < out.size() && out[i + 1] == '/') {
      for (; i < out.size() && out[i] != '\n'; ++i) out[i] = ' ';
    } else {
      ++i;
    }
  }
  return out;
}

std::vector<Token> tokenize(const std::string& code, int first_line) {
  std::vector<Token> tokens;
  int line = first_line;
  for (std::size_t i = 0; i < code.size();) {
    const unsigned char c = static_cast<unsigned char>(code[i]);
    if (c == '\n') {
      ++line;
      ++i;
    } else if (std::isspace(c)) {
      ++i;
    } else if (std::isalnum(c) || c == '_') {  // identifiers and numbers (a pp-number: 0x1u, 1e6f)
      std::size_t e = i;
      while (e < code.size() && (std::isalnum(static_cast<unsigned char>(code[e])) || code[e] == '_' ||
                                 (std::isdigit(c) && code[e] == '.'))) {
        ++e;
      }
      tokens.push_back({code.substr(i, e - i), line});
      i = e;
    } else if (c == '"' || c == '\'') {
      std::size_t e = i + 1;
      for (; e < code.size() && code[e] != static_cast<char>(c) && code[e] != '\n'; ++e) {
        if (code[e] == '\\') ++e;
      }
      tokens.push_back({code.substr(i, e + 1 - i), line});
      i = e + 1;
    } else {
      tokens.push_back({std::string(1, static_cast<char>(c)), line});
      ++i;
    }
  }
  return tokens;
}

using Tokens = std::vector<Token>;

// The tokens split at `separator` outside (), [] and {}.
std::vector<Tokens> split_top_level(const Tokens& tokens, const std::string& separator) {
  std::vector<Tokens> parts(1);
  int depth = 0;
  for (const Token& t : tokens) {
    if (t.text == "(" || t.text == "[" || t.text == "{") ++depth;
    if (t.text == ")" || t.text == "]" || t.text == "}") --depth;
    if (depth == 0 && t.text == separator) {
      parts.emplace_back();
      continue;
    }
    parts.back().push_back(t);
  }
  if (parts.back().empty()) parts.pop_back();
  return parts;
}

// Index of the first `open` at depth 0 and its matching close, or npos.
std::pair<std::size_t, std::size_t> top_level_group(const Tokens& tokens, const std::string& open,
                                                    const std::string& close) {
  int depth = 0;
  std::size_t begin = std::string::npos;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::string& s = tokens[i].text;
    if (s == "(" || s == "[" || s == "{") {
      if (depth == 0 && s == open && begin == std::string::npos) begin = i;
      ++depth;
    } else if (s == ")" || s == "]" || s == "}") {
      --depth;
      if (depth == 0 && s == close && begin != std::string::npos) return {begin, i};
    }
  }
  return {std::string::npos, std::string::npos};
}

class HeaderNames {
 public:
  std::vector<PublicName> names;

  void read(const fs::path& header, const std::string& shown) {
    if (!visited_.insert(fs::weakly_canonical(header).generic_string()).second) return;
    const std::string text = without_comments(read_text(header));
    const std::vector<std::string> lines = split_lines(text);
    std::string code;  // the lines outside directives and C++-only blocks; blank lines keep the count
    // #if nesting: whether each level is a `#ifdef __cplusplus`-like block, and whether it is skipped.
    struct Level {
      bool cplusplus;
      bool skipped;
    };
    std::vector<Level> levels;
    const auto skipping = [&levels] { return !levels.empty() && levels.back().skipped; };
    std::string guard;  // the include guard: the first directive is `#ifndef X`, the second `#define X`
    int directives = 0;
    for (std::size_t n = 0; n < lines.size(); ++n) {
      std::string line = lines[n];
      const int line_number = static_cast<int>(n) + 1;
      std::size_t joined = 0;
      while (!line.empty() && line.back() == '\\' && n + 1 < lines.size()) {
        line.pop_back();
        line += " " + lines[++n];
        ++joined;
      }
      const std::string t = trim(line);
      if (!starts_with(t, "#")) {
        code += skipping() ? "" : line;
        code += std::string(joined + 1, '\n');
        continue;
      }
      code += std::string(joined + 1, '\n');
      std::istringstream words(t.substr(1));
      std::string directive, argument;
      words >> directive >> argument;
      const bool is_cplusplus = argument.find("__cplusplus") != std::string::npos;
      ++directives;
      if (directives == 1 && directive == "ifndef") guard = argument;
      if (directives == 2 && !(directive == "define" && argument == guard)) guard.clear();
      if (directive == "if" || directive == "ifdef" || directive == "ifndef") {
        const bool parent = skipping();
        // `#ifdef __cplusplus` / `#if defined(__cplusplus)`: C++ only, not the C API; its #else is.
        const bool cpp_only = is_cplusplus && directive != "ifndef" && t.find('!') == std::string::npos;
        levels.push_back({is_cplusplus, parent || cpp_only});
      } else if (directive == "else" || directive == "elif") {
        if (!levels.empty() && levels.back().cplusplus) {
          const bool parent = levels.size() > 1 && levels[levels.size() - 2].skipped;
          levels.back().skipped = parent || !levels.back().skipped;
        }
      } else if (directive == "endif") {
        if (!levels.empty()) levels.pop_back();
      } else if (directive == "include" && !skipping()) {
        const std::size_t q = t.find('"');
        const std::size_t e = q == std::string::npos ? q : t.find('"', q + 1);
        if (e != std::string::npos) {  // "..." only: <...> is a system header
          const std::string included = t.substr(q + 1, e - q - 1);
          const fs::path dir = header.parent_path();
          const std::string shown_dir = fs::path(shown).parent_path().generic_string();
          read(dir / included, shown_dir.empty() ? included : shown_dir + "/" + included);
        }
      } else if (directive == "define" && !skipping()) {
        std::string name;
        for (char c : argument) {
          if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) break;
          name += c;
        }
        const bool is_guard = directives == 2 && name == guard;
        if (!name.empty() && !is_guard) add(name, "macro", "", shown, line_number);
        if (name.size() < argument.size() && argument[name.size()] == '(') function_macros_.insert(name);
      }
    }
    parse_declarations(tokenize(code, 1), shown);
  }

 private:
  std::set<std::string> visited_;
  std::set<std::string> seen_;
  std::set<std::string> function_macros_;  // a `NAME(` of these in a declaration is not its name

  void add(const std::string& name, const std::string& kind, const std::string& owner, const std::string& file,
           int line) {
    if (!seen_.insert(kind + " " + owner + "." + name).second) return;
    names.push_back({name, kind, owner, file + ":" + std::to_string(line)});
  }

  static bool keyword(const std::string& s) {
    static const std::set<std::string> k = {"struct", "union",  "enum",     "typedef", "const",  "volatile",
                                            "extern", "static", "unsigned", "signed",  "inline", "restrict"};
    return k.count(s) != 0;
  }

  // The name a declarator (without its type, or with it) declares: `*b`, `viewport[4]`,
  // `const struct x *kernel`, `(*fn)(int)`.
  static std::optional<Token> declarator_name(const Tokens& piece) {
    for (std::size_t i = 0; i + 1 < piece.size(); ++i) {
      if (piece[i].text == "(" && piece[i + 1].text == "*") {
        for (std::size_t j = i + 2; j < piece.size() && piece[j].text != ")"; ++j) {
          if (piece[j].identifier() && !keyword(piece[j].text)) return piece[j];
        }
      }
    }
    std::optional<Token> last;
    for (const Token& t : piece) {
      if (t.text == "[" || t.text == ":" || t.text == "=" || t.text == "(") break;
      if (t.identifier() && !keyword(t.text)) last = t;
    }
    return last;
  }

  void fields(const Tokens& body, const std::string& owner, const std::string& file) {
    for (const Tokens& member : split_top_level(body, ";")) {
      const auto [open, close] = top_level_group(member, "{", "}");
      Tokens declarators = member;
      if (open != std::string::npos) {  // a nested struct or union: its members, then its declarators
        fields(Tokens(member.begin() + static_cast<long>(open) + 1, member.begin() + static_cast<long>(close)), owner,
               file);
        declarators.assign(member.begin() + static_cast<long>(close) + 1, member.end());
      }
      for (const Tokens& piece : split_top_level(declarators, ",")) {
        if (const auto name = declarator_name(piece)) add(name->text, "field", owner, file, name->line);
      }
    }
  }

  void enumerators(const Tokens& body, const std::string& file) {
    for (const Tokens& piece : split_top_level(body, ",")) {
      if (!piece.empty() && piece[0].identifier()) add(piece[0].text, "enumerator", "", file, piece[0].line);
    }
  }

  void parse_declarations(const Tokens& tokens, const std::string& file) {
    for (const Tokens& d : split_top_level(tokens, ";")) {
      if (d.empty()) continue;
      const bool is_typedef = d[0].text == "typedef";
      const auto [open, close] = top_level_group(d, "{", "}");
      if (open != std::string::npos) {
        // struct/union/enum TAG { BODY } NAMES: the keyword and tag are the tokens before '{'.
        std::string kind, tag;
        for (std::size_t i = 0; i < open; ++i) {
          const std::string& s = d[i].text;
          if (s == "struct" || s == "union" || s == "enum") {
            kind = s;
            if (i + 1 < open && d[i + 1].identifier()) tag = d[i + 1].text;
          }
        }
        std::string owner = tag;
        for (std::size_t i = close + 1; i < d.size(); ++i) {
          if (d[i].identifier() && !keyword(d[i].text) && is_typedef) {
            if (owner == tag) owner = d[i].text;
            add(d[i].text, "type", "", file, d[i].line);
          }
        }
        if (!tag.empty()) add(tag, "type", "", file, d[open > 0 ? open - 1 : 0].line);
        const Tokens body(d.begin() + static_cast<long>(open) + 1, d.begin() + static_cast<long>(close));
        if (kind == "enum") enumerators(body, file);
        else if (kind == "struct" || kind == "union") fields(body, owner, file);
        continue;
      }
      if (!is_typedef && d.size() == 2 && (d[0].text == "struct" || d[0].text == "union" || d[0].text == "enum")) {
        continue;  // a forward declaration: another header's type
      }
      if (is_typedef) {
        if (const auto name = declarator_name(Tokens(d.begin() + 1, d.end()))) {
          add(name->text, "type", "", file, name->line);
        }
        continue;
      }
      // A function: the identifier before the first top-level '(' that is not a macro's (an
      // attribute or export macro taking arguments) nor `(*` (a pointer to a function).
      const Token* function = nullptr;
      int depth = 0;
      for (std::size_t i = 0; i < d.size() && function == nullptr; ++i) {
        const std::string& s = d[i].text;
        if (s == "(" && depth == 0 && i > 0 && d[i - 1].identifier() && function_macros_.count(d[i - 1].text) == 0 &&
            !(i + 1 < d.size() && d[i + 1].text == "*")) {
          function = &d[i - 1];
        }
        if (s == "(" || s == "[" || s == "{") ++depth;
        if (s == ")" || s == "]" || s == "}") --depth;
      }
      if (function != nullptr) {
        add(function->text, "function", "", file, function->line);
      } else if (const auto name = declarator_name(d)) {
        add(name->text, "variable", "", file, name->line);
      }
    }
  }
};

// What a markdown file writes as code (inline code spans and fenced blocks): the identifiers, the
// qualified names `a.b`, and by block (a paragraph, a table, a list item's text or a fenced code
// block: what blank lines, headings and fences separate) the identifiers and the names written as
// a field there: after `.` or `->`, or leading an inline code span (`viewport[4]`,
// `cbf_r_max_mm = 8`; not `f(ctx, projection)`).
struct GuideCode {
  struct Block {
    int line = 0;
    std::set<std::string> identifiers, fields;
  };
  std::vector<Block> blocks;
  std::set<std::string> identifiers, qualified;

  explicit GuideCode(const std::string& text) {
    blocks.push_back({1, {}, {}});
    bool in_code = false;
    int n = 0;
    for (const std::string& line : split_lines(text)) {
      ++n;
      if (is_fence(line)) {
        in_code = !in_code;
        blocks.push_back({n, {}, {}});
        continue;
      }
      if (in_code) {
        add_code(line, false);
        continue;
      }
      if (trim(line).empty() || starts_with(line, "#")) {
        blocks.push_back({n, {}, {}});
        continue;
      }
      for (std::size_t i = 0; i < line.size();) {
        if (line[i] != '`') {
          ++i;
          continue;
        }
        std::size_t ticks = 0;
        while (i + ticks < line.size() && line[i + ticks] == '`') ++ticks;
        const std::size_t close = line.find(std::string(ticks, '`'), i + ticks);
        if (close == std::string::npos) break;
        add_code(line.substr(i + ticks, close - i - ticks), true);
        i = close + ticks;
      }
    }
  }

  bool has(const std::string& name) const { return identifiers.count(name) != 0; }

  // A field is documented where it is written qualified (`sss_frame.region`), or written as a
  // field in a block that names its struct (a table of the struct's fields, a code block that
  // declares one and sets them).
  bool has_field(const std::string& owner, const std::string& field) const {
    if (qualified.count(owner + "." + field) != 0) return true;
    for (const Block& b : blocks) {
      if (b.identifiers.count(owner) != 0 && b.fields.count(field) != 0) return true;
    }
    return false;
  }

 private:
  void add_code(const std::string& code, bool inline_span) {
    std::string previous;  // the identifier just before a '.', for `a.b`
    bool first = inline_span;
    for (std::size_t i = 0; i < code.size();) {
      const unsigned char c = static_cast<unsigned char>(code[i]);
      if (std::isalpha(c) || c == '_') {
        std::size_t e = i;
        while (e < code.size() && (std::isalnum(static_cast<unsigned char>(code[e])) || code[e] == '_')) ++e;
        const std::string word = code.substr(i, e - i);
        identifiers.insert(word);
        blocks.back().identifiers.insert(word);
        const bool member = (i >= 1 && code[i - 1] == '.') || (i >= 2 && code.compare(i - 2, 2, "->") == 0);
        const bool leading = first && (e >= code.size() || code[e] != '(');
        if (member || leading) blocks.back().fields.insert(word);
        first = false;
        if (!previous.empty()) qualified.insert(previous + "." + word);
        previous.clear();
        if (e < code.size() && code[e] == '.') {
          previous = word;
          ++e;
        }
        i = e;
      } else if (std::isdigit(c)) {  // a number (0x881A, 1e6f) names nothing
        while (i < code.size() && (std::isalnum(static_cast<unsigned char>(code[i])) || code[i] == '_' || code[i] == '.')) {
          ++i;
        }
        previous.clear();
        first = false;
      } else {
        previous.clear();
        ++i;
      }
    }
  }
};

// The names of `header` the guide lacks, each explained on `report`.
std::vector<std::string> missing_names(const HeaderNames& h, const GuideCode& code, const std::string& guide,
                                       std::ostream& report) {
  std::vector<std::string> missing;
  for (const PublicName& p : h.names) {
    const bool found = p.kind == "field" ? code.has_field(p.owner, p.name) : code.has(p.name);
    if (found) continue;
    missing.push_back(p.kind + " " + p.display());
    report << guide << ": the " << p.kind << " " << p.display() << " (" << p.where << ") is not in the guide: ";
    if (p.kind == "field") {
      report << "write `" << p.display() << "`, or `" << p.name << "` as a field (leading a code span, or after '.' "
             << "or '->') in a paragraph, table or code block that names `" << p.owner << "`\n";
    } else {
      report << "write `" << p.name << "` (in backticks or a code block) where the guide documents it\n";
    }
  }
  return missing;
}

}  // namespace

// Every name `header` (and the headers it includes with "...") declares, against the guide.
int check_names(const fs::path& root, const std::string& header, const std::string& guide) {
  HeaderNames h;
  h.read(root / header, header);
  const GuideCode code(read_text(root / guide));
  const std::vector<std::string> missing = missing_names(h, code, guide, std::cerr);
  std::map<std::string, int> kinds;
  for (const PublicName& p : h.names) ++kinds[p.kind];
  std::cout << "sss_docs names: " << h.names.size() << " public names in " << header << " and what it includes (";
  const char* sep = "";
  for (const auto& [kind, count] : kinds) {
    std::cout << sep << count << " " << kind << (count == 1 ? "" : "s");
    sep = ", ";
  }
  std::cout << "), " << missing.size() << " missing from " << guide << "\n";
  if (h.names.empty()) {
    std::cerr << header << ": no public name found\n";
    return 1;
  }
  return missing.empty() ? 0 : 1;
}

// The parser on two layouts of one small header (several declarations, fields and enumerators a
// line, as sss.h 0.4 packs them; one a line, with /**< comments, as a header may be rewritten), and
// the guide's rules on a small guide. No files of the tree are read.
int names_selftest() {
  const std::string common = R"(/* fx_common.h: included by both layouts */
#ifndef FX_COMMON_H
#define FX_COMMON_H
#if defined(_WIN32)
#  define FX_API __declspec(dllexport)
#else
#  define FX_API
#endif
typedef enum fx_result { FX_OK = 0, FX_ERROR } fx_result;
#endif
)";
  const std::string packed = R"(/*
 * A fixture in the packed layout. Its example is no declaration:
 *   int not_a_name(void); typedef struct no_type { int no_field; } no_type;
 */
#ifndef FIX_H
#define FIX_H
#include <stdint.h>
#include "fx_common.h"
#ifdef __cplusplus
extern "C" {
#endif
typedef struct fx_context fx_context;
typedef void *(*fx_loader_fn)(const char *name, void *user); /**< loader: dlsym... */
typedef enum fx_level { FX_A, FX_B = 2, /**< two */ FX_C } fx_level;
#define FX_FLAG 0x1u /**< a flag; FX_NOT_A_MACRO in a comment */
#define FX_MAX(a, b) \
  ((a) > (b) ? (a) : (b))
struct fx_forward;
typedef struct fx_desc {
  uint32_t struct_size; fx_loader_fn load; void *load_user; /**< required; its user pointer */
  uint32_t ref, mask; /**< [0, 255] */ int32_t box[4]; const struct fx_forward *next; } fx_desc;
typedef enum fx_flag /* fx_desc.flags */ {
  FX_FLAG_X = 0x1, FX_FLAG_Y = 0x2, /**< x; y */
  FX_FLAG_Z = (1 << 2) /**< z */ } fx_flag;
FX_API fx_result fx_run(fx_context *ctx, const fx_desc *desc); /**< runs: fx_fake(1) */
FX_API const char *fx_name(fx_result r); void fx_two(void);
#ifdef __cplusplus
}
#endif
#endif
)";
  const std::string one_a_line = R"(#ifndef FIX_H
#define FIX_H

#include <stdint.h>

#include "fx_common.h"

#ifdef __cplusplus
extern "C" {
#endif

/** opaque */
typedef struct fx_context fx_context;
/** loader */
typedef void *(*fx_loader_fn)(const char *name,
                              void *user);

typedef enum fx_level {
  FX_A,     /**< a */
  FX_B = 2, /**< two */
  FX_C,     /**< c */
} fx_level;

#define FX_FLAG 0x1u /**< a flag */
#define FX_MAX(a, b) ((a) > (b) ? (a) : (b)) /**< the larger */

struct fx_forward;

/** A desc. */
typedef struct fx_desc {
  uint32_t struct_size;          /**< sizeof(fx_desc) */
  fx_loader_fn load;             /**< required */
  void *load_user;               /**< its user pointer */
  uint32_t ref;                  /**< [0, 255] */
  uint32_t mask;                 /**< [0, 255] */
  int32_t box[4];                /**< x, y, w, h */
  const struct fx_forward *next; /**< NULL */
} fx_desc;

typedef enum fx_flag {
  FX_FLAG_X = 0x1,      /**< x */
  FX_FLAG_Y = 0x2,      /**< y */
  FX_FLAG_Z = (1 << 2)  /**< z */
} fx_flag;

/**
 * Runs.
 * @retval FX_OK done
 */
FX_API fx_result fx_run(fx_context *ctx,
                        const fx_desc *desc);
/** A name. */
FX_API const char *fx_name(fx_result r);
void fx_two(void);

#ifdef __cplusplus
}
#endif

#endif /* FIX_H */
)";
  const std::set<std::string> expected = {
      "enumerator FX_A",       "enumerator FX_B",       "enumerator FX_C",       "enumerator FX_ERROR",
      "enumerator FX_FLAG_X",  "enumerator FX_FLAG_Y",  "enumerator FX_FLAG_Z",  "enumerator FX_OK",
      "field fx_desc.box",     "field fx_desc.load",    "field fx_desc.load_user", "field fx_desc.mask",
      "field fx_desc.next",    "field fx_desc.ref",     "field fx_desc.struct_size", "function fx_name",
      "function fx_run",       "function fx_two",       "macro FX_API",          "macro FX_FLAG",
      "macro FX_MAX",          "type fx_context",       "type fx_desc",          "type fx_flag",
      "type fx_level",         "type fx_loader_fn",     "type fx_result"};
  const fs::path dir = fs::temp_directory_path() /
                       ("sss_docs_selftest_" + std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
  fs::create_directories(dir);
  const auto write = [&dir](const std::string& name, const std::string& text) {
    std::ofstream(dir / name, std::ios::binary) << text;
  };
  write("fx_common.h", common);
  write("packed.h", packed);
  write("one_a_line.h", one_a_line);
  int problems = 0;
  for (const char* layout : {"packed.h", "one_a_line.h"}) {
    HeaderNames h;
    h.read(dir / layout, layout);
    std::set<std::string> got;
    for (const PublicName& p : h.names) got.insert(p.kind + " " + p.display());
    for (const std::string& e : expected) {
      if (got.count(e) == 0) {
        std::cerr << "names-selftest: " << layout << ": the parser missed " << e << "\n";
        ++problems;
      }
    }
    for (const std::string& g : got) {
      if (expected.count(g) == 0) {
        std::cerr << "names-selftest: " << layout << ": the parser found " << g << ", which is no public name\n";
        ++problems;
      }
    }
  }
  // The guide's rules: code only (backticks, fenced blocks); a field qualified, or written as a
  // field in a block that names its struct.
  const std::string guide = R"(# Guide
Intro naming `fx_run`, `fx_context`, `fx_two()` and `fx_result` (`FX_OK`, `FX_ERROR`).
## The desc
`fx_desc` holds `struct_size`, `load` and `load_user`; `fx_run(ctx, next)` has next as an argument
only, which is no field.
## Other
`ref` and `mask` here are not fx_desc's (no struct named in this section); FX_A in prose is no code.
## Qualified
The name in the block's comment is qualified.

```c
fx_name(FX_B); x = FX_MAX(1, 2); d.flags = FX_FLAG_X | FX_FLAG_Y | FX_FLAG_Z; /* fx_desc.box */
```
## Members
A member access names a field where the same block names the struct.

```c
fx_desc *d = get();
d->ref = 1;
```

`mask` alone, a paragraph after the one naming fx_desc, is not enough.
)";
  const std::set<std::string> expected_missing = {"type fx_loader_fn", "type fx_level",     "enumerator FX_A",
                                                  "enumerator FX_C",   "macro FX_FLAG",      "macro FX_API",
                                                  "type fx_flag",      "field fx_desc.mask", "field fx_desc.next"};
  HeaderNames h;
  h.read(dir / "one_a_line.h", "one_a_line.h");
  std::ostringstream ignored;
  const std::vector<std::string> missing = missing_names(h, GuideCode(guide), "guide.md", ignored);
  const std::set<std::string> got_missing(missing.begin(), missing.end());
  if (got_missing != expected_missing) {
    std::cerr << "names-selftest: the guide check reported as missing:";
    for (const std::string& m : got_missing) std::cerr << " [" << m << "]";
    std::cerr << "\n  expected:";
    for (const std::string& m : expected_missing) std::cerr << " [" << m << "]";
    std::cerr << "\n";
    ++problems;
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
  std::cout << "sss_docs names-selftest: " << expected.size() << " names in two layouts, " << problems
            << " problems\n";
  return problems == 0 ? 0 : 1;
}

}  // namespace sss_docs
