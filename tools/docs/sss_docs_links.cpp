// sss_docs links: every relative link and image in the README, integration/ and docs/ names a file
// or folder that exists, and every #anchor into a markdown file names one of its headings (ctest
// docs.links). Why: a moved file or a reworded heading breaks its links without a word, and a
// reader meets the dead link long after the change that made it. Links to other sites (://,
// mailto:) are not checked.
#include "sss_docs_links.hpp"

#include <algorithm>
#include <cctype>
#include <iostream>
#include <map>
#include <set>

#include "sss_docs_text.hpp"

namespace sss_docs {
namespace {

// GitHub's heading anchor: lower case, spaces to hyphens, punctuation and symbols dropped (letters,
// digits, '-' and '_' kept; other non-ASCII characters kept but for the common symbols below).
std::string slug(const std::string& heading) {
  static const std::vector<std::string> dropped = {"×", "—", "–", "·", "’", "‘", "“", "”", "…", "→", "←", "≤", "≥",
                                                   "±", "‖", "°", "§", "²", "³", "¹"};
  std::string out;
  for (std::size_t i = 0; i < heading.size();) {
    const unsigned char c = static_cast<unsigned char>(heading[i]);
    if (c < 0x80) {
      if (std::isalnum(c) || c == '-' || c == '_') out += static_cast<char>(std::tolower(c));
      else if (c == ' ') out += '-';
      ++i;
      continue;
    }
    std::size_t n = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : 2;
    const std::string ch = heading.substr(i, n);
    if (std::find(dropped.begin(), dropped.end(), ch) == dropped.end()) out += ch;
    i += n;
  }
  return out;
}

// The anchors of a markdown file: its headings' slugs (a repeated one gets -1, -2, ...), and the
// name/id of HTML anchors.
std::set<std::string> anchors_of(const fs::path& file) {
  std::set<std::string> anchors;
  std::map<std::string, int> seen;
  bool in_code = false;
  for (const std::string& line : split_lines(read_text(file))) {
    if (is_fence(line)) {
      in_code = !in_code;
      continue;
    }
    if (in_code) continue;
    if (starts_with(line, "#")) {
      std::size_t level = 0;
      while (level < line.size() && line[level] == '#') ++level;
      if (level <= 6 && level < line.size() && line[level] == ' ') {
        std::string text = trim(line.substr(level));
        while (!text.empty() && text.back() == '#') text.pop_back();
        const std::string base = slug(trim(text));
        const int n = seen[base]++;
        anchors.insert(n == 0 ? base : base + "-" + std::to_string(n));
      }
    }
    for (const char* attr : {"name=\"", "id=\""}) {
      for (std::size_t at = line.find(attr); at != std::string::npos; at = line.find(attr, at + 1)) {
        const std::size_t b = at + std::string(attr).size(), e = line.find('"', b);
        if (e != std::string::npos) anchors.insert(line.substr(b, e - b));
      }
    }
  }
  return anchors;
}

// The line with its inline code spans removed (links inside `...` are examples, not links).
std::string without_code_spans(const std::string& line) {
  std::string out;
  for (std::size_t i = 0; i < line.size();) {
    if (line[i] != '`') {
      out += line[i++];
      continue;
    }
    std::size_t ticks = 0;
    while (i + ticks < line.size() && line[i + ticks] == '`') ++ticks;
    const std::size_t close = line.find(std::string(ticks, '`'), i + ticks);
    if (close == std::string::npos) {
      out += line.substr(i);
      break;
    }
    i = close + ticks;
  }
  return out;
}

// Link targets of one line: [text](target "title"), ![alt](target), <img src="target">.
std::vector<std::string> link_targets(const std::string& raw) {
  const std::string line = without_code_spans(raw);
  std::vector<std::string> targets;
  for (std::size_t at = line.find("]("); at != std::string::npos; at = line.find("](", at + 2)) {
    std::size_t b = at + 2, depth = 1, e = b;
    for (; e < line.size(); ++e) {
      if (line[e] == '(') ++depth;
      if (line[e] == ')' && --depth == 0) break;
    }
    if (e >= line.size()) continue;
    std::string target = trim(line.substr(b, e - b));
    if (const std::size_t space = target.find(' '); space != std::string::npos) target = target.substr(0, space);
    if (target.size() >= 2 && target.front() == '<' && target.back() == '>') target = target.substr(1, target.size() - 2);
    targets.push_back(target);
  }
  for (std::size_t at = line.find("src=\""); at != std::string::npos; at = line.find("src=\"", at + 1)) {
    const std::size_t b = at + 5, e = line.find('"', b);
    if (e != std::string::npos) targets.push_back(line.substr(b, e - b));
  }
  return targets;
}

}  // namespace

int check_links(const fs::path& root, const std::vector<std::string>& paths) {
  std::vector<fs::path> files;
  for (const std::string& p : paths) {
    const fs::path full = root / p;
    if (fs::is_directory(full)) {
      for (const auto& entry : fs::recursive_directory_iterator(full)) {
        if (entry.is_regular_file() && entry.path().extension() == ".md") files.push_back(entry.path());
      }
    } else if (fs::is_regular_file(full)) {
      files.push_back(full);
    } else {
      std::cerr << "sss_docs: no such file or folder: " << full.generic_string() << "\n";
      throw Failure{};
    }
  }
  std::sort(files.begin(), files.end());
  std::map<fs::path, std::set<std::string>> anchor_cache;
  auto anchors = [&](const fs::path& f) -> const std::set<std::string>& {
    auto it = anchor_cache.find(f);
    if (it == anchor_cache.end()) it = anchor_cache.emplace(f, anchors_of(f)).first;
    return it->second;
  };
  int problems = 0, links = 0;
  for (const fs::path& file : files) {
    const std::vector<std::string> lines = split_lines(read_text(file));
    bool in_code = false;
    for (std::size_t n = 0; n < lines.size(); ++n) {
      if (is_fence(lines[n])) {
        in_code = !in_code;
        continue;
      }
      if (in_code) continue;
      for (const std::string& target : link_targets(lines[n])) {
        if (target.empty() || target.find("://") != std::string::npos || starts_with(target, "mailto:")) continue;
        ++links;
        const std::size_t hash = target.find('#');
        const std::string path_part = target.substr(0, hash);
        const std::string anchor = hash == std::string::npos ? "" : target.substr(hash + 1);
        const fs::path resolved = path_part.empty() ? file : (file.parent_path() / path_part).lexically_normal();
        const std::string where = fs::relative(file, root).generic_string() + ":" + std::to_string(n + 1) + ": ";
        if (!fs::exists(resolved)) {
          std::cerr << where << "link to a missing file: " << target << "\n";
          ++problems;
          continue;
        }
        if (!anchor.empty() && resolved.extension() == ".md" && anchors(resolved).count(anchor) == 0) {
          std::cerr << where << "no heading for the anchor #" << anchor << " in "
                    << fs::relative(resolved, root).generic_string() << "\n";
          ++problems;
        }
      }
    }
  }
  std::cout << "sss_docs links: " << files.size() << " files, " << links << " relative links, " << problems
            << " broken\n";
  return problems == 0 ? 0 : 1;
}

}  // namespace sss_docs
