// The benchmark programs' comma-separated arguments ("--scenes plane,sphere", "--turns 0,75").
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace sss_bench {

// The items of `text` between commas, in order. `drop_empty`: leave out empty items ("a,,b" gives
// a and b); else they stay, for the caller's check to refuse.
inline std::vector<std::string> split_list(const std::string& text, bool drop_empty = false) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (!drop_empty || !item.empty()) out.push_back(item);
  }
  return out;
}

}  // namespace sss_bench
