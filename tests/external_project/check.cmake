# CTest install.external_project: installs the build into a fresh prefix,
# builds this folder's project against that prefix alone, runs it, and holds
# its image to the installed `tsis render` of the same options (the same
# bytes), and its error to the CLI's (the same line).
# cmake -DBUILD_DIR=… -DPROJECT_DIR=… -DWORK_DIR=… -P check.cmake
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)

function(run)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${ARGN}\nfailed (${rc}):\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

file(MAKE_DIRECTORY ${WORK_DIR})
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(internal render/renderer.h util/error.h cli/scene_options.h)
  if(EXISTS ${prefix}/include/${internal} OR EXISTS ${prefix}/include/tsis/${internal})
    message(FATAL_ERROR "internal header ${internal} installed")
  endif()
endforeach()
run(${CMAKE_COMMAND} -S ${PROJECT_DIR} -B ${WORK_DIR}/build -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_BUILD_TYPE=Release)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)

set(opts width=96 height=64 atlas-res=128 light-res=256 method=tsis samples=128)
run(${WORK_DIR}/build/render_frame ${WORK_DIR}/lib.png ${opts})
message(STATUS "render_frame: ${out}")
set(cli)
foreach(o ${opts})
  string(REPLACE "=" ";" nv ${o})
  list(GET nv 0 n)
  list(GET nv 1 v)
  list(APPEND cli --${n} ${v})
endforeach()
run(${prefix}/bin/tsis render --mesh builtin:sphere --material marble
    --light point:0,12,6:150,150,150 ${cli} -o ${WORK_DIR}/cli.png)
run(${prefix}/bin/tsis compare ${WORK_DIR}/lib.png ${WORK_DIR}/cli.png --json)
string(JSON rmse GET "${out}" rmse)
string(JSON pixels GET "${out}" pixels)
if(NOT rmse EQUAL 0 OR NOT pixels EQUAL 6144)
  message(FATAL_ERROR "the library's image differs from tsis render's: ${out}")
endif()

# A refused option: the same line as the CLI's.
execute_process(COMMAND ${WORK_DIR}/build/render_frame ${WORK_DIR}/bad.png samples=0
                RESULT_VARIABLE rc ERROR_VARIABLE lib_err)
execute_process(COMMAND ${prefix}/bin/tsis render --samples 0 -o ${WORK_DIR}/bad.png
                ERROR_VARIABLE cli_err)
if(rc EQUAL 0 OR NOT lib_err STREQUAL cli_err OR NOT lib_err MATCHES "^tsis: error: --samples")
  message(FATAL_ERROR "errors differ:\n${lib_err}\n${cli_err}")
endif()
