// The Dear ImGui panel of the window (Debian's imgui 1.86; only long-standing calls are used).
#include "kernel_family.hpp"
#include "metrics.hpp"
#include "report.hpp"
#include "window_state.hpp"

#include <sss/sss_tools.h>

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <initializer_list>
#include <utility>
#include <vector>

namespace demo {

namespace {

// Radio buttons on one line: each choice's label sets *value to its number.
void radio_row(int *value, std::initializer_list<std::pair<const char *, int>> choices) {
  bool first = true;
  for (const auto &choice : choices) {
    if (!first) ImGui::SameLine();
    first = false;
    ImGui::RadioButton(choice.first, value, choice.second);
  }
}

const char *const kHelp =
    "S          SSS on / off\n"
    "F12        screenshot into the output folder\n"
    "1 / 2 / 3  close-up / mid shot / far shot\n"
    "V          next view\n"
    "Esc        quit\n"
    "left drag  orbit      right drag  pan\n"
    "wheel      zoom";

double percent(std::uint64_t part, std::uint64_t whole) {
  return whole == 0 ? 0.0 : 100.0 * static_cast<double>(part) / static_cast<double>(whole);
}

void sss_section(WindowState *s) {
  SssControls &c = s->controls;
  ImGui::Checkbox("SSS (S)", &c.enabled);
  ImGui::SameLine();
  if (ImGui::Button("library defaults")) {
    const bool enabled = c.enabled;
    c = default_sss_controls();
    c.enabled = enabled;
  }
  const float world_units_per_mm = s->scene->world_units_per_mm;
  ImGui::SliderFloat("scale (1 = physical)", &c.scale, 0.0f, 8.0f, "%.2f");
  ImGui::TextDisabled("  1 profile mm = %.5g world units (the scene: %.5g per mm)",
                      static_cast<double>(world_units_per_mm * c.scale), static_cast<double>(world_units_per_mm));
  ImGui::SliderFloat3("strength", c.strength, 0.0f, 1.0f, "%.2f");
  ImGui::SliderFloat3("falloff", c.falloff, 0.0f, 1.0f, "%.2f");
  if (ImGui::SliderInt("taps", &c.taps, SSS_MIN_TAPS, SSS_MAX_TAPS)) c.taps |= 1;  // odd only
  ImGui::Checkbox("follow surface", &c.follow_surface);
  ImGui::SameLine();
  ImGui::Checkbox("stencil mask", &c.use_stencil);
  // The kernel family and the material its profile comes from (sss_settings.kernel), and jitter.
  auto family_label = [](void *, int i, const char **out) {
    *out = kernel_family_info(i) != nullptr ? kernel_family_info(i)->label : nullptr;
    return *out != nullptr;
  };
  ImGui::Combo("kernel family", &c.kernel_family, family_label, nullptr, SSS_KERNEL_FAMILY_COUNT);
  const KernelFamilyInfo &family = *kernel_family_info(c.kernel_family);
  if (family.ranked) ImGui::SliderInt("terms (2 passes each)", &c.kernel_rank, 1, SSS_KERNEL_MAX_TERMS);
  if (family.from_profile) {
    auto material_name = [](void *, int i, const char **out) {
      *out = sss_profile_name(i);
      return *out != nullptr;
    };
    ImGui::Combo("material", &c.material, material_name, nullptr, SSS_PROFILE_WHOLEMILK + 1);
    ImGui::TextDisabled("  a measured material is fitted when chosen (up to ~0.3 s)");
  }
  ImGui::SliderFloat("jittered taps", &c.jitter, 0.0f, 1.0f, "%.2f");
  ImGui::Checkbox("move the jitter every frame (noise index, for TAA)", &c.moving_noise);
  ImGui::Checkbox("region from the head's bounds", &c.region);
  // Indexed by SSS_PATH_*: fragment 0, compute 1, auto 2, masked 3, half resolution 4.
  const char* const paths[] = {"fragment passes", "compute (GL 4.3+)", "auto (the fastest)", "fragment, masked",
                               "half resolution (wide kernels)"};
  ImGui::Combo("path", &c.path, paths, 5);
  ImGui::Checkbox("cross-bilateral (Mikkelsen 2010)", &c.cross_bilateral);
  ImGui::Checkbox("debug checks (SSS_CREATE_DEBUG_CHECKS: re-creates the context)", &c.debug_checks);
  if (c.cross_bilateral) {
    ImGui::TextDisabled("  13 taps, r_max 4.5 mm, Table 1 profile; strength, falloff, taps and\n"
                        "  follow surface apply to the separable mode only");
  }
}

void view_section(WindowState *s) {
  int view = static_cast<int>(s->view);
  ImGui::RadioButton("final", &view, static_cast<int>(ViewMode::kFinal));
  ImGui::SameLine();
  ImGui::RadioButton("split", &view, static_cast<int>(ViewMode::kSplit));
  ImGui::SameLine();
  ImGui::RadioButton("heat map", &view, static_cast<int>(ViewMode::kHeatMap));
  ImGui::SameLine();
  ImGui::RadioButton("touched", &view, static_cast<int>(ViewMode::kTouched));
  ImGui::SameLine();
  ImGui::RadioButton("profiles", &view, static_cast<int>(ViewMode::kProfiles));
  s->view = static_cast<ViewMode>(view);
  // The library's debug views (sss_frame.debug_view) replace the filtered image in the final, split and
  // touched views while one is chosen.
  auto view_name = [](void *, int i, const char **out) {
    *out = i == 0 ? "off (the filtered image)" : debug_view_name(i);
    return *out != nullptr;
  };
  ImGui::Combo("library debug view", &s->controls.debug_view, view_name, nullptr,
               static_cast<int>(SSS_DEBUG_VIEW_LAST) + 1);
  if (s->controls.debug_view != 0) {
    const char *refusal = debug_view_refusal(s->controls, s->controls.msaa_samples);
    ImGui::TextWrapped("  %s", refusal != nullptr ? refusal : debug_view_legend(s->controls.debug_view));
  }
  ImGui::SliderFloat("exposure", &s->exposure, 0.1f, 8.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
  if (s->view == ViewMode::kSplit) {
    ImGui::SliderFloat("divider", &s->split, 0.0f, 1.0f, "%.2f");
    ImGui::TextDisabled("left: without SSS, right: with SSS");
  }
  if (s->view == ViewMode::kHeatMap) {
    ImGui::SliderFloat("heat scale", &s->heat_scale, 0.001f, 1.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
    ImGui::SliderInt("1 / size", &s->heat_factor, 1, 16);
    // The ramp, 0 .. scale.
    ImDrawList *draw = ImGui::GetWindowDrawList();
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float w = ImGui::GetContentRegionAvail().x, h = 12.0f;
    for (int i = 0; i < 64; ++i) {
      const auto colour = sss_bench::error_ramp(static_cast<double>(i) / 63.0);
      draw->AddRectFilled(ImVec2(at.x + w * static_cast<float>(i) / 64.0f, at.y),
                          ImVec2(at.x + w * static_cast<float>(i + 1) / 64.0f, at.y + h),
                          IM_COL32(colour[0], colour[1], colour[2], 255));
    }
    ImGui::Dummy(ImVec2(w, h));
    ImGui::Text("0");
    ImGui::SameLine(std::max(w - 60.0f, 20.0f));
    ImGui::Text(">= %.3f", static_cast<double>(s->heat_scale));
    ImGui::TextWrapped(
        "|shown - exact| per pixel, max over RGB, linear. Exact reference: d'Eon's six-Gaussian skin profile at the "
        "physical scale (CPU, double) on a re-render of this frame at %dx%d (1/%d of each side), computed on a "
        "background thread and kept while the camera stands still.",
        s->small_width, s->small_height, s->heat_factor);
    if (s->heat_computing) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "computing the exact reference ...");
    if (s->heat_ready) {
      ImGui::Text("reference took %.2f s", s->reference_seconds);
      ImGui::Text("missed change (interior): %.3f, worst channel %.3f (no SSS: 1)", s->heat.miss_interior,
                  s->heat.miss_interior_worst_channel);
      ImGui::Text("relative RMSE: SSS %.4f, no SSS %.4f", s->heat.relative_rmse_after, s->heat.relative_rmse_before);
      ImGui::Text("|error| of the shown: max %.4f, p99 %.4f", s->heat.max_abs_error, s->heat.p99_abs_error);
    }
  }
  if (s->view == ViewMode::kTouched)
    ImGui::TextWrapped("orange: changed by the library; blue: translucent but unchanged; grey: left alone.");
  if (s->view == ViewMode::kProfiles) ImGui::TextWrapped("%s", profile_legend(*s->scene, s->controls).c_str());
}

void timing_section(WindowState *s) {
  if (s->times.empty()) return;
  const PassTimes m = median_times(std::vector<PassTimes>(s->times.begin(), s->times.end()));
  ImGui::Text("median of the last %zu frames, ms (glFinish around each pass)", s->times.size());
  const struct {
    const char *name;
    double ms;
  } rows[] = {{"shadow maps", m.shadow_ms},    {"lighting", m.lighting_ms}, {"SSS (library)", m.sss_ms},
              {"pixel counts", m.count_ms},    {"composite", m.composite_ms}, {"total", m.total_ms()}};
  for (const auto &r : rows) ImGui::Text("  %-14s %8.2f", r.name, r.ms);
  std::vector<float> totals;
  for (const PassTimes &t : s->times) totals.push_back(static_cast<float>(t.total_ms()));
  ImGui::PlotLines("##total", totals.data(), static_cast<int>(totals.size()), 0, "passes total", 0.0f,
                   *std::max_element(totals.begin(), totals.end()) * 1.2f, ImVec2(0, 40));
  ImGui::Text("frame %.1f ms (%.1f fps)", s->frame_ms, s->frame_ms > 0.0 ? 1000.0 / s->frame_ms : 0.0);
}

}  // namespace

void draw_panel(WindowState *s) {
  // Left edge, above the attribution line; scrolls when the window is short.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(400, std::max(display.y - 64.0f, 120.0f)), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::Begin("sss demo");
  ImGui::TextWrapped("Separable subsurface scattering (Jimenez et al. 2012). %s", s->scene->description.c_str());
  ImGui::TextDisabled("%s, %dx%d", s->renderer_name.c_str(), s->width, s->height);
  ImGui::TextWrapped("S: SSS on/off   F12: screenshot   1/2/3: presets   V: next view   drag: orbit (left), "
                     "pan (right)   wheel: zoom   Esc: quit");

  if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) {
    for (Preset p : kPresets) {
      if (p != Preset::kClose) ImGui::SameLine();
      if (ImGui::Button(preset_title(p))) {
        s->preset = p;
        s->preset_requested = true;
      }
    }
  }
  if (ImGui::CollapsingHeader("Subsurface scattering", ImGuiTreeNodeFlags_DefaultOpen)) sss_section(s);
  if (ImGui::CollapsingHeader("Pre-integrated skin (LUTs, no SSS pass)", ImGuiTreeNodeFlags_DefaultOpen)) {
    radio_row(&s->controls.shading, {{"screen-space filter", kShadingScreenSpace},
                                     {"pre-integrated", kShadingPreintegrated},
                                     {"automatic", kShadingAutomatic}});
    ImGui::TextDisabled("1 mm = %.2f px at the subject; automatic switches below %.2f", static_cast<double>(s->pixels_per_mm),
                        static_cast<double>(kAutoPreintegratedPixelsPerMm));
    ImGui::Text("this frame: %s", s->preintegrated ? "pre-integrated (diffuse and shadow LUTs)" : "screen-space filter");
  }
  if (ImGui::CollapsingHeader("MSAA", ImGuiTreeNodeFlags_DefaultOpen)) {
    bool msaa = s->controls.msaa_samples > 0;
    if (ImGui::Checkbox("4x MSAA targets (the library resolves them: averaged linear depth)", &msaa)) {
      s->controls.msaa_samples = msaa ? 4 : 0;
    }
  }
  if (ImGui::CollapsingHeader("Texturing", ImGuiTreeNodeFlags_DefaultOpen)) {
    // sss_settings.texturing: the lighting pass's albedo target goes with the frame for post and pre-and-post.
    radio_row(&s->controls.texturing, {{"pre-scatter", SSS_TEXTURING_PRE_SCATTER},
                                       {"post-scatter", SSS_TEXTURING_POST_SCATTER},
                                       {"pre-and-post", SSS_TEXTURING_PRE_AND_POST_SCATTER}});
    ImGui::TextDisabled(s->controls.texturing == SSS_TEXTURING_PRE_SCATTER ? "  the albedo blurred with the light"
                        : s->controls.texturing == SSS_TEXTURING_POST_SCATTER
                            ? "  the light alone blurred, the albedo's detail kept sharp"
                            : "  sqrt(albedo) blurred, sqrt(albedo) multiplied after");
  }
  if (s->scene->profiles.size() > 1 || !s->scene->object_names.empty()) {
    if (ImGui::CollapsingHeader("Materials and objects", ImGuiTreeNodeFlags_DefaultOpen)) {
      ImGui::Checkbox("object IDs (no light between objects)", &s->controls.object_ids);
      ImGui::TextWrapped("%s", profile_legend(*s->scene, s->controls).c_str());
      ImGui::TextDisabled("  the G-buffer's R8UI byte: profile | object << 4 (the \"profiles\" view)");
      if (!s->profile_note.empty()) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "%s", s->profile_note.c_str());
    }
  }
  if (ImGui::CollapsingHeader("Translucency")) {
    ImGui::Checkbox("translucency (transmittance through thin parts)", &s->controls.translucency);
    ImGui::SliderFloat("translucency", &s->controls.translucency_amount, 0.0f, 1.0f, "%.2f");
    ImGui::Combo("thickness", &s->controls.thickness_source, "shadow maps\0baked\0both (the larger)\0");
    ImGui::SliderFloat("baked thickness (mm)", &s->controls.baked_thickness_mm, 0.1f, 20.0f, "%.1f");
    ImGui::TextDisabled("  integration/glsl/sss_transmittance.glsl with the blur's profile;\n"
                        "  --back-light puts a light behind the head");
  }
  if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) view_section(s);
  if (ImGui::CollapsingHeader("Pass times", ImGuiTreeNodeFlags_DefaultOpen)) timing_section(s);
  if (ImGui::CollapsingHeader("Pixels the filter touched", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::Text("marked translucent %llu (%.1f %%)", static_cast<unsigned long long>(s->counts.marked),
                percent(s->counts.marked, s->counts.total));
    ImGui::Text("touched by the filter %llu (%.1f %%)", static_cast<unsigned long long>(s->counts.touched),
                percent(s->counts.touched, s->counts.total));
  }
  if (ImGui::CollapsingHeader("Help")) ImGui::TextUnformatted(kHelp);
  if (ImGui::Button("screenshot (F12)")) s->screenshot_requested = true;
  if (!s->message.empty()) ImGui::TextWrapped("%s", s->message.c_str());
  ImGui::End();

  // The attribution, on screen at all times (CC BY 3.0).
  if (!s->scene->attribution.empty()) {
    ImDrawList *draw = ImGui::GetForegroundDrawList();
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    const float wrap = size.x - 16.0f;
    const ImVec2 text = ImGui::CalcTextSize(s->scene->attribution.c_str(), nullptr, false, wrap);
    const ImVec2 at(8.0f, size.y - text.y - 8.0f);
    draw->AddRectFilled(ImVec2(at.x - 4.0f, at.y - 3.0f), ImVec2(at.x + text.x + 4.0f, at.y + text.y + 3.0f),
                        IM_COL32(0, 0, 0, 150));
    draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at, IM_COL32(230, 230, 230, 255),
                  s->scene->attribution.c_str(), nullptr, wrap);
  }
}

}  // namespace demo
