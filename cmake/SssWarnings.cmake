# sss_target_warnings(<target>): the project's warning set; errors when SSS_WARNINGS_AS_ERRORS.
function(sss_target_warnings target)
  if(MSVC)
    target_compile_options(${target} PRIVATE /W4 $<$<BOOL:${SSS_WARNINGS_AS_ERRORS}>:/WX>)
  else()
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
      -Wno-sign-conversion $<$<BOOL:${SSS_WARNINGS_AS_ERRORS}>:-Werror>)
  endif()
endfunction()
