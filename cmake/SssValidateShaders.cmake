# Run in script mode by the `shaders.glslang` test: validates every shader stage the module can
# build with glslangValidator, offline, without a GL driver. The stages are not composed here: the
# test's writer (tests/shaders/write_shader_variants.cpp) assembles each variant with the module's
# own assembler and recipes (module/src/gl/shader_variants.cpp), so no switch or size is repeated
# here; this script runs it and validates what it wrote.
#   -DVALIDATOR=<glslangValidator> -DVARIANTS=<sss_shader_variants> -DWORK_DIR=<scratch folder>
#   [-DSHADER_DIR=<module/shaders> -DINTEGRATION_GLSL_DIR=<integration/glsl>
#    -DINCLUDE_DIR=<integration/preintegrated>]: the host-side includes too, after each dialect's
#   header piece (module/shaders/version_*.glsl), as a host pastes them after its #version line
set(failures 0)
set(count 0)

function(validate path)
  execute_process(COMMAND "${VALIDATOR}" "${path}" RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  math(EXPR c "${count} + 1")
  set(count ${c} PARENT_SCOPE)
  if(NOT result EQUAL 0)
    set(log "${out}${err}")
    if(EXISTS "${path}.parts")
      # A module stage: its locations named by file and line, as the module names a driver's.
      file(WRITE "${path}.log" "${log}")
      execute_process(COMMAND "${VARIANTS}" --name-log "${path}" INPUT_FILE "${path}.log" OUTPUT_VARIABLE log)
    endif()
    get_filename_component(name "${path}" NAME)
    message(SEND_ERROR "${name}: glslangValidator failed:\n${log}")
    math(EXPR f "${failures} + 1")
    set(failures ${f} PARENT_SCOPE)
  endif()
endfunction()

# The module's stages, every variant.
set(module_dir "${WORK_DIR}/module")
file(REMOVE_RECURSE "${module_dir}")
file(MAKE_DIRECTORY "${module_dir}")
execute_process(COMMAND "${VARIANTS}" "${module_dir}" RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${VARIANTS} failed (${result})")
endif()
file(GLOB stages "${module_dir}/*.vert" "${module_dir}/*.frag" "${module_dir}/*.comp")
if(NOT stages)
  message(FATAL_ERROR "${VARIANTS} wrote no shader")
endif()
foreach(stage IN LISTS stages)
  validate("${stage}")
endforeach()

# The host-side includes, each under a small main that calls every function (hosts paste them
# after their own #version line, desktop or ES).
set(host_dir "${WORK_DIR}/host")
file(MAKE_DIRECTORY "${host_dir}")
function(validate_host name body)
  file(WRITE "${host_dir}/${name}.frag" "${body}")
  validate("${host_dir}/${name}.frag")
  set(count ${count} PARENT_SCOPE)
  set(failures ${failures} PARENT_SCOPE)
endfunction()
set(preintegrated_main "uniform sampler2D d; uniform sampler2D s; in vec3 n; in vec3 p; out vec4 c;
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
if(SHADER_DIR)
  foreach(dialect 330 420 es300)
    file(READ "${SHADER_DIR}/version_${dialect}.glsl" header)
    if(INTEGRATION_GLSL_DIR)
      file(READ "${INTEGRATION_GLSL_DIR}/sss_transmittance.glsl" transmittance)
      set(main "uniform sampler2D m; uniform mat4 v, p; out vec4 o;\nvoid main() {\n  float t = sss_thickness(m, v, p, vec3(0.0), vec3(0.0, 0.0, 1.0), 0.005) + sss_thickness_linear(m, v, p, vec3(0.0), vec3(0.0, 0.0, 1.0), 0.005);\n  t = sss_thickness_combined(sss_thickness_baked(m, vec2(0.5), 0.01) + sss_thickness_from_unit(0.5, 0.01), t);\n  o = vec4(sss_transmittance(t, 0.012, 0.5, vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, -1.0)), 1.0);\n}\n")
      validate_host(${dialect}_sss_transmittance "${header}${transmittance}${main}")
      file(READ "${INTEGRATION_GLSL_DIR}/sss_back_transmittance.glsl" back)
      set(main "uniform sampler2D b, n; uniform mat4 p; out vec4 o;\nvoid main() {\n  o = vec4(sss_back_transmittance(b, n, gl_FragCoord.xy, vec3(0.0, 0.0, -1.0), vec3(0.0, 0.0, 1.0), p, vec4(0.0, 0.0, 64.0, 64.0), 0.0015, 4.5), 1.0);\n}\n")
      validate_host(${dialect}_sss_back_transmittance "${header}${transmittance}${back}${main}")
    endif()
    if(INCLUDE_DIR)
      file(READ "${INCLUDE_DIR}/sss_preintegrated.glsl" include)
      validate_host(${dialect}_host_preintegrated "${header}${include}${preintegrated_main}")
    endif()
  endforeach()
endif()
message(STATUS "glslangValidator: ${count} shader stages, ${failures} failed")
if(failures GREATER 0)
  message(FATAL_ERROR "shader validation failed")
endif()
