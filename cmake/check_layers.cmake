# Which parts of src/ each part may include (DESIGN.md's table "Parts and what each may know"):
# run by ctest as `cmake -DSOURCE_DIR=<a folder holding src/> -P check_layers.cmake`. Every
# library shares the include root src/, so the compiler alone would let scene/scene.hpp include a
# render header; this check fails the build's tests instead, naming the file and the include.
cmake_minimum_required(VERSION 3.25)

set(allowed_common common)
set(allowed_physics physics)
set(allowed_sim sim physics)
set(allowed_scene scene sim physics common)
set(allowed_io io common)
set(allowed_render render io common)
set(allowed_bench bench sim physics common)

set(breaks "")
foreach(part common physics sim scene io render bench)
  file(GLOB_RECURSE files "${SOURCE_DIR}/src/${part}/*.hpp" "${SOURCE_DIR}/src/${part}/*.cpp")
  foreach(file ${files})
    file(STRINGS "${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"[^\"/]+/")
    foreach(line ${includes})
      string(REGEX REPLACE "^[^\"]*\"([^\"/]+)/.*$" "\\1" included "${line}")
      if(NOT included IN_LIST allowed_${part})
        file(RELATIVE_PATH shown "${SOURCE_DIR}" "${file}")
        string(REGEX REPLACE "^[^\"]*(\"[^\"]+\").*$" "\\1" quoted "${line}")
        list(JOIN allowed_${part} ", " may)
        string(APPEND breaks "  ${shown} includes ${quoted}: ${part} may include only ${may}\n")
      endif()
    endforeach()
  endforeach()
endforeach()
if(breaks)
  message(FATAL_ERROR "includes across parts that DESIGN.md forbids:\n${breaks}")
endif()
