# cmake -DHEADER=<sss.h> -DMAX_LINES=N -P SssCheckRuntimeHeader.cmake (ctest docs.runtime_header_is_short):
# the runtime header has at most MAX_LINES lines and includes sss_common.h alone (never a tools
# header, which would make the runtime header include its includer).
file(READ "${HEADER}" content)
string(REGEX MATCHALL "\n" newlines "${content}")
list(LENGTH newlines count)
file(STRINGS "${HEADER}" lines REGEX "^#[ \t]*include")
if(count GREATER MAX_LINES)
  message(FATAL_ERROR "${HEADER}: ${count} lines, more than ${MAX_LINES}: move reference prose to docs/integration.md")
endif()
foreach(line IN LISTS lines)
  if(line MATCHES "^#[ \t]*include" AND NOT line MATCHES "sss_common\\.h")
    message(FATAL_ERROR "${HEADER}: includes more than sss_common.h: ${line}")
  endif()
endforeach()
message(STATUS "${HEADER}: ${count} lines, includes sss_common.h alone")
