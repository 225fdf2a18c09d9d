# Run in script mode by sss_embed_shaders(); see SssEmbedShaders.cmake.
set(hpp "// Generated from module/shaders by cmake/SssEmbedShadersScript.cmake. Do not edit.\n#pragma once\nnamespace ${NAMESPACE} {\n")
set(cpp "// Generated from module/shaders by cmake/SssEmbedShadersScript.cmake. Do not edit.\n#include \"embedded_shaders.hpp\"\nnamespace ${NAMESPACE} {\n")
set(table "")
set(count 0)
foreach(file IN LISTS FILES)
  get_filename_component(name "${file}" NAME)
  string(MAKE_C_IDENTIFIER "${name}" ident)
  file(READ "${file}" body)
  string(FIND "${body}" ")sss_glsl\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${file} contains the raw-string delimiter")
  endif()
  string(APPEND hpp "extern const char* const ${ident};\n")
  # constexpr (external linkage from the header's declaration), so that `files` below is constant
  # data, not initialised at start-up.
  string(APPEND cpp "constexpr const char* ${ident} = R\"sss_glsl(${body})sss_glsl\";\n")
  string(APPEND table "    {\"${name}\", ${ident}},\n")
  math(EXPR count "${count} + 1")
endforeach()
# The same strings by file name, for the #include directives the module expands
# (module/src/gl/shader_source.cpp).
string(APPEND hpp "struct File {\n  const char* name;\n  const char* text;\n};\nextern const File files[${count}];\n")
string(APPEND cpp "constexpr File files[${count}] = {\n${table}};\n")
string(APPEND hpp "}  // namespace ${NAMESPACE}\n")
string(APPEND cpp "}  // namespace ${NAMESPACE}\n")
file(WRITE "${OUT_HPP}" "${hpp}")
file(WRITE "${OUT_CPP}" "${cpp}")
