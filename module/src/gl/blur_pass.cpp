#include "blur_pass.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "texture_units.hpp"

namespace sss::gl {

BlurVariant blur_variant(const FilterRun& run, std::size_t term, int axis, Outside outside) {
  const math::PassTerm& t = run.kernel->terms[term];
  BlurVariant v;
  v.outside = outside;
  v.follow_surface = !run.follow_surface ? 0 : (t.depth_variance_mm2 > 0.0f ? 2 : 1);
  v.linear_depth = run.constants.linear_depth;
  v.jitter = run.kernel->jittered();
  v.accumulate = axis == 1 && term > 0;
  return v;
}

int profile_ids_variant(const FilterRun& run) {
  if (!run.has_profiles()) return 0;
  return run.profile_ids.internal_format == static_cast<GLint>(R16UI) ? 2 : 1;
}

BlurVariant fragment_blur_variant(const FilterRun& run, std::size_t term, int axis, Outside outside) {
  BlurVariant v = blur_variant(run, term, axis, outside);
  v.linear_depth = false;  // pass_inputs.frag linearised
  v.profile_ids = profile_ids_variant(run);
  v.packed_output = axis == 0;
  v.half_taps = compile_time_half_taps(static_cast<int>(run.kernel->spacing.size()));
  v.debug_view = static_cast<int>(run.debug_view);
  return v;
}

bool writes_half_float(const Functions& gl, const FilterRun& run, std::size_t term, int axis) {
  if (axis == 0) return run.intermediate_format() == static_cast<GLint>(RGBA16F);
  // (A debug view runs the first term alone: its vertical pass writes the output.)
  const std::size_t terms = run.cross_bilateral || run.debug_view != 0 ? 1 : run.kernel->terms.size();
  if (term + 1 < terms) return accumulators_are_half(gl, run);
  return run.target().internal_format == static_cast<GLint>(RGBA16F);
}

namespace {
// The pass's cumulative table, its reach and centre delta, the sparse layout's spacing, the most
// taps per side, the first that jitters and the depth Gaussian of the term.
void upload_kernel(const Functions& f, const BlurProgram& p, const FilterRun& run, const math::PassTerm& t,
                   const math::PassTaps& taps) {
  if (p.cdf >= 0) {  // a per-pixel profile variant reads its tables from a uniform block instead
    const math::FootprintTable& table = taps.footprint;
    std::vector<float> packed;
    packed.reserve(table.half_cdf.size() * 4);
    for (const auto& entry : table.half_cdf) packed.insert(packed.end(), {entry[0], entry[1], entry[2], 0.0f});
    f.Uniform4fv(p.cdf, static_cast<GLsizei>(packed.size() / 4), packed.data());
  }
  // Apart from the table: a debug view's pass reads the reach alone (its table is optimised away).
  if (p.footprint >= 0) {
    const math::FootprintTable& table = taps.footprint;
    f.Uniform4f(p.footprint, table.reach_mm, table.delta[0], table.delta[1], table.delta[2]);
  }
  // (A fragment variant at a preset count has its tap count as a constant: no u_half_taps.)
  const std::vector<float>& spacing = run.kernel->spacing;
  if (!spacing.empty() && p.spacing >= 0) f.Uniform1fv(p.spacing, static_cast<GLsizei>(spacing.size()), spacing.data());
  if (p.half_taps >= 0) f.Uniform1i(p.half_taps, static_cast<GLint>(spacing.size()));
  if (p.jitter_from >= 0) f.Uniform1i(p.jitter_from, run.kernel->jitter_from);
  if (p.inv_two_variance >= 0) f.Uniform1f(p.inv_two_variance, 0.5f / t.depth_variance_mm2);
}
}  // namespace

void set_blur_uniforms(PassContext& ctx, BlurProgram& p, const FilterRun& run, std::size_t term, int axis) {
  const Functions& f = ctx.gl;
  const math::PassConstants& k = run.constants;
  const math::PassTerm& t = run.kernel->terms[term];
  f.UseProgram(p.program);
  if (p.kernel_revision != run.kernel_revision || p.uploaded_term != term || p.uploaded_axis != axis) {
    upload_kernel(f, p, run, t, axis == 0 ? t.horizontal : t.vertical);
    p.kernel_revision = run.kernel_revision;
    p.uploaded_term = term;
    p.uploaded_axis = axis;
  }
  // (No axis uniform: the compute variants have SSS_AXIS, and a fragment variant's axis follows
  // from SSS_PACKED_OUTPUT.)
  f.Uniform1f(p.pixels_per_mm, k.pixels_per_mm[static_cast<std::size_t>(axis)]);
  // The Gaussian depth correction measures depth in profile millimetres; the ramp in reaches.
  f.Uniform1f(p.follow_surface, p.inv_two_variance >= 0 ? k.mm_per_world : k.follow_surface_factor);
  f.Uniform2f(p.ndc_from_depth, k.ndc_scale, k.ndc_bias);
  f.Uniform4f(p.depth_terms, k.depth_terms[0], k.depth_terms[1], k.depth_terms[2], k.depth_terms[3]);
  f.Uniform4f(p.clamp, k.clamp_min[0], k.clamp_min[1], k.clamp_max[0], k.clamp_max[1]);
  f.Uniform2f(p.pixel_span, k.pixel_span[0], k.pixel_span[1]);
  f.Uniform4f(p.ray_slope, k.slope_scale[0], k.slope_scale[1], k.slope_bias[0], k.slope_bias[1]);
  f.Uniform1i(p.round_to_half, writes_half_float(f, run, term, axis) ? 1 : 0);
  if (p.noise_index >= 0) f.Uniform1ui(p.noise_index, run.noise_index);
  if (p.profile >= 0) {
    // Each profile's step and follow-surface numbers for this pass (its tables are in the block).
    std::array<float, 4 * math::kMaxProfiles> looks{};
    for (int i = 0; i < run.profile_count; ++i) {
      const auto look = math::profile_pass_vector(run.profile_constants[static_cast<std::size_t>(i)],
                                                  run.profile_kernels[static_cast<std::size_t>(i)]->terms[term], axis);
      std::copy(look.begin(), look.end(), looks.begin() + 4 * i);
    }
    f.Uniform4fv(p.profile, run.profile_count, looks.data());
  }
  // Apart from the looks: a debug view that needs no step (mask, depth, profile) has them optimised
  // away, but still leaves the pixels of an index without a profile alone.
  if (p.profile_count >= 0) f.Uniform1i(p.profile_count, run.profile_count);
}

void bind_blur_inputs(PassContext& ctx, GLuint source, GLuint depth) {
  bind_texture(ctx, unit::source, source, ctx.objects.sampler);
  bind_texture(ctx, unit::depth, depth, ctx.objects.depth_sampler);
}

// An integer texture is incomplete under GL_LINEAR, even for texelFetch: the nearest sampler.
void bind_packed_inputs(PassContext& ctx, const BlurProgram& program, GLuint source, GLuint strength) {
  bind_texture(ctx, unit::source, source, ctx.objects.nearest_sampler);
  bind_texture(ctx, unit::pass_strength, strength, ctx.objects.nearest_sampler);
  if (program.image_taps) {
    // `source` was last written as a render target (the inputs draw, or the horizontal pass), which
    // is not one of the incoherent shader writes glMemoryBarrier is for; the barrier costs llvmpipe
    // nothing measurable and keeps a driver that caches image reads apart from its render targets
    // from serving an older frame's texels.
    ctx.gl.MemoryBarrier(SHADER_IMAGE_ACCESS_BARRIER_BIT);
    ctx.gl.BindImageTexture(0, source, 0, 0, 0, READ_ONLY, RGBA32UI);
    ctx.gl.BindImageTexture(1, strength, 0, 0, 0, READ_ONLY, R32UI);
  }
}

void bind_profile_inputs(PassContext& ctx, const FilterRun& run, int axis) {
  if (profile_ids_variant(run) == 2) bind_texture(ctx, unit::profile_ids, run.profile_ids.name, ctx.objects.nearest_sampler);
  ctx.profile_tables->bind(axis);
}

}  // namespace sss::gl
