# cmake -DSOURCE=... -DBINARY=... -DCXX=... -P check-layers.cmake
# Shows that the two guards of cmake/NeptusLayers.cmake bite: a library that
# links what the table does not allow is named, and a header outside a
# library's allowed folders does not even preprocess with its include root.
cmake_minimum_required(VERSION 3.28)
include(${SOURCE}/cmake/NeptusLayers.cmake)

function(expect what actual expected)
  if(NOT "${actual}" STREQUAL "${expected}")
    message(FATAL_ERROR "${what}: got '${actual}', expected '${expected}'")
  endif()
  message(STATUS "ok: ${what}")
endfunction()

neptus_layer_violations(neptus-tree "neptus-messages;Qt6::Core" bad)
expect("the tree may link messages" "${bad}" "")
neptus_layer_violations(neptus-tree "neptus-messages;neptus-transport" bad)
expect("the tree may not link the transports" "${bad}" "neptus-transport")
neptus_layer_violations(neptus-transport "neptus-messages;neptus-tree" bad)
expect("the transports may not link the tree" "${bad}" "neptus-tree")
neptus_layer_violations(neptus-msg "neptus-messages;neptus-engine" bad)
expect("a command-line tool may not link the QML module" "${bad}" "neptus-engine")
neptus_layer_violations(neptus-session "neptus-scripting;neptus-transport;neptus-core" bad)
expect("the session may link what it builds on, transitively" "${bad}" "")

# Includes: the tree's include root has messages/ but not transport/.
set(root ${BINARY}/layers/neptus-tree)
if(NOT EXISTS ${root}/messages/Message.h)
  message(FATAL_ERROR "${root} does not show messages/, which the tree may use")
endif()
set(source ${BINARY}/check-layers-wrong-include.cpp)
file(WRITE ${source} "#include \"transport/OutputSink.h\"\n")
execute_process(COMMAND ${CXX} -E -I${root} ${source} RESULT_VARIABLE result ERROR_VARIABLE error OUTPUT_QUIET)
if(result EQUAL 0 OR NOT error MATCHES "transport/OutputSink.h: No such file")
  message(FATAL_ERROR "a tree source including transport/OutputSink.h preprocessed (${result}): ${error}")
endif()
message(STATUS "ok: a tree source cannot include transport/OutputSink.h")
file(REMOVE ${source})
