// Generated LUTs kept by the text of their inputs (preintegrated_lut.hpp's *_key), so a LUT is
// generated once while its parameters stay the same. Thread-safe; holds at most `capacity`
// entries, dropping the least recently used. Math layer: no GL.
#pragma once

#include <cstdint>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace sss::math {

class LutCache {
 public:
  using Data = std::shared_ptr<const std::vector<float>>;

  explicit LutCache(std::size_t capacity = 8) : capacity_(capacity) {}

  // The data for `key`; `generate` runs (under the cache's lock, so two callers never generate the
  // same LUT twice) only when the key is not held.
  Data get(const std::string& key, const std::function<std::vector<float>()>& generate);

  // How many times `generate` ran: a hit leaves it unchanged.
  std::uint64_t generations() const;
  std::size_t size() const;

 private:
  mutable std::mutex mutex_;
  std::size_t capacity_;
  std::list<std::pair<std::string, Data>> entries_;  // most recently used first
  std::uint64_t generations_ = 0;
};

}  // namespace sss::math
