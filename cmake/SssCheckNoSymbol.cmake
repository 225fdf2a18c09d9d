# ctest library.has_no_test_hook (tests/CMakeLists.txt): LIBRARY's symbols (nm: the symbol table,
# local and hidden ones included, as the linker left them) must not name SYMBOL, and HOOKED's must,
# which shows that nm read the archive and that the name is spelt as the compiler writes it.
# cmake -DNM=nm -DLIBRARY=libsss.a -DHOOKED=libsss_state_guard_hook.a -DSYMBOL=name -P SssCheckNoSymbol.cmake
# Also ctest library.runtime_has_no_nlopt / _no_eigen: LIBRARY = the runtime libsss, HOOKED = the tools
# library, SYMBOL = "nlopt_" / "Eigen::", WHAT = what the symbol stands for; INTERFACE (optional) =
# the runtime target's link interface, which must not name SYMBOL's library either.
cmake_minimum_required(VERSION 3.16)
if(NOT WHAT)
  set(WHAT "the tests' hook")
endif()

function(names_symbol file result)
  execute_process(COMMAND ${NM} -C ${file} RESULT_VARIABLE rc OUTPUT_VARIABLE symbols ERROR_VARIABLE errors)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${NM} -C ${file} failed (${rc}): ${errors}")
  endif()
  string(FIND "${symbols}" "${SYMBOL}" at)
  if(at EQUAL -1)
    set(${result} OFF PARENT_SCOPE)
  else()
    set(${result} ON PARENT_SCOPE)
  endif()
endfunction()

names_symbol(${HOOKED} hooked_has_it)
if(NOT hooked_has_it)
  message(FATAL_ERROR "${HOOKED} lacks ${SYMBOL}: the check cannot see ${WHAT} where it is")
endif()
names_symbol(${LIBRARY} library_has_it)
if(library_has_it)
  message(FATAL_ERROR "${LIBRARY} contains ${SYMBOL}, ${WHAT}")
endif()
if(DEFINED INTERFACE)
  string(TOLOWER "${INTERFACE}" interface)
  string(TOLOWER "${SYMBOL}" symbol)
  string(REGEX REPLACE "[^a-z]" "" symbol "${symbol}")
  string(FIND "${interface}" "${symbol}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "the runtime's link interface names ${symbol}: ${INTERFACE}")
  endif()
endif()
message(STATUS "${LIBRARY}: no ${SYMBOL} (${HOOKED} has it)")
