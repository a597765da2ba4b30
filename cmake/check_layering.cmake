# The layering rule of docs/architecture.md, checked on the sources: a folder may include only the
# folders listed for it (its own included). Run at configure time by the top-level CMakeLists and
# as the test `layering` (cmake -DGRANBENCH_SOURCE_DIR=... -P cmake/check_layering.cmake), so an
# include that crosses a layer fails both the configure step and CI.
#
#   common                                      (nothing of ours)
#   depthavg, twod                              common
#   analysis/{theory,spectral,linear2d}         common, each other
#   analysis/comparison                         the above, depthavg, twod
#   analysis/cases                              the above and analysis/comparison
#   analysis/cli                                everything but tests and bench
cmake_policy(VERSION 3.25)  # also when run alone with -P
if(NOT GRANBENCH_SOURCE_DIR)
  set(GRANBENCH_SOURCE_DIR "${CMAKE_SOURCE_DIR}")
endif()
set(theories "analysis/theory;analysis/spectral;analysis/linear2d")
set(allowed_common "common")
set(allowed_depthavg "common;depthavg")
set(allowed_twod "common;twod")
set(allowed_analysis/theory "common;${theories}")
set(allowed_analysis/spectral "common;${theories}")
set(allowed_analysis/linear2d "common;${theories}")
set(allowed_analysis/comparison "common;depthavg;twod;${theories};analysis/comparison")
set(allowed_analysis/cases "common;depthavg;twod;${theories};analysis/comparison;analysis/cases")
set(allowed_analysis/cli "common;depthavg;twod;${theories};analysis/comparison;analysis/cases;analysis/cli")

# Written into the build tree at build time (common/CMakeLists.txt), so not under a folder here.
set(generated_headers "granbench_build_info.hpp")
set(violations "")
foreach(layer common depthavg twod analysis/theory analysis/spectral analysis/linear2d
        analysis/comparison analysis/cases analysis/cli)
  file(GLOB sources "${GRANBENCH_SOURCE_DIR}/${layer}/*.cpp" "${GRANBENCH_SOURCE_DIR}/${layer}/*.hpp")
  foreach(src ${sources})
    file(STRINGS "${src}" includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"")
    foreach(line ${includes})
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"([^\"]+)\".*" "\\1" header "${line}")
      if(header IN_LIST generated_headers)
        continue()
      endif()
      string(REGEX MATCH "^(.*)/[^/]+$" _ "${header}")
      set(folder "${CMAKE_MATCH_1}")
      list(FIND allowed_${layer} "${folder}" found)
      if(found EQUAL -1)
        file(RELATIVE_PATH rel "${GRANBENCH_SOURCE_DIR}" "${src}")
        list(APPEND violations "${rel} includes \"${header}\"")
      endif()
    endforeach()
  endforeach()
endforeach()
if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "layering (docs/architecture.md): includes that cross a layer or are not "
                      "root-qualified:\n  ${text}")
endif()
