# tsis_embed(<target-sources-var> <c++ symbol> <file>...)
# Turns OpenCL C and GLSL files into a generated C++ source holding one
# `EmbeddedFile{name, text}` per file, so the binary never reads kernels or
# shaders from disk. Includes are resolved when a program is built
# (embeddedSource in host/util/embedded.h), with `#line` markers so compiler
# messages name the real file and line.
set(TSIS_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/embed_script.cmake)

function(tsis_embed out_var symbol)
  set(out_cpp ${CMAKE_CURRENT_BINARY_DIR}/${symbol}.cpp)
  set(files ${ARGN})
  set(deps)
  foreach(f ${files})
    list(APPEND deps ${f})
  endforeach()
  string(REPLACE ";" "|" files_arg "${files}")
  add_custom_command(
    OUTPUT ${out_cpp}
    COMMAND ${CMAKE_COMMAND} -DSYMBOL=${symbol} "-DFILES=${files_arg}"
            -DOUT=${out_cpp}
            -P ${TSIS_EMBED_SCRIPT}
    DEPENDS ${deps} ${TSIS_EMBED_SCRIPT}
    COMMENT "Embedding ${symbol}"
    VERBATIM)
  set(${out_var} ${out_cpp} PARENT_SCOPE)
endfunction()
