# Installs the build tree into a scratch prefix, then configures, builds and runs a tiny consumer
# project that only knows `find_package(tapeline)`; with PYTHON, imports the installed Python
# package from PREFIX/PYTHON_DIR and computes a distance field with it.
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
if(NOT EXISTS ${prefix}/lib/cmake/tapeline/tapelineConfig.cmake
   AND NOT EXISTS ${prefix}/lib/x86_64-linux-gnu/cmake/tapeline/tapelineConfig.cmake)
  message(FATAL_ERROR "no tapelineConfig.cmake under ${prefix}")
endif()
set(extra)
if(LAUNCHER)
  set(extra -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_BUILD_TYPE= ${extra})  # no optimisation: the check is that it builds and links
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/consumer)
if(NOT last_output MATCHES "consumer ok")
  message(FATAL_ERROR "consumer printed: ${last_output}")
endif()
message(STATUS "${last_output}")

if(PYTHON)
  set(package ${prefix}/${PYTHON_DIR}/tapeline)
  if(NOT EXISTS ${package}/__init__.py OR NOT EXISTS ${package}/geodesic.pyi)
    message(FATAL_ERROR "no Python package under ${package}")
  endif()
  run(${CMAKE_COMMAND} -E env PYTHONPATH=${prefix}/${PYTHON_DIR} ${PYTHON} -c
      "import sys, tapeline\nfrom tapeline import geodesic as g\nV, F, _ = tapeline.read_mesh(sys.argv[1])\nd = g.distances(V, F, 0, method='heat')\nassert tapeline.__file__.startswith(sys.argv[2]), tapeline.__file__\nassert d[0] == 0 and d.max() > 0\nprint('python ok', len(d))"
      ${MESH} ${prefix})
  if(NOT last_output MATCHES "python ok")
    message(FATAL_ERROR "the installed Python package printed: ${last_output}")
  endif()
  message(STATUS "${last_output}")
endif()
