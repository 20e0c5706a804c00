# Which parts of src/ each part may include (docs/design.md, "Parts and what each may know"):
# run by ctest as `cmake -DSOURCE_DIR=<a folder holding src/> -P check_layers.cmake`. Every
# library shares the include root src/, so the compiler alone would let scene/scene.hpp include a
# render header; this check fails the build's tests instead, naming the file and the include.
#
# A part is a folder of src/; a nested part (bench/jobs) is told apart from its parent by the
# longest folder that holds the file, or that begins the included path. A file of src/ in no part
# is an error too, so that a new folder cannot escape the table.
cmake_minimum_required(VERSION 3.25)

set(parts common physics sim scene io render sys diff view pipeline job bench bench/jobs cli python)
set(allowed_common common)
set(allowed_physics physics common)
set(allowed_sim sim physics common)
set(allowed_scene scene sim physics common)
set(allowed_io io common)
set(allowed_render render io common)
set(allowed_sys sys common)
set(allowed_diff diff io common)
set(allowed_view view pipeline scene sim physics render common)
set(allowed_pipeline pipeline render io common)
set(allowed_job job view pipeline diff scene sim physics render io sys common)
set(allowed_bench bench sim physics common)
set(allowed_bench/jobs bench/jobs bench job view pipeline diff scene sim physics render io sys
    common)
set(allowed_cli ${parts})
set(allowed_python job view pipeline diff scene sim physics render io sys common python)

# The part that `path` (relative to src/, a file's or an include's) lies in, or "" for none.
function(part_of path out)
  set(found "")
  foreach(part ${parts})
    string(LENGTH "${part}/" length)
    string(SUBSTRING "${path}" 0 ${length} head)
    string(LENGTH "${found}" found_length)
    if(head STREQUAL "${part}/" AND length GREATER found_length)
      set(found "${part}")
    endif()
  endforeach()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

set(breaks "")
file(GLOB_RECURSE files RELATIVE "${SOURCE_DIR}/src" "${SOURCE_DIR}/src/*.hpp"
     "${SOURCE_DIR}/src/*.cpp")
foreach(file ${files})
  part_of("${file}" part)
  if(part STREQUAL "")
    string(APPEND breaks "  src/${file} is in no part: add its folder to cmake/check_layers.cmake\n")
    continue()
  endif()
  file(STRINGS "${SOURCE_DIR}/src/${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"[^\"/]+/")
  foreach(line ${includes})
    string(REGEX REPLACE "^[^\"]*\"([^\"]+)\".*$" "\\1" included "${line}")
    part_of("${included}" included_part)
    if(NOT included_part IN_LIST allowed_${part})
      list(JOIN allowed_${part} ", " may)
      string(APPEND breaks "  src/${file} includes \"${included}\": ${part} may include only ${may}\n")
    endif()
  endforeach()
endforeach()
if(breaks)
  message(FATAL_ERROR "includes across parts that docs/design.md forbids:\n${breaks}")
endif()
