# cmake -DEXPORT=<ltc_export> -DCXX=<GCC or Clang driver> -DOUT=<scratch dir> -P tools/blender_check/run.cmake
#
# Writes the one-lobe table with ltc_export --formats blender and compiles each file against the
# declarations Blender's EEVEE headers make of the two arrays (eevee_lut_declarations.h): the C++
# ones as C++17, the flat one as C99 and as C++17 (eevee_lut.cc's flat arrays), warnings as errors.
get_filename_component(_here "${CMAKE_CURRENT_LIST_FILE}" DIRECTORY)
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
execute_process(COMMAND "${EXPORT}" --table ggx --formats blender --out "${OUT}" --quiet
                RESULT_VARIABLE _rc ERROR_VARIABLE _err)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "ltc_export failed: ${_err}")
endif()
set(_decl "${_here}/eevee_lut_declarations.h")
foreach(_case IN ITEMS "ggx_eevee_lut.cc|c++|-std=c++17|-DLTC_EEVEE_FLOAT_ARRAYS"
                       "ggx_eevee_lut_vecbase.cc|c++|-std=c++17|-DLTC_EEVEE_VEC_BASE"
                       "ggx_eevee_lut.c|c|-std=c99|-DLTC_EEVEE_C"
                       "ggx_eevee_lut.c|c++|-std=c++17|-DLTC_EEVEE_C")
  string(REPLACE "|" ";" _case "${_case}")
  list(GET _case 0 _file)
  list(GET _case 1 _language)
  list(GET _case 2 _standard)
  list(GET _case 3 _define)
  if(NOT EXISTS "${OUT}/${_file}")
    message(FATAL_ERROR "ltc_export wrote no ${_file}")
  endif()
  execute_process(COMMAND "${CXX}" -x ${_language} ${_standard} ${_define} -fsyntax-only -Wall -Wextra -Werror
                          -include "${_decl}" "${OUT}/${_file}"
                  RESULT_VARIABLE _rc ERROR_VARIABLE _err)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "${_file} does not compile against EEVEE's declarations:\n${_err}")
  endif()
endforeach()
message(STATUS "the EEVEE sources compile against their declarations")
