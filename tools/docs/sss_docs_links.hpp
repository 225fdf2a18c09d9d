// sss_docs links (sss_docs_links.cpp): the relative links and images of the docs resolve.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sss_docs {

// Every relative link and image in the markdown files `paths` (relative to `root`; a folder: every
// *.md under it) names a file or folder that exists, and an #anchor into a markdown file names one
// of its headings. 0 when all do, 1 when one does not (each on stderr); Failure for a path that is
// neither a file nor a folder.
int check_links(const std::filesystem::path& root, const std::vector<std::string>& paths);

}  // namespace sss_docs
