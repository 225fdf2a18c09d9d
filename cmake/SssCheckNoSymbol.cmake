# ctest library.has_no_test_hook (tests/CMakeLists.txt): LIBRARY's symbols (nm: the symbol table,
# local and hidden ones included, as the linker left them) must not name SYMBOL, and HOOKED's must,
# which shows that nm read the archive and that the name is spelt as the compiler writes it.
# cmake -DNM=nm -DLIBRARY=libsss.a -DHOOKED=libsss_state_guard_hook.a -DSYMBOL=name -P SssCheckNoSymbol.cmake
cmake_minimum_required(VERSION 3.16)

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
  message(FATAL_ERROR "${HOOKED} lacks ${SYMBOL}: the check cannot see the hook where it is")
endif()
names_symbol(${LIBRARY} library_has_it)
if(library_has_it)
  message(FATAL_ERROR "${LIBRARY} contains ${SYMBOL}, the tests' hook")
endif()
message(STATUS "${LIBRARY}: no ${SYMBOL} (${HOOKED} has it)")
