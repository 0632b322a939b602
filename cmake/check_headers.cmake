# cmake -DCXX=<compiler> -DLTC_INCLUDE_DIR=<include/> "-DFLAGS=-std=c++17|-Wall|..." -P cmake/check_headers.cmake
#
# Each header of ltc compiles on its own, and twice in a row (its include guard): one syntax-only
# compiler run per header, no object files.
string(REPLACE "|" ";" _flags "${FLAGS}")
file(GLOB_RECURSE _headers RELATIVE "${LTC_INCLUDE_DIR}" "${LTC_INCLUDE_DIR}/ltc/*.hpp")
list(SORT _headers)
set(_failed 0)
foreach(header IN LISTS _headers)
  string(MAKE_C_IDENTIFIER "${header}" _id)
  set(_tu "${CMAKE_CURRENT_BINARY_DIR}/header_check_${_id}.cpp")
  file(WRITE "${_tu}" "#include <${header}>\n#include <${header}>  // include guard\n")
  execute_process(
    COMMAND "${CXX}" ${_flags} "-I${LTC_INCLUDE_DIR}" -fsyntax-only "${_tu}"
    RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
  file(REMOVE "${_tu}")
  if(NOT _rc EQUAL 0)
    message(SEND_ERROR "${header} does not compile on its own:\n${_out}")
    math(EXPR _failed "${_failed} + 1")
  endif()
endforeach()
list(LENGTH _headers _count)
if(_failed GREATER 0)
  message(FATAL_ERROR "check_headers: ${_failed} of ${_count} headers failed")
endif()
message(STATUS "check_headers: ${_count} headers compile on their own")
