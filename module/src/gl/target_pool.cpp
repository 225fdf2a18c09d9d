#include "target_pool.hpp"

#include <cstdio>

#include "../math/tile_culling.hpp"
#include "debug_label.hpp"

namespace sss::gl {

namespace {
// SSS_ERROR_OUT_OF_MEMORY or SSS_ERROR_GL for a GL error after an allocation, with *message.
sss_result allocation_failed(GLenum error, const char* what, int width, int height, std::string* message) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, "allocating the %dx%d %s failed: %s", width, height, what,
                error_name(error).c_str());
  *message = buffer;
  return error == OUT_OF_MEMORY ? SSS_ERROR_OUT_OF_MEMORY : SSS_ERROR_GL;
}

}  // namespace

// (Re)specifies a single-sample texture with one level and no data, and records its storage.
void TargetPool::specify_2d(GLuint texture, GLint format, GLenum pixel_format, GLenum type, int width, int height) {
  const Functions& f = *gl_;
  memory_.set_2d(TEXTURE, texture, format, width, height);
  f.ActiveTexture(TEXTURE0);
  f.BindTexture(TEXTURE_2D, texture);
  f.BindBuffer(PIXEL_UNPACK_BUFFER, 0);  // NULL data must not read from a host buffer
  f.TexParameteri(TEXTURE_2D, TEXTURE_MAX_LEVEL, 0);
  f.TexImage2D(TEXTURE_2D, 0, format, width, height, 0, pixel_format, type, nullptr);
}

void TargetPool::init(const Functions* gl, bool labels, const Log* log) {
  gl_ = gl;
  labels_ = labels;
  log_ = log;
  const Functions& f = *gl_;
  // A framebuffer name becomes an object on first bind; the caller's StateGuard restores bindings.
  GLuint framebuffers[4] = {0, 0, 0, 0};
  f.GenFramebuffers(4, framebuffers);
  t_.intermediate_framebuffer = framebuffers[0];
  t_.output_framebuffer = framebuffers[1];
  t_.stencil_source_framebuffer = framebuffers[2];
  t_.accumulator_framebuffer = framebuffers[3];
  for (GLuint fb : framebuffers) f.BindFramebuffer(FRAMEBUFFER, fb);
  // The stencil source is only ever read from, and has no colour.
  f.BindFramebuffer(READ_FRAMEBUFFER, t_.stencil_source_framebuffer);
  f.ReadBuffer(NONE);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, t_.stencil_source_framebuffer);
  const GLenum no_colour = NONE;
  f.DrawBuffers(1, &no_colour);  // glDrawBuffer is not in ES
  label_object(f, labels_, FRAMEBUFFER, t_.intermediate_framebuffer, "sss horizontal pass target");
  label_object(f, labels_, FRAMEBUFFER, t_.output_framebuffer, "sss vertical pass target");
  label_object(f, labels_, FRAMEBUFFER, t_.stencil_source_framebuffer, "sss host stencil source");
  label_object(f, labels_, FRAMEBUFFER, t_.accumulator_framebuffer, "sss sum of the kernel's terms");
}

void TargetPool::destroy() {
  if (gl_ == nullptr) return;
  const Functions& f = *gl_;
  const GLuint framebuffers[] = {t_.intermediate_framebuffer, t_.output_framebuffer, t_.stencil_source_framebuffer,
                                 t_.accumulator_framebuffer,  t_.masked_framebuffer, t_.resolve_framebuffer,
                                 t_.sample_write_framebuffer, t_.colour_copy_framebuffer, t_.pass_inputs_framebuffer,
                                 t_.pass_intermediate_framebuffer, t_.half_inputs_framebuffer,
                                 t_.half_intermediate_framebuffer, t_.half_result_framebuffer,
                                 t_.tiles_framebuffer,        t_.tile_columns_framebuffer};
  const GLuint textures[] = {t_.intermediate,       t_.accumulators[0],  t_.accumulators[1], t_.masked_source,
                             t_.resolved_color,     t_.resolved_distance, t_.blurred,         t_.translucent_mean,
                             t_.translucent_lowest, t_.colour_copy,   t_.pass_taps,       t_.pass_strength,
                             t_.pass_intermediate,  t_.half_taps,         t_.half_strength,   t_.half_intermediate,
                             t_.half_result,        t_.half_tables,       t_.tiles,           t_.tile_columns,
                             t_.resolved_albedo};
  // Name 0 is silently ignored by both calls.
  f.DeleteFramebuffers(static_cast<GLsizei>(sizeof framebuffers / sizeof framebuffers[0]), framebuffers);
  f.DeleteTextures(static_cast<GLsizei>(sizeof textures / sizeof textures[0]), textures);
  if (t_.stencil_buffer != 0) f.DeleteRenderbuffers(1, &t_.stencil_buffer);
  if (t_.half_depth != 0) f.DeleteRenderbuffers(1, &t_.half_depth);
  forget();
}

void TargetPool::forget() { *this = TargetPool{}; }

void TargetPool::note(const std::string& text) const {
  if (log_ != nullptr && *log_) (*log_)(SSS_LOG_DEBUG, text);
}

sss_result TargetPool::allocate_target(GLuint* texture, GLenum internal_format, GLenum type, int width, int height,
                                       const char* what, std::string* message, GLenum pixel_format) {
  const Functions& f = *gl_;
  if (*texture == 0) f.GenTextures(1, texture);
  specify_2d(*texture, static_cast<GLint>(internal_format), pixel_format, type, width, height);
  const GLenum error = f.GetError();
  if (error != NO_ERROR) {
    memory_.erase(TEXTURE, *texture);
    f.DeleteTextures(1, texture);
    *texture = 0;
    return allocation_failed(error, what, width, height, message);
  }
  label_object(f, labels_, TEXTURE, *texture, (std::string("sss ") + what).c_str());
  char note_text[160];
  std::snprintf(note_text, sizeof note_text, "allocated the %dx%d %s", width, height, what);
  note(note_text);
  return SSS_OK;
}

sss_result TargetPool::ensure_intermediate(GLint format, int width, int height, std::string* message) {
  if (t_.intermediate != 0 && intermediate_format_ == format && intermediate_width_ == width &&
      intermediate_height_ == height) {
    return SSS_OK;
  }
  intermediate_width_ = intermediate_height_ = 0;
  const bool single = format == static_cast<GLint>(RGBA32F);
  const sss_result r = allocate_target(&t_.intermediate, single ? RGBA32F : RGBA16F, single ? FLOAT : HALF_FLOAT,
                                       width, height,
                                       single ? "RGBA32F intermediate target" : "RGBA16F intermediate target", message);
  if (r != SSS_OK) return r;
  intermediate_format_ = single ? static_cast<GLint>(RGBA32F) : static_cast<GLint>(RGBA16F);
  intermediate_width_ = width;
  intermediate_height_ = height;
  const Functions& f = *gl_;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, t_.intermediate_framebuffer);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, t_.intermediate, 0);
  return SSS_OK;
}

sss_result TargetPool::ensure_accumulators(int width, int height, bool half, std::string* message) {
  if (t_.accumulators[1] != 0 && accumulator_half_ == half && accumulator_width_ == width &&
      accumulator_height_ == height) {
    return SSS_OK;
  }
  accumulator_width_ = accumulator_height_ = 0;
  for (GLuint& t : t_.accumulators) {
    const sss_result r =
        allocate_target(&t, half ? RGBA16F : RGBA32F, half ? HALF_FLOAT : FLOAT, width, height,
                        half ? "RGBA16F sum of the kernel's terms" : "RGBA32F sum of the kernel's terms", message);
    if (r != SSS_OK) return r;
  }
  accumulator_half_ = half;
  accumulator_width_ = width;
  accumulator_height_ = height;
  return SSS_OK;
}

sss_result TargetPool::ensure_stencil_buffer(GLint format, int width, int height, std::string* message) {
  if (t_.stencil_buffer != 0 && stencil_format_ == format && stencil_width_ == width && stencil_height_ == height) {
    return SSS_OK;
  }
  const Functions& f = *gl_;
  if (t_.stencil_buffer == 0) f.GenRenderbuffers(1, &t_.stencil_buffer);
  f.BindRenderbuffer(RENDERBUFFER, t_.stencil_buffer);
  // The copy is a blit, which needs the host's exact depth-stencil format.
  f.RenderbufferStorage(RENDERBUFFER, static_cast<GLenum>(format), width, height);
  memory_.set_2d(RENDERBUFFER, t_.stencil_buffer, format, width, height);
  const GLenum error = f.GetError();
  if (error != NO_ERROR) {
    memory_.erase(RENDERBUFFER, t_.stencil_buffer);
    f.DeleteRenderbuffers(1, &t_.stencil_buffer);
    t_.stencil_buffer = 0;
    stencil_format_ = 0;
    return allocation_failed(error, (format_name(format) + " stencil copy").c_str(), width, height, message);
  }
  label_object(f, labels_, RENDERBUFFER, t_.stencil_buffer, "sss stencil copy");
  stencil_format_ = format;
  stencil_width_ = width;
  stencil_height_ = height;
  return SSS_OK;
}

sss_result TargetPool::ensure_masked_source(GLint format, int width, int height, std::string* message) {
  const Functions& f = *gl_;
  ensure_framebuffer(&t_.masked_framebuffer, "sss masked colour copy target");
  if (t_.masked_source != 0 && masked_format_ == format && masked_width_ == width && masked_height_ == height) {
    return SSS_OK;
  }
  if (t_.masked_source == 0) f.GenTextures(1, &t_.masked_source);
  // The host colour's own format: the copy must hold it exactly (its centre share is not blurred),
  // and on OpenGL ES that format is the one the create-time and frame checks found renderable and
  // sampleable (RGBA32F there needs extensions an RGBA16F host may lack).
  specify_2d(t_.masked_source, format, RGBA, FLOAT, width, height);
  const GLenum error = f.GetError();
  if (error != NO_ERROR) {
    memory_.erase(TEXTURE, t_.masked_source);
    f.DeleteTextures(1, &t_.masked_source);
    t_.masked_source = 0;
    masked_width_ = masked_height_ = 0;
    masked_format_ = 0;
    return allocation_failed(error, (format_name(format) + " masked colour copy").c_str(), width, height, message);
  }
  label_object(f, labels_, TEXTURE, t_.masked_source, "sss masked colour copy");
  masked_format_ = format;
  masked_width_ = width;
  masked_height_ = height;
  attach_colour(t_.masked_framebuffer, t_.masked_source);
  return SSS_OK;
}

void TargetPool::ensure_msaa_framebuffers() {
  if (t_.resolve_framebuffer != 0) return;
  const Functions& f = *gl_;
  GLuint framebuffers[2] = {0, 0};
  f.GenFramebuffers(2, framebuffers);
  t_.resolve_framebuffer = framebuffers[0];
  t_.sample_write_framebuffer = framebuffers[1];
  // The resolve's draw buffers are set per frame (msaa_resolve.cpp): 2, or 4 writing back, and 7
  // with the passes' inputs (attach_resolve_inputs).
  resolve_inputs_attached_ = false;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, t_.resolve_framebuffer);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, t_.sample_write_framebuffer);
  label_object(f, labels_, FRAMEBUFFER, t_.resolve_framebuffer, "sss msaa resolve target");
  label_object(f, labels_, FRAMEBUFFER, t_.sample_write_framebuffer, "sss msaa write-back target");
}

sss_result TargetPool::ensure_msaa_targets(GLint color_format, int width, int height, bool write_back, bool albedo,
                                           std::string* message) {
  const Functions& f = *gl_;
  const bool same = t_.resolved_color != 0 && msaa_color_format_ == color_format && msaa_width_ == width &&
                    msaa_height_ == height;
  if (!same) {
    if (t_.resolved_color == 0) {
      GLuint t[5] = {0, 0, 0, 0, 0};
      f.GenTextures(5, t);
      t_.resolved_color = t[0];
      t_.resolved_distance = t[1];
      t_.blurred = t[2];
      t_.translucent_mean = t[3];
      t_.translucent_lowest = t[4];
    }
    has_write_back_targets_ = has_resolved_albedo_ = false;
    specify_2d(t_.resolved_color, color_format, RGBA, FLOAT, width, height);
    specify_2d(t_.resolved_distance, static_cast<GLint>(R32F), RED, FLOAT, width, height);
    const GLenum error = f.GetError();
    if (error != NO_ERROR) {
      msaa_color_format_ = 0;  // reallocated next time
      return allocation_failed(error, "MSAA resolve targets", width, height, message);
    }
    label_object(f, labels_, TEXTURE, t_.resolved_color, "sss msaa resolved colour");
    label_object(f, labels_, TEXTURE, t_.resolved_distance, "sss msaa resolved view distance");
    msaa_color_format_ = color_format;
    msaa_width_ = width;
    msaa_height_ = height;
    f.BindFramebuffer(DRAW_FRAMEBUFFER, t_.resolve_framebuffer);
    f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, t_.resolved_color, 0);
    f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT1, TEXTURE_2D, t_.resolved_distance, 0);
  }
  // A texturing mode into a separate output: translucent_mean holds the resolve's undivided mean.
  if ((write_back || albedo) && !has_write_back_targets_) {
    specify_2d(t_.blurred, color_format, RGBA, FLOAT, width, height);
    specify_2d(t_.translucent_mean, static_cast<GLint>(RGBA32F), RGBA, FLOAT, width, height);
    specify_2d(t_.translucent_lowest, static_cast<GLint>(RGBA32UI), RGBA_INTEGER, UNSIGNED_INT, width, height);
    const GLenum error = f.GetError();
    if (error != NO_ERROR) return allocation_failed(error, "MSAA write-back targets", width, height, message);
    label_object(f, labels_, TEXTURE, t_.blurred, "sss msaa blurred (before the write-back)");
    label_object(f, labels_, TEXTURE, t_.translucent_mean, "sss msaa translucent samples' mean and count");
    label_object(f, labels_, TEXTURE, t_.translucent_lowest, "sss msaa translucent samples' lowest values and mask");
    f.BindFramebuffer(DRAW_FRAMEBUFFER, t_.resolve_framebuffer);
    f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT2, TEXTURE_2D, t_.translucent_mean, 0);
    f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT3, TEXTURE_2D, t_.translucent_lowest, 0);
    has_write_back_targets_ = true;
  }
  return albedo && !has_resolved_albedo_ ? ensure_resolved_albedo(width, height, message) : SSS_OK;
}

// The samples' mean A_post (RGBA32F: the last pass into an output multiplies by it as it is), the
// resolve's attachment 7.
sss_result TargetPool::ensure_resolved_albedo(int width, int height, std::string* message) {
  const Functions& f = *gl_;
  if (t_.resolved_albedo == 0) f.GenTextures(1, &t_.resolved_albedo);
  specify_2d(t_.resolved_albedo, static_cast<GLint>(RGBA32F), RGBA, FLOAT, width, height);
  const GLenum error = f.GetError();
  if (error != NO_ERROR) return allocation_failed(error, "MSAA resolved albedo", width, height, message);
  label_object(f, labels_, TEXTURE, t_.resolved_albedo, "sss msaa samples' mean A_post");
  f.BindFramebuffer(DRAW_FRAMEBUFFER, t_.resolve_framebuffer);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT7, TEXTURE_2D, t_.resolved_albedo, 0);
  has_resolved_albedo_ = true;
  return SSS_OK;
}

sss_result TargetPool::ensure_colour_copy(GLint format, int width, int height, std::string* message) {
  ensure_framebuffer(&t_.colour_copy_framebuffer, "sss colour with the strength texture target");
  if (t_.colour_copy != 0 && strength_format_ == format && strength_width_ == width &&
      strength_height_ == height) {
    return SSS_OK;
  }
  strength_width_ = strength_height_ = 0;
  const bool single = format == static_cast<GLint>(RGBA32F);
  const sss_result r =
      allocate_target(&t_.colour_copy, single ? RGBA32F : RGBA16F, single ? FLOAT : HALF_FLOAT, width, height,
                      single ? "RGBA32F colour with the strength texture" : "RGBA16F colour with the strength texture",
                      message);
  if (r != SSS_OK) return r;
  strength_format_ = format;
  strength_width_ = width;
  strength_height_ = height;
  attach_colour(t_.colour_copy_framebuffer, t_.colour_copy);
  return SSS_OK;
}

sss_result TargetPool::allocate_inputs(const PackedInputs& inputs, int width, int height, const char* size,
                                       std::string* message) {
  const std::string prefix = size;
  sss_result r = allocate_target(inputs.taps, RGBA32UI, UNSIGNED_INT, width, height,
                                 (prefix + "RGBA32UI pass input (colour and view distance)").c_str(), message,
                                 RGBA_INTEGER);
  if (r == SSS_OK) {
    r = allocate_target(inputs.strength, R32UI, UNSIGNED_INT, width, height, (prefix + "R32UI strength").c_str(),
                        message, RED_INTEGER);
  }
  if (r == SSS_OK) {
    r = allocate_target(inputs.intermediate, RGBA32UI, UNSIGNED_INT, width, height,
                        (prefix + "RGBA32UI intermediate (horizontal pass result and view distance)").c_str(),
                        message, RGBA_INTEGER);
  }
  return r;
}

void TargetPool::attach_inputs(GLuint framebuffer, const PackedInputs& inputs) {
  const Functions& f = *gl_;
  const GLenum buffers[3] = {COLOR_ATTACHMENT0, COLOR_ATTACHMENT1, COLOR_ATTACHMENT2};
  attach_colour(framebuffer, *inputs.taps);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT1, TEXTURE_2D, *inputs.strength, 0);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT2, TEXTURE_2D, *inputs.intermediate, 0);
  f.DrawBuffers(3, buffers);
}

void TargetPool::attach_resolve_inputs() {
  if (resolve_inputs_attached_ || t_.resolve_framebuffer == 0 || t_.pass_taps == 0) return;
  const Functions& f = *gl_;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, t_.resolve_framebuffer);
  const GLuint inputs[3] = {t_.pass_taps, t_.pass_strength, t_.pass_intermediate};
  for (int i = 0; i < 3; ++i) {
    f.FramebufferTexture2D(DRAW_FRAMEBUFFER, static_cast<GLenum>(COLOR_ATTACHMENT4 + i), TEXTURE_2D, inputs[i], 0);
  }
  resolve_inputs_attached_ = true;
}

sss_result TargetPool::ensure_pass_targets(int width, int height, std::string* message) {
  if (t_.pass_intermediate_framebuffer != 0 && pass_width_ == width && pass_height_ == height) return SSS_OK;
  pass_width_ = pass_height_ = 0;
  const PackedInputs inputs{&t_.pass_taps, &t_.pass_strength, &t_.pass_intermediate};
  resolve_inputs_attached_ = false;  // a failed allocation may leave new names behind
  const sss_result r = allocate_inputs(inputs, width, height, "", message);
  if (r != SSS_OK) return r;
  pass_width_ = width;
  pass_height_ = height;
  // The framebuffers once the targets exist: a failed allocation leaves no new object behind.
  ensure_framebuffer(&t_.pass_inputs_framebuffer, "sss pass inputs target");
  ensure_framebuffer(&t_.pass_intermediate_framebuffer, "sss horizontal pass target (packed)");
  attach_inputs(t_.pass_inputs_framebuffer, inputs);
  attach_colour(t_.pass_intermediate_framebuffer, t_.pass_intermediate);
  return SSS_OK;
}

sss_result TargetPool::ensure_half_targets(int width, int height, GLint result_format, std::string* message) {
  const int w = (width + 1) / 2, h = (height + 1) / 2;  // math::half_size
  if (t_.half_result_framebuffer != 0 && half_width_ == w && half_height_ == h && half_result_format_ == result_format) {
    return SSS_OK;
  }
  half_width_ = half_height_ = 0;
  const bool single = result_format == static_cast<GLint>(RGBA32F);
  const PackedInputs inputs{&t_.half_taps, &t_.half_strength, &t_.half_intermediate};
  sss_result r = allocate_inputs(inputs, w, h, "half-size ", message);
  if (r == SSS_OK) {
    r = allocate_target(&t_.half_result, single ? RGBA32F : RGBA16F, single ? FLOAT : HALF_FLOAT, w, h,
                        single ? "half-size RGBA32F result" : "half-size RGBA16F result", message);
  }
  if (r != SSS_OK) return r;
  const Functions& f = *gl_;
  if (t_.half_depth == 0) f.GenRenderbuffers(1, &t_.half_depth);
  f.BindRenderbuffer(RENDERBUFFER, t_.half_depth);
  f.RenderbufferStorage(RENDERBUFFER, DEPTH24_STENCIL8, w, h);
  memory_.set_2d(RENDERBUFFER, t_.half_depth, static_cast<GLint>(DEPTH24_STENCIL8), w, h);
  const GLenum error = f.GetError();
  if (error != NO_ERROR) {
    memory_.erase(RENDERBUFFER, t_.half_depth);
    f.DeleteRenderbuffers(1, &t_.half_depth);
    t_.half_depth = 0;
    return allocation_failed(error, "half-size DEPTH24_STENCIL8 culling depth", w, h, message);
  }
  label_object(f, labels_, RENDERBUFFER, t_.half_depth, "sss half-size culling depth");
  half_width_ = w;
  half_height_ = h;
  half_result_format_ = result_format;
  ensure_framebuffer(&t_.half_inputs_framebuffer, "sss half-size inputs target");
  ensure_framebuffer(&t_.half_intermediate_framebuffer, "sss half-size horizontal pass target");
  ensure_framebuffer(&t_.half_result_framebuffer, "sss half-size vertical pass target");
  attach_inputs(t_.half_inputs_framebuffer, inputs);
  attach_colour(t_.half_intermediate_framebuffer, t_.half_intermediate);
  attach_colour(t_.half_result_framebuffer, t_.half_result);
  for (const GLuint framebuffer : {t_.half_inputs_framebuffer, t_.half_intermediate_framebuffer, t_.half_result_framebuffer}) {
    f.BindFramebuffer(DRAW_FRAMEBUFFER, framebuffer);
    f.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, t_.half_depth);
  }
  return SSS_OK;
}

sss_result TargetPool::ensure_tile_targets(int width, int height, std::string* message) {
  const int across = math::tiles_across(width), down = math::tiles_across(height);
  if (t_.tile_columns_framebuffer != 0 && tiles_across_ == across && tiles_down_ == down) return SSS_OK;
  tiles_across_ = tiles_down_ = 0;
  sss_result r = allocate_target(&t_.tiles, R8, UNSIGNED_BYTE, across, down, "R8 tile marks", message, RED);
  if (r == SSS_OK) {
    r = allocate_target(&t_.tile_columns, R8, UNSIGNED_BYTE, across, 1, "R8 tile column marks", message, RED);
  }
  if (r != SSS_OK) return r;
  tiles_across_ = across;
  tiles_down_ = down;
  ensure_framebuffer(&t_.tiles_framebuffer, "sss tile marks target");
  ensure_framebuffer(&t_.tile_columns_framebuffer, "sss tile column marks target");
  attach_colour(t_.tiles_framebuffer, t_.tiles);
  attach_colour(t_.tile_columns_framebuffer, t_.tile_columns);
  return SSS_OK;
}

sss_result TargetPool::upload_half_tables(std::uint64_t revision, int rows, const std::vector<float>& texels,
                                          std::string* message) {
  half_tables_revision_ = 0;
  const int width = static_cast<int>(texels.size() / 4) / rows;
  const Functions& f = *gl_;
  sss_result r = allocate_target(&t_.half_tables, RGBA32F, FLOAT, width, rows, "RGBA32F pass tables", message);
  if (r != SSS_OK) return r;
  // The host's unpack parameters would reshape the upload: tight rows, the host's put back after.
  // (allocate_target left the texture bound on unit 0 and no unpack buffer.)
  const GLenum params[4] = {UNPACK_ALIGNMENT, UNPACK_ROW_LENGTH, UNPACK_SKIP_ROWS, UNPACK_SKIP_PIXELS};
  GLint saved[4] = {4, 0, 0, 0};
  for (int i = 0; i < 4; ++i) f.GetIntegerv(params[i], &saved[i]);
  f.PixelStorei(UNPACK_ALIGNMENT, 4);
  for (int i = 1; i < 4; ++i) f.PixelStorei(params[i], 0);
  f.TexImage2D(TEXTURE_2D, 0, static_cast<GLint>(RGBA32F), width, rows, 0, RGBA, FLOAT, texels.data());
  for (int i = 0; i < 4; ++i) f.PixelStorei(params[i], saved[i]);
  const GLenum error = f.GetError();
  if (error != NO_ERROR) return allocation_failed(error, "RGBA32F pass tables", width, rows, message);
  half_tables_revision_ = revision;
  return SSS_OK;
}

void TargetPool::ensure_framebuffer(GLuint* framebuffer, const char* label) {
  if (*framebuffer != 0) return;
  const Functions& f = *gl_;
  f.GenFramebuffers(1, framebuffer);
  f.BindFramebuffer(DRAW_FRAMEBUFFER, *framebuffer);  // a name is an object only once bound (for the label)
  label_object(f, labels_, FRAMEBUFFER, *framebuffer, label);
}

void TargetPool::attach_colour(GLuint framebuffer, GLuint texture) {
  const Functions& f = *gl_;
  f.BindFramebuffer(DRAW_FRAMEBUFFER, framebuffer);
  f.FramebufferTexture2D(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, texture, 0);
}

}  // namespace sss::gl
