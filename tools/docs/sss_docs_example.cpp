// sss_docs example: the code block of the README's integration example is, line for line, the
// marked region of its source (tools/docs/readme_example.c; ctest docs.readme_example_matches).
// Why: that source is built as strict C99 and run headless (docs.readme_example), so the example a
// reader copies is code that compiles and runs against the current library, not a sketch that
// drifted from the API.
#include "sss_docs_example.hpp"

#include <iostream>
#include <string>
#include <vector>

#include "sss_docs_text.hpp"

namespace sss_docs {

int check_examples(const fs::path& root, const fs::path& readme) {
  const std::vector<std::string> lines = split_lines(read_text(root / readme));
  const std::string marker = "<!-- example: ";
  int examples = 0, problems = 0;
  for (std::size_t n = 0; n < lines.size(); ++n) {
    if (!starts_with(trim(lines[n]), marker)) continue;
    ++examples;
    std::string rest = trim(lines[n]).substr(marker.size());
    const std::string source = rest.substr(0, rest.find(' '));
    // The README's block: the first fence after the marker up to its closing fence.
    std::size_t open = n + 1;
    while (open < lines.size() && !is_fence(lines[open])) ++open;
    std::size_t close = open + 1;
    while (close < lines.size() && !is_fence(lines[close])) ++close;
    if (close >= lines.size()) {
      std::cerr << readme.generic_string() << ":" << n + 1 << ": no fenced block after the example marker\n";
      ++problems;
      continue;
    }
    const std::vector<std::string> block(lines.begin() + static_cast<long>(open) + 1,
                                         lines.begin() + static_cast<long>(close));
    // The source's region.
    const std::vector<std::string> code = split_lines(read_text(root / source));
    std::size_t begin = code.size(), end = code.size();
    for (std::size_t i = 0; i < code.size(); ++i) {
      if (begin == code.size() && code[i].find("readme-example: begin") != std::string::npos) begin = i;
      else if (begin != code.size() && code[i].find("readme-example: end") != std::string::npos) {
        end = i;
        break;
      }
    }
    if (begin == code.size() || end == code.size()) {
      std::cerr << source << ": no \"readme-example: begin\" ... \"readme-example: end\" lines\n";
      ++problems;
      continue;
    }
    const std::vector<std::string> region(code.begin() + static_cast<long>(begin) + 1,
                                          code.begin() + static_cast<long>(end));
    if (region == block) continue;
    ++problems;
    std::size_t i = 0;
    while (i < region.size() && i < block.size() && region[i] == block[i]) ++i;
    std::cerr << readme.generic_string() << ":" << open + 2 + i << ": the example differs from " << source << ":"
              << begin + 2 + i << "\n  README: " << (i < block.size() ? block[i] : "(the block ends here)")
              << "\n  source: " << (i < region.size() ? region[i] : "(the region ends here)") << "\n";
  }
  if (examples == 0) {
    std::cerr << readme.generic_string() << ": no \"" << marker << "PATH -->\" marker\n";
    ++problems;
  }
  std::cout << "sss_docs example: " << examples << " examples, " << problems << " differ\n";
  return problems == 0 ? 0 : 1;
}

}  // namespace sss_docs
