// The passes' inputs draw (pass_inputs.frag), and on the masked path the tile marks
// (tile_mark.frag), read the colour through image unit 0 on desktop GL 4.3+ when the colour texture
// is complete (PassInputsVariant::color_image, TileMarkProgram::color_image): image loads from an
// incomplete texture read 0, where the sampler's fetch, under the module's own sampler object,
// reads the texel. Whether it is complete: the host's promise in place (SSS_FRAME_TARGET_COMPLETE),
// else the GL's answer for an undescribed frame (its min filter and base level), else not.
//
// Which read a frame took is seen through the loader (fault_loader.hpp counts the colour's
// glBindImageTexture calls), not the pixels: llvmpipe loads from an incomplete texture all the
// same (it checks the bound level only), so there the two reads give the same image either way.
// That image must be the same bit for bit: the load and the fetch return the texel's exact value.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "fault_loader.hpp"
#include "filter_case.hpp"
#include "host_gl_util.hpp"

using namespace host_gl;

namespace sss_test {
namespace {

class ImageInputs : public GlTest {
 protected:
  bool image_units() const { return !is_gles() && host_gl::has_compute_shaders(); }

  struct Result {
    std::vector<float> image;
    int image_bindings = 0;  // of the colour
    int queries = 0;         // glGetTexParameteriv
  };

  // One frame of the relief scene on the fragment path `path` (plain or masked), with a fresh
  // context: the colour in `format`, complete (GL_NEAREST) or on the default filter with level 0
  // alone; in place or into a separate output; described (with `flags`) or not.
  Result run(GLenum format, bool complete, bool separate, bool describe, uint32_t flags, uint32_t path) {
    const SyntheticScene scene = make_relief_scene(48, 32, 7, perspective_matrix(40.0f, 1.5f, 0.1f, 10.0f));
    const int w = scene.width, h = scene.height;
    const GLuint color = make_texture(format, w, h, GL_RGBA, GL_FLOAT, scene.color.data());
    glBindTexture(GL_TEXTURE_2D, color);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, complete ? GL_NEAREST : GL_NEAREST_MIPMAP_LINEAR);
    glBindTexture(GL_TEXTURE_2D, 0);
    const GLuint depth = make_depth32f(w, h, scene.window_depth);
    const GLuint output = separate ? make_rgba32f(w, h, std::vector<float>(scene.color.size(), -1.0f)) : 0u;
    loader_override_ = fault_get_proc_address;
    sss_context* ctx = create_sss();
    EXPECT_NE(ctx, nullptr);
    Result result;
    if (ctx == nullptr) return result;
    sss_settings s = visible_settings(17, SSS_FOLLOW_SURFACE, 0.045f);
    s.path = path;
    EXPECT_EQ(sss_set_settings(ctx, &s), SSS_OK);
    EXPECT_EQ(sss_set_camera(ctx, scene.projection.data()), SSS_OK);
    sss_frame f = frame_of(color, depth, output);
    f.flags = flags;
    if (describe) describe_frame(&f, format, GL_RGBA32F, GL_DEPTH_COMPONENT32F, w, h);
    reset_faults();
    faults().watched_image_texture = color;
    EXPECT_EQ(sss_apply_frame(ctx, &f), SSS_OK) << sss_last_error(ctx);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    result.image_bindings = faults().watched_image_bindings;
    result.queries = faults().texture_parameter_queries;
    reset_faults();
    sss_destroy(ctx);
    result.image = read_rgba(separate ? output : color, w, h);
    return result;
  }
};

TEST_F(ImageInputs, OnlyAColourKnownToBeCompleteIsReadThroughTheImageUnit) {
  const int completeness = image_units() ? 2 : 0;  // min filter and base level, asked once
  for (const uint32_t path : {SSS_PATH_FRAGMENT, SSS_PATH_FRAGMENT_MASKED})
  for (const GLenum format : {static_cast<GLenum>(GL_RGBA16F), static_cast<GLenum>(GL_RGBA32F)}) {
    for (const bool separate : {false, true}) {
      SCOPED_TRACE(std::string(path == SSS_PATH_FRAGMENT ? "plain, " : "masked, ") +
                   (format == GL_RGBA16F ? "RGBA16F" : "RGBA32F") + (separate ? ", into a separate output" : ", in place"));
      // The colour's bindings where it is read so: the inputs draw's, and the masked path's tile marks'.
      const int image = image_units() ? (path == SSS_PATH_FRAGMENT ? 1 : 2) : 0;
      if (is_gles()) {  // frames are described on ES; no image units there
        const Result described = run(format, true, separate, true, SSS_FRAME_TARGET_COMPLETE, path);
        EXPECT_EQ(described.image_bindings, 0);
        EXPECT_EQ(described.queries, 0);
        continue;
      }
      // The GL's answer for an undescribed frame.
      const Result asked = run(format, true, separate, false, 0, path);
      EXPECT_EQ(asked.image_bindings, image);
      EXPECT_EQ(asked.queries, completeness);
      const Result incomplete = run(format, false, separate, false, 0, path);
      EXPECT_EQ(incomplete.image_bindings, 0);
      EXPECT_EQ(incomplete.queries, completeness + (image_units() ? 2 : 0))
          << "a mipmap filter: also its max level and whether it is immutable";
      // The host's promise covers the colour in place only (it names the written texture).
      const Result promised = run(format, true, separate, true, SSS_FRAME_TARGET_COMPLETE, path);
      EXPECT_EQ(promised.image_bindings, separate ? 0 : image);
      EXPECT_EQ(promised.queries, 0);
      // A described frame without the promise: the default filter is assumed, nothing asked.
      const Result assumed = run(format, true, separate, true, 0, path);
      EXPECT_EQ(assumed.image_bindings, 0);
      EXPECT_EQ(assumed.queries, 0);
      // The same bits through either read.
      for (const Result* other : {&incomplete, &promised, &assumed}) {
        ASSERT_EQ(other->image.size(), asked.image.size());
        EXPECT_EQ(0, std::memcmp(other->image.data(), asked.image.data(), asked.image.size() * sizeof(float)));
      }
    }
  }
}

}  // namespace
}  // namespace sss_test
