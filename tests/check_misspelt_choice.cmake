# A misspelt choice does not compile (tests/compile_fail/misspelt_choice.cpp): the file compiles as it stands, so the
# kit's headers are fine, and fails with each misspelling, naming it. Syntax only: nothing is linked.
# cmake -DCXX=<compiler> -DROOT=<kit> [-DFLAGS=<flags;...>] -P check_misspelt_choice.cmake
set(source ${ROOT}/tests/compile_fail/misspelt_choice.cpp)
set(compile ${CXX} -std=c++17 -fsyntax-only ${FLAGS} -I${ROOT} ${source})
execute_process(COMMAND ${compile} RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "check_misspelt_choice: the file spelt right does not compile, so the check proves nothing:\n${err}")
endif()
foreach(case IN ITEMS "COMPARISON:Rk5" "CONDITION:Midpiont" "ONE_OF:Fiel" "WRONG_ENUM:ParticleScene")
  string(REPLACE ":" ";" case ${case})
  list(GET case 0 variant)
  list(GET case 1 named)
  execute_process(COMMAND ${CXX} -std=c++17 -fsyntax-only ${FLAGS} -DGSV_MISSPELT_${variant} -I${ROOT} ${source}
                  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
  if(rc EQUAL 0)
    message(FATAL_ERROR "check_misspelt_choice: ${variant}: a misspelt choice compiled")
  endif()
  if(NOT err MATCHES "${named}")
    message(FATAL_ERROR "check_misspelt_choice: ${variant}: the compiler refused it without naming '${named}':\n${err}")
  endif()
  message(STATUS "${variant}: refused, naming ${named}")
endforeach()
