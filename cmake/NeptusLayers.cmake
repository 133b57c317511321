# The architecture's arrows, as the build enforces them. Each engine library
# lives in one folder of engine/ and may use only the libraries listed after
# it (and what those may use). Two guards follow from this table:
#  - includes: a library's include root (build/layers/<library>) holds links
#    to its own folder and its allowed ones only, so "#include
#    "transport/OutputSink.h"" in tree/ does not compile;
#  - links: neptus_check_layers() (run at the end of configuring) fails when
#    a library, a program or a test library links a neptus-* library the
#    table does not allow it.
set(NEPTUS_LAYERS
  "neptus-core         core        "
  "neptus-xml          xml         neptus-core"
  "neptus-messages     messages    neptus-xml"
  "neptus-tree         tree        neptus-messages"
  "neptus-alarms       alarms      neptus-tree"
  "neptus-scripting    scripting   neptus-alarms"
  "neptus-transport    transport   neptus-messages"
  "neptus-geo          geo         neptus-core"
  "neptus-coastline    geo         neptus-core"
  "neptus-mission-model mission    neptus-messages neptus-geo"
  "neptus-processor    processor   neptus-mission-model"
  "neptus-plan-runs    runs        neptus-messages"
  "neptus-plans        plans       neptus-mission-model neptus-scripting neptus-plan-runs"
  "neptus-charts       charts      neptus-mission-model"
  "neptus-chart-reader charts      neptus-charts"
  "neptus-models       models      neptus-core"
  "neptus-model-reader models      neptus-models"
  "neptus-simulation   sim         neptus-messages neptus-geo neptus-plans"
  "neptus-logs         log         neptus-messages neptus-geo neptus-plan-runs"
  "neptus-database     database    neptus-core"
  "neptus-web          web         neptus-session neptus-database neptus-coastline neptus-charts"
  "neptus-session      session     neptus-scripting neptus-transport neptus-logs neptus-database"
  "neptus-engine       qmlmodels   neptus-session neptus-geo neptus-plans neptus-processor neptus-models neptus-charts"
  # Programs: the command-line tools link no QML.
  "neptus-msg          -           neptus-messages"
  "neptus-sim          -           neptus-simulation neptus-transport"
  "neptus-model-import -           neptus-model-reader"
  "neptus-chart-import -           neptus-chart-reader"
  "neptus-chart        -           neptus-charts"
  "neptus-script-host  -           neptus-scripting"
  "neptus-xslt         -           neptus-processor"
  "neptus-mission      -           neptus-processor neptus-models neptus-charts"
  "neptus-log          -           neptus-logs neptus-database"
  "neptus-logd         -           neptus-session neptus-web"
)

# neptus_layer(LIBRARY <folder-var> <uses-var> <allowed-var>): the table's
# row for LIBRARY; allowed = LIBRARY and everything it may use, transitively.
function(neptus_layer library folder_var uses_var allowed_var)
  set(folder "")
  set(uses "")
  set(found FALSE)
  foreach(row ${NEPTUS_LAYERS})
    string(REGEX REPLACE " +" ";" row "${row}")
    list(GET row 0 name)
    if(name STREQUAL library)
      list(GET row 1 folder)
      list(LENGTH row count)
      if(count GREATER 2)
        list(SUBLIST row 2 -1 uses)
      endif()
      set(found TRUE)
    endif()
  endforeach()
  if(NOT found)
    message(FATAL_ERROR "${library} has no row in NEPTUS_LAYERS (cmake/NeptusLayers.cmake)")
  endif()
  set(allowed ${library})
  foreach(use ${uses})
    neptus_layer(${use} _f _u use_allowed)
    list(APPEND allowed ${use_allowed})
  endforeach()
  list(REMOVE_DUPLICATES allowed)
  set(${folder_var} ${folder} PARENT_SCOPE)
  set(${uses_var} ${uses} PARENT_SCOPE)
  set(${allowed_var} ${allowed} PARENT_SCOPE)
endfunction()

# neptus_layer_violations(LIBRARY "<linked libraries>" <out-var>): the
# neptus-* libraries in the list that LIBRARY may not use.
function(neptus_layer_violations library links out_var)
  neptus_layer(${library} _folder _uses allowed)
  set(bad "")
  foreach(link ${links})
    if(link MATCHES "^neptus-" AND NOT link MATCHES "plugin(_init)?$" AND NOT link IN_LIST allowed
       AND NOT link STREQUAL "neptus-dds-envelope")
      list(APPEND bad ${link})
    endif()
  endforeach()
  set(${out_var} ${bad} PARENT_SCOPE)
endfunction()

# neptus_engine_library(NAME SOURCES... [LINKS external...]): a library of the
# table, linking what its row allows and exposing only allowed folders.
function(neptus_engine_library name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "SOURCES;LINKS")
  neptus_layer(${name} folder uses allowed)
  if(NOT TARGET ${name})
    add_library(${name} STATIC ${arg_SOURCES})
  else()
    target_sources(${name} PRIVATE ${arg_SOURCES})
  endif()
  set(root ${CMAKE_BINARY_DIR}/layers/${name})
  file(MAKE_DIRECTORY ${root})
  foreach(lib ${allowed})
    neptus_layer(${lib} lib_folder _u _a)
    if(NOT lib_folder STREQUAL "-" AND NOT IS_SYMLINK ${root}/${lib_folder})
      file(CREATE_LINK ${NEPTUS_ENGINE_DIR}/${lib_folder} ${root}/${lib_folder} SYMBOLIC)
    endif()
  endforeach()
  target_include_directories(${name} PUBLIC ${root})
  target_link_libraries(${name} PUBLIC ${uses} ${arg_LINKS})
  neptus_set_warnings(${name})
endfunction()

# Fails configuring when any target of the table links what it may not.
function(neptus_check_layers)
  foreach(row ${NEPTUS_LAYERS})
    string(REGEX REPLACE " +" ";" row "${row}")
    list(GET row 0 name)
    if(NOT TARGET ${name})
      continue()
    endif()
    get_target_property(links ${name} LINK_LIBRARIES)
    neptus_layer_violations(${name} "${links}" bad)
    if(bad)
      message(FATAL_ERROR "${name} links ${bad}, which cmake/NeptusLayers.cmake does not allow it: "
                          "move the code, or change the table (and docs/architecture.md) on purpose")
    endif()
  endforeach()
endfunction()
