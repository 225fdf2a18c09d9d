# Run in script mode by the `code.shape` test: the library's sources stay in pieces a reader holds
# in their head (docs/development.md). Fails when a file in module/src has more than MAX_FILE_LINES
# lines, or (clang-tidy's readability-function-size over the compilation database) a function more
# than MAX_FUNCTION_LINES.
#   -DSOURCE_DIR=<module/src> -DBUILD_DIR=<folder with compile_commands.json> -DCLANG_TIDY=<clang-tidy>
#   -DMAX_FILE_LINES=500 -DMAX_FUNCTION_LINES=80
file(GLOB_RECURSE sources "${SOURCE_DIR}/*.cpp" "${SOURCE_DIR}/*.hpp")
list(SORT sources)
set(failures "")
set(cpp_files "")
foreach(path IN LISTS sources)
  # Count newlines (file(STRINGS) would split at semicolons too).
  file(READ "${path}" text)
  string(REGEX REPLACE "[^\n]" "" newlines "${text}")
  string(LENGTH "${newlines}" lines)
  if(lines GREATER MAX_FILE_LINES)
    file(RELATIVE_PATH name "${SOURCE_DIR}" "${path}")
    string(APPEND failures "  ${name}: ${lines} lines (at most ${MAX_FILE_LINES})\n")
  endif()
  if(path MATCHES "\\.cpp$")
    list(APPEND cpp_files "${path}")
  endif()
endforeach()
list(LENGTH sources file_count)

execute_process(
  COMMAND "${CLANG_TIDY}" -p "${BUILD_DIR}" --quiet "--checks=-*,readability-function-size"
          "--config={CheckOptions: [{key: readability-function-size.LineThreshold, value: ${MAX_FUNCTION_LINES}}]}"
          ${cpp_files}
  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
# Each finding: "<file>:<line>:<col>: warning: function '<name>' exceeds ..." and, a few lines on,
# "<file>:<line>:<col>: note: <n> lines including whitespace and comments (threshold <max>)".
string(REGEX MATCHALL "[^\n]*(warning: function '[^']*' exceeds|note: [0-9]+ lines including)[^\n]*" long "${out}")
foreach(entry IN LISTS long)
  string(APPEND failures "  ${entry}\n")
endforeach()
if(NOT result EQUAL 0 AND long STREQUAL "")
  message(FATAL_ERROR "clang-tidy failed (${result}):\n${out}${err}")
endif()
if(NOT failures STREQUAL "")
  message(FATAL_ERROR "module/src has pieces too long to hold in one's head:\n${failures}")
endif()
message(STATUS "code.shape: ${file_count} files at most ${MAX_FILE_LINES} lines, functions at most ${MAX_FUNCTION_LINES}")
