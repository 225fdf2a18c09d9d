#include "web_app.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <string>

#include "gltf_mesh.hpp"
#include "web_materials.hpp"

namespace web {

App::~App() {
  sss_destroy(sss_);  // NULL is a no-op; the GL context is still current here
}

bool App::init(sss_get_proc_address_fn get_proc_address, void* user, const std::string& gltf_path, int width,
               int height) {
  gltf_mesh::Model model;
  try {
    model = gltf_mesh::load_gltf(gltf_path);
  } catch (const std::exception& e) {
    message_ = e.what();
    return false;
  }
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  renderer_ = renderer != nullptr ? renderer : "";
  scene_ = std::make_unique<Scene>();
  if (!scene_->init(model, width, height, &message_)) return false;
  sss_create_desc desc{};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = get_proc_address;
  desc.get_proc_address_user = user;
  if (sss_create(&desc, &sss_) != SSS_OK) {
    message_ = sss_last_error(nullptr);
    return false;
  }
  // The head is in metres (gltf_mesh: glTF's unit); the rest are the library's defaults.
  sss_settings s;
  sss_default_settings(&s);
  s.world_units_per_mm = 0.001f;
  if (sss_set_settings(sss_, &s) != SSS_OK || scene_->prepare(sss_) != SSS_OK) {
    message_ = sss_last_error(sss_);
    return false;
  }
  return true;
}

Knobs App::default_knobs() const {
  sss_settings s;
  sss_default_settings(&s);
  Knobs k;
  k.scale = s.scale;
  std::copy(s.strength, s.strength + 3, k.strength);
  std::copy(s.falloff, s.falloff + 3, k.falloff);
  k.taps = s.taps;
  k.follow_surface = (s.flags & SSS_FOLLOW_SURFACE) != 0;
  return k;
}

sss_result App::set_knobs(const Knobs& knobs) {
  if (knobs.material < 0 || knobs.material >= kMaterialCount) {
    message_ = "material " + std::to_string(knobs.material) + ": the page knows " + std::to_string(kMaterialCount);
    return SSS_ERROR_INVALID_ARGUMENT;
  }
  sss_settings s;
  s.struct_size = sizeof s;
  sss_result r = sss_get_settings(sss_, &s);
  if (r == SSS_OK) {
    s.scale = knobs.scale;
    std::copy(knobs.strength, knobs.strength + 3, s.strength);
    std::copy(knobs.falloff, knobs.falloff + 3, s.falloff);
    s.taps = knobs.taps;
    sss_kernel_desc kernel;
    apply_material(knobs.material, &kernel, &s);
    s.flags = knobs.follow_surface ? (s.flags | SSS_FOLLOW_SURFACE) : (s.flags & ~static_cast<uint32_t>(SSS_FOLLOW_SURFACE));
    r = sss_set_settings(sss_, &s);
  }
  if (r == SSS_OK) r = scene_->prepare(sss_);  // the next frame compiles and allocates nothing
  if (r != SSS_OK) {
    message_ = sss_last_error(sss_);
    return r;
  }
  enabled_ = knobs.enabled;
  message_.clear();
  return SSS_OK;
}

sss_result App::render(float split) {
  const sss_result r = scene_->render(enabled_ ? sss_ : nullptr, split);
  if (r != SSS_OK) message_ = sss_last_error(sss_);
  return r;
}

double App::time_frames(int frames, float split) {
  std::vector<double> ms;
  uint8_t pixel[4];
  for (int i = 0; i < frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    render(split);
    scene_->read_pixel(pixel);  // waits for the frame on every GL (glFinish does not in a browser)
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  if (ms.empty()) return 0.0;
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

std::vector<uint8_t> App::pixels_top_first() const {
  std::vector<uint8_t> bottom(static_cast<size_t>(scene_->width()) * scene_->height() * 4);
  scene_->read_pixels(bottom.data());
  return flip_rows(bottom, scene_->width(), scene_->height());
}

}  // namespace web
