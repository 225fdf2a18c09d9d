// sss_docs: what keeps the README and docs/ true, and the README's generated numbers.
//
//   sss_docs links ROOT PATH...        every relative link and image in the markdown files (a folder:
//                                      every *.md under it) names a file or folder that exists, and a
//                                      #anchor into a markdown file names one of its headings
//   sss_docs example ROOT README       each fenced block that follows "<!-- example: PATH ... -->" in
//                                      README equals the lines of ROOT/PATH between the lines holding
//                                      "readme-example: begin" and "readme-example: end"
//   sss_docs headline ROOT README [--write]
//                                      the lines between "<!-- headline: begin" and "<!-- headline: end -->"
//                                      in README equal the table made from the committed benchmark
//                                      results (ROOT/docs/benchmarks/results.csv and .json, and
//                                      ROOT/docs/benchmarks-gpu/ when present); --write rewrites them
//                                      (scripts/update-readme-numbers.sh)
//   sss_docs names ROOT HEADER GUIDE   every public name HEADER declares (and the headers it includes
//                                      with "..."): function, type, field, enumerator, macro but the
//                                      include guard, is written as code in GUIDE; a field as
//                                      `struct.field`, or as a field in a paragraph, table or code block
//                                      that names its struct
//   sss_docs names-selftest            the parser on a packed and a one-declaration-a-line header
//   sss_docs quickstart ROOT GUIDE SOURCE
//                                      the numbered steps between "<!-- quick-start: begin" and
//                                      "<!-- quick-start: end" in GUIDE ("N. **Title**" and one code
//                                      block each) are SOURCE's, in order: the lines between
//                                      "quick-start N: Title" and "quick-start N: end", same title
//
// Exit status 0 when everything holds (or was written), 1 when something does not (each problem on
// stderr), 2 for bad usage or unreadable inputs. No dependency beyond the C++17 standard library.
//
// Each subcommand is its own file, sss_docs_links.cpp, sss_docs_example.cpp, sss_docs_headline.cpp,
// sss_docs_names.cpp (names and names-selftest) and sss_docs_quickstart.cpp; what they share is in
// sss_docs_text.cpp. This file holds the usage and the dispatch.
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "sss_docs_example.hpp"
#include "sss_docs_headline.hpp"
#include "sss_docs_links.hpp"
#include "sss_docs_names.hpp"
#include "sss_docs_quickstart.hpp"
#include "sss_docs_text.hpp"

namespace {

int usage() {
  std::cerr << "usage: sss_docs links ROOT PATH...\n"
               "       sss_docs example ROOT README\n"
               "       sss_docs headline ROOT README [--write]\n"
               "       sss_docs names ROOT HEADER GUIDE\n"
               "       sss_docs names-selftest\n"
               "       sss_docs quickstart ROOT GUIDE SOURCE\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "names-selftest") {
    try {
      return sss_docs::names_selftest();
    } catch (const std::exception& e) {
      std::cerr << "sss_docs: " << e.what() << "\n";
      return 2;
    }
  }
  if (argc < 3) return usage();
  const std::string command = argv[1];
  const std::filesystem::path root = argv[2];
  try {
    if (command == "links" && argc >= 4) {
      return sss_docs::check_links(root, std::vector<std::string>(argv + 3, argv + argc));
    }
    if (command == "example" && argc == 4) return sss_docs::check_examples(root, argv[3]);
    if (command == "names" && argc == 5) return sss_docs::check_names(root, argv[3], argv[4]);
    if (command == "quickstart" && argc == 5) return sss_docs::check_quickstart(root, argv[3], argv[4]);
    if (command == "headline" && (argc == 4 || (argc == 5 && std::string(argv[4]) == "--write"))) {
      return sss_docs::run_headline(root, argv[3], argc == 5);
    }
  } catch (const sss_docs::Failure&) {
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "sss_docs: " << e.what() << "\n";
    return 2;
  }
  return usage();
}
