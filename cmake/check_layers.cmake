# cmake -DLTC_INCLUDE_DIR=<repo>/include -P cmake/check_layers.cmake
#
# Fails when a header of ltc includes a header of a higher layer. The layers, lowest first, are
# written here once; a header belongs to the layer of the longest prefix that matches its path,
# and may include headers of its own layer or of a lower one (core/detail/ is core's own, below
# nothing else; ltc/*.hpp at the top are the umbrellas and deprecated forwarders).
set(_layers
  "ltc/config.hpp"
  "ltc/detail/"
  "ltc/core/"
  "ltc/brdf/"
  "ltc/tables/"
  "ltc/shading/"
  "ltc/reference/"
  "ltc/fitting/"
  "ltc/")

if(NOT LTC_INCLUDE_DIR)
  message(FATAL_ERROR "check_layers: set -DLTC_INCLUDE_DIR=<path to include/>")
endif()

function(_ltc_layer_of path out)
  set(best -1)
  set(best_len 0)
  set(i 0)
  foreach(prefix IN LISTS _layers)
    string(LENGTH "${prefix}" len)
    string(SUBSTRING "${path}" 0 ${len} head)
    if(head STREQUAL prefix AND len GREATER best_len)
      set(best ${i})
      set(best_len ${len})
    endif()
    math(EXPR i "${i} + 1")
  endforeach()
  set(${out} ${best} PARENT_SCOPE)
endfunction()

file(GLOB_RECURSE _headers RELATIVE "${LTC_INCLUDE_DIR}" "${LTC_INCLUDE_DIR}/ltc/*.hpp" "${LTC_INCLUDE_DIR}/ltc/*.inc")
list(SORT _headers)
set(_violations 0)
foreach(header IN LISTS _headers)
  _ltc_layer_of("${header}" own)
  list(GET _layers ${own} own_name)
  file(STRINGS "${LTC_INCLUDE_DIR}/${header}" _lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]ltc/")
  foreach(line IN LISTS _lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]+)[>\"].*" "\\1" target "${line}")
    _ltc_layer_of("${target}" theirs)
    if(theirs GREATER own)
      list(GET _layers ${theirs} their_name)
      message(SEND_ERROR "${header} (layer ${own_name}) includes ${target} (higher layer ${their_name})")
      math(EXPR _violations "${_violations} + 1")
    endif()
  endforeach()
endforeach()
list(LENGTH _headers _count)
if(_violations GREATER 0)
  message(FATAL_ERROR "check_layers: ${_violations} include(s) point up a layer")
endif()
message(STATUS "check_layers: ${_count} headers, every include points down or sideways")
