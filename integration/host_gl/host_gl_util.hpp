// Small GL helpers for the project's host programs (demo, benchmark, scenes): error checks,
// programs, textures, framebuffers, a clock. Messages go to stderr.
#pragma once

#include "host_gl.hpp"

#include <string>

namespace host_gl {

// Drains glGetError; prints each error with `stage` and returns false when there was any.
bool check_gl(const char *stage);

// Compiles and links a vertex + fragment program. Returns 0 and prints the driver log on failure.
GLuint build_program(const char *name, const char *vertex_source, const char *fragment_source);

// Desktop OpenGL 4.3 or newer: compute shaders. The loader takes glDispatchCompute and the image
// functions from every context (the drivers hand out their entry points); only such a context
// may call them.
bool has_compute_shaders();
// A compute program, as build_program.
GLuint build_compute_program(const char *name, const char *source);

// A 2D texture with storage of the given format, NEAREST filtering, CLAMP_TO_EDGE.
GLuint make_texture(GLint internal_format, GLsizei width, GLsizei height, GLenum format, GLenum type);

// Checks the bound draw framebuffer; prints `name` and the status on failure.
bool check_framebuffer(const char *name);

// "#version 330 core" vertex shader of one triangle covering the viewport (gl_VertexID 0..2, no
// vertex buffer): the vertex stage of every full-screen pass.
extern const char *const kFullscreenVertexShader;

// Monotonic milliseconds, for stage timings.
double now_ms();

}  // namespace host_gl
