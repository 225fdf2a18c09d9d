// What more than one sss_docs check needs to read a markdown or source file: its text, its lines,
// a trimmed line, whether a line is a code fence. One copy, so that every check splits lines and
// finds fences the same way.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sss_docs {

namespace fs = std::filesystem;

// Thrown where an input cannot be read; main catches it: bad input, not a doc that does not hold.
struct Failure {};  // unreadable input: exit status 2

// The file's bytes; "sss_docs: cannot read PATH" on stderr and Failure where it cannot be read.
std::string read_text(const fs::path& path);
// The text's lines, without their '\n'.
std::vector<std::string> split_lines(const std::string& text);
bool starts_with(const std::string& s, const std::string& prefix);
// s without its leading and trailing white space.
std::string trim(const std::string& s);
// A fence line (``` or ~~~, possibly indented): opens or closes a code block.
bool is_fence(const std::string& line);

}  // namespace sss_docs
