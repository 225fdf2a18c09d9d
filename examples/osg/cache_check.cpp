#include "cache_check.hpp"

#include <osg/BlendFunc>
#include <osg/ColorMask>
#include <osg/Depth>
#include <osg/GL>
#include <osg/RenderInfo>
#include <osg/GLExtensions>
#include <osg/Program>
#include <osg/State>
#include <osg/Texture>
#include <osg/VertexArrayState>
#include <osg/Viewport>

#include <cstdio>

namespace sss_osg_host {

namespace {

// GL enums past GL 1.1 (osg/GL includes only the system's gl.h).
constexpr GLenum kCurrentProgram = 0x8B8D, kActiveTexture = 0x84E0, kTextureBinding2D = 0x8069;
constexpr GLenum kSamplerBinding = 0x8919, kVertexArrayBinding = 0x85B5, kArrayBufferBinding = 0x8894;
constexpr GLenum kPixelUnpackBufferBinding = 0x88EF, kDrawFramebufferBinding = 0x8CA6;
constexpr GLenum kReadFramebufferBinding = 0x8CAA, kBlendSrcRgb = 0x80C9, kBlendDstRgb = 0x80C8;
constexpr GLenum kTexture0 = 0x84C0;
constexpr unsigned kUnits = 8;  // the library uses units 0-5

GLint get(GLenum name) {
  GLint v = 0;
  glGetIntegerv(name, &v);
  return v;
}

struct Mismatches {
  std::vector<std::string> lines;
  void compare(const char* what, long believed, long actual) {
    if (believed == actual) return;
    char line[160];
    std::snprintf(line, sizeof line, "%s: OSG believes %ld, the GL has %ld", what, believed, actual);
    lines.emplace_back(line);
  }
};

// The modes the library enables or disables while it draws (sss.h's list).
const GLenum kModes[] = {GL_DEPTH_TEST, GL_BLEND, GL_CULL_FACE, GL_STENCIL_TEST, GL_SCISSOR_TEST,
                         GL_POLYGON_OFFSET_FILL, 0x809E /* GL_SAMPLE_ALPHA_TO_COVERAGE */};
const char* const kModeNames[] = {"GL_DEPTH_TEST", "GL_BLEND", "GL_CULL_FACE", "GL_STENCIL_TEST", "GL_SCISSOR_TEST",
                                  "GL_POLYGON_OFFSET_FILL", "GL_SAMPLE_ALPHA_TO_COVERAGE"};

}  // namespace

std::vector<std::string> samplers_left_bound(osg::RenderInfo& info) {
  osg::GLExtensions* gl = info.getState()->get<osg::GLExtensions>();
  const GLint active = get(kActiveTexture);
  std::vector<std::string> lines;
  for (unsigned unit = 0; unit < kUnits; ++unit) {
    gl->glActiveTexture(kTexture0 + unit);
    const GLint sampler = get(kSamplerBinding);
    if (sampler == 0) continue;
    char line[64];
    std::snprintf(line, sizeof line, "GL_SAMPLER_BINDING of unit %u: %d", unit, sampler);
    lines.emplace_back(line);
  }
  gl->glActiveTexture(static_cast<GLenum>(active));
  return lines;
}

FramebufferBindings read_framebuffer_bindings() { return {get(kDrawFramebufferBinding), get(kReadFramebufferBinding)}; }

std::vector<std::string> compare_cache_with_gl(osg::RenderInfo& info, const FramebufferBindings& bound) {
  osg::State& state = *info.getState();
  const unsigned context = state.getContextID();
  Mismatches m;
  for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError()) {
    char line[64];
    std::snprintf(line, sizeof line, "a GL error is pending: 0x%04X", error);
    m.lines.emplace_back(line);
  }

  const osg::Program::PerContextProgram* program = state.getLastAppliedProgramObject();
  m.compare("GL_CURRENT_PROGRAM", program != nullptr ? program->getHandle() : 0, get(kCurrentProgram));
  const GLint active = get(kActiveTexture);
  m.compare("GL_ACTIVE_TEXTURE", kTexture0 + state.getActiveTextureUnit(), active);

  osg::GLExtensions* gl = state.get<osg::GLExtensions>();
  for (unsigned unit = 0; unit < kUnits; ++unit) {
    gl->glActiveTexture(kTexture0 + unit);
    char what[64];
    const auto* texture =
        dynamic_cast<const osg::Texture*>(state.getLastAppliedTextureAttribute(unit, osg::StateAttribute::TEXTURE));
    if (texture != nullptr && texture->getTextureTarget() == GL_TEXTURE_2D) {
      const osg::Texture::TextureObject* object = texture->getTextureObject(context);
      std::snprintf(what, sizeof what, "GL_TEXTURE_BINDING_2D of unit %u", unit);
      m.compare(what, object != nullptr ? static_cast<long>(object->id()) : 0, get(kTextureBinding2D));
    }
    std::snprintf(what, sizeof what, "GL_SAMPLER_BINDING of unit %u", unit);
    m.compare(what, 0, get(kSamplerBinding));  // OSG binds no sampler objects here
  }
  gl->glActiveTexture(static_cast<GLenum>(active));

  for (std::size_t i = 0; i < sizeof kModes / sizeof kModes[0]; ++i) {
    m.compare(kModeNames[i], state.getLastAppliedModeValue(kModes[i]) ? 1 : 0, glIsEnabled(kModes[i]) ? 1 : 0);
  }
  if (const osg::Viewport* v = state.getCurrentViewport()) {
    GLint vp[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_VIEWPORT, vp);
    m.compare("GL_VIEWPORT x", static_cast<long>(v->x()), vp[0]);
    m.compare("GL_VIEWPORT y", static_cast<long>(v->y()), vp[1]);
    m.compare("GL_VIEWPORT width", static_cast<long>(v->width()), vp[2]);
    m.compare("GL_VIEWPORT height", static_cast<long>(v->height()), vp[3]);
  }
  m.compare("GL_VERTEX_ARRAY_BINDING", static_cast<long>(state.getCurrentVertexArrayObject()), get(kVertexArrayBinding));
  if (osg::VertexArrayState* vas = state.getCurrentVertexArrayState()) {
    const osg::GLBufferObject* vbo = vas->getCurrentVertexBufferObject();
    m.compare("GL_ARRAY_BUFFER_BINDING", vbo != nullptr ? static_cast<long>(vbo->getGLObjectID()) : 0,
              get(kArrayBufferBinding));
  }
  const osg::GLBufferObject* pbo = state.getCurrentPixelBufferObject();
  m.compare("GL_PIXEL_UNPACK_BUFFER_BINDING", pbo != nullptr ? static_cast<long>(pbo->getGLObjectID()) : 0,
            get(kPixelUnpackBufferBinding));

  if (const auto* mask = dynamic_cast<const osg::ColorMask*>(state.getLastAppliedAttribute(osg::StateAttribute::COLORMASK))) {
    GLboolean rgba[4] = {0, 0, 0, 0};
    glGetBooleanv(GL_COLOR_WRITEMASK, rgba);
    m.compare("GL_COLOR_WRITEMASK red", mask->getRedMask(), rgba[0]);
    m.compare("GL_COLOR_WRITEMASK green", mask->getGreenMask(), rgba[1]);
    m.compare("GL_COLOR_WRITEMASK blue", mask->getBlueMask(), rgba[2]);
    m.compare("GL_COLOR_WRITEMASK alpha", mask->getAlphaMask(), rgba[3]);
  }
  if (const auto* depth = dynamic_cast<const osg::Depth*>(state.getLastAppliedAttribute(osg::StateAttribute::DEPTH))) {
    GLboolean write = 0;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &write);
    GLfloat range[2] = {0.0f, 0.0f};
    glGetFloatv(GL_DEPTH_RANGE, range);
    m.compare("GL_DEPTH_FUNC", depth->getFunction(), get(GL_DEPTH_FUNC));
    m.compare("GL_DEPTH_WRITEMASK", depth->getWriteMask() ? 1 : 0, write);
    m.compare("GL_DEPTH_RANGE near (x 1000)", static_cast<long>(depth->getZNear() * 1000.0), static_cast<long>(range[0] * 1000.0f));
    m.compare("GL_DEPTH_RANGE far (x 1000)", static_cast<long>(depth->getZFar() * 1000.0), static_cast<long>(range[1] * 1000.0f));
  }
  if (const auto* blend = dynamic_cast<const osg::BlendFunc*>(state.getLastAppliedAttribute(osg::StateAttribute::BLENDFUNC))) {
    m.compare("GL_BLEND_SRC_RGB", blend->getSourceRGB(), get(kBlendSrcRgb));
    m.compare("GL_BLEND_DST_RGB", blend->getDestinationRGB(), get(kBlendDstRgb));
  }
  m.compare("GL_DRAW_FRAMEBUFFER_BINDING (as the engine bound it)", bound.draw, get(kDrawFramebufferBinding));
  m.compare("GL_READ_FRAMEBUFFER_BINDING (as the engine bound it)", bound.read, get(kReadFramebufferBinding));
  return m.lines;
}

}  // namespace sss_osg_host
