// The text helpers the sss_docs checks share (sss_docs_text.hpp).
#include "sss_docs_text.hpp"

#include <cctype>
#include <fstream>
#include <iostream>
#include <sstream>

namespace sss_docs {

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::cerr << "sss_docs: cannot read " << path.generic_string() << "\n";
    throw Failure{};
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::string line;
  std::istringstream in(text);
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

std::string trim(const std::string& s) {
  std::size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

// A fence line (``` or ~~~, possibly indented): opens or closes a code block.
bool is_fence(const std::string& line) {
  const std::string t = trim(line);
  return starts_with(t, "```") || starts_with(t, "~~~");
}

}  // namespace sss_docs
