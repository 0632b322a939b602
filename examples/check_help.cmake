# examples/check_help.cmake -- the CTest check of an example's command line (examples/CMakeLists.txt):
#   cmake -DPROGRAM=path -DOPTIONS=--a,--b,-c -P check_help.cmake
# PROGRAM --help and PROGRAM -h exit 0 with the same text on stdout, which names every option of
# OPTIONS (comma-separated: a CMake list would be split on its way through add_test); an unknown
# option exits 2 with a message on stderr that names it. Nothing else runs: the check is cheap.
foreach(var PROGRAM OPTIONS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_help.cmake: -D${var}=... is required")
  endif()
endforeach()

execute_process(COMMAND "${PROGRAM}" --help RESULT_VARIABLE rc OUTPUT_VARIABLE help ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} --help: exit status ${rc}, expected 0\n${err}")
endif()
execute_process(COMMAND "${PROGRAM}" -h RESULT_VARIABLE rc OUTPUT_VARIABLE short_help)
if(NOT rc EQUAL 0 OR NOT short_help STREQUAL help)
  message(FATAL_ERROR "${PROGRAM} -h: exit status ${rc} (expected 0), or not the text of --help")
endif()

string(REPLACE "," ";" options "${OPTIONS}")
set(missing "")
foreach(option IN LISTS options)
  # A whole word: -h is not the -h of --height.
  if(NOT help MATCHES "(^|[^-a-z0-9])${option}([^-a-z0-9]|$)")
    list(APPEND missing "${option}")
  endif()
endforeach()
if(missing)
  message(FATAL_ERROR "${PROGRAM} --help does not mention: ${missing}\n${help}")
endif()

execute_process(COMMAND "${PROGRAM}" --no-such-option RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--no-such-option")
  message(FATAL_ERROR "${PROGRAM} --no-such-option: exit status ${rc} (expected 2), stderr: ${err}")
endif()
list(LENGTH options count)
message(STATUS "${PROGRAM}: --help and -h name all ${count} options; an unknown one exits 2")
