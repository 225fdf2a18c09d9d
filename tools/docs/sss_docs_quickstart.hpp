// sss_docs quickstart (sss_docs_quickstart.cpp): the guide's quick-start checklist is the program
// ctest runs.
#pragma once

#include <filesystem>
#include <string>

namespace sss_docs {

// The numbered steps between "<!-- quick-start: begin" and "<!-- quick-start: end" in root/guide
// ("N. **Title**" and one code block each) are root/source's, in order: the lines between
// "quick-start N: Title" and "quick-start N: end", same title. 0 when they are, 1 when not (each
// problem on stderr).
int check_quickstart(const std::filesystem::path& root, const std::string& guide, const std::string& source);

}  // namespace sss_docs
