# Run in script mode by the `shaders.tap_fetches` test (issue 24): how many texture fetches one tap
# of each OpenGL ES blur variant makes, counted in the stage as the module assembles it
# (sss_shader_variants writes it), preprocessed by glslangValidator -E (so only the variant's own
# #if branches count), by sss_shader_variants --tap-fetches (sss_fetch_tap's body and the bodies of
# the functions it calls). Colour and view distance come in one texel (pass_inputs.frag), so a tap
# is one fetch, and two only with R16UI profile indices (SSS_PROFILE_IDS 2), which are read per tap.
#   -DVALIDATOR=<glslangValidator> -DVARIANTS=<sss_shader_variants> -DWORK_DIR=<scratch folder>
set(dir "${WORK_DIR}/tap_fetches")
file(REMOVE_RECURSE "${dir}")
file(MAKE_DIRECTORY "${dir}")
execute_process(COMMAND "${VARIANTS}" "${dir}" RESULT_VARIABLE result OUTPUT_QUIET)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${VARIANTS} failed (${result})")
endif()
file(GLOB stages "${dir}/es300_blur_*.frag")
list(LENGTH stages stage_count)
if(stage_count LESS 100)
  message(FATAL_ERROR "only ${stage_count} OpenGL ES blur variants written")
endif()
set(failures 0)
foreach(stage IN LISTS stages)
  get_filename_component(name "${stage}" NAME)
  execute_process(COMMAND "${VALIDATOR}" -E "${stage}" OUTPUT_FILE "${stage}.i" RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${name}: glslangValidator -E failed")
  endif()
  execute_process(COMMAND "${VARIANTS}" --tap-fetches INPUT_FILE "${stage}.i" OUTPUT_VARIABLE fetches
                  RESULT_VARIABLE result OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${name}: no sss_fetch_tap found")
  endif()
  set(allowed 1)
  if(name MATCHES "_p2_")  # R16UI profile indices: the index texture too
    set(allowed 2)
  endif()
  if(NOT fetches EQUAL allowed)
    message(SEND_ERROR "${name}: ${fetches} fetches per tap, expected ${allowed}")
    math(EXPR failures "${failures} + 1")
  endif()
endforeach()
message(STATUS "${stage_count} OpenGL ES blur variants: one fetch per tap (two with R16UI indices)")
if(failures GREATER 0)
  message(FATAL_ERROR "${failures} variants fetch more per tap than allowed")
endif()
