#include "gl_state_snapshot.hpp"

#include <algorithm>
#include <iterator>

#include <array>
#include <cstring>
#include <sstream>

using namespace host_gl;

namespace sss_test {

void Snapshot::integer(const char* name, GLenum pname, int count) {
  std::vector<GLint> v(static_cast<std::size_t>(count), -12345);
  glGetIntegerv(pname, v.data());
  add(name, v);
}

void Snapshot::boolean(const char* name, GLenum pname, int count) {
  std::array<GLboolean, 4> b{};
  glGetBooleanv(pname, b.data());
  add(name, std::vector<GLint>(b.begin(), b.begin() + count));
}

void Snapshot::enabled(const char* name, GLenum cap) { add(name, {glIsEnabled(cap)}); }

Snapshot take_snapshot(bool es) {
  Snapshot s;
  s.integer("GL_CURRENT_PROGRAM", GL_CURRENT_PROGRAM);
  s.integer("GL_VERTEX_ARRAY_BINDING", GL_VERTEX_ARRAY_BINDING);
  s.integer("GL_DRAW_FRAMEBUFFER_BINDING", GL_DRAW_FRAMEBUFFER_BINDING);
  s.integer("GL_READ_FRAMEBUFFER_BINDING", GL_READ_FRAMEBUFFER_BINDING);
  s.integer("GL_RENDERBUFFER_BINDING", GL_RENDERBUFFER_BINDING);
  s.integer("GL_PIXEL_UNPACK_BUFFER_BINDING", GL_PIXEL_UNPACK_BUFFER_BINDING);
  s.integer("GL_PIXEL_PACK_BUFFER_BINDING", GL_PIXEL_PACK_BUFFER_BINDING);
  s.integer("GL_ARRAY_BUFFER_BINDING", GL_ARRAY_BUFFER_BINDING);
  s.integer("GL_UNIFORM_BUFFER_BINDING", GL_UNIFORM_BUFFER_BINDING);
  {
    GLint name = -1;
    GLint64 start = -1, size = -1;
    glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, 0, &name);
    glGetInteger64i_v(GL_UNIFORM_BUFFER_START, 0, &start);
    glGetInteger64i_v(GL_UNIFORM_BUFFER_SIZE, 0, &size);
    s.add("GL_UNIFORM_BUFFER_BINDING index 0 (name, start, size)",
          {name, static_cast<GLint>(start), static_cast<GLint>(size)});
  }
  s.integer("GL_ACTIVE_TEXTURE", GL_ACTIVE_TEXTURE);
  GLint active = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
  for (GLenum unit = 0; unit < 7; ++unit) {  // units 0-6: the restored list (sss.h; 6 with an albedo)
    glActiveTexture(GL_TEXTURE0 + unit);
    s.integer(("GL_TEXTURE_BINDING_2D unit " + std::to_string(unit)).c_str(), GL_TEXTURE_BINDING_2D);
    s.integer(("GL_SAMPLER_BINDING unit " + std::to_string(unit)).c_str(), GL_SAMPLER_BINDING);
    s.integer(("GL_TEXTURE_BINDING_2D_MULTISAMPLE unit " + std::to_string(unit)).c_str(),
              GL_TEXTURE_BINDING_2D_MULTISAMPLE);
  }
  glActiveTexture(static_cast<GLenum>(active));
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  // Image units 0 (the compute path's target, the fragment taps) and 1 (the fragment passes' strength).
  for (GLuint index = 0; !es && major * 10 + minor >= 43 && index < 2; ++index) {
    std::vector<GLint> unit(6, -1);
    glGetIntegeri_v(GL_IMAGE_BINDING_NAME, index, &unit[0]);
    glGetIntegeri_v(GL_IMAGE_BINDING_LEVEL, index, &unit[1]);
    GLboolean layered = 2;
    glGetBooleani_v(GL_IMAGE_BINDING_LAYERED, index, &layered);
    unit[2] = layered;
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYER, index, &unit[3]);
    glGetIntegeri_v(GL_IMAGE_BINDING_ACCESS, index, &unit[4]);
    glGetIntegeri_v(GL_IMAGE_BINDING_FORMAT, index, &unit[5]);
    s.add("GL_IMAGE_BINDING_* unit " + std::to_string(index) + " (name, level, layered, layer, access, format)", unit);
  }
  s.integer("GL_VIEWPORT", GL_VIEWPORT, 4);
  s.integer("GL_SCISSOR_BOX", GL_SCISSOR_BOX, 4);
  {
    GLint mask = -12345;
    glGetIntegeri_v(GL_SAMPLE_MASK_VALUE, 0, &mask);
    s.add("GL_SAMPLE_MASK_VALUE[0]", {mask});
  }
  const std::pair<const char*, GLenum> caps[] = {
      {"GL_SCISSOR_TEST", GL_SCISSOR_TEST},
      {"GL_DEPTH_TEST", GL_DEPTH_TEST},
      {"GL_STENCIL_TEST", GL_STENCIL_TEST},
      {"GL_BLEND", GL_BLEND},
      {"GL_CULL_FACE", GL_CULL_FACE},
      {"GL_FRAMEBUFFER_SRGB", GL_FRAMEBUFFER_SRGB},
      {"GL_RASTERIZER_DISCARD", GL_RASTERIZER_DISCARD},
      {"GL_SAMPLE_ALPHA_TO_COVERAGE", GL_SAMPLE_ALPHA_TO_COVERAGE},
      {"GL_SAMPLE_COVERAGE", GL_SAMPLE_COVERAGE},
      {"GL_SAMPLE_MASK", GL_SAMPLE_MASK},
      {"GL_POLYGON_OFFSET_FILL", GL_POLYGON_OFFSET_FILL},
      {"GL_DEPTH_CLAMP", GL_DEPTH_CLAMP},
      {"GL_COLOR_LOGIC_OP", GL_COLOR_LOGIC_OP},
      {"GL_CLIP_DISTANCE0", GL_CLIP_DISTANCE0},
      {"GL_CLIP_DISTANCE5", GL_CLIP_DISTANCE5},
      {"GL_CLIP_DISTANCE7", GL_CLIP_DISTANCE7},
      {"GL_DITHER", GL_DITHER},
      {"GL_MULTISAMPLE", GL_MULTISAMPLE},
  };
  // OpenGL ES has none of these (asking raises GL_INVALID_ENUM).
  const GLenum desktop_only[] = {GL_FRAMEBUFFER_SRGB, GL_DEPTH_CLAMP,     GL_COLOR_LOGIC_OP, GL_CLIP_DISTANCE0,
                                 GL_CLIP_DISTANCE5,   GL_CLIP_DISTANCE7, GL_MULTISAMPLE};
  for (const auto& cap : caps) {
    if (es && std::find(std::begin(desktop_only), std::end(desktop_only), cap.second) != std::end(desktop_only)) continue;
    s.enabled(cap.first, cap.second);
  }
  s.boolean("GL_COLOR_WRITEMASK", GL_COLOR_WRITEMASK, 4);
  s.boolean("GL_DEPTH_WRITEMASK", GL_DEPTH_WRITEMASK);
  if (!es) s.integer("GL_POLYGON_MODE", GL_POLYGON_MODE, 2);
  s.integer("GL_DEPTH_FUNC", GL_DEPTH_FUNC);
  {
    GLfloat range[2] = {0.0f, 0.0f};  // as bits: the snapshot compares integers
    glGetFloatv(GL_DEPTH_RANGE, range);
    GLint bits[2];
    std::memcpy(bits, range, sizeof bits);
    s.add("GL_DEPTH_RANGE (float bits)", {bits[0], bits[1]});
  }
  s.integer("GL_BLEND_SRC_RGB", GL_BLEND_SRC_RGB);
  s.integer("GL_BLEND_DST_RGB", GL_BLEND_DST_RGB);
  s.integer("GL_BLEND_SRC_ALPHA", GL_BLEND_SRC_ALPHA);
  s.integer("GL_BLEND_DST_ALPHA", GL_BLEND_DST_ALPHA);
  s.integer("GL_BLEND_EQUATION_RGB", GL_BLEND_EQUATION_RGB);
  s.integer("GL_BLEND_EQUATION_ALPHA", GL_BLEND_EQUATION_ALPHA);
  s.integer("GL_CULL_FACE_MODE", GL_CULL_FACE_MODE);
  s.integer("GL_FRONT_FACE", GL_FRONT_FACE);
  s.integer("GL_UNPACK_ALIGNMENT", GL_UNPACK_ALIGNMENT);
  s.integer("GL_PACK_ALIGNMENT", GL_PACK_ALIGNMENT);
  s.integer("GL_PACK_ROW_LENGTH", GL_PACK_ROW_LENGTH);
  s.integer("GL_PACK_SKIP_ROWS", GL_PACK_SKIP_ROWS);
  s.integer("GL_PACK_SKIP_PIXELS", GL_PACK_SKIP_PIXELS);
  const std::pair<const char*, GLenum> stencil[] = {
      {"GL_STENCIL_FUNC", GL_STENCIL_FUNC},
      {"GL_STENCIL_REF", GL_STENCIL_REF},
      {"GL_STENCIL_VALUE_MASK", GL_STENCIL_VALUE_MASK},
      {"GL_STENCIL_FAIL", GL_STENCIL_FAIL},
      {"GL_STENCIL_PASS_DEPTH_FAIL", GL_STENCIL_PASS_DEPTH_FAIL},
      {"GL_STENCIL_PASS_DEPTH_PASS", GL_STENCIL_PASS_DEPTH_PASS},
      {"GL_STENCIL_WRITEMASK", GL_STENCIL_WRITEMASK},
      {"GL_STENCIL_BACK_FUNC", GL_STENCIL_BACK_FUNC},
      {"GL_STENCIL_BACK_REF", GL_STENCIL_BACK_REF},
      {"GL_STENCIL_BACK_VALUE_MASK", GL_STENCIL_BACK_VALUE_MASK},
      {"GL_STENCIL_BACK_FAIL", GL_STENCIL_BACK_FAIL},
      {"GL_STENCIL_BACK_PASS_DEPTH_FAIL", GL_STENCIL_BACK_PASS_DEPTH_FAIL},
      {"GL_STENCIL_BACK_PASS_DEPTH_PASS", GL_STENCIL_BACK_PASS_DEPTH_PASS},
      {"GL_STENCIL_BACK_WRITEMASK", GL_STENCIL_BACK_WRITEMASK},
  };
  for (const auto& st : stencil) s.integer(st.first, st.second);
  s.integer("GL_DEBUG_GROUP_STACK_DEPTH", GL_DEBUG_GROUP_STACK_DEPTH);
  return s;
}

std::string describe_differences(const Snapshot& a, const Snapshot& b) {
  std::ostringstream out;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    if (a.values[i].second == b.values[i].second) continue;
    out << a.values[i].first << ": before {";
    for (GLint v : a.values[i].second) out << ' ' << v;
    out << " } after {";
    for (GLint v : b.values[i].second) out << ' ' << v;
    out << " }\n";
  }
  return out.str();
}


}  // namespace sss_test
