// sss_docs names and names-selftest (sss_docs_names.cpp): every public name of a C header is in
// the guide, and the parser that finds the names works on more than one layout of a header.
#pragma once

#include <filesystem>
#include <string>

namespace sss_docs {

// Every public name root/header declares (and the headers it includes with "..."): function, type,
// field, enumerator, macro but the include guard, is written as code in root/guide. 0 when all are,
// 1 when one is missing or the header declares none (each missing name on stderr).
int check_names(const std::filesystem::path& root, const std::string& header, const std::string& guide);
// The header parser and the guide's rules on fixtures written to a temporary folder: 0 when they
// find what the fixtures hold, 1 when not (each difference on stderr).
int names_selftest();

}  // namespace sss_docs
