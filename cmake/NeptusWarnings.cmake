# neptus_set_warnings(TARGET): the project's warning flags for a target's own code.
function(neptus_set_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wimplicit-fallthrough
    $<$<COMPILE_LANGUAGE:CXX>:-Wnon-virtual-dtor -Woverloaded-virtual>
    $<$<BOOL:${NEPTUS_WERROR}>:-Werror>)
endfunction()
