# Shader embedding: each GLSL file becomes a C++ string constant at build time, so the library
# reads no file at run time.
#
# sss_embed_shaders(<out_cpp> <out_hpp> <namespace> FILES <glsl>...)
#   writes <out_hpp> declaring `extern const char* const <name>;` for each file (name from the file
#   name, dots and dashes as underscores) and `files[]`, each file's text by its file name (for the
#   #include directives the module expands), and <out_cpp> defining them as raw string literals.

set(SSS_EMBED_SCRIPT "${CMAKE_CURRENT_LIST_DIR}/SssEmbedShadersScript.cmake")

function(sss_embed_shaders out_cpp out_hpp namespace)
  cmake_parse_arguments(ARG "" "" "FILES" ${ARGN})
  add_custom_command(
    OUTPUT "${out_cpp}" "${out_hpp}"
    COMMAND "${CMAKE_COMMAND}" -DOUT_CPP=${out_cpp} -DOUT_HPP=${out_hpp} -DNAMESPACE=${namespace}
            "-DFILES=${ARG_FILES}" -P "${SSS_EMBED_SCRIPT}"
    DEPENDS ${ARG_FILES} "${SSS_EMBED_SCRIPT}"
    COMMENT "Embedding GLSL shaders"
    VERBATIM)
endfunction()
