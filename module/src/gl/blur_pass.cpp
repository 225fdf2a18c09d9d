#include "blur_pass.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "pass_uniforms.hpp"
#include "texture_units.hpp"

namespace sss::gl {

bool writes_half_float(const Functions& gl, const FilterRun& run, std::size_t term, int axis) {
  if (axis == 0) return run.intermediate_format() == static_cast<GLint>(RGBA16F);
  // (A debug view runs the first term alone: its vertical pass writes the output.)
  const std::size_t terms = run.cross_bilateral || run.debug_view != 0 ? 1 : run.kernel->terms.size();
  if (term + 1 < terms) return accumulators_are_half(gl.api.es, run);
  return run.target().internal_format == static_cast<GLint>(RGBA16F);
}

namespace {
// The pass's tables: the cumulative one and the sparse layout's spacing (its reach, centre delta and
// tap count are in the struct, pass_uniforms.hpp).
void upload_kernel(const Functions& f, const BlurProgram& p, const FilterRun& run, const math::PassTaps& taps) {
  if (p.cdf >= 0) {  // a per-pixel profile variant reads its tables from a uniform block instead
    const math::FootprintTable& table = taps.footprint;
    std::vector<float> packed;
    packed.reserve(table.half_cdf.size() * 4);
    for (const auto& entry : table.half_cdf) packed.insert(packed.end(), {entry[0], entry[1], entry[2], 0.0f});
    f.Uniform4fv(p.cdf, static_cast<GLsizei>(packed.size() / 4), packed.data());
  }
  const std::vector<float>& spacing = run.kernel->spacing;
  if (!spacing.empty() && p.spacing >= 0) f.Uniform1fv(p.spacing, static_cast<GLsizei>(spacing.size()), spacing.data());
}
}  // namespace

void set_blur_uniforms(PassContext& ctx, BlurProgram& p, const FilterRun& run, std::size_t term, int axis,
                       int round_to_half) {
  const Functions& f = ctx.gl;
  const math::PassTerm& t = run.kernel->terms[term];
  f.UseProgram(p.program);
  if (p.kernel_revision != run.kernel_revision || p.uploaded_term != term || p.uploaded_axis != axis) {
    upload_kernel(f, p, run, axis == 0 ? t.horizontal : t.vertical);
    p.kernel_revision = run.kernel_revision;
    p.uploaded_term = term;
    p.uploaded_axis = axis;
  }
  // (No axis uniform: the compute variants have SSS_AXIS, and a fragment variant's axis follows
  // from SSS_PACKED_OUTPUT.)
  // The pass's struct in one call (a variant whose depth correction is the Gaussian reads
  // u_inv_two_variance, and its follow-surface number in profile mm per world unit).
  const bool rounds = round_to_half >= 0 ? round_to_half != 0 : writes_half_float(f, run, term, axis);
  const BlurUniforms u = fill_blur_uniforms(run, term, axis, p.gaussian_depth, rounds);
  upload_uniforms(f, kBlurUniforms, p.fields, u.values.data());
  if (p.profile >= 0) {
    // Each profile's step and follow-surface numbers for this pass (its tables are in the block).
    std::array<float, 4 * math::kMaxProfiles> looks{};
    for (int i = 0; i < run.profile_count; ++i) {
      const auto look = math::profile_pass_vector(run.profile_constants[static_cast<std::size_t>(i)],
                                                  run.profile_kernels[static_cast<std::size_t>(i)]->terms[term], axis);
      std::copy(look.begin(), look.end(), looks.begin() + 4 * i);
      looks[static_cast<std::size_t>(4 * i + 3)] = run.texturing[static_cast<std::size_t>(i)];  // albedo.glsl's mode
    }
    f.Uniform4fv(p.profile, run.profile_count, looks.data());
  }
}

void set_debug_fill(const Functions& f, const BlurProgram& p, bool fill) {
  // The values the program holds (UniformLocations::held), with the one field changed: only it is set.
  BlurUniforms u;
  std::copy_n(p.fields.held.begin(), u.values.size(), u.values.begin());
  u.set(kBlurUniforms, BlurField::debug_fill, fill ? 1.0f : 0.0f);
  upload_uniforms(f, kBlurUniforms, p.fields, u.values.data());
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
