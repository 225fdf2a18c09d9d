// sss_demo --headless: for each preset, renders the frame through a headless context (EGL, falling
// back to OSMesa), writes before/after/split/heat map/touched PNGs, and prints the pass times
// (medians over --repeat frames) and the heat map's errors. README.txt and ATTRIBUTION.txt go
// beside the images.
#include "apps.hpp"

#include "context.hpp"
#include "dump_output.hpp"
#include "gl_functions.hpp"
#include "heat_map.hpp"
#include "host_gl_util.hpp"
#include "image.hpp"
#include "png_output.hpp"
#include "renderer.hpp"
#include "metrics.hpp"
#include "report.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace demo {

namespace {

struct PresetReport {
  Preset preset;
  PassTimes times;
  PixelCounts counts;
  HeatMap heat;
  Reference reference;  // rgb dropped after use; size and time kept
  int small_width = 0;
  int small_height = 0;
  bool preintegrated = false;  // skin shaded with the pre-integrated LUTs (no SSS pass)
  float pixels_per_mm = 0.0f;
  // The frame scored against the post-scatter reference A * (R * E) whatever mode ran: the answer
  // where the albedo already holds the scattering (the head scan's). The interior miss and its worst
  // channel; NaN where the library did not run.
  double miss_post = std::nan("");
  double miss_post_worst_channel = std::nan("");
};

// The ramp with its ends labelled, in the bottom-right corner.
void draw_heat_legend(Image *image, float scale) {
  const int unit = std::max(1, image->height / 270);  // font pixel size: 2 at 540 lines
  const int bar_w = 64 * unit * 2, bar_h = 6 * unit, margin = 8 * unit;
  const int x0 = image->width - bar_w - margin, y0 = image->height - margin - bar_h - 12 * unit;
  static const std::uint8_t kWhite[3] = {230, 230, 230};
  static const std::uint8_t kFrame[3] = {20, 20, 20};
  fill_rect(image, x0 - unit, y0 - 14 * unit, x0 + bar_w + unit, y0 + bar_h + 13 * unit, kFrame);
  for (int i = 0; i < bar_w; ++i) {
    const std::array<uint8_t, 3> colour = sss_bench::error_ramp(static_cast<double>(i) / (bar_w - 1));
    fill_rect(image, x0 + i, y0, x0 + i + 1, y0 + bar_h, colour.data());
  }
  char top[48];
  std::snprintf(top, sizeof top, ">= %.3g", static_cast<double>(scale));
  draw_text(image, x0, y0 - 12 * unit, "error: after vs exact", unit, kWhite);
  draw_text(image, x0, y0 + bar_h + 2 * unit, "0", unit, kWhite);
  draw_text(image, x0 + bar_w - 6 * unit * static_cast<int>(std::strlen(top)), y0 + bar_h + 2 * unit, top, unit, kWhite);
}

// The heat map's small frame: the same camera and settings at 1/factor size, its exact reference,
// and the coloured map uploaded as a texture the composite can show.
bool make_heat_texture(Renderer *renderer, const Options &o, const OrbitCamera &camera, const SssControls &controls,
                       PresetReport *report, GLuint *texture) {
  small_frame_size(o.width, o.height, o.heat_factor, &report->small_width, &report->small_height);
  FrameTargets small;
  if (!create_frame_targets(&small, report->small_width, report->small_height)) return false;
  const CameraMatrices m = camera_matrices(camera, renderer->scene->all, small.width, small.height);
  FrameResult frame;
  SssControls small_controls = controls;
  small_controls.decision_height = o.height;  // choose the shading as the full frame does
  small_controls.debug_view = 0;              // the error of the filtered image
  const bool ok = render_frame(renderer, m, small_controls, &small, false, &frame);
  SmallFrame data;
  if (ok) {
    data = read_small_frame(small, m, frame.sss_ran, renderer->scene->world_units_per_mm,
                            frame.preintegrated ? 0 : static_cast<int>(renderer->sss.settings.texturing));
  }
  data.materials = reference_materials(*renderer->scene);
  destroy_frame_targets(&small);
  if (!ok) return false;

  report->reference = compute_reference(data);
  report->heat = make_heat_map(data, report->reference, true, o.heat_scale, o.exposure);
  if (frame.sss_ran && !frame.preintegrated) {
    HeatMap post = report->heat;
    if (data.texturing != SSS_TEXTURING_POST_SCATTER) {
      SmallFrame as_post = data;
      as_post.texturing = SSS_TEXTURING_POST_SCATTER;
      post = make_heat_map(as_post, compute_reference(as_post), true, o.heat_scale, o.exposure);
    }
    report->miss_post = post.miss_interior;
    report->miss_post_worst_channel = post.miss_interior_worst_channel;
  }
  report->reference.rgb.clear();
  const std::vector<std::uint8_t> rows = gl_rows_from_image(report->heat.image);
  *texture = make_texture(GL_RGBA8, report->small_width, report->small_height, GL_RGBA, GL_UNSIGNED_BYTE);
  glBindTexture(GL_TEXTURE_2D, *texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, report->small_width, report->small_height, GL_RGBA, GL_UNSIGNED_BYTE,
                  rows.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glBindTexture(GL_TEXTURE_2D, 0);
  return check_gl("heat map upload");
}

// --debug-view: each view the library writes for this frame (sss_frame.debug_view), in the
// composite's false colours, as PRESET-view-NAME.png.
bool write_debug_views(Renderer *renderer, const Options &o, const Context &context, const SssControls &controls,
                       const CameraMatrices &m, FrameTargets *targets, const std::string &prefix, Preset preset,
                       const std::string &settings) {
  const DemoScene &scene = *renderer->scene;
  bool ok = true;
  for (const int view : o.debug_views) {
    SssControls with_view = controls;
    with_view.debug_view = view;
    const char *refusal = debug_view_refusal(with_view, targets->samples);
    if (refusal != nullptr || !controls.enabled) {
      std::fprintf(stderr, "sss_demo: no %s view: %s\n", debug_view_name(view),
                   refusal != nullptr ? refusal : "the library is off (--no-sss)");
      continue;
    }
    FrameResult frame;
    if (!render_frame(renderer, m, with_view, targets, false, &frame)) return false;
    if (frame.debug_view != view) continue;  // pre-integrated shading: no pass ran
    composite_frame(*renderer, *targets, frame, ViewMode::kFinal, o.exposure, 0.5f, 0, nullptr);
    const Image image = image_from_gl_rows(read_output(*targets), targets->width, targets->height);
    const std::string name = std::string("view-") + debug_view_name(view);
    const std::string description = std::string("the library's debug view '") + debug_view_name(view) + "' (" +
                                    debug_view_legend(view) + "). " + scene.name + ", " + preset_title(preset) +
                                    ", " + std::to_string(targets->width) + "x" + std::to_string(targets->height) +
                                    ". " + settings;
    ok = write_png(prefix + name + ".png", image,
                   image_text(scene, "sss_demo " + name, description, context.renderer)) &&
         ok;
  }
  return ok && check_gl("the debug views");
}

// The close-up's zoom in each texturing mode side by side (pre | post | pre-and-post, each labelled),
// 3x around the block where pre- and post-scatter differ most, as close-zoom-texturing.png. Not
// written where the modes cannot differ: the library off, pre-integrated shading.
bool write_texturing_zoom(Renderer *renderer, const Options &o, const Context &context, const SssControls &controls,
                          const CameraMatrices &m, FrameTargets *targets, const std::string &prefix,
                          const std::string &settings) {
  if (!controls.enabled) return true;
  Image images[3];
  for (int mode = SSS_TEXTURING_PRE_SCATTER; mode <= SSS_TEXTURING_PRE_AND_POST_SCATTER; ++mode) {
    SssControls with_mode = controls;
    with_mode.texturing = mode;
    FrameResult frame;
    if (!render_frame(renderer, m, with_mode, targets, false, &frame)) return false;
    if (frame.preintegrated) return true;
    composite_frame(*renderer, *targets, frame, ViewMode::kFinal, o.exposure, 0.5f, 0, nullptr);
    images[mode] = image_from_gl_rows(read_output(*targets), targets->width, targets->height);
  }
  const int crop_w = targets->width / 8, crop_h = targets->height / 6;
  int cx = 0, cy = 0;
  largest_difference(images[0], images[1], std::min(crop_w, crop_h), &cx, &cy);
  Image panels[3];
  for (int mode = 0; mode < 3; ++mode) {
    panels[mode] = crop_zoom(images[mode], cx, cy, crop_w, crop_h, 3);
    const int unit = std::max(1, panels[mode].height / 135);
    static const std::uint8_t kWhite[3] = {235, 235, 235};
    static const std::uint8_t kFrame[3] = {20, 20, 20};
    const char *name = texturing_name(mode);
    fill_rect(&panels[mode], 0, 0, (static_cast<int>(std::strlen(name)) * 6 + 3) * unit, 10 * unit, kFrame);
    draw_text(&panels[mode], 2 * unit, 2 * unit, name, unit, kWhite);
  }
  const Image zoom = side_by_side(side_by_side(panels[0], panels[1], 4), panels[2], 4);
  char where[256];
  std::snprintf(where, sizeof where,
                "left to right: texturing pre-scatter, post-scatter, pre-and-post-scatter (sss_settings.texturing), 3x "
                "around pixel (%d, %d), where pre- and post-scatter differ most. ",
                cx, cy);
  const DemoScene &scene = *renderer->scene;
  return write_png(
      prefix + "zoom-texturing.png", zoom,
      image_text(scene, "sss_demo zoom-texturing",
                 where + scene.name + ", " + preset_title(Preset::kClose) + ". " + settings, context.renderer));
}

bool render_preset(Renderer *renderer, const Options &o, const Context &context, const SssControls &controls,
                   Preset preset, FrameTargets *targets, PresetReport *report) {
  const DemoScene &scene = *renderer->scene;
  report->preset = preset;
  const OrbitCamera camera = preset_camera(scene, preset);
  const CameraMatrices m = camera_matrices(camera, scene.all, targets->width, targets->height);

  // One warm-up frame (shader variants, first-use allocations), then the timed ones.
  std::vector<PassTimes> times;
  FrameResult frame;
  for (int i = 0; i <= o.repeat; ++i) {
    if (!render_frame(renderer, m, controls, targets, true, &frame)) return false;
    composite_frame(*renderer, *targets, frame, ViewMode::kFinal, o.exposure, 0.5f, 0, &frame.times);
    if (i > 0) times.push_back(frame.times);
  }
  report->times = median_times(times);
  report->counts = frame.counts;
  report->preintegrated = frame.preintegrated;
  report->pixels_per_mm = frame.pixels_per_mm;

  GLuint heat_texture = 0;
  const bool heat_ok = make_heat_texture(renderer, o, camera, controls, report, &heat_texture);
  if (!heat_ok) {
    glDeleteTextures(1, &heat_texture);
    return false;
  }
  // The close-up in each texturing mode (before the big frame again, which sets the controls' mode back).
  const std::string prefix = (std::filesystem::path(o.out_dir) / preset_name(preset)).string() + "-";
  if (preset == Preset::kClose &&
      !write_texturing_zoom(renderer, o, context, controls, m, targets, prefix,
                            format_settings(renderer->sss.settings, controls, scene.world_units_per_mm))) {
    glDeleteTextures(1, &heat_texture);
    return false;
  }
  // The big frame again (the small one used the same passes), then each view read back.
  if (!render_frame(renderer, m, controls, targets, false, &frame)) return false;
  FrameResult no_sss = frame;
  no_sss.sss_ran = false;
  struct View {
    const char *file;
    const char *title;
    const FrameResult *frame;
    ViewMode mode;
  };
  const View views[] = {
      {"before", "without subsurface scattering (diffuse + specular)", &no_sss, ViewMode::kFinal},
      {"after", "with the library's subsurface scattering", &frame, ViewMode::kFinal},
      {"split", "left: without, right: with subsurface scattering", &frame, ViewMode::kSplit},
      {"heatmap", "error against the exact reference (small frame, scaled up)", &frame, ViewMode::kHeatMap},
      {"touched", "pixels the library changed (orange), translucent but unchanged (blue)", &frame, ViewMode::kTouched},
      {"profiles", "the G-buffer's profile/object byte in false colours (a hue per profile, a shade per object)",
       &frame, ViewMode::kProfiles},
  };
  const std::string settings = format_settings(renderer->sss.settings, controls, scene.world_units_per_mm);
  bool ok = true;
  Image before, after;
  for (const View &v : views) {
    composite_frame(*renderer, *targets, *v.frame, v.mode, o.exposure, 0.5f, heat_texture, nullptr);
    Image image = image_from_gl_rows(read_output(*targets), targets->width, targets->height);
    if (v.mode == ViewMode::kHeatMap) draw_heat_legend(&image, o.heat_scale);
    if (&v == &views[0]) before = image;
    if (&v == &views[1]) after = image;
    std::string description = std::string(v.title) + ". " + scene.name + ", " + preset_title(preset) + ", " +
                              std::to_string(targets->width) + "x" + std::to_string(targets->height) + ". " + settings;
    if (v.mode == ViewMode::kProfiles) description += ". " + profile_legend(scene, controls);
    if (v.mode == ViewMode::kHeatMap) {
      char extra[256];
      std::snprintf(extra, sizeof extra,
                    ". Heat map: |after - exact| (max over RGB, linear) / %.3g on a viridis-like ramp, computed at "
                    "%dx%d; share of the needed change missed on the interior %.3f (no SSS: 1), relative RMSE "
                    "%.4f (no SSS: %.4f)",
                    static_cast<double>(o.heat_scale), report->small_width, report->small_height,
                    report->heat.miss_interior, report->heat.relative_rmse_after, report->heat.relative_rmse_before);
      description += extra;
    }
    ok = write_png(prefix + v.file + ".png", image,
                   image_text(scene, std::string("sss_demo ") + v.file, description, context.renderer)) &&
         ok;
  }
  // Before | after, 3x, where they differ most.
  const int crop_w = targets->width / 8, crop_h = targets->height / 6;
  int cx = 0, cy = 0;
  largest_difference(before, after, std::min(crop_w, crop_h), &cx, &cy);
  const Image zoom = side_by_side(crop_zoom(before, cx, cy, crop_w, crop_h, 3), crop_zoom(after, cx, cy, crop_w, crop_h, 3), 4);
  char where[160];
  std::snprintf(where, sizeof where, "left: without, right: with subsurface scattering, 3x around pixel (%d, %d), "
                "where they differ most. ", cx, cy);
  ok = write_png(prefix + "zoom.png", zoom,
                 image_text(scene, "sss_demo zoom", where + scene.name + ", " + preset_title(preset) + ". " + settings,
                            context.renderer)) &&
       ok;
  glDeleteTextures(1, &heat_texture);
  if (o.dump) ok = write_frame_dumps(*targets, frame.sss_ran, prefix) && ok;
  ok = ok && write_debug_views(renderer, o, context, controls, m, targets, prefix, preset, settings);
  return ok && check_gl("the views");
}

bool write_text(const std::string &path, const std::string &text) {
  std::FILE *f = std::fopen(path.c_str(), "w");
  bool ok = f != nullptr && std::fputs(text.c_str(), f) >= 0;
  if (f != nullptr) ok = std::fclose(f) == 0 && ok;
  if (!ok) std::fprintf(stderr, "sss_demo: could not write %s\n", path.c_str());
  return ok;
}

std::string readme(const Options &o, const Context &context, const DemoScene &scene, const std::string &settings,
                   const std::vector<PresetReport> &reports, const std::string &profile_note) {
  std::string t =
      "sss_demo --headless: screen-space separable subsurface scattering (Jimenez et al. 2012)\n\n"
      "For each camera preset (close = close-up, mid = mid shot, far = far shot):\n"
      "  PRESET-before.png   diffuse + specular, no subsurface scattering\n"
      "  PRESET-after.png    the diffuse through the library (sss_apply_frame), then + specular\n"
      "  PRESET-split.png    left half before, right half after (2-pixel white divider)\n"
      "  PRESET-heatmap.png  |after - exact reference| per pixel (max over RGB, linear irradiance) / heat scale,\n"
      "                      dark violet = 0 .. yellow >= scale; non-translucent pixels in dim grey. The exact\n"
      "                      reference (d'Eon's six-Gaussian skin profile at the physical scale, CPU) runs on a\n"
      "                      re-render of the same frame at 1/heat-factor of each side, shown scaled up.\n"
      "  PRESET-touched.png  orange: pixels the library changed; blue: translucent but unchanged; grey: the rest\n"
      "  PRESET-zoom.png     before | after, magnified 3x, around the block where they differ most\n"
      "  PRESET-profiles.png the G-buffer's profile/object byte (sss_frame.profile_texture) in false colours\n"
      "  close-zoom-texturing.png  the close-up in each texturing mode (sss_settings.texturing), left to right\n"
      "                      pre-scatter | post-scatter | pre-and-post, magnified 3x where pre and post differ most\n"
      "                      (not with MSAA, --no-sss or pre-integrated shading)\n";
  for (const int view : o.debug_views) {
    char line[320];
    std::snprintf(line, sizeof line, "  PRESET-view-%s.png the library's debug view (sss_frame.debug_view): %s\n",
                  debug_view_name(view), debug_view_legend(view));
    t += line;
  }
  t += "Tone mapping: x exposure, Narkowicz's ACES filmic fit, sRGB.\n\n";
  t += "Scene        " + scene.name + ": " + scene.description + "\n";
  t += "GL_RENDERER  " + context.renderer + "\nGL_VERSION   " + context.version + "\nbackend      " +
       context.backend + " (requested " + o.backend + ")\n";
  t += "size         " + std::to_string(o.width) + "x" + std::to_string(o.height) + "\n";
  t += "settings     " + settings + "\n";
  t += "materials    " + profile_legend(scene, controls_from_options(o)) + "\n";
  if (!profile_note.empty()) t += "             " + profile_note + "\n";
  char line[512];
  std::snprintf(line, sizeof line, "exposure %.3g, heat scale %.3g, heat factor %d, %d timed frames per preset\n\n",
                static_cast<double>(o.exposure), static_cast<double>(o.heat_scale), o.heat_factor, o.repeat);
  t += line;
  t += "Pass times, milliseconds, median of the timed frames (glFinish around each pass):\n";
  for (const PresetReport &r : reports) {
    std::snprintf(line, sizeof line, "  %-5s  %s\n", preset_name(r.preset), format_times(r.times).c_str());
    t += line;
  }
  t += "\nPixels and error against the exact reference:\n";
  for (const PresetReport &r : reports) {
    std::snprintf(line, sizeof line,
                  "  %-5s  marked %7llu (%4.1f %%), touched %7llu; reference at %dx%d (%zu translucent px) in %.2f s;"
                  " interior (%zu px) miss %.3f (worst channel %.3f; no SSS: 1); relative RMSE %.4f with SSS, %.4f"
                  " without; p99 |error| %.4f\n",
                  preset_name(r.preset), static_cast<unsigned long long>(r.counts.marked),
                  100.0 * static_cast<double>(r.counts.marked) / static_cast<double>(std::max<std::uint64_t>(r.counts.total, 1)),
                  static_cast<unsigned long long>(r.counts.touched), r.small_width, r.small_height,
                  r.reference.translucent_pixels, r.reference.seconds, r.heat.interior_pixels, r.heat.miss_interior,
                  r.heat.miss_interior_worst_channel, r.heat.relative_rmse_after, r.heat.relative_rmse_before,
                  r.heat.p99_abs_error);
    t += line;
    std::snprintf(line, sizeof line,
                  "         against the post-scatter reference A * (R * E), whatever the mode (the answer where the "
                  "albedo already holds the scattering, as a scan's does): interior miss %.3f (worst channel %.3f)\n",
                  r.miss_post, r.miss_post_worst_channel);
    t += line;
  }
  if (!scene.attribution.empty()) t += "\nAttribution: " + scene.attribution + "\n";
  return t;
}

}  // namespace

int run_headless(const Options &o, const DemoScene &scene) {
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir, ec);
  if (ec) {
    std::fprintf(stderr, "sss_demo: cannot create %s: %s\n", o.out_dir.c_str(), ec.message().c_str());
    return 1;
  }
  Context context;
  if (!create_context(o.backend, &context)) return 1;
  std::printf("sss_demo --headless: %s, %dx%d\nGL_RENDERER: %s\nGL_VERSION:  %s\nbackend:     %s\n",
              scene.name.c_str(), o.width, o.height, context.renderer.c_str(), context.version.c_str(),
              context.backend.c_str());

  const SssControls controls = controls_from_options(o);
  Renderer renderer;
  FrameTargets targets;
  std::vector<PresetReport> reports;
  bool ok = create_renderer(&renderer, scene, sss_headless_get_proc_address, context.headless) &&
            create_frame_targets(&targets, o.width, o.height, controls.msaa_samples);
  if (ok) {
    std::printf("pass times in ms, median of %d frames (glFinish around each pass):\n", o.repeat);
    for (Preset preset : o.presets) {
      PresetReport report{};
      ok = render_preset(&renderer, o, context, controls, preset, &targets, &report);
      if (!ok) break;
      std::printf("  %-5s  %s\n", preset_name(preset), format_times(report.times).c_str());
      std::printf("         shading: %s (1 mm = %.2f px at the subject)\n",
                  report.preintegrated ? "pre-integrated LUTs" : "screen-space filter",
                  static_cast<double>(report.pixels_per_mm));
      sss_stats stats = {};
      stats.struct_size = sizeof stats;
      if (!report.preintegrated && sss_get_stats(renderer.sss.context, &stats) == SSS_OK && stats.frames > 0) {
        std::printf("         passes: %s (sss_stats.last_frame_path)\n",
                    stats.last_frame_path == SSS_PATH_COMPUTE           ? "compute dispatches"
                    : stats.last_frame_path == SSS_PATH_FRAGMENT_MASKED ? "fragment passes behind a stencil from alpha"
                    : stats.last_frame_path == SSS_PATH_HALF_RESOLUTION ? "half size where kernels are wide, an upsample"
                                                                        : "fragment passes");
      }
      if (!renderer.sss.profile_note.empty()) std::printf("         note: %s\n", renderer.sss.profile_note.c_str());
      std::printf("         heat map: exact reference at %dx%d in %.2f s; interior miss %.3f (worst channel %.3f; no SSS:"
                  " 1); relative RMSE %.4f with SSS, %.4f without; touched %llu of %llu marked pixels\n",
                  report.small_width, report.small_height, report.reference.seconds, report.heat.miss_interior,
                  report.heat.miss_interior_worst_channel, report.heat.relative_rmse_after,
                  report.heat.relative_rmse_before, static_cast<unsigned long long>(report.counts.touched),
                  static_cast<unsigned long long>(report.counts.marked));
      std::printf("         against the post-scatter reference A * (R * E): interior miss %.3f (worst channel %.3f)\n",
                  report.miss_post, report.miss_post_worst_channel);
      reports.push_back(report);
    }
  }
  if (ok) {
    const std::string settings =
        format_settings(renderer.sss.settings, controls, scene.world_units_per_mm);
    const std::filesystem::path dir(o.out_dir);
    ok = write_text((dir / "README.txt").string(), readme(o, context, scene, settings, reports, renderer.sss.profile_note));
    if (ok && !scene.attribution.empty())
      ok = write_text((dir / "ATTRIBUTION.txt").string(), "The images in this folder show a model whose licence asks for this attribution:\n" +
                                                              scene.attribution + "\n");
    if (ok) std::printf("wrote %zu presets x {before,after,split,heatmap,touched,zoom,profiles}.png and README.txt into %s\n",
                        reports.size(), o.out_dir.c_str());
  }
  if (!scene.attribution.empty()) std::printf("%s\n", scene.attribution.c_str());
  destroy_frame_targets(&targets);
  destroy_renderer(&renderer);
  check_gl("clean-up");
  destroy_context(&context);
  return ok ? 0 : 1;
}

}  // namespace demo
