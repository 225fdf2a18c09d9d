// The module's own GL function table, filled from the host's get_proc_address. Nothing here
// collides with a host's loader: the functions are members of a struct, not global symbols, and
// the types and constants are declared locally (no GL header is needed to build the module).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "sss/sss.h"

#if defined(_WIN32)
#define SSS_GL_APIENTRY __stdcall
#else
#define SSS_GL_APIENTRY
#endif

namespace sss::gl {

using GLenum = unsigned int;
using GLboolean = unsigned char;
using GLbitfield = unsigned int;
using GLint = int;
using GLuint = unsigned int;
using GLsizei = int;
using GLfloat = float;
using GLchar = char;
using GLubyte = unsigned char;

// X(return type, name without the gl prefix, parameter list). Required on every API the module
// runs on: the common part of OpenGL 3.3 and OpenGL ES 3.0.
#define SSS_GL_REQUIRED_FUNCTIONS(X)                                                                   \
  X(GLenum, GetError, (void))                                                                          \
  X(const GLubyte*, GetString, (GLenum name))                                                          \
  X(const GLubyte*, GetStringi, (GLenum name, GLuint index))                                           \
  X(void, GetIntegerv, (GLenum pname, GLint * data))                                                   \
  X(void, GetBooleanv, (GLenum pname, GLboolean * data))                                               \
  X(void, GetFloatv, (GLenum pname, GLfloat * data))                                                   \
  X(void, DepthFunc, (GLenum func))                                                                    \
  X(void, DepthMask, (GLboolean flag))                                                                 \
  X(GLboolean, IsEnabled, (GLenum cap))                                                                \
  X(void, Enable, (GLenum cap))                                                                        \
  X(void, Disable, (GLenum cap))                                                                       \
  X(GLboolean, IsTexture, (GLuint texture))                                                            \
  X(void, ActiveTexture, (GLenum texture))                                                             \
  X(void, BindTexture, (GLenum target, GLuint texture))                                                \
  X(void, GenTextures, (GLsizei n, GLuint * textures))                                                 \
  X(void, DeleteTextures, (GLsizei n, const GLuint* textures))                                         \
  X(void, TexImage2D, (GLenum target, GLint level, GLint internalformat, GLsizei width, GLsizei height, \
                       GLint border, GLenum format, GLenum type, const void* pixels))                  \
  X(void, TexParameteri, (GLenum target, GLenum pname, GLint param))                                   \
  X(void, GetTexParameteriv, (GLenum target, GLenum pname, GLint * params))                            \
  X(void, GenSamplers, (GLsizei count, GLuint * samplers))                                             \
  X(void, DeleteSamplers, (GLsizei count, const GLuint* samplers))                                     \
  X(void, BindSampler, (GLuint unit, GLuint sampler))                                                  \
  X(void, SamplerParameteri, (GLuint sampler, GLenum pname, GLint param))                              \
  X(void, SamplerParameterf, (GLuint sampler, GLenum pname, GLfloat param))                            \
  X(void, GetSamplerParameterfv, (GLuint sampler, GLenum pname, GLfloat * params))                     \
  X(GLboolean, IsSampler, (GLuint sampler))                                                            \
  X(void, GenFramebuffers, (GLsizei n, GLuint * framebuffers))                                         \
  X(void, DeleteFramebuffers, (GLsizei n, const GLuint* framebuffers))                                 \
  X(void, BindFramebuffer, (GLenum target, GLuint framebuffer))                                        \
  X(GLboolean, IsFramebuffer, (GLuint framebuffer))                                                    \
  X(void, FramebufferTexture2D, (GLenum target, GLenum attachment, GLenum textarget, GLuint texture,   \
                                 GLint level))                                                         \
  X(void, FramebufferRenderbuffer, (GLenum target, GLenum attachment, GLenum renderbuffertarget,       \
                                    GLuint renderbuffer))                                              \
  X(GLenum, CheckFramebufferStatus, (GLenum target))                                                   \
  X(void, BlitFramebuffer, (GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1, GLint dstX0,           \
                            GLint dstY0, GLint dstX1, GLint dstY1, GLbitfield mask, GLenum filter))    \
  X(void, DrawBuffers, (GLsizei n, const GLenum* bufs))                                                \
  X(void, ReadBuffer, (GLenum src))                                                                    \
  X(void, GenRenderbuffers, (GLsizei n, GLuint * renderbuffers))                                       \
  X(void, DeleteRenderbuffers, (GLsizei n, const GLuint* renderbuffers))                               \
  X(void, BindRenderbuffer, (GLenum target, GLuint renderbuffer))                                      \
  X(void, RenderbufferStorage, (GLenum target, GLenum internalformat, GLsizei width, GLsizei height))  \
  X(GLuint, CreateShader, (GLenum type))                                                               \
  X(void, ShaderSource, (GLuint shader, GLsizei count, const GLchar* const* string, const GLint* length)) \
  X(void, CompileShader, (GLuint shader))                                                              \
  X(void, GetShaderiv, (GLuint shader, GLenum pname, GLint * params))                                  \
  X(void, GetShaderInfoLog, (GLuint shader, GLsizei bufSize, GLsizei * length, GLchar * infoLog))      \
  X(void, DeleteShader, (GLuint shader))                                                               \
  X(GLuint, CreateProgram, (void))                                                                     \
  X(void, AttachShader, (GLuint program, GLuint shader))                                               \
  X(void, LinkProgram, (GLuint program))                                                               \
  X(void, GetProgramiv, (GLuint program, GLenum pname, GLint * params))                                \
  X(void, GetProgramInfoLog, (GLuint program, GLsizei bufSize, GLsizei * length, GLchar * infoLog))    \
  X(void, DeleteProgram, (GLuint program))                                                             \
  X(GLboolean, IsProgram, (GLuint program))                                                            \
  X(void, UseProgram, (GLuint program))                                                                \
  X(GLint, GetUniformLocation, (GLuint program, const GLchar* name))                                   \
  X(void, GetUniformIndices, (GLuint program, GLsizei count, const GLchar* const* names, GLuint* indices)) \
  X(void, Uniform1i, (GLint location, GLint v0))                                                       \
  X(void, Uniform1f, (GLint location, GLfloat v0))                                                     \
  X(void, Uniform1fv, (GLint location, GLsizei count, const GLfloat* value))                           \
  X(void, Uniform2f, (GLint location, GLfloat v0, GLfloat v1))                                         \
  X(void, Uniform4f, (GLint location, GLfloat v0, GLfloat v1, GLfloat v2, GLfloat v3))                 \
  X(void, Uniform4fv, (GLint location, GLsizei count, const GLfloat* value))                           \
  X(void, GenVertexArrays, (GLsizei n, GLuint * arrays))                                               \
  X(void, DeleteVertexArrays, (GLsizei n, const GLuint* arrays))                                       \
  X(void, BindVertexArray, (GLuint array))                                                             \
  X(GLboolean, IsVertexArray, (GLuint array))                                                          \
  X(void, DrawArrays, (GLenum mode, GLint first, GLsizei count))                                       \
  X(void, DrawArraysInstanced, (GLenum mode, GLint first, GLsizei count, GLsizei instancecount))        \
  X(void, Viewport, (GLint x, GLint y, GLsizei width, GLsizei height))                                 \
  X(void, ColorMask, (GLboolean r, GLboolean g, GLboolean b, GLboolean a))                             \
  X(void, StencilFuncSeparate, (GLenum face, GLenum func, GLint ref, GLuint mask))                     \
  X(void, StencilOpSeparate, (GLenum face, GLenum sfail, GLenum dpfail, GLenum dppass))                \
  X(void, StencilMaskSeparate, (GLenum face, GLuint mask))                                             \
  X(void, BindBuffer, (GLenum target, GLuint buffer))                                                  \
  X(void, GenQueries, (GLsizei n, GLuint * ids))                                                       \
  X(void, DeleteQueries, (GLsizei n, const GLuint* ids))                                               \
  X(void, BeginQuery, (GLenum target, GLuint id))                                                      \
  X(void, EndQuery, (GLenum target))                                                                   \
  X(void, GetQueryObjectuiv, (GLuint id, GLenum pname, GLuint * params))                              \
  X(void, GetQueryiv, (GLenum target, GLenum pname, GLint * params))                                  \
  X(void, PixelStorei, (GLenum pname, GLint param))                                                   \
  X(void, ClearBufferfv, (GLenum buffer, GLint drawbuffer, const GLfloat* value))                   \
  X(void, GetIntegeri_v, (GLenum target, GLuint index, GLint * data))                                  \
  X(void, ClearBufferiv, (GLenum buffer, GLint drawbuffer, const GLint* value))                    \
  X(void, ReadPixels, (GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type,    \
                       void* pixels))                                                                  \
  X(void, GenBuffers, (GLsizei n, GLuint * buffers))                                                   \
  X(void, DeleteBuffers, (GLsizei n, const GLuint* buffers))                                           \
  X(GLboolean, IsBuffer, (GLuint buffer))                                                              \
  X(void, BufferData, (GLenum target, std::ptrdiff_t size, const void* data, GLenum usage))            \
  X(void, BufferSubData, (GLenum target, std::ptrdiff_t offset, std::ptrdiff_t size, const void* data)) \
  X(void, BindBufferBase, (GLenum target, GLuint index, GLuint buffer))                                \
  X(void, BindBufferRange, (GLenum target, GLuint index, GLuint buffer, std::ptrdiff_t offset,         \
                            std::ptrdiff_t size))                                                      \
  X(void, GetInteger64i_v, (GLenum target, GLuint index, std::int64_t * data))                         \
  X(GLuint, GetUniformBlockIndex, (GLuint program, const GLchar* name))                                \
  X(void, UniformBlockBinding, (GLuint program, GLuint block_index, GLuint binding))                   \
  X(void, Uniform1ui, (GLint location, GLuint v0))                                                     \
  X(void, Uniform4i, (GLint location, GLint v0, GLint v1, GLint v2, GLint v3))                         \
  X(void, Uniform4iv, (GLint location, GLsizei count, const GLint* value))

// Compute shaders and image load/store (desktop OpenGL 4.3+): the compute path of the separable
// filter (sss.h SSS_PATH_*). Loaded on desktop GL 4.3+ only; has_compute says they are there.
#define SSS_GL_COMPUTE_FUNCTIONS(X)                                                                    \
  X(void, DispatchCompute, (GLuint x, GLuint y, GLuint z))                                              \
  X(void, BindImageTexture, (GLuint unit, GLuint texture, GLint level, GLboolean layered, GLint layer, \
                             GLenum access, GLenum format))                                            \
  X(void, MemoryBarrier, (GLbitfield barriers))                                                        \
  X(void, Uniform2i, (GLint location, GLint v0, GLint v1))                                             \
  X(void, GetBooleani_v, (GLenum target, GLuint index, GLboolean * data))
// Desktop OpenGL only (ES 3.0 lacks them; glGetTexLevelParameteriv came back in ES 3.1). Loaded on
// desktop GL, where they are required; never called on ES. The multisample and blend ones serve the
// MSAA path, which is desktop GL only (sss.h, sss_frame): its write-back blends.
#define SSS_GL_DESKTOP_FUNCTIONS(X)                                                                    \
  X(void, PolygonMode, (GLenum face, GLenum mode))                                                     \
  X(void, GetQueryObjectui64v, (GLuint id, GLenum pname, std::uint64_t * params))                     \
  X(void, TexImage2DMultisample, (GLenum target, GLsizei samples, GLenum internalformat, GLsizei width, \
                                  GLsizei height, GLboolean fixedsamplelocations))                     \
  X(void, SampleMaski, (GLuint maskNumber, GLbitfield mask))                                           \
  X(void, DepthRange, (double n, double f))                                                             \
  X(void, BlendFuncSeparate, (GLenum srcRGB, GLenum dstRGB, GLenum srcAlpha, GLenum dstAlpha))         \
  X(void, BlendEquationSeparate, (GLenum modeRGB, GLenum modeAlpha))

// OpenGL ES only (desktop GL before 4.1 lacks it; it has glDepthRange with doubles instead).
#define SSS_GL_ES_FUNCTIONS(X) X(void, DepthRangef, (GLfloat n, GLfloat f))

// glGetTexLevelParameteriv: desktop GL and OpenGL ES 3.1+. On ES 3.0 the frame describes the
// textures instead (sss_frame's format and size fields).
#define SSS_GL_TEXTURE_QUERY_FUNCTIONS(X) \
  X(void, GetTexLevelParameteriv, (GLenum target, GLint level, GLenum pname, GLint * params))

// EXT_disjoint_timer_query on OpenGL ES (the EXT-suffixed names).
#define SSS_GL_ES_TIMER_FUNCTIONS(X)                                                                   \
  X(void, GetQueryObjectui64vEXT, (GLuint id, GLenum pname, std::uint64_t * params))

// KHR_debug (core in 4.3): used only when present.
#define SSS_GL_DEBUG_FUNCTIONS(X)                                                                      \
  X(void, PushDebugGroup, (GLenum source, GLuint id, GLsizei length, const GLchar* message))           \
  X(void, PopDebugGroup, (void))                                                                       \
  X(void, ObjectLabel, (GLenum identifier, GLuint name, GLsizei length, const GLchar* label))

// The API of the running context, from GL_VERSION.
struct Api {
  bool es = false;       // OpenGL ES
  int major = 0, minor = 0;
  int version() const { return major * 10 + minor; }
};

struct Functions {
#define SSS_GL_DECLARE_MEMBER(ret, name, params) ret(SSS_GL_APIENTRY* name) params = nullptr;
  SSS_GL_REQUIRED_FUNCTIONS(SSS_GL_DECLARE_MEMBER)
  SSS_GL_DESKTOP_FUNCTIONS(SSS_GL_DECLARE_MEMBER)
  SSS_GL_ES_FUNCTIONS(SSS_GL_DECLARE_MEMBER)
  SSS_GL_TEXTURE_QUERY_FUNCTIONS(SSS_GL_DECLARE_MEMBER)
  SSS_GL_ES_TIMER_FUNCTIONS(SSS_GL_DECLARE_MEMBER)
  SSS_GL_DEBUG_FUNCTIONS(SSS_GL_DECLARE_MEMBER)
  SSS_GL_COMPUTE_FUNCTIONS(SSS_GL_DECLARE_MEMBER)
#undef SSS_GL_DECLARE_MEMBER
  Api api;
  bool has_debug = false;          // KHR_debug present and all three functions loaded
  bool has_texture_query = false;  // glGetTexLevelParameteriv may be called (desktop, ES 3.1+)
  bool has_compute = false;        // compute shaders and image units (desktop GL 4.3+, all loaded)
  // Desktop-only state exists (polygon mode, depth clamp, logic op, clip distances, sRGB enable).
  bool desktop() const { return !api.es; }
  // GL_SAMPLE_MASK exists (GL 3.2+, ES 3.1+).
  bool has_sample_mask() const { return !api.es || api.version() >= 31; }
  // GL_TEXTURE_2D_MULTISAMPLE exists (GL 3.2+, ES 3.1+): on ES 3.0 the enum is invalid, so the
  // module never binds or queries that target there.
  bool has_multisample_textures() const { return !api.es || api.version() >= 31; }
  // The MSAA path (sampler2DMS shaders, glTexImage2DMultisample, glSampleMaski): desktop GL only.
  bool has_msaa_path() const { return !api.es; }
  // glDepthRange (desktop) or glDepthRangef (ES).
  void set_depth_range(GLfloat n, GLfloat f) const {
    if (api.es) {
      DepthRangef(n, f);
    } else {
      DepthRange(static_cast<double>(n), static_cast<double>(f));
    }
  }
};

// Loads what `api` needs; on failure returns the name of the first missing one ("glFoo"). Optional
// functions (debug, ES timer queries, the texture query on ES) are loaded when found; the flags
// are set later, once the version and extension list confirm them (Mesa returns non-NULL stubs
// for anything, so a pointer proves nothing).
bool load_functions(sss_get_proc_address_fn get_proc_address, void* user, const Api& api, Functions* out,
                    std::string* missing);

// glGetUniformBlockIndex's "no such block".
inline constexpr GLuint kInvalidIndex = 0xFFFFFFFFu;

// GL constants used by the module (values from the Khronos registry).
enum : GLenum {
  NO_ERROR = 0,
  INVALID_ENUM = 0x0500,
  INVALID_VALUE = 0x0501,
  INVALID_OPERATION = 0x0502,
  OUT_OF_MEMORY = 0x0505,
  INVALID_FRAMEBUFFER_OPERATION = 0x0506,
  VERSION = 0x1F02,
  RENDERER = 0x1F01,
  EXTENSIONS = 0x1F03,
  NUM_EXTENSIONS = 0x821D,
  MAJOR_VERSION = 0x821B,
  MINOR_VERSION = 0x821C,
  TEXTURE_2D = 0x0DE1,
  TEXTURE0 = 0x84C0,
  TEXTURE_BINDING_2D = 0x8069,
  SAMPLER_BINDING = 0x8919,
  ACTIVE_TEXTURE = 0x84E0,
  TEXTURE_WIDTH = 0x1000,
  MAX_TEXTURE_SIZE = 0x0D33,
  TEXTURE_HEIGHT = 0x1001,
  TEXTURE_INTERNAL_FORMAT = 0x1003,
  TEXTURE_SAMPLES = 0x9106,
  TEXTURE_FIXED_SAMPLE_LOCATIONS = 0x9107,
  TEXTURE_2D_MULTISAMPLE = 0x9100,
  TEXTURE_BINDING_2D_MULTISAMPLE = 0x9104,
  MAX_SAMPLES = 0x8D57,
  MAX_COLOR_TEXTURE_SAMPLES = 0x910E,
  MAX_DEPTH_TEXTURE_SAMPLES = 0x910F,
  SAMPLE_MASK_VALUE = 0x8E52,
  COLOR_ATTACHMENT1 = 0x8CE1,
  COLOR_ATTACHMENT2 = 0x8CE2,
  COLOR_ATTACHMENT3 = 0x8CE3,
  COLOR_ATTACHMENT4 = 0x8CE4,
  COLOR_ATTACHMENT5 = 0x8CE5,
  COLOR_ATTACHMENT6 = 0x8CE6,
  COLOR_ATTACHMENT7 = 0x8CE7,
  ZERO = 0,
  ONE = 1,
  SRC1_COLOR = 0x88F9,
  FUNC_ADD = 0x8006,
  BLEND_SRC_RGB = 0x80C9,
  BLEND_DST_RGB = 0x80C8,
  BLEND_SRC_ALPHA = 0x80CB,
  BLEND_DST_ALPHA = 0x80CA,
  BLEND_EQUATION_RGB = 0x8009,
  BLEND_EQUATION_ALPHA = 0x883D,
  STENCIL = 0x1802,
  ALWAYS = 0x0207,
  GREATER = 0x0204,
  LEQUAL = 0x0203,
  DEPTH_FUNC = 0x0B74,
  DEPTH_WRITEMASK = 0x0B72,
  DEPTH_RANGE = 0x0B70,
  REPLACE = 0x1E01,
  TEXTURE_MIN_FILTER = 0x2801,
  TEXTURE_MAG_FILTER = 0x2800,
  TEXTURE_WRAP_S = 0x2802,
  TEXTURE_WRAP_T = 0x2803,
  TEXTURE_COMPARE_MODE = 0x884C,
  TEXTURE_BORDER_COLOR = 0x1004,
  TEXTURE_MAX_LEVEL = 0x813D,
  TEXTURE_MAX_LOD = 0x813B,
  NEAREST = 0x2600,
  LINEAR = 0x2601,
  CLAMP_TO_EDGE = 0x812F,
  NONE = 0,
  RGBA = 0x1908,
  HALF_FLOAT = 0x140B,
  FLOAT = 0x1406,
  COLOR = 0x1800,
  RGBA16F = 0x881A,
  RGBA32F = 0x8814,
  R16F = 0x822D,
  R32F = 0x822E,
  R8 = 0x8229,
  R8UI = 0x8232,
  R16UI = 0x8234,
  RG32UI = 0x823C,
  R32UI = 0x8236,
  RGBA32UI = 0x8D70,
  RG_INTEGER = 0x8228,
  RGBA_INTEGER = 0x8D99,
  RED_INTEGER = 0x8D94,
  UNSIGNED_INT = 0x1405,
  UNIFORM_BUFFER = 0x8A11,
  UNIFORM_BUFFER_BINDING = 0x8A28,
  UNIFORM_BUFFER_START = 0x8A29,
  UNIFORM_BUFFER_SIZE = 0x8A2A,
  MAX_UNIFORM_BLOCK_SIZE = 0x8A30,
  UNIFORM_BUFFER_OFFSET_ALIGNMENT = 0x8A34,
  DYNAMIC_DRAW = 0x88E8,
  BUFFER = 0x82E0,
  PIXEL_PACK_BUFFER = 0x88EB,
  PIXEL_PACK_BUFFER_BINDING = 0x88ED,
  PACK_ROW_LENGTH = 0x0D02,
  PACK_SKIP_ROWS = 0x0D03,
  PACK_SKIP_PIXELS = 0x0D04,
  PACK_ALIGNMENT = 0x0D05,
  R11F_G11F_B10F = 0x8C3A,
  DEPTH_COMPONENT16 = 0x81A5,
  DEPTH_COMPONENT24 = 0x81A6,
  DEPTH_COMPONENT32 = 0x81A7,
  DEPTH_COMPONENT32F = 0x8CAC,
  DEPTH24_STENCIL8 = 0x88F0,
  DEPTH32F_STENCIL8 = 0x8CAD,
  FRAMEBUFFER = 0x8D40,
  READ_FRAMEBUFFER = 0x8CA8,
  DRAW_FRAMEBUFFER = 0x8CA9,
  READ_FRAMEBUFFER_BINDING = 0x8CAA,
  DRAW_FRAMEBUFFER_BINDING = 0x8CA6,
  RENDERBUFFER = 0x8D41,
  RENDERBUFFER_BINDING = 0x8CA7,
  COLOR_ATTACHMENT0 = 0x8CE0,
  DEPTH_STENCIL_ATTACHMENT = 0x821A,
  STENCIL_ATTACHMENT = 0x8D20,
  FRAMEBUFFER_COMPLETE = 0x8CD5,
  STENCIL_BUFFER_BIT = 0x00000400,
  COLOR_BUFFER_BIT = 0x00004000,
  RED = 0x1903,
  VERTEX_SHADER = 0x8B31,
  FRAGMENT_SHADER = 0x8B30,
  COMPILE_STATUS = 0x8B81,
  LINK_STATUS = 0x8B82,
  INFO_LOG_LENGTH = 0x8B84,
  CURRENT_PROGRAM = 0x8B8D,
  VERTEX_ARRAY_BINDING = 0x85B5,
  PIXEL_UNPACK_BUFFER = 0x88EC,
  PIXEL_UNPACK_BUFFER_BINDING = 0x88EF,
  TRIANGLES = 0x0004,
  TRIANGLE_STRIP = 0x0005,
  VIEWPORT = 0x0BA2,
  SCISSOR_TEST = 0x0C11,
  DEPTH_TEST = 0x0B71,
  DEPTH = 0x1801,
  STENCIL_TEST = 0x0B90,
  BLEND = 0x0BE2,
  CULL_FACE = 0x0B44,
  FRAMEBUFFER_SRGB = 0x8DB9,
  RASTERIZER_DISCARD = 0x8C89,
  SAMPLE_ALPHA_TO_COVERAGE = 0x809E,
  SAMPLE_COVERAGE = 0x80A0,
  SAMPLE_MASK = 0x8E51,
  MULTISAMPLE = 0x809D,
  DEPTH_STENCIL_TEXTURE_MODE = 0x90EA,
  DEPTH_COMPONENT = 0x1902,
  STENCIL_INDEX = 0x1901,
  TEXTURE_BASE_LEVEL = 0x813C,
  TEXTURE_IMMUTABLE_FORMAT = 0x912F,
  POLYGON_OFFSET_FILL = 0x8037,
  DEPTH_CLAMP = 0x864F,
  COLOR_LOGIC_OP = 0x0BF2,
  CLIP_DISTANCE0 = 0x3000,
  COLOR_WRITEMASK = 0x0C23,
  POLYGON_MODE = 0x0B40,
  FRONT_AND_BACK = 0x0408,
  FRONT = 0x0404,
  BACK = 0x0405,
  FILL = 0x1B02,
  STENCIL_FUNC = 0x0B92,
  STENCIL_VALUE_MASK = 0x0B93,
  STENCIL_REF = 0x0B97,
  STENCIL_FAIL = 0x0B94,
  STENCIL_PASS_DEPTH_FAIL = 0x0B95,
  STENCIL_PASS_DEPTH_PASS = 0x0B96,
  STENCIL_WRITEMASK = 0x0B98,
  STENCIL_BACK_FUNC = 0x8800,
  STENCIL_BACK_VALUE_MASK = 0x8CA4,
  STENCIL_BACK_REF = 0x8CA3,
  STENCIL_BACK_FAIL = 0x8801,
  STENCIL_BACK_PASS_DEPTH_FAIL = 0x8802,
  STENCIL_BACK_PASS_DEPTH_PASS = 0x8803,
  STENCIL_BACK_WRITEMASK = 0x8CA5,
  EQUAL = 0x0202,
  NOTEQUAL = 0x0205,
  KEEP = 0x1E00,
  DEBUG_SOURCE_APPLICATION = 0x824A,
  PROGRAM = 0x82E2,
  SHADER = 0x82E1,
  VERTEX_ARRAY = 0x8074,
  SAMPLER = 0x82E6,
  TEXTURE = 0x1702,
  RGBA8 = 0x8058,
  SRGB8_ALPHA8 = 0x8C43,
  UNSIGNED_BYTE = 0x1401,
  UNPACK_ROW_LENGTH = 0x0CF2,
  UNPACK_SKIP_ROWS = 0x0CF3,
  UNPACK_SKIP_PIXELS = 0x0CF4,
  UNPACK_ALIGNMENT = 0x0CF5,
  QUERY = 0x82E3,
  SAMPLES_PASSED = 0x8914,
  ANY_SAMPLES_PASSED = 0x8C2F,
  TIME_ELAPSED = 0x88BF,
  QUERY_COUNTER_BITS = 0x8864,
  CURRENT_QUERY = 0x8865,
  QUERY_RESULT = 0x8866,
  QUERY_RESULT_AVAILABLE = 0x8867,
  GPU_DISJOINT = 0x8FBB,
  COMPUTE_SHADER = 0x91B9,
  IMAGE_BINDING_NAME = 0x8F3A,
  IMAGE_BINDING_LEVEL = 0x8F3B,
  IMAGE_BINDING_LAYERED = 0x8F3C,
  IMAGE_BINDING_LAYER = 0x8F3D,
  IMAGE_BINDING_ACCESS = 0x8F3E,
  IMAGE_BINDING_FORMAT = 0x906E,
  READ_ONLY = 0x88B8,
  WRITE_ONLY = 0x88B9,
  READ_WRITE = 0x88BA,
  TEXTURE_FETCH_BARRIER_BIT = 0x00000008,
  SHADER_IMAGE_ACCESS_BARRIER_BIT = 0x00000020,
  ALL_BARRIER_BITS = 0xFFFFFFFF,
};

// "GL_INVALID_OPERATION" for an error code, or "0x1234".
std::string error_name(GLenum error);
// "GL_RGBA16F" for the internal formats the module knows, or "0x1234".
std::string format_name(GLint internal_format);

}  // namespace sss::gl
