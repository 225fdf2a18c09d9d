#include "half_float.hpp"

#include <cmath>
#include <limits>

namespace sss::math {

float round_to_half(float x) {
  if (!std::isfinite(x) || x == 0.0f) return x;
  const float a = std::fabs(x);
  if (a >= 65520.0f) return std::copysign(std::numeric_limits<float>::infinity(), x);
  float quantum;
  if (a < 6.103515625e-05f) {  // below the smallest normal half: fixed quantum 2^-24
    quantum = std::ldexp(1.0f, -24);
  } else {  // 11 significant bits
    int exponent = 0;
    std::frexp(a, &exponent);
    quantum = std::ldexp(1.0f, exponent - 11);
  }
  // a / quantum is exact (power-of-two scale); nearbyint rounds half to even in the default mode.
  return std::copysign(std::nearbyint(a / quantum) * quantum, x);
}

}  // namespace sss::math
