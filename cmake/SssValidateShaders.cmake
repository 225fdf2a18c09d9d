# Run in script mode by the `shaders.glslang` test: composes every variant of the embedded shaders
# the way the library does (a #version line, the variant's #defines, then the file) and validates
# each with glslangValidator, offline, without a GL driver.
#   -DVALIDATOR=<glslangValidator> -DSHADER_DIR=<module/shaders> -DWORK_DIR=<scratch folder>
# Variants: GLSL 330 core (the only one the library negotiates today); SSS_OUTSIDE 0..2 ×
# SSS_FOLLOW_SURFACE 0/1 × SSS_LINEAR_DEPTH 0/1 for the blur; SSS_OUTSIDE × SSS_LINEAR_DEPTH × SSS_NORMALS
# for the cross-bilateral blur.
file(MAKE_DIRECTORY "${WORK_DIR}")
set(header "#version 330 core\n")
set(failures 0)
set(count 0)

function(validate name stage body)
  set(path "${WORK_DIR}/${name}.${stage}")
  file(WRITE "${path}" "${body}")
  execute_process(COMMAND "${VALIDATOR}" "${path}" RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  math(EXPR c "${count} + 1")
  set(count ${c} PARENT_SCOPE)
  if(NOT result EQUAL 0)
    message(SEND_ERROR "${name}.${stage}: glslangValidator failed:\n${out}${err}")
    math(EXPR f "${failures} + 1")
    set(failures ${f} PARENT_SCOPE)
  endif()
endfunction()

file(READ "${SHADER_DIR}/fullscreen.vert" vertex)
file(READ "${SHADER_DIR}/copy.frag" copy)
file(READ "${SHADER_DIR}/separable_blur.frag" blur)
file(READ "${SHADER_DIR}/cbf_blur.frag" cbf)
validate(fullscreen vert "${header}${vertex}")
validate(copy frag "${header}${copy}")
foreach(outside 0 1 2)
  foreach(follow 0 1)
    foreach(linear 0 1)
      set(defines "#define SSS_OUTSIDE ${outside}\n#define SSS_FOLLOW_SURFACE ${follow}\n#define SSS_LINEAR_DEPTH ${linear}\n#define SSS_MAX_TAPS 65\n")
      validate("blur_o${outside}_f${follow}_l${linear}" frag "${header}${defines}${blur}")
    endforeach()
  endforeach()
endforeach()
# The cross-bilateral blur: SSS_OUTSIDE 0..2 × SSS_LINEAR_DEPTH 0/1.
foreach(outside 0 1 2)
  foreach(linear 0 1)
    foreach(normals 0 1)
      set(defines "#define SSS_OUTSIDE ${outside}\n#define SSS_LINEAR_DEPTH ${linear}\n#define SSS_NORMALS ${normals}\n#define SSS_MAX_TAPS 65\n")
      validate("cbf_o${outside}_l${linear}_n${normals}" frag "${header}${defines}${cbf}")
    endforeach()
  endforeach()
endforeach()
message(STATUS "glslangValidator: ${count} shader variants, ${failures} failed")
if(failures GREATER 0)
  message(FATAL_ERROR "shader validation failed")
endif()
