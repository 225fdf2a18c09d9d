// sss_lut_desc to the math layer's LUT descriptions, and the profile it names. No GL.
#pragma once

#include "../math/preintegrated_lut.hpp"
#include "sss/sss_lut.h"

namespace sss::api {

const sss::math::RadialProfile& lut_profile(const sss_lut_desc& desc);
sss::math::DiffuseLutDesc diffuse_lut_desc(const sss_lut_desc& desc);
sss::math::ShadowLutDesc shadow_lut_desc(const sss_lut_desc& desc);

}  // namespace sss::api
