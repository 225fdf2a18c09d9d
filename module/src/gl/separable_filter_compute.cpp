// The compute path of the separable filter (sss.h SSS_PATH_COMPUTE, OpenGL 4.3+): the same two
// passes as run_single, as dispatches of separable_blur.comp that cache each row (then column)
// segment in shared memory. Horizontal: host colour -> the RGBA16F intermediate (image unit 0);
// vertical: intermediate -> the host's colour or the separate output (image unit 0). The image
// unit is part of the StateGuard's list; samplers and texture units are the fragment path's.
#include <cstdio>

#include "debug_label.hpp"
#include "program.hpp"
#include "separable_filter.hpp"
#include "state_guard.hpp"

namespace sss::gl {

namespace {
constexpr GLuint kOriginalUnit = 2;

// The target formats the vertical pass writes through an image unit, with their GLSL qualifiers:
// the colour and output formats sss_apply_frame accepts (both have image formats).
constexpr const auto& kImageFormatTable = kComputeImageFormats;

int image_format_index(GLint internal_format) {
  static_assert(sizeof kImageFormatTable / sizeof kImageFormatTable[0] == SeparableFilter::kImageFormats,
                "one compute variant per image format");
  for (int i = 0; i < SeparableFilter::kImageFormats; ++i) {
    if (kImageFormatTable[i].internal_format == static_cast<GLenum>(internal_format)) return i;
  }
  return -1;
}

GLuint groups(int pixels) { return static_cast<GLuint>((pixels + kComputeSegment - 1) / kComputeSegment); }
}  // namespace

const char* SeparableFilter::compute_unavailable(const FilterRun& run) const {
  if (!gl_->has_compute) return "the context has no compute shaders (OpenGL 4.3+ desktop)";
  if (run.color.multisampled()) return "the colour is multisampled";
  if (run.cross_bilateral) return "the cross-bilateral mode runs as fragment passes";
  if (run.stencil != nullptr) return "a stencil mask needs the fragment passes' stencil test";
  if (run.kernel == nullptr || run.kernel->terms.size() != 1) return "the kernel has several terms";
  const TextureInfo& target = run.output.name != 0 ? run.output : run.color;
  if (image_format_index(target.internal_format) < 0) {
    return "the target's format has no image format (RGBA16F or RGBA32F)";
  }
  return "";
}

sss_result SeparableFilter::compute_program(const BlurVariant& v, int image_format, BlurProgram** out,
                                            std::string* message) {
  BlurProgram& p = compute_programs_[static_cast<std::size_t>(blur_variant_index(v) * kImageFormats + image_format)];
  *out = &p;
  if (p.program != 0) return SSS_OK;

  // The fragment variant's switches (SSS_ACCUMULATE is always 0 here), then the compute ones.
  const std::string defines = compute_blur_defines(v, image_format);
  std::string log;
  const Functions& f = *gl_;
  p.program = build_compute_program(f, compute_recipe(defines), &log);
  if (p.program == 0) {
    *message = "separable blur compute shader (" + defines + "): " + log;
    return SSS_ERROR_SHADER_COMPILE;
  }
  char label[128];
  std::snprintf(label, sizeof label, "sss compute blur outside=%d follow=%d linear=%d jitter=%d %s",
                static_cast<int>(v.outside), v.follow_surface, v.linear_depth ? 1 : 0, v.jitter ? 1 : 0,
                kImageFormatTable[image_format].qualifier);
  label_object(f, labels_, PROGRAM, p.program, label);
  note(std::string("built the blur program (GLSL 430 core, ") + label + ")");
  find_blur_uniforms(&p);
  p.compute = true;
  return SSS_OK;
}

void SeparableFilter::dispatch_blur(BlurProgram& p, const FilterRun& run, GLuint source, int axis) {
  const Functions& f = *gl_;
  set_blur_uniforms(p, run, 0, axis);
  const std::array<int, 4>& rect = run.draw_rect;
  f.Uniform4i(p.rect, rect[0], rect[1], rect[2], rect[3]);
  bind_blur_inputs(source, run.depth.name);
  // One work group per segment of a row (horizontal) or column (vertical) of the rectangle.
  if (axis == 0) {
    f.DispatchCompute(groups(rect[2]), static_cast<GLuint>(rect[3]), 1);
  } else {
    f.DispatchCompute(groups(rect[3]), static_cast<GLuint>(rect[2]), 1);
  }
  ++last_draws_;
}

sss_result SeparableFilter::run_compute(const FilterRun& run, std::string* message) {
  const Functions& f = *gl_;
  const bool write_back = run.output.name == 0;
  const TextureInfo& target = write_back ? run.color : run.output;
  const int target_format = image_format_index(target.internal_format);
  BlurProgram* horizontal = nullptr;
  BlurProgram* vertical = nullptr;
  sss_result r = compute_program(blur_variant(run, 0, 0, Outside::write_centre), 0, &horizontal, message);
  if (r == SSS_OK) {
    const Outside outside = write_back ? Outside::discard : Outside::copy_original;
    r = compute_program(blur_variant(run, 0, 1, outside), target_format, &vertical, message);
  }
  if (r == SSS_OK) r = ensure_intermediate(run.color.width, run.color.height, message);
  if (r != SSS_OK) return r;

  if (run.region && !write_back) {
    // The pixels of the viewport outside the region keep their input: a fragment copy first.
    set_pass_state(f);
    f.BindVertexArray(vertex_array_);
    f.BindFramebuffer(DRAW_FRAMEBUFFER, output_framebuffer_);
    f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, run.output.name, 0);
    f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, 0);
    r = check_framebuffer("output copy", message);
    if (r == SSS_OK) copy_outside_region(run);
    f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, 0, 0);
    if (r != SSS_OK) return r;
  }

  const bool measured = measure_ && queries_.begin_frame(run.frame);
  {
    DebugGroup group(f, labels_, "sss horizontal pass (compute)");
    if (measured) queries_.begin_pass(PassQueries::horizontal);
    f.BindImageTexture(0, intermediate_, 0, 0, 0, WRITE_ONLY, RGBA16F);
    dispatch_blur(*horizontal, run, run.color.name, 0);
    if (measured) queries_.end_pass(PassQueries::horizontal);
  }
  // The vertical pass reads what the horizontal one stored, through its sampler.
  f.MemoryBarrier(TEXTURE_FETCH_BARRIER_BIT);
  {
    DebugGroup group(f, labels_, "sss vertical pass (compute)");
    if (measured) queries_.begin_pass(PassQueries::vertical);
    f.ActiveTexture(TEXTURE0 + kOriginalUnit);
    f.BindTexture(TEXTURE_2D, write_back ? 0 : run.color.name);
    f.BindSampler(kOriginalUnit, sampler_);
    f.BindImageTexture(0, target.name, 0, 0, 0, write_back ? READ_WRITE : WRITE_ONLY,
                       kImageFormatTable[target_format].internal_format);
    dispatch_blur(*vertical, run, intermediate_, 1);
    if (measured) queries_.end_pass(PassQueries::vertical);
  }
  if (measured) queries_.end_frame();
  // The host may use its texture in any way next (sampling, attaching, reading back, copying):
  // every kind of access waits for the image stores.
  f.MemoryBarrier(ALL_BARRIER_BITS);
  // Never leave a host texture on the unit (the StateGuard puts the host's binding back; without
  // it the unit is left empty).
  f.BindImageTexture(0, 0, 0, 0, 0, READ_ONLY, RGBA16F);
  return SSS_OK;
}

}  // namespace sss::gl
