# Run in script mode by the `shaders.glslang` test: composes every variant of the embedded shaders
# the way the library does (a #version line, the variant's #defines, then the file) and validates
# each with glslangValidator, offline, without a GL driver.
#   -DVALIDATOR=<glslangValidator> -DSHADER_DIR=<module/shaders> -DWORK_DIR=<scratch folder>
#   [-DINTEGRATION_GLSL_DIR=<integration/glsl>]: the host-side includes too
# Variants: each dialect the library negotiates at create time (module/shaders/version_*.glsl:
# GLSL 330 core, GLSL 420 core, GLSL ES 300; glslangValidator takes the profile from #version) ×
# SSS_OUTSIDE 0..2 × SSS_FOLLOW_SURFACE 0..2 × SSS_LINEAR_DEPTH 0/1 × SSS_JITTER 0/1 × SSS_ACCUMULATE 0/1
# for the blur, SSS_OUTSIDE × SSS_LINEAR_DEPTH × SSS_NORMALS for the cross-bilateral blur (both with
# module/shaders/nearest_half.glsl before them, as the module puts it); SSS_LUT_KIND 0/1 for the LUT generator and the host include of
# pre-integrated skin shading; and, for the desktop dialects only, the MSAA resolve
# (SSS_LINEAR_DEPTH 0/1), mask and write-back shaders; and the compute path's blur in GLSL 430
# (every variant).
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
file(READ "${SHADER_DIR}/nearest_half.glsl" nearest_half)
file(READ "${SHADER_DIR}/cbf_blur.frag" cbf)
file(READ "${SHADER_DIR}/msaa_resolve.frag" msaa_resolve)
file(READ "${SHADER_DIR}/msaa_mask.frag" msaa_mask)
file(READ "${SHADER_DIR}/msaa_write.frag" msaa_write)
foreach(dialect 330 420 es300)
  file(READ "${SHADER_DIR}/version_${dialect}.glsl" header)
  validate(${dialect}_fullscreen vert "${header}${vertex}")
  validate(${dialect}_copy frag "${header}${copy}")
  # The MSAA path runs on desktop GL only (sss.h, sss_frame): its shaders read sampler2DMS, which
  # GLSL ES 3.00 does not have (ES 3.10 does, but the module never builds them on ES).
  if(NOT dialect STREQUAL "es300")
    foreach(linear 0 1)
      validate("${dialect}_msaa_resolve_l${linear}" frag "${header}#define SSS_LINEAR_DEPTH ${linear}\n${msaa_resolve}")
    endforeach()
    validate(${dialect}_msaa_mask frag "${header}${msaa_mask}")
    validate(${dialect}_msaa_write frag "${header}${msaa_write}")
  endif()
  # The blur: SSS_OUTSIDE × SSS_FOLLOW_SURFACE × SSS_LINEAR_DEPTH × SSS_JITTER × SSS_ACCUMULATE.
  foreach(outside 0 1 2)
    foreach(follow 0 1 2)
      foreach(linear 0 1)
        foreach(jitter 0 1)
          foreach(accumulate 0 1)
            set(defines "#define SSS_OUTSIDE ${outside}\n#define SSS_FOLLOW_SURFACE ${follow}\n#define SSS_LINEAR_DEPTH ${linear}\n#define SSS_JITTER ${jitter}\n#define SSS_ACCUMULATE ${accumulate}\n#define SSS_CDF_ENTRIES 128\n#define SSS_MAX_HALF_TAPS 32\n")
            validate("${dialect}_blur_o${outside}_f${follow}_l${linear}_j${jitter}_a${accumulate}" frag "${header}${defines}${nearest_half}${blur}")
          endforeach()
        endforeach()
      endforeach()
    endforeach()
  endforeach()
  # The cross-bilateral blur: SSS_OUTSIDE 0..2 × SSS_LINEAR_DEPTH 0/1 × SSS_NORMALS 0/1.
  foreach(outside 0 1 2)
    foreach(linear 0 1)
      foreach(normals 0 1)
        set(defines "#define SSS_OUTSIDE ${outside}\n#define SSS_LINEAR_DEPTH ${linear}\n#define SSS_NORMALS ${normals}\n#define SSS_MAX_TAPS 65\n")
        validate("${dialect}_cbf_o${outside}_l${linear}_n${normals}" frag "${header}${defines}${nearest_half}${cbf}")
      endforeach()
    endforeach()
  endforeach()
  # The host-side includes of integration/glsl, each under a small main that calls every function
  # (hosts paste them after their own #version line, desktop or ES).
  if(INTEGRATION_GLSL_DIR)
    file(READ "${INTEGRATION_GLSL_DIR}/sss_transmittance.glsl" transmittance)
    set(main "uniform sampler2D m; uniform mat4 v, p; out vec4 o;\nvoid main() {\n  float t = sss_thickness(m, v, p, vec3(0.0), vec3(0.0, 0.0, 1.0), 0.005) + sss_thickness_linear(m, v, p, vec3(0.0), vec3(0.0, 0.0, 1.0), 0.005);\n  o = vec4(sss_transmittance(t, 0.012, 0.5, vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, -1.0)), 1.0);\n}\n")
    validate(${dialect}_sss_transmittance frag "${header}${transmittance}${main}")
    file(READ "${INTEGRATION_GLSL_DIR}/sss_back_transmittance.glsl" back)
    set(main "uniform sampler2D b, n; uniform mat4 p; out vec4 o;\nvoid main() {\n  o = vec4(sss_back_transmittance(b, n, gl_FragCoord.xy, vec3(0.0, 0.0, -1.0), vec3(0.0, 0.0, 1.0), p, vec4(0.0, 0.0, 64.0, 64.0), 0.0015, 4.5), 1.0);\n}\n")
    validate(${dialect}_sss_back_transmittance frag "${header}${transmittance}${back}${main}")
  endif()
endforeach()
# The compute path's blur (desktop GLSL 430 only: the module builds it on OpenGL 4.3+), every
# variant: SSS_OUTSIDE × SSS_FOLLOW_SURFACE × SSS_LINEAR_DEPTH × SSS_JITTER × image format.
file(READ "${SHADER_DIR}/separable_blur.comp" blur_compute)
foreach(outside 0 1 2)
  foreach(follow 0 1 2)
    foreach(linear 0 1)
      foreach(jitter 0 1)
        foreach(format rgba16f rgba32f)
          set(defines "#version 430 core\n#define SSS_OUTSIDE ${outside}\n#define SSS_FOLLOW_SURFACE ${follow}\n#define SSS_LINEAR_DEPTH ${linear}\n#define SSS_JITTER ${jitter}\n#define SSS_ACCUMULATE 0\n#define SSS_CDF_ENTRIES 128\n#define SSS_MAX_HALF_TAPS 32\n#define SSS_SEGMENT 128\n#define SSS_APRON 64\n#define SSS_IMAGE_FORMAT ${format}\n")
          validate("430_blur_compute_o${outside}_f${follow}_l${linear}_j${jitter}_${format}" comp "${defines}${nearest_half}${blur_compute}")
        endforeach()
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
