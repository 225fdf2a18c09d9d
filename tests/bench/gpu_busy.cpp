#include "gpu_busy.hpp"

#include <algorithm>

#include "host_gl_util.hpp"

using namespace host_gl;

namespace sss_bench {

namespace {

// One work group of 64 invocations, each iterating a chain of dependent multiply-adds: long in
// time, nothing in memory traffic. The result goes to a 64-texel image so the loop is kept.
const char* const kSpinShader = R"(#version 430 core
layout(local_size_x = 64) in;
layout(binding = 0, r32f) uniform writeonly image2D u_sink;
uniform int u_iterations;
void main() {
  float x = float(gl_LocalInvocationID.x) * 0.001;
  for (int i = 0; i < u_iterations; ++i) x = fract(x * 1.000173 + 0.618034);
  imageStore(u_sink, ivec2(gl_LocalInvocationID.x, 0), vec4(x));
}
)";

}  // namespace

std::unique_ptr<GpuBusy> GpuBusy::create(double busy_ms) {
  if (!has_compute_shaders()) return nullptr;
  const GLuint program = build_compute_program("gpu busy", kSpinShader);
  if (program == 0) return nullptr;
  const GLuint sink = make_texture(GL_R32F, 64, 1, GL_RED, GL_FLOAT);
  std::unique_ptr<GpuBusy> busy(new GpuBusy(program, sink));
  // Calibrate: the spin's time grows with its iterations; scale them to the wanted time.
  for (int round = 0; round < 3; ++round) {
    const double ms = busy->time_once();
    if (!(ms > 0.0)) break;
    busy->iterations_ = std::clamp(static_cast<int>(busy->iterations_ * busy_ms / ms), 64, 1 << 24);
  }
  busy->calibrated_ms_ = busy->time_once();
  return busy;
}

GpuBusy::GpuBusy(GLuint program, GLuint sink)
    : program_(program), sink_(sink), iterations_location_(glGetUniformLocation(program, "u_iterations")) {}

GpuBusy::~GpuBusy() {
  glDeleteProgram(program_);
  glDeleteTextures(1, &sink_);
}

void GpuBusy::run() {
  glUseProgram(program_);
  glUniform1i(iterations_location_, iterations_);
  glBindImageTexture(0, sink_, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  glDispatchCompute(1, 1, 1);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  glUseProgram(0);
  glFlush();  // the GPU starts spinning now, while the CPU goes on to issue the timed frame
}

double GpuBusy::time_once() {
  GLuint query = 0;
  glGenQueries(1, &query);
  glFinish();
  glBeginQuery(GL_TIME_ELAPSED, query);
  run();
  glEndQuery(GL_TIME_ELAPSED);
  GLuint64 ns = 0;
  glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
  glDeleteQueries(1, &query);
  return static_cast<double>(ns) * 1e-6;
}

}  // namespace sss_bench
