// Rounding to IEEE binary16, as the GL does when it stores into an RGBA16F target. Used by the CPU
// model so that it predicts the GPU's result bit for bit where the arithmetic agrees.
#pragma once

namespace sss::math {

// The float nearest to x that binary16 can hold (round to nearest even; ±Inf beyond 65504 + ulp/2).
float round_to_half(float x);

}  // namespace sss::math
