#include "creation_counter.hpp"

#include <GL/glcorearb.h>

#include <cstring>

#include "sss_headless.h"

namespace sss_test {

namespace {

CreationCounts g_counts;
sss_get_proc_address_fn g_base = sss_headless_get_proc_address;

void counted(const char* name) { ++g_counts[name]; }

// One wrapper per function: the real pointer (loaded from the base loader when the module asks for
// the name) and a replacement that counts, then calls it. `return f(...)` is valid for void too.
#define SSS_COUNTED(type, name, ret, params, args)                 \
  type real_##name = nullptr;                                      \
  ret APIENTRY counted_##name params {                             \
    counted("gl" #name);                                           \
    return real_##name args;                                       \
  }

SSS_COUNTED(PFNGLCREATESHADERPROC, CreateShader, GLuint, (GLenum t), (t))
SSS_COUNTED(PFNGLCOMPILESHADERPROC, CompileShader, void, (GLuint s), (s))
SSS_COUNTED(PFNGLCREATEPROGRAMPROC, CreateProgram, GLuint, (), ())
SSS_COUNTED(PFNGLLINKPROGRAMPROC, LinkProgram, void, (GLuint p), (p))
SSS_COUNTED(PFNGLPROGRAMBINARYPROC, ProgramBinary, void, (GLuint p, GLenum f, const void* b, GLsizei n), (p, f, b, n))
SSS_COUNTED(PFNGLGENTEXTURESPROC, GenTextures, void, (GLsizei n, GLuint* o), (n, o))
SSS_COUNTED(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers, void, (GLsizei n, GLuint* o), (n, o))
SSS_COUNTED(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers, void, (GLsizei n, GLuint* o), (n, o))
SSS_COUNTED(PFNGLGENQUERIESPROC, GenQueries, void, (GLsizei n, GLuint* o), (n, o))
SSS_COUNTED(PFNGLGENSAMPLERSPROC, GenSamplers, void, (GLsizei n, GLuint* o), (n, o))
SSS_COUNTED(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays, void, (GLsizei n, GLuint* o), (n, o))
SSS_COUNTED(PFNGLGENBUFFERSPROC, GenBuffers, void, (GLsizei n, GLuint* o), (n, o))
SSS_COUNTED(PFNGLTEXIMAGE2DPROC, TexImage2D, void,
            (GLenum t, GLint l, GLint i, GLsizei w, GLsizei h, GLint b, GLenum f, GLenum y, const void* p),
            (t, l, i, w, h, b, f, y, p))
SSS_COUNTED(PFNGLTEXIMAGE2DMULTISAMPLEPROC, TexImage2DMultisample, void,
            (GLenum t, GLsizei s, GLenum i, GLsizei w, GLsizei h, GLboolean x), (t, s, i, w, h, x))
SSS_COUNTED(PFNGLTEXSTORAGE2DPROC, TexStorage2D, void, (GLenum t, GLsizei l, GLenum i, GLsizei w, GLsizei h),
            (t, l, i, w, h))
SSS_COUNTED(PFNGLTEXSTORAGE2DMULTISAMPLEPROC, TexStorage2DMultisample, void,
            (GLenum t, GLsizei s, GLenum i, GLsizei w, GLsizei h, GLboolean x), (t, s, i, w, h, x))
SSS_COUNTED(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage, void, (GLenum t, GLenum i, GLsizei w, GLsizei h),
            (t, i, w, h))
SSS_COUNTED(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, RenderbufferStorageMultisample, void,
            (GLenum t, GLsizei s, GLenum i, GLsizei w, GLsizei h), (t, s, i, w, h))
SSS_COUNTED(PFNGLBUFFERDATAPROC, BufferData, void, (GLenum t, GLsizeiptr n, const void* d, GLenum u), (t, n, d, u))
#undef SSS_COUNTED

template <typename T>
void* as_address(T function) {
  void* address = nullptr;
  static_assert(sizeof address == sizeof function, "function pointers are data-pointer sized");
  std::memcpy(&address, &function, sizeof address);
  return address;
}

// The counting replacement for `name` when the base loader has the function; else what the base gives.
template <typename T, typename W>
bool wrap(const char* name, const char* wanted, T* real, W replacement, void* user, void** out) {
  if (std::strcmp(name, wanted) != 0) return false;
  void* address = g_base(name, user);
  std::memcpy(real, &address, sizeof *real);
  *out = address != nullptr ? as_address(replacement) : nullptr;
  return true;
}

}  // namespace

void set_counting_base(sss_get_proc_address_fn base) { g_base = base; }

void* counting_get_proc_address(const char* name, void* user) {
  void* out = nullptr;
#define SSS_WRAP(name_) \
  if (wrap(name, "gl" #name_, &real_##name_, &counted_##name_, user, &out)) return out;
  SSS_WRAP(CreateShader)
  SSS_WRAP(CompileShader)
  SSS_WRAP(CreateProgram)
  SSS_WRAP(LinkProgram)
  SSS_WRAP(ProgramBinary)
  SSS_WRAP(GenTextures)
  SSS_WRAP(GenFramebuffers)
  SSS_WRAP(GenRenderbuffers)
  SSS_WRAP(GenQueries)
  SSS_WRAP(GenSamplers)
  SSS_WRAP(GenVertexArrays)
  SSS_WRAP(GenBuffers)
  SSS_WRAP(TexImage2D)
  SSS_WRAP(TexImage2DMultisample)
  SSS_WRAP(TexStorage2D)
  SSS_WRAP(TexStorage2DMultisample)
  SSS_WRAP(RenderbufferStorage)
  SSS_WRAP(RenderbufferStorageMultisample)
  SSS_WRAP(BufferData)
#undef SSS_WRAP
  return g_base(name, user);
}

void reset_creations() { g_counts.clear(); }

const CreationCounts& creations() { return g_counts; }

int total_creations() {
  int n = 0;
  for (const auto& entry : g_counts) n += entry.second;
  return n;
}

int count_of(const std::string& function) {
  const auto it = g_counts.find(function);
  return it == g_counts.end() ? 0 : it->second;
}

std::string describe(const CreationCounts& counts) {
  std::string out;
  for (const auto& entry : counts) {
    if (!out.empty()) out += ", ";
    out += entry.first + " " + std::to_string(entry.second);
  }
  return out.empty() ? "none" : out;
}

}  // namespace sss_test
