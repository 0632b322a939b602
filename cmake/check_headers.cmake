# cmake -DCXX=<compiler> -DLTC_INCLUDE_DIR=<include/> "-DFLAGS=-std=c++17|-Wall|..." [-DPART=k -DPARTS=n]
#       -P cmake/check_headers.cmake
#
# Each header of ltc compiles on its own, and twice in a row (its include guard): one syntax-only
# compiler run per header, no object files; forwarders are left to the consumer test. With PART and PARTS: only the headers whose index in
# the sorted list is PART modulo PARTS.
string(REPLACE "|" ";" _flags "${FLAGS}")
file(GLOB_RECURSE _headers RELATIVE "${LTC_INCLUDE_DIR}" "${LTC_INCLUDE_DIR}/ltc/*.hpp")
list(SORT _headers)
if(NOT DEFINED PARTS)
  set(PARTS 1)
  set(PART 0)
endif()
set(_failed 0)
set(_checked 0)
set(_index -1)
foreach(header IN LISTS _headers)
  math(EXPR _index "${_index} + 1")
  math(EXPR _mine "${_index} % ${PARTS}")
  if(NOT _mine EQUAL PART)
    continue()
  endif()
  # A forwarder of a deprecated path (its first line says so) compiles where its target does;
  # tests/consumer/old_paths.cpp includes every one of them.
  file(STRINGS "${LTC_INCLUDE_DIR}/${header}" _first LIMIT_COUNT 1)
  if(_first MATCHES "-- deprecated path")
    continue()
  endif()
  math(EXPR _checked "${_checked} + 1")
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
if(_failed GREATER 0)
  message(FATAL_ERROR "check_headers: ${_failed} of ${_checked} headers failed")
endif()
message(STATUS "check_headers: ${_checked} headers compile on their own")
