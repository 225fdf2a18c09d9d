// sss_docs example (sss_docs_example.cpp): the README's example is the code ctest builds.
#pragma once

#include <filesystem>

namespace sss_docs {

// Each fenced block that follows "<!-- example: PATH ... -->" in `readme` equals the lines of
// root/PATH between the lines holding "readme-example: begin" and "readme-example: end". 0 when all
// do, 1 when one differs or there is no marker (the first difference on stderr).
int check_examples(const std::filesystem::path& root, const std::filesystem::path& readme);

}  // namespace sss_docs
