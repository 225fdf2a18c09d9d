#include "heat_map.hpp"

#include "regions.hpp"

#include "gl_functions.hpp"
#include "metrics.hpp"

#include "math/exact_reference.hpp"
#include "math/projection.hpp"
#include "material_terms.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

namespace demo {

std::vector<float> read_texture_rgba(GLuint texture, int width, int height) {
  std::vector<float> rgba(static_cast<size_t>(width) * static_cast<size_t>(height) * 4u);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, rgba.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  return rgba;
}

std::vector<uint8_t> read_texture_r8ui(GLuint texture, int width, int height) {
  std::vector<uint8_t> bytes(static_cast<size_t>(width) * static_cast<size_t>(height));
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, bytes.data());
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glBindTexture(GL_TEXTURE_2D, 0);
  return bytes;
}

namespace {

sss_bench::RgbImage rgb_of(const std::vector<float> &rgba, int width, int height) {
  return sss_bench::RgbImage::from_rgba(rgba.data(), width, height);
}

}  // namespace

void small_frame_size(int width, int height, int factor, int *small_width, int *small_height) {
  factor = std::max(factor, 1);
  *small_width = std::max(16, (width + factor / 2) / factor);
  *small_height = std::max(16, (height + factor / 2) / factor);
}

double texturing_post_factor(int texturing, double albedo) {
  const double a = std::max(albedo, 1.0 / 256.0);
  return texturing == SSS_TEXTURING_POST_SCATTER           ? a
         : texturing == SSS_TEXTURING_PRE_AND_POST_SCATTER ? std::sqrt(a)
                                                           : 1.0;
}

SmallFrame read_small_frame(const FrameTargets &targets, const CameraMatrices &camera, bool sss_ran,
                            double world_units_per_mm, int texturing) {
  SmallFrame f;
  f.width = targets.width;
  f.height = targets.height;
  f.world_units_per_mm = world_units_per_mm;
  std::memcpy(f.projection.data(), glm::value_ptr(camera.projection), sizeof(float) * 16);
  f.before = read_texture_rgba(targets.diffuse, f.width, f.height);
  if (sss_ran) f.after = read_texture_rgba(targets.after, f.width, f.height);
  f.ids = read_texture_r8ui(targets.profile, f.width, f.height);
  f.texturing = texturing;
  f.albedo = read_texture_rgba(targets.albedo, f.width, f.height);  // for every mode: the post-scatter score

  const size_t n = static_cast<size_t>(f.width) * static_cast<size_t>(f.height);
  std::vector<float> depth(n);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.lighting_framebuffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, f.width, f.height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  f.distance.resize(n);
  f.mask.resize(n);
  for (size_t i = 0; i < n; ++i) {
    f.mask[i] = f.before[i * 4 + 3] > 0.0f ? 1 : 0;
    const double ndc_z = 2.0 * static_cast<double>(depth[i]) - 1.0;
    f.distance[i] = static_cast<float>(sss::math::distance_from_ndc_z(f.projection, ndc_z));
  }
  return f;
}

std::vector<int> reference_materials(const DemoScene &scene) {
  std::vector<int> materials;
  if (!uses_profiles(scene)) return materials;
  for (const SceneProfile &p : scene.profiles) materials.push_back(p.material < 0 ? SSS_PROFILE_SKIN_DEON : p.material);
  return materials;
}

namespace {

// Each profile/object byte's pixels with their own profile over their own pixels.
void per_material_reference(const SmallFrame &frame, const sss::math::ExactInput &base, Reference *r) {
  std::vector<uint8_t> values;
  for (size_t i = 0; i < frame.ids.size(); ++i) {
    if (frame.mask[i] != 0 && std::find(values.begin(), values.end(), frame.ids[i]) == values.end())
      values.push_back(frame.ids[i]);
  }
  std::vector<double> rgb(r->rgb.size());
  for (uint8_t value : values) {
    std::vector<uint8_t> mask(frame.mask.size());
    for (size_t i = 0; i < mask.size(); ++i) mask[i] = frame.mask[i] != 0 && frame.ids[i] == value ? 1 : 0;
    sss::math::ExactInput input = base;
    input.mask = mask.data();
    const size_t profile = value & 15u;
    const int material = profile < frame.materials.size() ? frame.materials[profile] : SSS_PROFILE_SKIN_DEON;
    sss::math::ExactSurfaceConvolution(input, sss_bench::material_profile_terms(material))
        .convolve({0, 0, frame.width, frame.height}, rgb.data());
    for (size_t i = 0; i < mask.size(); ++i) {
      if (mask[i] == 0) continue;
      for (size_t c = 0; c < 3; ++c) r->rgb[i * 3 + c] = rgb[i * 3 + c];
    }
  }
}

}  // namespace

Reference compute_reference(const SmallFrame &frame) {
  const auto start = std::chrono::steady_clock::now();
  // A texturing mode other than pre-scatter: the light divided by A_post is convolved, then multiplied by it.
  const bool textured = frame.texturing != SSS_TEXTURING_PRE_SCATTER && frame.albedo.size() == frame.before.size();
  std::vector<float> lit = frame.before;
  if (textured) {
    for (size_t i = 0; i < lit.size(); ++i) {
      if (i % 4 != 3) lit[i] = static_cast<float>(lit[i] / texturing_post_factor(frame.texturing, frame.albedo[i]));
    }
  }
  sss::math::ExactInput input;
  input.width = frame.width;
  input.height = frame.height;
  input.irradiance = lit.data();
  input.distance = frame.distance.data();
  input.mask = frame.mask.data();
  input.projection = frame.projection;
  input.world_units_per_mm = frame.world_units_per_mm;
  Reference r;
  r.width = frame.width;
  r.height = frame.height;
  r.rgb.resize(static_cast<size_t>(frame.width) * static_cast<size_t>(frame.height) * 3u);
  if (!frame.materials.empty()) {
    // Pixels outside every mask keep their input (the convolution's rule for them).
    for (size_t i = 0; i < frame.mask.size(); ++i) {
      for (size_t c = 0; c < 3; ++c) r.rgb[i * 3 + c] = lit[i * 4 + c];
    }
    per_material_reference(frame, input, &r);
  } else {
    const sss::math::ExactSurfaceConvolution exact(input, sss::math::skin_profile_terms());
    exact.convolve({0, 0, frame.width, frame.height}, r.rgb.data());
  }
  if (textured) {
    for (size_t i = 0; i < r.rgb.size(); ++i) {
      r.rgb[i] *= texturing_post_factor(frame.texturing, frame.albedo[i / 3 * 4 + i % 3]);
    }
  }
  r.texturing = frame.texturing;
  r.translucent_pixels = static_cast<size_t>(std::count(frame.mask.begin(), frame.mask.end(), 1));
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

HeatMap make_heat_map(const SmallFrame &frame, const Reference &reference, bool show_after, double scale,
                      double exposure) {
  HeatMap h;
  const int w = frame.width, height = frame.height;
  const sss_bench::RgbImage ref = sss_bench::RgbImage::from_rgb(reference.rgb.data(), w, height);
  const sss_bench::RgbImage before = rgb_of(frame.before, w, height);
  h.relative_rmse_before = sss_bench::relative_rmse(before, ref, frame.mask.data());
  h.shows_after = show_after && !frame.after.empty();
  sss_bench::RgbImage shown = before;
  if (!frame.after.empty()) {
    const sss_bench::RgbImage after = rgb_of(frame.after, w, height);
    h.relative_rmse_after = sss_bench::relative_rmse(after, ref, frame.mask.data());
    if (h.shows_after) shown = after;
  }
  {
    sss_bench::RegionInput regions;
    regions.width = w;
    regions.height = height;
    regions.mask = frame.mask.data();
    regions.distance = frame.distance.data();
    regions.projection = frame.projection;
    regions.world_units_per_mm = frame.world_units_per_mm;
    regions.reach_mm = sss_bench::profile_reach_mm(sss::math::skin_profile_terms());
    const std::vector<uint8_t> interior =
        sss_bench::region_mask(sss_bench::classify_regions(regions), sss_bench::Region::interior);
    const sss_bench::Miss miss =
        sss_bench::miss_share(frame.after.empty() ? before : rgb_of(frame.after, w, height), ref, before, interior.data());
    h.interior_pixels = miss.pixels;
    h.miss_interior = frame.after.empty() ? std::nan("") : miss.pooled;
    h.miss_interior_worst_channel = frame.after.empty() ? std::nan("") : miss.worst_channel();
  }
  h.max_abs_error = sss_bench::max_abs_error(shown, ref, frame.mask.data());
  h.p99_abs_error = sss_bench::percentile_abs_error(shown, ref, frame.mask.data(), 0.99);

  h.image.width = w;
  h.image.height = height;
  h.image.rgba.assign(static_cast<size_t>(w) * static_cast<size_t>(height) * 4u, 255);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = shown.index(x, y);
      uint8_t *out = &h.image.rgba[(static_cast<size_t>(height - 1 - y) * static_cast<size_t>(w) + static_cast<size_t>(x)) * 4u];
      if (frame.mask[i] != 0) {
        double e = 0.0;
        for (int c = 0; c < 3; ++c) e = std::max(e, std::fabs(shown.at(x, y, c) - ref.at(x, y, c)));
        const std::array<uint8_t, 3> colour = sss_bench::error_ramp(e / scale);
        std::copy(colour.begin(), colour.end(), out);
      } else {
        const double luminance = 0.2126 * shown.at(x, y, 0) + 0.7152 * shown.at(x, y, 1) + 0.0722 * shown.at(x, y, 2);
        const double grey = 0.45 * sss_bench::tone_map(luminance, exposure);
        const uint8_t g = static_cast<uint8_t>(std::lround(255.0 * std::clamp(grey, 0.0, 1.0)));
        out[0] = out[1] = out[2] = g;
      }
    }
  }
  return h;
}

}  // namespace demo
