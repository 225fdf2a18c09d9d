// sss_osg_host: the library inside OpenSceneGraph 3.6, on the engine's own GL names, callback and
// state cache (examples/osg/README.md, docs/integration.md §18). The head scan is lit into an RTT
// camera's G-buffer, the library filters its diffuse from that camera's final draw callback
// (sss_osg_pass.hpp), and the engine's own post-render cameras add specular, tone-map, and draw a
// second scene of OSG's standard materials.
//
//   sss_osg_host [--width W] [--height H] [--threading single|draw] [--no-sss] [--out DIR]
//       renders a few frames and writes DIR/final.png (with the module, or without: --no-sss),
//       DIR/standard.png and DIR/ATTRIBUTION.txt
//   [--texturing pre|post|pre-and-post]: sss_settings.texturing (default pre; post and pre-and-post
//       hand the library the G-buffer's albedo, on texture unit 6 during the call)
//   sss_osg_host --check [--no-state-restore] [...]   the tests (exit 0: passed, 1: failed, 77: no
//       display); --no-state-restore: the library created with SSS_CREATE_NO_STATE_RESTORE, which
//       must ask the GL nothing in a steady frame, with the callback telling OSG instead; with
//       --leak-state the host itself enables GL_BLEND behind OSG's back after each call, which the
//       check must report (its own test)
//   sss_osg_host --bench N [--bench-out FILE]   frame times with and without the module
// Needs an X display (a pbuffer context): under xvfb-run where there is none.
#include "cache_check.hpp"
#include "host_scene.hpp"
#include "sss_osg_pass.hpp"

#include <counting_loader.hpp>
#include <gltf_mesh.hpp>
#include <shared_assets.hpp>

#include <osg/ArgumentParser>
#include <osg/GraphicsContext>
#include <osgDB/WriteFile>
#include <osg/Version>
#include <osgViewer/Viewer>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

namespace {

using Pixels = std::vector<unsigned char>;

Pixels pixels_of(const osg::Image& image) {
  return Pixels(image.data(), image.data() + image.getTotalSizeInBytes());
}

// The library's callback, wrapped by the host to check OSG's cache right after each call.
class CheckedCallback : public osg::Camera::DrawCallback {
 public:
  explicit CheckedCallback(sss_osg::SssDrawCallback* inner) : inner_(inner) {}
  void operator()(osg::RenderInfo& info) const override {
    const sss_osg_host::FramebufferBindings bound = sss_osg_host::read_framebuffer_bindings();
    const int before = inner_->frames_applied();
    sss_test::reset_call_counts();
    (*inner_)(info);
    const sss_test::GlCallCounts counts = sss_test::call_counts();
    if (leak_state_) glEnable(GL_BLEND);  // --leak-state: what a library that forgot a state would do
    if (!checking_ || inner_->frames_applied() == before) return;
    ++checked_;
    queries_ += counts.total_queries();
    if (counts.total_queries() > 0) query_names_ = counts.describe_queries();
    // Without the restore the callback has told OSG to re-apply everything: its beliefs are stale
    // on purpose until then, so the comparison is for the restoring library only; what OSG cannot be
    // told (it tracks no sampler objects) the callback must have unbound.
    if (no_restore_) {
      for (const std::string& line : sss_osg_host::samplers_left_bound(info)) {
        mismatches_.push_back("frame " + std::to_string(inner_->frames_applied()) + ": " + line);
      }
      return;
    }
    for (const std::string& line : sss_osg_host::compare_cache_with_gl(info, bound)) {
      mismatches_.push_back("frame " + std::to_string(inner_->frames_applied()) + ": " + line);
    }
  }
  void set_no_restore(bool on) { no_restore_ = on; }
  // The library's GL queries over the checked calls, and the last call's list of them.
  long queries() const { return queries_; }
  const std::string& query_names() const { return query_names_; }
  void set_checking(bool on) { checking_ = on; }
  void set_leak_state(bool on) { leak_state_ = on; }
  const std::vector<std::string>& mismatches() const { return mismatches_; }
  int checked() const { return checked_; }

 private:
  osg::ref_ptr<sss_osg::SssDrawCallback> inner_;
  bool checking_ = false;
  bool leak_state_ = false;
  bool no_restore_ = false;
  mutable long queries_ = 0;
  mutable std::string query_names_;
  mutable std::vector<std::string> mismatches_;
  mutable int checked_ = 0;
};

struct Host {
  int width = 1280, height = 720;
  osgViewer::Viewer viewer;
  sss_osg_host::GBuffer g;
  osg::ref_ptr<osg::Texture2D> output;
  osg::ref_ptr<sss_osg::SssDrawCallback> sss;
  osg::ref_ptr<CheckedCallback> checked;
  osg::ref_ptr<osg::Camera> composite;
  osg::ref_ptr<osg::Image> final_image, standard_image, mask_image;

  // The module on (the composite reads its output) or off (the composite reads the diffuse).
  void set_module(bool on) {
    sss->set_enabled(on);
    sss_osg_host::set_composite_input(composite.get(), on ? output.get() : g.diffuse.get());
  }
};

bool build(Host* host, const std::string& threading, const gltf_mesh::Model& head) {
  osg::ref_ptr<osg::GraphicsContext::Traits> traits = new osg::GraphicsContext::Traits;
  traits->readDISPLAY();
  traits->setUndefinedScreenDetailsToDefaultScreen();
  traits->width = host->width;
  traits->height = host->height;
  traits->pbuffer = true;
  traits->doubleBuffer = false;
  osg::ref_ptr<osg::GraphicsContext> gc = osg::GraphicsContext::createGraphicsContext(traits.get());
  if (!gc.valid()) return false;
  const int w = host->width, h = host->height;
  host->g.diffuse = sss_osg::make_half_float_texture(w, h);
  host->g.specular = sss_osg::make_half_float_texture(w, h);
  host->g.albedo = sss_osg::make_half_float_texture(w, h);
  host->g.depth = sss_osg::make_depth_texture(w, h);
  host->output = sss_osg::make_half_float_texture(w, h);
  host->final_image = sss_osg_host::make_readback_image(w, h);
  host->standard_image = sss_osg_host::make_readback_image(w, h);
  host->mask_image = sss_osg_host::make_readback_image(w, h);

  osg::ref_ptr<osg::Camera> gbuffer = sss_osg_host::make_gbuffer_camera(sss_osg_host::make_lit_scene(head).get(), head, host->g);
  host->sss = new sss_osg::SssDrawCallback({host->g.diffuse, host->g.depth, host->output, host->g.albedo},
                                           0.001f);  // metres
  host->checked = new CheckedCallback(host->sss.get());
  gbuffer->setFinalDrawCallback(host->checked.get());
  host->composite = sss_osg_host::make_composite_camera(host->output.get(), host->g.specular.get(), host->final_image.get());
  osg::ref_ptr<osg::Group> root = new osg::Group;
  root->addChild(gbuffer.get());
  root->addChild(host->composite.get());
  root->addChild(sss_osg_host::make_standard_scene_camera(host->standard_image.get()).get());
  root->addChild(sss_osg_host::make_composite_camera(host->g.diffuse.get(), host->g.specular.get(),
                                                     host->mask_image.get(), true, 2).get());
  osg::Camera* main = host->viewer.getCamera();
  main->setGraphicsContext(gc.get());
  main->setViewport(0, 0, w, h);
  host->viewer.setSceneData(root.get());
  host->viewer.setThreadingModel(threading == "draw" ? osgViewer::Viewer::CullDrawThreadPerContext
                                                     : osgViewer::Viewer::SingleThreaded);
  host->viewer.setCameraManipulator(nullptr);
  host->viewer.realize();
  return host->viewer.isRealized();
}

// Frames of the same scene: the final images and the standard scene's after each.
struct Frames {
  std::vector<Pixels> finals, standards;
};
Frames render(Host* host, int count) {
  Frames f;
  for (int i = 0; i < count; ++i) {
    host->viewer.frame();
    f.finals.push_back(pixels_of(*host->final_image));
    f.standards.push_back(pixels_of(*host->standard_image));
  }
  return f;
}

int failures = 0;
void check(bool ok, const std::string& what) {
  std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what.c_str());
  if (!ok) ++failures;
}

int run_checks(Host* host, bool no_restore) {
  const int applied_before = host->sss->frames_applied();
  host->checked->set_checking(true);
  host->set_module(true);
  const Frames with = render(host, 3);
  const Pixels mask = pixels_of(*host->mask_image);
  host->set_module(false);
  const Frames without = render(host, 3);
  host->set_module(true);
  const Frames again = render(host, 1);
  const Pixels& a = with.finals.back();
  const Pixels& b = without.finals.back();
  std::size_t skin = 0, changed = 0, other_changed = 0, pixels = a.size() / 4;
  for (std::size_t p = 0; p < pixels; ++p) {
    const bool is_skin = mask[4 * p] != 0;
    const bool differs = !std::equal(a.begin() + 4 * p, a.begin() + 4 * p + 4, b.begin() + 4 * p);
    skin += is_skin ? 1 : 0;
    changed += is_skin && differs ? 1 : 0;
    other_changed += !is_skin && differs ? 1 : 0;
  }
  std::printf("%zu skin pixels of %zu; the module changed %zu of them and %zu other pixels\n", skin, pixels, changed,
              other_changed);
  check(host->sss->last_error().empty(), "every call succeeded" +
                                             (host->sss->last_error().empty() ? "" : ": " + host->sss->last_error()));
  check(host->sss->frames_applied() - applied_before == 4 && host->checked->checked() == 4,
        "the module ran on the 4 frames it was on, and only on those");
  // Compared after tone mapping to 8 bits: where the light is smooth the blur moves a pixel by less
  // than a level; the terminator, the shadows and the creases must change.
  check(skin > pixels / 50 && changed > skin / 10, "the module changed the skin (a tenth of its pixels at least)");
  check(other_changed == 0, "every pixel that is not skin is bit-identical to the engine's frame without the module");
  for (const std::string& line : host->checked->mismatches()) std::printf("      %s\n", line.c_str());
  if (no_restore) {
    check(host->checked->mismatches().empty(),
          "without the restore no sampler object is left bound after the callback");
    check(host->checked->queries() == 0, "without the restore a steady frame asks the GL nothing (" +
                                             std::to_string(host->checked->queries()) + " queries: " +
                                             host->checked->query_names() + ")");
  } else {
    std::printf("      the restoring library's queries: %ld over 4 steady frames (the last: %s)\n",
                host->checked->queries(), host->checked->query_names().c_str());
    check(host->checked->mismatches().empty(), "OSG's state cache equals the GL after every call (and no GL error)");
  }
  bool standard_same = true;
  for (std::size_t i = 0; i < with.standards.size(); ++i) {
    standard_same = standard_same && with.standards[i] == without.standards[i] && again.standards[0] == with.standards[i];
  }
  check(standard_same, "the standard-materials scene drawn after the module is bit-identical to it drawn without");
  check(without.finals.front() == without.finals.back(), "the first frame without the module is already the engine's own");
  check(again.finals.front() == a, "the module on again gives the same frame");
  return failures == 0 ? 0 : 1;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

int run_bench(Host* host, int frames, const std::string& out_path, const std::string& renderer) {
  const auto time_frames = [host, frames](bool on) {
    host->set_module(on);
    render(host, 3);  // warm: programs, targets, OSG's GL objects
    std::vector<double> ms;
    for (int i = 0; i < frames; ++i) {
      const auto start = std::chrono::steady_clock::now();
      host->viewer.frame();  // single-threaded: returns after the draw and the read-backs
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    return median(ms);
  };
  const double off = time_frames(false), on = time_frames(true), off_again = time_frames(false);
  const double engine = 0.5 * (off + off_again);
  const Pixels mask = pixels_of(*host->mask_image);
  std::size_t skin = 0;
  for (std::size_t p = 0; p < mask.size(); p += 4) skin += mask[p] != 0 ? 1 : 0;
  // The row docs/benchmarks/osg-host.md takes (scripts/update-osg-docs.sh): size, skin pixels,
  // frames timed, the engine's frame without and with the module, what the module adds.
  char row[256];
  std::snprintf(row, sizeof row, "osg-row %dx%d %zu %d %.1f %.1f %.1f", host->width, host->height, skin, frames,
                engine, on, on - engine);
  std::printf("OpenSceneGraph frame (median of %d, ms): without the module %.1f, with it %.1f, the module adds %.1f "
              "(%zu skin pixels)\nrenderer: %s\n%s\n", frames, engine, on, on - engine, skin, renderer.c_str(), row);
  if (!out_path.empty()) {
    std::ofstream out(out_path);
    out << row << "\n";
    if (!out) return 1;
  }
  return 0;
}

std::string renderer_of(Host* host) {
  struct Probe : osg::Camera::DrawCallback {
    mutable std::string text;
    void operator()(osg::RenderInfo&) const override {
      const GLubyte* r = glGetString(GL_RENDERER);
      const GLubyte* v = glGetString(GL_VERSION);
      text = std::string(r != nullptr ? reinterpret_cast<const char*>(r) : "?") + ", " +
             (v != nullptr ? reinterpret_cast<const char*>(v) : "?");
    }
  };
  osg::ref_ptr<Probe> probe = new Probe;
  host->viewer.getCamera()->setFinalDrawCallback(probe.get());
  host->viewer.frame();
  host->viewer.getCamera()->setFinalDrawCallback(nullptr);
  return probe->text;
}

}  // namespace

int main(int argc, char** argv) {
  osg::ArgumentParser args(&argc, argv);
  args.getApplicationUsage()->setCommandLineUsage(args.getApplicationName() + " [options]");
  Host host;
  std::string threading = "single", out_dir, bench_out, texturing = "pre";
  int bench = 0;
  args.read("--width", host.width);
  args.read("--height", host.height);
  args.read("--threading", threading);
  args.read("--out", out_dir);
  args.read("--bench", bench);
  args.read("--bench-out", bench_out);
  args.read("--texturing", texturing);
  const bool checks = args.read("--check");
  const bool no_sss = args.read("--no-sss");
  const bool leak_state = args.read("--leak-state");
  // The library created without its state restore (SSS_CREATE_NO_STATE_RESTORE): it asks the GL
  // nothing, and the callback tells OSG what changed instead (sss_osg::tell_osg_the_library_drew).
  const bool no_restore = args.read("--no-state-restore");
  args.reportRemainingOptionsAsUnrecognized();
  if (args.errors()) {
    args.writeErrorMessages(std::cerr);
    return 2;
  }
  if (host.width < 64 || host.height < 64 || (threading != "single" && threading != "draw")) {
    std::fprintf(stderr, "sss_osg_host: --width/--height want at least 64, --threading single or draw\n");
    return 2;
  }
  // sss_settings.texturing: the G-buffer's albedo goes with each frame for post and pre-and-post.
  const char* const kTexturings[] = {"pre", "post", "pre-and-post"};
  const auto mode = std::find(std::begin(kTexturings), std::end(kTexturings), texturing);
  if (mode == std::end(kTexturings)) {
    std::fprintf(stderr, "sss_osg_host: --texturing wants pre, post or pre-and-post, got '%s'\n", texturing.c_str());
    return 2;
  }
  gltf_mesh::Model head;
  try {
    head = gltf_mesh::load_gltf(sss_assets::head_path());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sss_osg_host: %s\n", e.what());
    return 1;
  }
  if (!build(&host, threading, head)) {
    std::fprintf(stderr, "sss_osg_host: no OpenGL pbuffer context (no X display? run under xvfb-run)\n");
    return 77;
  }
  sss_settings settings;
  sss_default_settings(&settings);
  settings.texturing = static_cast<std::uint32_t>(mode - std::begin(kTexturings));
  host.sss->set_settings(settings);
  host.checked->set_leak_state(leak_state);
  host.checked->set_no_restore(no_restore);
  if (no_restore) host.sss->set_create_flags(SSS_CREATE_NO_STATE_RESTORE);
  // The library's GL goes through a loader that counts its queries (tests/support/counting_loader).
  host.sss->set_loader(sss_test::counting_loader(sss_osg::osg_gl_loader), nullptr);
  const std::string renderer = renderer_of(&host);
  std::printf("sss_osg_host: OpenSceneGraph %s, %s, threading %s, %dx%d, texturing %s\n", osgGetVersion(),
              renderer.c_str(), threading.c_str(), host.width, host.height, texturing.c_str());
  int status = 0;
  if (checks) {
    status = run_checks(&host, no_restore);
  } else if (bench > 0) {
    status = run_bench(&host, bench, bench_out, renderer);
  } else {
    host.set_module(!no_sss);
    render(&host, 3);
    if (!host.sss->last_error().empty()) std::fprintf(stderr, "sss_osg_host: %s\n", host.sss->last_error().c_str());
    if (!out_dir.empty()) {
      // OSG's images are bottom-up, as GL reads them; its PNG writer stores them upright.
      const bool ok = osgDB::writeImageFile(*host.final_image, out_dir + "/final.png") &&
                      osgDB::writeImageFile(*host.standard_image, out_dir + "/standard.png");
      std::ofstream(out_dir + "/ATTRIBUTION.txt") << "final.png shows a model whose licence asks for this attribution:\n"
                                                  << sss_assets::head_attribution() << "\n";
      if (!ok) status = 1;
      std::printf("sss_osg_host: wrote %s/final.png (%s) and standard.png\n", out_dir.c_str(),
                  no_sss ? "without the module" : "with the module");
    }
  }
  host.sss->request_release();
  host.viewer.frame();  // the library's context goes on the draw thread, its GL context current
  return status;
}
