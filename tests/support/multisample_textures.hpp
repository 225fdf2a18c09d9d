// Multisampled host textures for the MSAA tests, filled from a scene made at twice the size (see
// downsample_2x2 in synthetic_scene.hpp: sample i of pixel (x, y) is texel (2x + i % 2, 2y + i / 2)
// of the fine image), and a per-sample read-back. Each call restores the bindings it changes.
#pragma once

#include <vector>

#include "host_gl.hpp"

namespace sss_test {

// A GL_TEXTURE_2D_MULTISAMPLE of `internal_format` (colour: RGBA16F/RGBA32F; depth: a
// DEPTH_COMPONENT* or DEPTH*_STENCIL8 format, written through gl_FragDepth) whose samples come
// from `fine` (RGBA for colour, one value per texel for depth) of size 2w x 2h. Returns 0 when
// the GL refused the storage (e.g. more samples than the context offers); the GL error is cleared.
GLuint make_multisample_texture(GLenum internal_format, int width, int height, int samples,
                                const std::vector<float>& fine);

// A multisampled GL_DEPTH24_STENCIL8 with depth from `fine_depth` and stencil 1 where
// `fine_stencil` is non-zero (0 elsewhere), both of size 2w x 2h.
GLuint make_multisample_depth_stencil(int width, int height, int samples, const std::vector<float>& fine_depth,
                                      const std::vector<uint8_t>& fine_stencil);

// Every sample of a multisampled colour texture: result[sample][(y * width + x) * 4 + channel].
std::vector<std::vector<float>> read_samples(GLuint texture, int width, int height, int samples);

// The number of samples of a multisampled texture (GL_TEXTURE_SAMPLES).
int texture_samples(GLuint texture);

}  // namespace sss_test
