#include "stress_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "colour_range.hpp"

using namespace host_gl;

namespace sss_test {

const char* depth_format_name(DepthFormat f) {
  switch (f) {
    case DepthFormat::depth16:
      return "DEPTH_COMPONENT16";
    case DepthFormat::depth24:
      return "DEPTH_COMPONENT24";
    case DepthFormat::depth32f:
      return "DEPTH_COMPONENT32F";
    case DepthFormat::depth24_stencil8:
      return "DEPTH24_STENCIL8";
    case DepthFormat::depth32f_stencil8:
      return "DEPTH32F_STENCIL8";
    case DepthFormat::r16f:
      return "R16F";
    case DepthFormat::r32f:
      return "R32F";
  }
  return "?";
}

bool is_linear(DepthFormat f) { return f == DepthFormat::r16f || f == DepthFormat::r32f; }

float window_depth(const sss::math::Matrix4& m, double distance, bool zero_to_one) {
  const double z = -distance;
  const double ndc = (m[10] * z + m[14]) / (m[11] * z + m[15]);
  return static_cast<float>(zero_to_one ? ndc : 0.5 * ndc + 0.5);
}

StressFrame relief_frame(int width, int height, uint32_t seed, const sss::math::Matrix4& projection, double near_d,
                         double far_d, DepthFormat depth_format, float lo, float hi) {
  StressFrame f;
  f.width = width;
  f.height = height;
  f.depth_format = depth_format;
  const std::size_t n = static_cast<std::size_t>(width) * height;
  f.color.resize(n * 4);
  f.depth.resize(n);
  f.stencil.resize(n);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> value(lo, hi);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      const double u = (x + 0.5) / width, v = (y + 0.5) / height;
      double t = 0.2 + 0.5 * u + 0.2 * v;  // tilted plane
      if (u < 0.3 && v < 0.35) t = 0.1;    // a nearer step
      const double distance = near_d + (far_d - near_d) * t;
      f.depth[i] = is_linear(depth_format) ? static_cast<float>(distance) : window_depth(projection, distance, false);
      for (int c = 0; c < 3; ++c) f.color[i * 4 + c] = value(rng);
      float alpha = 1.0f;
      if (v > 0.75 && v < 0.85) alpha = 0.5f;
      if (u > 0.85 && v > 0.85) alpha = 0.0f;
      f.color[i * 4 + 3] = alpha;
      f.stencil[i] = u < 0.75 ? 1 : 0;
    }
  }
  return f;
}

void StressTest::SetUp() {
  GlTest::SetUp();
  if (HasFatalFailure()) return;
  sss_ = create_sss();
  ASSERT_NE(sss_, nullptr);
}

void StressTest::TearDown() {
  report_tally(category_, tally_);
  std::printf("[stress] %s: %ld cases, %ld checks, %ld failures\n", category_.c_str(), tally_.cases, tally_.checks,
              tally_.failures);
  GlTest::TearDown();
}

void StressTest::set_wide_kernel(const sss::math::Matrix4& camera, float world_units_per_mm, int samples) {
  ASSERT_EQ(sss_set_camera(sss_, camera.data()), SSS_OK);
  sss_settings s;
  sss_default_settings(&s);
  s.world_units_per_mm = world_units_per_mm;
  s.strength[0] = s.strength[1] = s.strength[2] = 1.0f;
  s.taps = samples;
  ASSERT_EQ(set_settings(s), SSS_OK);
}

void StressTest::add_second_profile(float scale) {
  sss_settings profiles[2];
  profiles[0].struct_size = sizeof profiles[0];
  ASSERT_EQ(sss_get_settings(sss_, &profiles[0]), SSS_OK);
  profiles[1] = profiles[0];
  profiles[1].scale = scale;
  ASSERT_EQ(sss_set_profiles(sss_, profiles, 2), SSS_OK) << sss_last_error(sss_);
}

std::vector<uint16_t> StressTest::banded_ids(int width, int height) {
  std::vector<uint16_t> ids(static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const int band = (x / 3 + y / 2) % 3;  // 0: profile 0; 1: profile 1; 2: profile 0, object 1
      ids[static_cast<std::size_t>(y) * width + x] = static_cast<uint16_t>(band == 0 ? 0 : band == 1 ? 1 : 0x10);
    }
  }
  return ids;
}

sss_result StressTest::set_settings(const sss_settings& s) {
  const sss_result r = sss_set_settings(sss_, &s);
  EXPECT_EQ(r, SSS_OK) << sss_last_error(sss_);
  return r;
}

bool StressTest::check(bool ok, const std::string& what) {
  ++tally_.checks;
  if (ok) return true;
  ++tally_.failures;
  if (++reported_ <= 12) ADD_FAILURE() << what;
  return false;
}

namespace {

using MakeTexture = std::function<GLuint(GLenum, int, int, GLenum, GLenum, const void*)>;

GLuint upload_depth(const StressFrame& f, const MakeTexture& make) {
  const std::size_t n = f.depth.size();
  auto stencil_of = [&](std::size_t i) -> uint32_t { return f.stencil.empty() ? 0u : f.stencil[i]; };
  switch (f.depth_format) {
    case DepthFormat::depth16:
      return make(GL_DEPTH_COMPONENT16, f.width, f.height, GL_DEPTH_COMPONENT, GL_FLOAT, f.depth.data());
    case DepthFormat::depth24:
      return make(GL_DEPTH_COMPONENT24, f.width, f.height, GL_DEPTH_COMPONENT, GL_FLOAT, f.depth.data());
    case DepthFormat::depth32f:
      return make(GL_DEPTH_COMPONENT32F, f.width, f.height, GL_DEPTH_COMPONENT, GL_FLOAT, f.depth.data());
    case DepthFormat::depth24_stencil8: {
      std::vector<uint32_t> packed(n);
      for (std::size_t i = 0; i < n; ++i) {
        const float d = f.depth[i];
        const double clamped = d >= 0.0f ? (d <= 1.0f ? d : 1.0) : 0.0;  // NaN -> 0
        packed[i] = (static_cast<uint32_t>(std::lround(clamped * 16777215.0)) << 8) | stencil_of(i);
      }
      return make(GL_DEPTH24_STENCIL8, f.width, f.height, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed.data());
    }
    case DepthFormat::depth32f_stencil8: {
      std::vector<uint32_t> packed(n * 2);
      for (std::size_t i = 0; i < n; ++i) {
        std::memcpy(&packed[i * 2], &f.depth[i], sizeof(float));
        packed[i * 2 + 1] = stencil_of(i);
      }
      return make(GL_DEPTH32F_STENCIL8, f.width, f.height, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV,
                  packed.data());
    }
    case DepthFormat::r16f:
      return make(GL_R16F, f.width, f.height, GL_RED, GL_FLOAT, f.depth.data());
    case DepthFormat::r32f:
      return make(GL_R32F, f.width, f.height, GL_RED, GL_FLOAT, f.depth.data());
  }
  return 0;
}

bool same_bits(const float* a, const float* b, int n) { return std::memcmp(a, b, sizeof(float) * n) == 0; }

std::string pixel_name(const StressFrame& f, std::size_t i) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "pixel (%d, %d) of %dx%d", static_cast<int>(i % f.width),
                static_cast<int>(i / f.width), f.width, f.height);
  return buffer;
}

std::string rgba(const float* v) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "{%g, %g, %g, %g}", static_cast<double>(v[0]), static_cast<double>(v[1]),
                static_cast<double>(v[2]), static_cast<double>(v[3]));
  return buffer;
}

}  // namespace

StressOutcome StressTest::run(const StressFrame& f) {
  StressOutcome o;
  const std::size_t first_texture = textures_.size();
  const GLenum color_format = f.half_color ? GL_RGBA16F : GL_RGBA32F;
  const GLuint color = make_texture(color_format, f.width, f.height, GL_RGBA, GL_FLOAT, f.color.data());
  const GLuint depth =
      upload_depth(f, [this](GLenum internal_format, int w, int h, GLenum format, GLenum type, const void* data) {
        return make_texture(internal_format, w, h, format, type, data);
      });
  GLuint output = 0;
  if (f.separate_output) {
    const std::vector<float> sentinel(f.color.size(), kSentinel);
    output = make_texture(color_format, f.width, f.height, GL_RGBA, GL_FLOAT, sentinel.data());
  }
  o.input = read_rgba(color, f.width, f.height);
  sss_stencil stencil = {depth, 1, 0xFF};
  sss_frame frame = frame_of(color, depth, output);
  if (!f.profile_ids.empty()) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    frame.profile_texture =
        make_texture(GL_R16UI, f.width, f.height, GL_RED_INTEGER, GL_UNSIGNED_SHORT, f.profile_ids.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  }
  frame.stencil = f.use_stencil ? &stencil : nullptr;
  std::memcpy(frame.viewport, f.viewport, sizeof frame.viewport);
  frame.flags = f.flags;
  frame.projection = f.projection;
  o.result = sss_apply_frame(sss_, &frame);
  o.output = read_rgba(output != 0 ? output : color, f.width, f.height);
  const GLenum error = glGetError();
  check(error == GL_NO_ERROR, "GL error left behind: " + std::to_string(error));
  glDeleteTextures(static_cast<GLsizei>(textures_.size() - first_texture), textures_.data() + first_texture);
  textures_.resize(first_texture);
  ++tally_.cases;
  return o;
}

bool StressTest::run_and_check(const StressFrame& frame, const Expectations& expect) {
  return check_invariants(frame, run(frame), expect);
}

bool StressTest::check_invariants(const StressFrame& f, const StressOutcome& o, const Expectations& e) {
  if (!check(o.result == SSS_OK, std::string("sss_apply_frame failed: ") + sss_last_error(sss_))) return false;
  const long failures_before = tally_.failures;
  const std::size_t n = static_cast<std::size_t>(f.width) * f.height;
  const bool whole = f.viewport[2] == 0;
  const int vx = whole ? 0 : f.viewport[0], vy = whole ? 0 : f.viewport[1];
  const int vw = whole ? f.width : f.viewport[2], vh = whole ? f.height : f.viewport[3];

  // The range of each channel over the pixels a tap can take (finite colour).
  const ColourRange range = finite_colour_range(o.input.data(), n);
  const std::array<float, 3>& lo = range.lo;
  const std::array<float, 3>& hi = range.hi;
  // Two fp16 roundings (the intermediate target, then an RGBA16F output) may each lose one ulp
  // (llvmpipe stores toward zero: a sum of 122.99999 becomes 122.9375): 2^-9 of the value. The
  // float sum of up to 65 taps adds ~65·2^-24 of the largest magnitude; 2^-24 covers fp16's
  // smallest denormal.
  constexpr float kUlp = 1.0f / 512.0f, kTiny = 1.0f / 16777216.0f;
  const float accumulation = range.magnitude * 4e-6f;

  for (std::size_t i = 0; i < n; ++i) {
    const int x = static_cast<int>(i % f.width), y = static_cast<int>(i / f.width);
    const float* in = &o.input[i * 4];
    const float* out = &o.output[i * 4];
    const bool inside = x >= vx && x < vx + vw && y >= vy && y < vy + vh;
    if (!inside) {
      if (f.separate_output) {
        const float sentinel[4] = {kSentinel, kSentinel, kSentinel, kSentinel};
        check_lazy(same_bits(out, sentinel, 4),
                   [&] { return pixel_name(f, i) + " outside the viewport was written: " + rgba(out); });
      } else {
        check_lazy(same_bits(out, in, 4), [&] {
          return pixel_name(f, i) + " outside the viewport changed: " + rgba(in) + " -> " + rgba(out);
        });
      }
      continue;
    }
    const bool finite = std::isfinite(in[0]) && std::isfinite(in[1]) && std::isfinite(in[2]) && std::isfinite(in[3]);
    const bool masked_out = f.use_stencil && (f.stencil.empty() || f.stencil[i] != 1);
    const bool kept = e.identity || !finite || !(in[3] > 0.0f) || masked_out || (e.kept && e.kept(i));
    if (kept) {
      check_lazy(same_bits(out, in, 4),
                 [&] { return pixel_name(f, i) + " must keep its value: " + rgba(in) + " -> " + rgba(out); });
      continue;
    }
    check_lazy(same_bits(out + 3, in + 3, 1),
               [&] { return pixel_name(f, i) + " alpha changed: " + rgba(in) + " -> " + rgba(out); });
    for (int c = 0; c < 3; ++c) {
      const float v = out[c];
      if (!check_lazy(std::isfinite(v),
                      [&] { return pixel_name(f, i) + " is not finite: " + rgba(in) + " -> " + rgba(out); }))
        break;
      const std::size_t k = static_cast<std::size_t>(c);
      const float low = lo[k] - (std::fabs(lo[k]) * kUlp + accumulation + kTiny);
      const float high = hi[k] + (std::fabs(hi[k]) * kUlp + accumulation + kTiny);
      check_lazy(v >= low && v <= high, [&] {
        return pixel_name(f, i) + " channel " + std::to_string(c) + " = " + std::to_string(v) +
               " outside the input's range [" + std::to_string(lo[k]) + ", " + std::to_string(hi[k]) + "]";
      });
      if (e.flat) {
        check_lazy(std::fabs(v - in[c]) <= std::fabs(in[c]) * kUlp + kTiny,
                   [&] { return pixel_name(f, i) + " of a flat image changed: " + rgba(in) + " -> " + rgba(out); });
      }
    }
  }
  return tally_.failures == failures_before;
}

uint32_t stress_seed(uint32_t fallback) {
  const char* text = std::getenv("SSS_STRESS_SEED");
  if (text == nullptr || *text == '\0') return fallback;
  return static_cast<uint32_t>(std::strtoul(text, nullptr, 0));
}

void report_tally(const std::string& category, const Tally& tally) {
  const char* path = std::getenv("SSS_STRESS_REPORT");
  if (path == nullptr || *path == '\0') return;
  std::FILE* file = std::fopen(path, "a");
  if (file == nullptr) return;
  std::fprintf(file, "%s %ld %ld %ld\n", category.c_str(), tally.cases, tally.checks, tally.failures);
  std::fclose(file);
}

std::vector<float> extreme_floats() {
  const float inf = std::numeric_limits<float>::infinity();
  return {0.0f,
          -0.0f,
          std::numeric_limits<float>::denorm_min(),
          -std::numeric_limits<float>::denorm_min(),
          std::numeric_limits<float>::min(),
          1e-30f,
          5.9604645e-08f,  // the smallest fp16 denormal
          6.1035156e-05f,  // the smallest fp16 normal
          0.5f,
          1.0f,
          -1.0f,
          65504.0f,  // the largest fp16
          -65504.0f,
          65520.0f,  // rounds to Inf in fp16
          1e5f,
          1e30f,
          std::numeric_limits<float>::max(),
          -std::numeric_limits<float>::max(),
          inf,
          -inf,
          std::nanf("")};
}

}  // namespace sss_test
