# The kit's own code compiles with the compiler's warnings on: the framework, the domain code, the reference, the
# grader, the tools, the labs as the kit builds them, and the tests. A switch over an enum without a default names
# every case, so a value added to the enum and missed in a switch is a warning (-Wswitch, in -Wall).
#
# GSV_WERROR turns them into errors: CI's build only (.ci/run). Never by default, and never in the grader's build of a
# submission (grader/submission, which does not include this file): another compiler may warn where ours does not,
# and a student's lab must not fail to build over a warning.
option(GSV_WERROR "Make the kit's own warnings errors (CI)" OFF)

function(gsv_warnings target)
  if(MSVC)
    target_compile_options(${target} PRIVATE /W4 $<$<BOOL:${GSV_WERROR}>:/WX>)
  else()
    target_compile_options(${target} PRIVATE -Wall -Wextra $<$<BOOL:${GSV_WERROR}>:-Werror>)
  endif()
endfunction()
