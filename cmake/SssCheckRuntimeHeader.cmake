# cmake -DHEADER=<sss.h> -P SssCheckRuntimeHeader.cmake (ctest docs.runtime_header_includes): the
# runtime header includes sss_common.h alone (never a tools header, which would make the runtime
# header include its includer). Its shape is docs.runtime_header_shape's (tools/docs/header_shape.cpp).
file(STRINGS "${HEADER}" lines REGEX "^#[ \t]*include")
foreach(line IN LISTS lines)
  if(line MATCHES "^#[ \t]*include" AND NOT line MATCHES "sss_common\\.h")
    message(FATAL_ERROR "${HEADER}: includes more than sss_common.h: ${line}")
  endif()
endforeach()
message(STATUS "${HEADER}: includes sss_common.h alone")
