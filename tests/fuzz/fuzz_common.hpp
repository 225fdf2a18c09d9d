// Shared by the libFuzzer targets: a reader over the input bytes and a failure that libFuzzer
// reports as a crash (with the input saved).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace sss_fuzz {

// Takes values off the front of the input; past the end it yields zeros.
class Bytes {
 public:
  Bytes(const uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  template <typename T>
  T take() {
    T value{};
    const std::size_t n = size_ < sizeof value ? size_ : sizeof value;
    std::memcpy(&value, data_, n);
    data_ += n;
    size_ -= n;
    return value;
  }
  std::size_t left() const { return size_; }

 private:
  const uint8_t* data_;
  std::size_t size_;
};

// An invariant failed: say which, then abort (libFuzzer saves the input as crash-*).
[[noreturn]] inline void violated(const char* what, const char* file, int line) {
  std::fprintf(stderr, "invariant violated: %s (%s:%d)\n", what, file, line);
  std::abort();
}

}  // namespace sss_fuzz

#define SSS_FUZZ_CHECK(condition)                                           \
  do {                                                                      \
    if (!(condition)) ::sss_fuzz::violated(#condition, __FILE__, __LINE__); \
  } while (0)
