# Run in script mode by the `shaders.glslang` test: composes every variant of the embedded shaders
# the way the library does (a #version line, the variant's #defines, then the file) and validates
# each with glslangValidator, offline, without a GL driver.
#   -DVALIDATOR=<glslangValidator> -DSHADER_DIR=<module/shaders> -DWORK_DIR=<scratch folder>
# Variants: each dialect the library negotiates at create time (module/shaders/version_*.glsl:
# GLSL 330 core, GLSL 420 core, GLSL ES 300; glslangValidator takes the profile from #version) ×
# SSS_OUTSIDE 0..2 × SSS_FOLLOW_SURFACE 0/1 × SSS_LINEAR_DEPTH 0/1 for the blur; SSS_LUT_KIND 0/1
# for the LUT generator; the host include of pre-integrated skin shading.
file(MAKE_DIRECTORY "${WORK_DIR}")
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
foreach(dialect 330 420 es300)
  file(READ "${SHADER_DIR}/version_${dialect}.glsl" header)
  validate(${dialect}_fullscreen vert "${header}${vertex}")
  validate(${dialect}_copy frag "${header}${copy}")
  foreach(outside 0 1 2)
    foreach(follow 0 1)
      foreach(linear 0 1)
        set(defines "#define SSS_OUTSIDE ${outside}\n#define SSS_FOLLOW_SURFACE ${follow}\n#define SSS_LINEAR_DEPTH ${linear}\n#define SSS_MAX_TAPS 65\n")
        validate("${dialect}_blur_o${outside}_f${follow}_l${linear}" frag "${header}${defines}${blur}")
      endforeach()
    endforeach()
  endforeach()
endforeach()
# The pre-integrated LUT generator (SSS_LUT_KIND 0 = diffuse, 1 = shadow) and the host-side
# include (integration/preintegrated/sss_preintegrated.glsl, in a fragment shader that calls every
# function), in every dialect.
file(READ "${SHADER_DIR}/lut_generate.frag" lut)
if(INCLUDE_DIR)
  file(READ "${INCLUDE_DIR}/sss_preintegrated.glsl" include)
endif()
set(host "uniform sampler2D d; uniform sampler2D s; in vec3 n; in vec3 p; out vec4 c;
void main() {
  vec3 r, g, b;
  sss_skin_normals(n, normalize(n + 0.1), vec3(1.0, 0.5, 0.3), r, g, b);
  float k = sss_curvature_per_mm(n, p, 0.001);
  vec3 l = normalize(vec3(1.0));
  vec3 dif = sss_skin_diffuse(d, vec2(0.0, 1.0), k, sss_skin_ndotl(r, g, b, l));
  vec3 sh = sss_skin_shadow(s, vec2(0.001, 0.032), 0.5, sss_penumbra_width(0.01, n, l));
  c = vec4(dif * sh, 1.0);
}
")
foreach(dialect 330 420 es300)
  file(READ "${SHADER_DIR}/version_${dialect}.glsl" header)
  foreach(kind 0 1)
    validate("${dialect}_lut_generate_k${kind}" frag "${header}#define SSS_LUT_KIND ${kind}\n${lut}")
  endforeach()
  if(INCLUDE_DIR)
    validate(${dialect}_host_preintegrated frag "${header}${include}${host}")
  endif()
endforeach()
message(STATUS "glslangValidator: ${count} shader variants, ${failures} failed")
if(failures GREATER 0)
  message(FATAL_ERROR "shader validation failed")
endif()
