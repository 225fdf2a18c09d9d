#include "lut_cache.hpp"

namespace sss::math {

LutCache::Data LutCache::get(const std::string& key, const std::function<std::vector<float>()>& generate) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto it = entries_.begin(); it != entries_.end(); ++it) {
    if (it->first == key) {  // the whole key, not only its hash: no collision can alias two LUTs
      entries_.splice(entries_.begin(), entries_, it);
      return entries_.front().second;
    }
  }
  Data data = std::make_shared<const std::vector<float>>(generate());
  ++generations_;
  entries_.emplace_front(key, data);
  while (entries_.size() > capacity_ && !entries_.empty()) entries_.pop_back();
  return data;
}

std::uint64_t LutCache::generations() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return generations_;
}

std::size_t LutCache::size() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return entries_.size();
}

}  // namespace sss::math
