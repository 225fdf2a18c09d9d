#include "report.hpp"

#include "kernel_family.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

namespace demo {

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

PassTimes median_times(const std::vector<PassTimes> &frames) {
  auto column = [&frames](double PassTimes::*field) {
    std::vector<double> v;
    for (const PassTimes &t : frames) v.push_back(t.*field);
    return median(v);
  };
  PassTimes m;
  m.shadow_ms = column(&PassTimes::shadow_ms);
  m.lighting_ms = column(&PassTimes::lighting_ms);
  m.sss_ms = column(&PassTimes::sss_ms);
  m.count_ms = column(&PassTimes::count_ms);
  m.composite_ms = column(&PassTimes::composite_ms);
  return m;
}

std::string format_times(const PassTimes &t) {
  char line[256];
  std::snprintf(line, sizeof line, "shadow %7.2f  lighting %7.2f  sss %7.2f  count %6.2f  composite %6.2f  total %7.2f ms",
                t.shadow_ms, t.lighting_ms, t.sss_ms, t.count_ms, t.composite_ms, t.total_ms());
  return line;
}

std::string profile_legend(const DemoScene &scene, const SssControls &controls) {
  // The hues of composite.cpp's kProfileColours, in order.
  static const char *const kHues[8] = {"pink", "blue", "yellow", "green", "violet", "cyan", "rose", "grey"};
  std::string t = "profiles (one pass pair):";
  for (size_t i = 0; i < scene.profiles.size(); ++i) {
    t += (i == 0 ? " " : ", ") + std::to_string(i) + " " + scene.profiles[i].name + " (" + kHues[i % 8] + ")";
  }
  if (scene.object_names.empty()) return t + "; no object IDs (object 0 everywhere)";
  t += "; objects (a darker shade for each further object of a profile):";
  for (size_t i = 0; i < scene.object_names.size(); ++i) {
    t += (i == 0 ? " " : ", ") + std::to_string(i + 1) + " " + scene.object_names[i];
  }
  t += controls.object_ids ? "; object IDs on (no light crosses between objects)"
                           : "; object IDs off (the byte holds the profile alone: light crosses between objects)";
  if (controls.msaa_samples > 0) t += "; with MSAA the byte is not written (the library refuses it with MSAA colour)";
  return t;
}

std::string format_settings(const sss_settings &s, const SssControls &c, float world_units_per_mm) {
  char text[768];
  std::snprintf(text, sizeof text,
                "SSS %s; scale %.3g x the physical size (%.6g world units per mm); strength %.2f %.2f %.2f;"
                " falloff %.2f %.2f %.2f; separable_scale %.3g; %s %d taps per pass%s; follow-surface %s; mask %s; %s;"
                " shading %s",
                c.enabled ? "on" : "off", static_cast<double>(c.scale), static_cast<double>(world_units_per_mm),
                static_cast<double>(s.strength[0]), static_cast<double>(s.strength[1]),
                static_cast<double>(s.strength[2]), static_cast<double>(s.falloff[0]),
                static_cast<double>(s.falloff[1]), static_cast<double>(s.falloff[2]),
                static_cast<double>(s.separable_scale), s.jitter > 0.0f ? "all" : "up to", s.taps,
                s.jitter > 0.0f ? "" : " (as each pixel's footprint needs)",
                (s.flags & SSS_FOLLOW_SURFACE) != 0 ? "on" : "off",
                c.use_stencil ? "stencil == 1 and alpha > 0" : "alpha > 0",
                c.msaa_samples > 0 ? "4x MSAA targets handed to the library (resolved there: averaged linear depth)"
                                   : "no MSAA",
                c.shading == kShadingPreintegrated ? "pre-integrated (LUTs, no SSS pass)"
                : c.shading == kShadingAutomatic   ? "automatic (pre-integrated below 0.5 px per mm)"
                                                   : "screen-space filter");
  std::string result = text;
  sss_kernel_desc kernel;
  sss_default_kernel_desc(&kernel);
  if (s.kernel != nullptr) kernel = *s.kernel;
  if (s.mode == SSS_MODE_SEPARABLE && (kernel.family != SSS_KERNEL_SEPARABLE || s.jitter > 0.0f)) {
    // (sss_set_settings checked the family: it has a row.)
    const KernelFamilyInfo &family = *kernel_family_info(kernel.family);
    std::snprintf(text, sizeof text, "; kernel family %s%s%s%s, jitter %.2f", family.report,
                  family.ranked ? (" rank " + std::to_string(kernel.rank)).c_str() : "",
                  family.from_profile ? " of " : "",
                  family.from_profile ? sss_profile_name(kernel.profile.profile) : "",
                  static_cast<double>(s.jitter));
    result += text;
  }
  if (s.mode == SSS_MODE_CROSS_BILATERAL) {
    std::snprintf(text, sizeof text,
                  "; cross-bilateral mode (Mikkelsen 2010): %d taps, r_max %.2f mm, profile %u (strength, falloff, "
                  "taps and follow-surface above are not used)",
                  s.cbf_taps, static_cast<double>(s.cbf_r_max_mm), s.cbf_profile);
    result += text;
  }
  // The texturing mode the library ran (s.texturing, the controls' c.texturing).
  result +=
      std::string("; texturing ") + texturing_name(static_cast<int>(s.texturing)) +
      (s.texturing == SSS_TEXTURING_PRE_SCATTER    ? "-scatter (the colour blurred as it is, albedo with it)"
       : s.texturing == SSS_TEXTURING_POST_SCATTER ? "-scatter (the light alone blurred, the albedo's detail sharp)"
                                                   : "-scatter (sqrt(albedo) blurred, sqrt(albedo) after)");
  if (c.translucency) {
    std::snprintf(text, sizeof text, "; translucency %.2f (integration/glsl/sss_transmittance.glsl)",
                  static_cast<double>(c.translucency_amount));
    result += text;
    std::snprintf(text, sizeof text, "%.1f mm", static_cast<double>(c.baked_thickness_mm));
    result += c.thickness_source == 0   ? ", thickness from the shadow maps"
              : c.thickness_source == 1 ? std::string(", thickness baked ") + text
                                        : std::string(", thickness the larger of baked ") + text + " and the shadow maps";
  }
  return result;
}

PngText image_text(const DemoScene &scene, const std::string &title, const std::string &description,
                   const std::string &renderer) {
  PngText text = {{"Title", title},
                  {"Software", "sss_demo (screen-space separable subsurface scattering, Jimenez et al. 2012)"},
                  {"Description", description}};
  if (!scene.attribution.empty()) text.emplace_back("Copyright", scene.attribution);
  text.emplace_back("Source", "GL_RENDERER " + renderer);
  return text;
}

}  // namespace demo
