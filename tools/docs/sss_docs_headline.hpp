// sss_docs headline (sss_docs_headline.cpp): the README's table of numbers is the one the committed
// benchmark results give.
#pragma once

#include <filesystem>

namespace sss_docs {

// The lines between "<!-- headline: begin" and "<!-- headline: end -->" in `readme` against the
// table made from root/docs/benchmarks/ (and root/docs/benchmarks-gpu/ when present): 0 when they
// are equal, or when `write` rewrote them; 1 when they differ (the expected table on stderr) or the
// markers are missing; 2 when the README cannot be written; Failure for unreadable results.
int run_headline(const std::filesystem::path& root, const std::filesystem::path& readme, bool write);

}  // namespace sss_docs
