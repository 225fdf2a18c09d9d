// sss_docs quickstart: the steps of the quick start in docs/integration.md, titles and code, are
// those of tools/docs/guide_quickstart.c, in order (ctest docs.guide_quickstart_matches). Why: that
// source is built as strict C99 and run headless, step by step (docs.guide_quickstart), so a host
// that follows the checklist copies code that compiles and works. Each side's common indentation
// is dropped before the code is compared (dedent below).
#include "sss_docs_quickstart.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "sss_docs_text.hpp"

namespace sss_docs {
namespace {

std::string rtrim(const std::string& s) {
  std::size_t e = s.size();
  while (e > 0 && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(0, e);
}

// The lines without their common indentation and trailing blanks (a list item's block is indented
// for the list, a function's body for the function).
std::vector<std::string> dedent(const std::vector<std::string>& lines) {
  std::size_t common = std::string::npos;
  for (const std::string& l : lines) {
    if (trim(l).empty()) continue;
    common = std::min(common, l.find_first_not_of(" \t"));
  }
  std::vector<std::string> out;
  for (const std::string& l : lines) out.push_back(trim(l).empty() ? "" : rtrim(l.substr(common)));
  return out;
}

struct Step {
  int number = 0;
  std::string title;
  std::size_t line = 0;       // where the step begins (1-based)
  std::size_t code_line = 0;  // where its code begins
  std::vector<std::string> code;
  int blocks = 0;
};

// The checklist between "<!-- quick-start: begin" and "<!-- quick-start: end": items "N. **Title**
// ..." each followed by one fenced block.
bool guide_steps(const std::vector<std::string>& lines, const std::string& guide, std::vector<Step>* steps) {
  std::size_t begin = lines.size(), end = lines.size();
  for (std::size_t n = 0; n < lines.size(); ++n) {
    if (begin == lines.size() && starts_with(trim(lines[n]), "<!-- quick-start: begin")) begin = n;
    else if (begin != lines.size() && starts_with(trim(lines[n]), "<!-- quick-start: end")) {
      end = n;
      break;
    }
  }
  if (end == lines.size()) {
    std::cerr << guide << ": no \"<!-- quick-start: begin ... -->\" and \"<!-- quick-start: end -->\" lines\n";
    return false;
  }
  bool in_code = false;
  for (std::size_t n = begin + 1; n < end; ++n) {
    const std::string& line = lines[n];
    if (is_fence(line)) {
      in_code = !in_code;
      if (steps->empty()) continue;
      Step& s = steps->back();
      if (in_code) {
        ++s.blocks;
        s.code_line = n + 2;
      }
      continue;
    }
    if (in_code) {
      if (!steps->empty() && steps->back().blocks == 1) steps->back().code.push_back(line);
      continue;
    }
    // "N. **Title**" at the start of a line.
    std::size_t digits = 0;
    while (digits < line.size() && std::isdigit(static_cast<unsigned char>(line[digits]))) ++digits;
    if (digits == 0 || line.compare(digits, 4, ". **") != 0) continue;
    const std::size_t close = line.find("**", digits + 4);
    if (close == std::string::npos) continue;
    Step s;
    s.number = std::atoi(line.substr(0, digits).c_str());
    s.title = line.substr(digits + 4, close - digits - 4);
    s.line = n + 1;
    steps->push_back(s);
  }
  return true;
}

// The program's steps: the lines between "quick-start N: TITLE" and "quick-start N: end".
bool source_steps(const std::vector<std::string>& lines, const std::string& source, std::vector<Step>* steps) {
  const std::string marker = "quick-start ";
  Step* open = nullptr;
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const std::size_t at = lines[n].find(marker);
    if (at == std::string::npos) {
      if (open != nullptr) open->code.push_back(lines[n]);
      continue;
    }
    const std::string rest = lines[n].substr(at + marker.size());
    std::size_t digits = 0;
    while (digits < rest.size() && std::isdigit(static_cast<unsigned char>(rest[digits]))) ++digits;
    if (digits == 0 || rest.compare(digits, 2, ": ") != 0) {
      if (open != nullptr) open->code.push_back(lines[n]);
      continue;
    }
    const int number = std::atoi(rest.substr(0, digits).c_str());
    std::string title = rest.substr(digits + 2);
    if (const std::size_t comment_end = title.rfind("*/"); comment_end != std::string::npos) title.resize(comment_end);
    title = trim(title);
    if (title == "end") {
      if (open == nullptr || open->number != number) {
        std::cerr << source << ":" << n + 1 << ": \"quick-start " << number << ": end\" closes no open step\n";
        return false;
      }
      open = nullptr;
      continue;
    }
    if (open != nullptr) {
      std::cerr << source << ":" << n + 1 << ": step " << number << " begins inside step " << open->number << "\n";
      return false;
    }
    Step s;
    s.number = number;
    s.title = title;
    s.line = n + 1;
    s.code_line = n + 2;
    s.blocks = 1;
    steps->push_back(s);
    open = &steps->back();
  }
  if (open != nullptr) {
    std::cerr << source << ":" << open->line << ": step " << open->number << " has no \"quick-start "
              << open->number << ": end\" line\n";
    return false;
  }
  return true;
}

}  // namespace

int check_quickstart(const fs::path& root, const std::string& guide, const std::string& source) {
  std::vector<Step> in_guide, in_source;
  if (!guide_steps(split_lines(read_text(root / guide)), guide, &in_guide) ||
      !source_steps(split_lines(read_text(root / source)), source, &in_source)) {
    return 1;
  }
  int problems = 0;
  const auto numbered = [&](const std::vector<Step>& steps, const std::string& file) {
    for (std::size_t i = 0; i < steps.size(); ++i) {
      if (steps[i].number != static_cast<int>(i) + 1) {
        std::cerr << file << ":" << steps[i].line << ": step " << steps[i].number << " where step " << i + 1
                  << " belongs: steps are numbered 1, 2, 3... in order\n";
        ++problems;
      }
    }
  };
  numbered(in_guide, guide);
  numbered(in_source, source);
  if (in_guide.empty()) {
    std::cerr << guide << ": the quick start has no steps (\"N. **Title** ...\" lines)\n";
    ++problems;
  }
  if (in_guide.size() != in_source.size()) {
    std::cerr << guide << " has " << in_guide.size() << " quick-start steps, " << source << " "
              << in_source.size() << "\n";
    ++problems;
  }
  for (std::size_t i = 0; i < std::min(in_guide.size(), in_source.size()); ++i) {
    const Step& g = in_guide[i];
    const Step& s = in_source[i];
    if (g.title != s.title) {
      std::cerr << guide << ":" << g.line << ": step " << g.number << " is \"" << g.title << "\" but " << source << ":"
                << s.line << " calls it \"" << s.title << "\"\n";
      ++problems;
    }
    if (g.blocks != 1) {
      std::cerr << guide << ":" << g.line << ": step " << g.number << " has " << g.blocks
                << " code blocks; each step has one, its code in " << source << "\n";
      ++problems;
      continue;
    }
    const std::vector<std::string> a = dedent(g.code), b = dedent(s.code);
    if (a == b) continue;
    ++problems;
    std::size_t k = 0;
    while (k < a.size() && k < b.size() && a[k] == b[k]) ++k;
    std::cerr << guide << ":" << g.code_line + k << ": step " << g.number << "'s code differs from " << source << ":"
              << s.code_line + k << "\n  guide:  " << (k < a.size() ? a[k] : "(the block ends here)")
              << "\n  source: " << (k < b.size() ? b[k] : "(the step ends here)") << "\n";
  }
  std::cout << "sss_docs quickstart: " << in_guide.size() << " steps in " << guide << ", " << in_source.size()
            << " in " << source << ", " << problems << " problems\n";
  return problems == 0 ? 0 : 1;
}

}  // namespace sss_docs
