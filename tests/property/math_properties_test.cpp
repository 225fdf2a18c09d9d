// Property-based tests of the math layer (RapidCheck): the kernel generator, the projection checks
// and depth linearisation, fp16 rounding, the pass constants, the CPU model of the two passes and
// the exact reference, each over generated inputs, with failures shrunk to a minimal case.
// ctest runs them with a fixed seed (RC_PARAMS in tests/CMakeLists.txt); RC_PARAMS="seed=N" on the
// command line explores others, and a failure prints the `reproduce` string to replay it.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "colour_range.hpp"
#include "math/cpu_separable_filter.hpp"
#include "math/exact_reference.hpp"
#include "math/filter_constants.hpp"
#include "math/half_float.hpp"
#include "math/projection.hpp"
#include "math/separable_kernel.hpp"
#include "sss/sss_tools.h"

namespace {

using sss::math::Matrix4;

float from_bits(uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

uint32_t to_bits(float f) {
  uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  return bits;
}

// ---- generators ----

// A value in [0, 1]: the ends and a denormal often, else uniform (shrinks towards 0).
rc::Gen<float> unit_float() {
  return rc::gen::weightedOneOf<float>(
      {{1, rc::gen::just(0.0f)},
       {1, rc::gen::just(1.0f)},
       {1, rc::gen::just(std::numeric_limits<float>::denorm_min())},
       {1, rc::gen::just(0.001f)},
       {6, rc::gen::map(rc::gen::inRange(0, 1000001), [](int i) { return static_cast<float>(i) * 1e-6f; })}});
}

rc::Gen<int> tap_count() {
  return rc::gen::map(rc::gen::inRange(0, (SSS_MAX_TAPS - SSS_MIN_TAPS) / 2 + 1),
                      [](int k) { return SSS_MIN_TAPS + 2 * k; });
}

rc::Gen<std::array<float, 3>> unit_triple() {
  return rc::gen::map(rc::gen::tuple(unit_float(), unit_float(), unit_float()),
                      [](const std::tuple<float, float, float>& t) {
                        return std::array<float, 3>{std::get<0>(t), std::get<1>(t), std::get<2>(t)};
                      });
}

// Any float at all: every bit pattern (NaN, infinities, denormals, -0).
rc::Gen<float> any_float() { return rc::gen::map(rc::gen::arbitrary<uint32_t>(), from_bits); }

// Colours: ordinary values, and every extreme.
rc::Gen<float> colour_value() {
  return rc::gen::weightedOneOf<float>(
      {{8, rc::gen::map(rc::gen::inRange(-1000, 100001), [](int i) { return static_cast<float>(i) * 1e-3f; })},
       {1, rc::gen::element(0.0f, -0.0f, 65504.0f, -65504.0f, 65520.0f, 1e5f, std::numeric_limits<float>::max(),
                            std::numeric_limits<float>::denorm_min(), 5.9604645e-08f)},
       {1, any_float()}});
}

struct Camera {
  Matrix4 m{};
  double near_d = 0.1, far_d = 10.0;  // a range of distances in front of it
  bool zero_to_one = false;
  const char* kind = "";
};

void show(const Camera& c, std::ostream& os) {
  os << c.kind << " near " << c.near_d << " far " << c.far_d << " m = {";
  for (float v : c.m) os << v << ' ';
  os << '}';
}

rc::Gen<Camera> camera() {
  return rc::gen::exec([] {
    Camera c;
    const int kind = *rc::gen::inRange(0, 5);
    const double near_d = std::pow(10.0, *rc::gen::inRange(-60, 21) / 10.0);  // 1e-6 .. 100
    const double far_d = near_d * std::pow(10.0, *rc::gen::inRange(1, 81) / 10.0);
    const double fov = *rc::gen::inRange(1, 17900) * 0.01;  // degrees
    const double aspect = std::pow(10.0, *rc::gen::inRange(-20, 21) / 10.0);
    const double f = 1.0 / std::tan(fov * 3.14159265358979323846 / 360.0);
    c.near_d = near_d;
    c.far_d = far_d;
    if (kind == 4) {  // orthographic
      c.kind = "orthographic";
      const double half = std::pow(10.0, *rc::gen::inRange(-30, 41) / 10.0);
      c.m[0] = static_cast<float>(1.0 / (half * aspect));
      c.m[5] = static_cast<float>(1.0 / half);
      c.m[10] = static_cast<float>(-2.0 / (far_d - near_d));
      c.m[14] = static_cast<float>(-(far_d + near_d) / (far_d - near_d));
      c.m[15] = 1.0f;
      return c;
    }
    c.m[0] = static_cast<float>(f / aspect);
    c.m[5] = static_cast<float>(f);
    c.m[11] = -1.0f;
    if (kind == 0) {
      c.kind = "perspective";
      c.m[10] = static_cast<float>((far_d + near_d) / (near_d - far_d));
      c.m[14] = static_cast<float>(2.0 * far_d * near_d / (near_d - far_d));
    } else if (kind == 1) {
      c.kind = "infinite";
      c.m[10] = -1.0f;
      c.m[14] = static_cast<float>(-2.0 * near_d);
    } else if (kind == 2) {
      c.kind = "reversed-Z [0,1]";
      c.zero_to_one = true;
      c.m[10] = static_cast<float>(near_d / (far_d - near_d));
      c.m[14] = static_cast<float>(far_d * near_d / (far_d - near_d));
    } else {
      c.kind = "off-centre";
      c.m[8] = static_cast<float>(*rc::gen::inRange(-300, 301)) * 0.01f;
      c.m[9] = static_cast<float>(*rc::gen::inRange(-300, 301)) * 0.01f;
      c.m[10] = static_cast<float>((far_d + near_d) / (near_d - far_d));
      c.m[14] = static_cast<float>(2.0 * far_d * near_d / (near_d - far_d));
    }
    return c;
  });
}

double ndc_of(const Matrix4& m, double distance) {
  const double z = -distance;
  return (m[10] * z + m[14]) / (m[11] * z + m[15]);
}

// ---- kernel ----

RC_GTEST_PROP(KernelProperties, WeightsAreFiniteNonNegativeAndSumToOne, ()) {
  const int n = *tap_count();
  const auto strength = *unit_triple();
  const auto falloff = *unit_triple();
  const auto kernel = sss::math::separable_kernel(n, strength, falloff);
  RC_ASSERT(kernel.size() == static_cast<std::size_t>(n));
  const double range = sss::math::kSeparableKernelRangeMm;
  RC_ASSERT(kernel[0].offset_mm == 0.0f);
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0;
    for (const auto& tap : kernel) {
      const float w = tap.weight[static_cast<std::size_t>(c)];
      RC_ASSERT(std::isfinite(w));
      RC_ASSERT(w >= 0.0f);
      sum += w;
    }
    RC_ASSERT(std::fabs(sum - 1.0) <= 1e-6);
  }
  for (std::size_t i = 1; i < kernel.size(); ++i) {
    RC_ASSERT(std::fabs(kernel[i].offset_mm) <= static_cast<float>(range));
    if (i >= 2) RC_ASSERT(kernel[i - 1].offset_mm < kernel[i].offset_mm);
    const auto& mirror = kernel[kernel.size() - i];  // taps 1 + k and n - 1 - k mirror each other
    RC_ASSERT(mirror.offset_mm == -kernel[i].offset_mm);
    for (int c = 0; c < 3; ++c) {
      RC_ASSERT(std::fabs(mirror.weight[static_cast<std::size_t>(c)] - kernel[i].weight[static_cast<std::size_t>(c)]) <=
                1e-7f);
    }
  }
}

RC_GTEST_PROP(KernelProperties, StrengthZeroIsTheIdentityAndMoreStrengthNeverRaisesTheCentre, ()) {
  const int n = *tap_count();
  const auto falloff = *unit_triple();
  const auto identity = sss::math::separable_kernel(n, {0.0f, 0.0f, 0.0f}, falloff);
  RC_ASSERT(identity[0].weight == (std::array<float, 3>{1.0f, 1.0f, 1.0f}));
  for (std::size_t i = 1; i < identity.size(); ++i) RC_ASSERT(identity[i].weight == (std::array<float, 3>{0, 0, 0}));
  float a = *unit_float(), b = *unit_float();
  if (a > b) std::swap(a, b);
  const auto weak = sss::math::separable_kernel(n, {a, a, a}, falloff);
  const auto strong = sss::math::separable_kernel(n, {b, b, b}, falloff);
  for (int c = 0; c < 3; ++c)
    RC_ASSERT(strong[0].weight[static_cast<std::size_t>(c)] <= weak[0].weight[static_cast<std::size_t>(c)] + 1e-7f);
}

RC_GTEST_PROP(KernelProperties, ThePublicKernelApiAcceptsExactlyTheDocumentedRange, ()) {
  const int n =
      *rc::gen::weightedOneOf<int>({{3, tap_count()}, {1, rc::gen::arbitrary<int>()}, {1, rc::gen::inRange(-3, 70)}});
  const float s[3] = {*rc::gen::weightedOneOf<float>({{4, unit_float()}, {1, any_float()}}), *unit_float(),
                      *unit_float()};
  const float f[3] = {*unit_float(), *unit_float(),
                      *rc::gen::weightedOneOf<float>({{4, unit_float()}, {1, any_float()}})};
  std::vector<float> out(SSS_MAX_TAPS * 4 + 4, -9.0f);
  const bool valid = n >= SSS_MIN_TAPS && n <= SSS_MAX_TAPS && n % 2 != 0 && s[0] >= 0.0f && s[0] <= 1.0f &&
                     f[2] >= 0.0f && f[2] <= 1.0f;
  const sss_result r = sss_kernel_separable(n, s, f, out.data());
  RC_ASSERT(r == (valid ? SSS_OK : SSS_ERROR_INVALID_ARGUMENT));
  const std::size_t written = valid ? static_cast<std::size_t>(n) * 4 : 0;
  for (std::size_t i = written; i < out.size(); ++i) RC_ASSERT(out[i] == -9.0f);  // nothing beyond
}

// ---- projection ----

RC_GTEST_PROP(ProjectionProperties, GeneratedCamerasAreAcceptedAndDepthRoundTrips, ()) {
  const Camera c = *camera();
  RC_LOG() << [&] {
    std::ostringstream os;
    show(c, os);
    return os.str();
  }();
  std::string why;
  RC_ASSERT(sss::math::check_projection(c.m, &why) == sss::math::ProjectionCheck::ok);
  const double t = *rc::gen::inRange(0, 1001) / 1000.0;
  const double d = c.near_d * std::pow(c.far_d / c.near_d, t);
  const double back = sss::math::distance_from_ndc_z(c.m, ndc_of(c.m, d));
  // float matrix elements: the round trip is exact up to their rounding, amplified where depth
  // has little resolution (near the far plane of a deep frustum); checked where it has enough.
  const double ndc = ndc_of(c.m, d), ndc_near = ndc_of(c.m, c.near_d);
  if (std::fabs(ndc - ndc_of(c.m, d * 1.001)) > 1e-9 && std::isfinite(ndc_near)) {
    RC_ASSERT(std::fabs(back - d) <= 2e-3 * d);
  }
  const double w = sss::math::clip_w_from_distance(c.m, d);
  RC_ASSERT(w > 0.0);
}

RC_GTEST_PROP(ProjectionProperties, ArbitraryMatricesAreJudgedConsistently, ()) {
  Matrix4 m;
  for (float& v : m)
    v = *rc::gen::weightedOneOf<float>({{3, rc::gen::just(0.0f)}, {2, colour_value()}, {1, any_float()}});
  std::string why = "unset";
  const auto verdict = sss::math::check_projection(m, &why);
  if (verdict != sss::math::ProjectionCheck::ok) {
    RC_ASSERT(why != "unset");
    RC_ASSERT(!why.empty());
    return;
  }
  for (float v : m) RC_ASSERT(std::isfinite(v));
  RC_ASSERT(m[0] != 0.0f);
  RC_ASSERT(m[5] != 0.0f);
  RC_ASSERT(sss::math::depth_map_determinant(m) != 0.0);
  RC_ASSERT(m[1] == 0.0f && m[3] == 0.0f && m[4] == 0.0f && m[7] == 0.0f);
}

// ---- fp16 rounding ----

// binary16 rounding by integer arithmetic, independent of round_to_half's frexp/nearbyint.
float half_reference(float x) {
  const uint32_t bits = to_bits(x);
  const uint32_t sign = bits & 0x80000000u;
  const uint32_t magnitude = bits & 0x7FFFFFFFu;
  if (magnitude >= 0x7F800000u) return x;  // Inf, NaN
  // Work in units of 2^-24 (the half denormal quantum) on a 64-bit integer with 2 extra bits.
  const int exponent = static_cast<int>(magnitude >> 23);
  const uint64_t mantissa = exponent == 0 ? (magnitude & 0x7FFFFF) : ((magnitude & 0x7FFFFF) | 0x800000);
  const int e = exponent == 0 ? -126 : exponent - 127;  // value = mantissa · 2^(e - 23)
  // The half quantum for this magnitude: 2^-24 below 2^-14, else 2^(floor(log2) - 10).
  const int floor_log2 = exponent == 0 ? -127 : e;
  const int q = std::max(-24, floor_log2 - 10);
  // value / 2^q = mantissa · 2^(e - 23 - q), rounded to nearest even.
  const int shift = q - (e - 23);
  uint64_t units;
  if (shift <= 0) {
    units = mantissa << (-shift);
  } else if (shift >= 63) {
    units = 0;
  } else {
    const uint64_t whole = mantissa >> shift, rest = mantissa & ((uint64_t{1} << shift) - 1);
    const uint64_t halfway = uint64_t{1} << (shift - 1);
    units = whole + ((rest > halfway || (rest == halfway && (whole & 1))) ? 1 : 0);
  }
  const double value = std::ldexp(static_cast<double>(units), q);
  if (value >= 65520.0) return sign ? -std::numeric_limits<float>::infinity() : std::numeric_limits<float>::infinity();
  const float result = static_cast<float>(value);
  return sign ? -result : result;
}

RC_GTEST_PROP(HalfFloatProperties, RoundingMatchesAnIntegerReferenceIsIdempotentAndMonotone, ()) {
  const float x = *rc::gen::weightedOneOf<float>({{3, any_float()}, {2, colour_value()}});
  const float r = sss::math::round_to_half(x);
  const float expected = half_reference(x);
  if (std::isnan(x)) {
    RC_ASSERT(std::isnan(r));
    return;
  }
  RC_ASSERT(to_bits(r) == to_bits(expected));
  RC_ASSERT(to_bits(sss::math::round_to_half(r)) == to_bits(r));
  const float y = *colour_value();
  if (!std::isnan(y) && x <= y) RC_ASSERT(sss::math::round_to_half(x) <= sss::math::round_to_half(y));
}

// ---- pass constants ----

RC_GTEST_PROP(PassConstantProperties, AreNeverNaNAndClampInsideTheViewport, ()) {
  const Camera c = *camera();
  sss::math::FilterSettings s;
  s.world_units_per_mm = *rc::gen::weightedOneOf<float>({{1, rc::gen::just(std::numeric_limits<float>::denorm_min())},
                                            {1, rc::gen::just(1e6f)},
                                            {4, rc::gen::map(unit_float(), [](float u) { return u * 10.0f; })}});
  s.samples = *tap_count();
  s.follow_surface = *rc::gen::arbitrary<bool>();
  sss::math::FrameGeometry g;
  g.texture_width = *rc::gen::inRange(1, 8193);
  g.texture_height = *rc::gen::inRange(1, 8193);
  const int vx = *rc::gen::inRange(0, g.texture_width), vy = *rc::gen::inRange(0, g.texture_height);
  g.viewport = {vx, vy, *rc::gen::inRange(1, g.texture_width - vx + 1),
                *rc::gen::inRange(1, g.texture_height - vy + 1)};
  const auto k = sss::math::compute_pass_constants(s, c.m, g);
  for (float p : k.pixels_per_mm) RC_ASSERT(p >= 0.0f);  // false for NaN
  RC_ASSERT(k.follow_surface_factor >= 0.0f);
  RC_ASSERT(s.follow_surface || k.follow_surface_factor == 0.0f);
  for (int a = 0; a < 2; ++a) {
    const float lo = k.clamp_min[static_cast<std::size_t>(a)], hi = k.clamp_max[static_cast<std::size_t>(a)];
    RC_ASSERT(lo <= hi);
    RC_ASSERT(lo >= static_cast<float>(g.viewport[static_cast<std::size_t>(a)]));
    RC_ASSERT(hi <= static_cast<float>(g.viewport[static_cast<std::size_t>(a)] +
                                       g.viewport[static_cast<std::size_t>(a) + 2]));
  }
}

// ---- the CPU model of the two passes ----

struct ModelCase {
  int width = 1, height = 1;
  std::vector<float> color, depth;
  std::vector<uint8_t> mask;
  sss::math::FilterSettings settings;
  Camera camera;
  bool linear = false, half_output = false, flat = false;
};

void show(const ModelCase& m, std::ostream& os) {
  os << m.width << "x" << m.height << (m.linear ? " linear" : " hardware") << " depth, samples " << m.settings.samples
     << " width " << m.settings.world_units_per_mm << (m.flat ? " flat" : "") << "; camera ";
  show(m.camera, os);
  os << "\ncolour:";
  for (float v : m.color) os << ' ' << v;
  os << "\ndepth:";
  for (float v : m.depth) os << ' ' << v;
}

rc::Gen<ModelCase> model_case() {
  return rc::gen::exec([] {
    ModelCase m;
    m.width = *rc::gen::inRange(1, 9);
    m.height = *rc::gen::inRange(1, 9);
    const std::size_t n = static_cast<std::size_t>(m.width) * m.height;
    m.camera = *camera();
    m.linear = *rc::gen::arbitrary<bool>();
    m.half_output = *rc::gen::arbitrary<bool>();
    m.flat = *rc::gen::inRange(0, 4) == 0;
    m.settings.world_units_per_mm = *rc::gen::map(unit_float(), [](float u) { return u * u * 2.0f; });
    m.settings.strength = *unit_triple();
    m.settings.falloff = *unit_triple();
    m.settings.samples = *tap_count();
    m.settings.follow_surface = *rc::gen::arbitrary<bool>();
    const float alpha_flat = *rc::gen::element(1.0f, 0.5f, 3.0f);
    const float rgb_flat[3] = {static_cast<float>(*rc::gen::inRange(0, 65000)) * 1.0f,
                               static_cast<float>(*rc::gen::inRange(0, 1000)) * 1e-3f, 0.25f};
    const double d_flat = m.camera.near_d * 1.5;
    for (std::size_t i = 0; i < n; ++i) {
      for (int c = 0; c < 4; ++c) {
        m.color.push_back(m.flat ? (c < 3 ? rgb_flat[c] : alpha_flat)
                                 : (c < 3 ? *colour_value()
                                          : *rc::gen::weightedOneOf<float>(
                                                {{6, rc::gen::just(1.0f)}, {2, unit_float()}, {1, colour_value()}})));
      }
      double d = m.flat
                     ? d_flat
                     : m.camera.near_d * std::pow(m.camera.far_d / m.camera.near_d, *rc::gen::inRange(0, 101) / 100.0);
      float raw = m.linear ? static_cast<float>(d)
                           : static_cast<float>(m.camera.zero_to_one ? ndc_of(m.camera.m, d)
                                                                     : 0.5 * ndc_of(m.camera.m, d) + 0.5);
      if (!m.flat && *rc::gen::inRange(0, 8) == 0) raw = *any_float();  // any value at all
      m.depth.push_back(raw);
      m.mask.push_back(m.flat ? 1 : static_cast<uint8_t>(*rc::gen::inRange(0, 5) != 0));
    }
    return m;
  });
}

std::vector<float> run_model(const ModelCase& m) {
  sss::math::FrameGeometry g;
  g.texture_width = m.width;
  g.texture_height = m.height;
  g.viewport = {0, 0, m.width, m.height};
  g.depth = m.linear               ? sss::math::DepthEncoding::linear_distance
            : m.camera.zero_to_one ? sss::math::DepthEncoding::hardware_zero_to_one
                                   : sss::math::DepthEncoding::hardware_minus_one_to_one;
  const auto kernel = sss::math::build_pass_kernel(m.settings);  // as the module builds it
  const auto constants = sss::math::compute_pass_constants(m.settings, m.camera.m, g, kernel.reach_mm);
  sss::math::CpuFilterImage image;
  image.width = m.width;
  image.height = m.height;
  image.color = m.color.data();
  image.depth = m.depth.data();
  image.mask = m.mask.data();
  image.output_is_half = m.half_output;
  std::vector<float> out(m.color.size());
  sss::math::cpu_pass_kernel_filter(kernel, constants, image, out.data());
  return out;
}

RC_GTEST_PROP(CpuModelProperties, FiniteStaysFiniteNothingSpreadsAndBlursStayInRange, ()) {
  const ModelCase m = *model_case();
  RC_LOG() << [&] {
    std::ostringstream os;
    show(m, os);
    return os.str();
  }();
  const std::vector<float> out = run_model(m);
  const std::size_t n = m.mask.size();
  const sss_test::ColourRange range = sss_test::finite_colour_range(m.color.data(), n);
  for (std::size_t i = 0; i < n; ++i) {
    const float* in = &m.color[i * 4];
    const float* o = &out[i * 4];
    const bool finite = std::isfinite(in[0]) && std::isfinite(in[1]) && std::isfinite(in[2]) && std::isfinite(in[3]);
    RC_ASSERT(to_bits(o[3]) == to_bits(in[3]));  // alpha is never written
    if (!finite || !(in[3] > 0.0f) || m.mask[i] == 0) {
      RC_ASSERT(std::memcmp(o, in, 16) == 0);  // kept bit for bit
      continue;
    }
    for (int c = 0; c < 3; ++c) {
      RC_ASSERT(std::isfinite(o[c]));
      // Kept (bit for bit), or a blur: within the finite inputs' range (fp16 rounding and the float
      // sum's error allowed: colour_range.hpp).
      if (to_bits(o[c]) == to_bits(in[c])) continue;
      RC_ASSERT(o[c] >= range.least(c));
      RC_ASSERT(o[c] <= range.greatest(c));
      if (m.flat) RC_ASSERT(std::fabs(o[c] - in[c]) <= std::fabs(in[c]) * (1.0f / 1024.0f) + 6e-8f);
    }
  }
}

RC_GTEST_PROP(CpuModelProperties, StrengthZeroChangesNothingButFp16Rounding, ()) {
  ModelCase m = *model_case();
  m.settings.strength = {0.0f, 0.0f, 0.0f};
  const std::vector<float> out = run_model(m);
  for (std::size_t i = 0; i < m.color.size(); ++i) {
    const float in = m.color[i];
    if (std::isnan(in)) {
      RC_ASSERT(std::isnan(out[i]));
      continue;
    }
    // The one-tap kernel returns the centre; only the RGBA16F intermediate (and a half output) round it.
    const float h = sss::math::round_to_half(in);
    RC_ASSERT(out[i] == in || out[i] == h);
  }
}

// ---- the exact reference ----

RC_GTEST_PROP(ExactReferenceProperties, FiniteNonNegativeLinearAndUnusablePixelsKept, ()) {
  const int w = *rc::gen::inRange(1, 6), h = *rc::gen::inRange(1, 6);
  const std::size_t n = static_cast<std::size_t>(w) * h;
  const Camera c = *camera();
  std::vector<float> irradiance(n * 4), distance(n);
  std::vector<uint8_t> mask(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int ch = 0; ch < 4; ++ch) irradiance[i * 4 + ch] = static_cast<float>(*rc::gen::inRange(0, 100001)) * 1e-3f;
    distance[i] = static_cast<float>(c.near_d * std::pow(c.far_d / c.near_d, *rc::gen::inRange(0, 101) / 100.0));
    if (*rc::gen::inRange(0, 10) == 0) distance[i] = *any_float();
    mask[i] = static_cast<uint8_t>(*rc::gen::inRange(0, 6) != 0);
  }
  sss::math::ExactInput input;
  input.width = w;
  input.height = h;
  input.irradiance = irradiance.data();
  input.distance = distance.data();
  input.mask = mask.data();
  input.projection = c.m;
  input.world_units_per_mm = std::pow(10.0, *rc::gen::inRange(-50, 11) / 10.0);
  sss::math::ExactOptions options;
  options.threads = 1;
  std::vector<double> out(n * 3), scaled(n * 3);
  const sss::math::PixelRegion all{0, 0, w, h};
  sss::math::exact_surface_convolution(input, sss::math::skin_profile_terms(), all, out.data(), options);
  std::vector<float> doubled = irradiance;
  for (float& v : doubled) v *= 2.0f;
  input.irradiance = doubled.data();
  sss::math::exact_surface_convolution(input, sss::math::skin_profile_terms(), all, scaled.data(), options);
  for (std::size_t i = 0; i < n; ++i) {
    const float d = distance[i];
    const bool usable = mask[i] != 0 && std::isfinite(d) && sss::math::clip_w_from_distance(c.m, d) > 0.0;
    for (int ch = 0; ch < 3; ++ch) {
      const double v = out[i * 3 + ch];
      RC_ASSERT(std::isfinite(v));
      RC_ASSERT(v >= 0.0);
      RC_ASSERT(std::fabs(scaled[i * 3 + ch] - 2.0 * v) <= 1e-12 * std::max(1.0, std::fabs(v)));
      if (!usable) RC_ASSERT(v == static_cast<double>(irradiance[i * 4 + ch]));
    }
  }
}

RC_GTEST_PROP(ExactReferenceProperties, BadInputThrowsInvalidArgument, ()) {
  sss::math::ExactInput input;
  std::vector<float> irradiance(16, 1.0f), distance(4, 1.0f);
  input.width = *rc::gen::inRange(-2, 3);
  input.height = 2;
  input.irradiance = irradiance.data();
  input.distance = distance.data();
  input.projection = (*camera()).m;
  input.world_units_per_mm = *rc::gen::element(0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity(), 1e-3);
  const bool valid = input.width > 0 && input.world_units_per_mm == 1e-3;
  sss::math::ExactOptions options;
  options.threads = 1;
  std::vector<double> out(12);
  try {
    sss::math::exact_surface_convolution(input, sss::math::skin_profile_terms(),
                                         sss::math::PixelRegion{0, 0, std::max(input.width, 0), 2}, out.data(),
                                         options);
    RC_ASSERT(valid);
  } catch (const std::invalid_argument&) {
    RC_ASSERT(!valid);
  }
}

}  // namespace
