# Every lab is built twice from the same framework: the student's work in labs/<dir> (as shipped: the
# starter generated from the solution) as <id>, and the reference in solutions/<dir> as <id>_solution.
# grader/submission reuses this with GSV_LABS_ROOT at a submission and only the starter variant.
# The labs are the kit's folders (cmake/lab_list.cmake), each with its description (lab.json), read here for the tests
# and the web edition. The grader's build of a submission, whose walls hide the kit's lab folders, takes the list the
# kit's build wrote (GSV_KIT_LAB_LIST, gsv-build-settings.cmake): the kit's labs, never a folder a submission adds.
include(${CMAKE_CURRENT_LIST_DIR}/lab_list.cmake)
get_filename_component(GSV_KIT_ROOT ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)
if(DEFINED GSV_KIT_LAB_LIST)
  set(GSV_LAB_LIST ${GSV_KIT_LAB_LIST})
else()
  gsv_lab_list(${GSV_KIT_ROOT} GSV_LAB_LIST)
  foreach(lab IN LISTS GSV_LAB_LIST)
    string(REPLACE ":" ";" lab_pair ${lab})
    gsv_lab_description(${GSV_KIT_ROOT} ${lab_pair})
  endforeach()
endif()

set(GSV_LABS "" CACHE INTERNAL "")
if(NOT DEFINED GSV_LABS_ROOT)
  set(GSV_LABS_ROOT ${PROJECT_SOURCE_DIR})
endif()
if(NOT DEFINED GSV_LAB_VARIANTS)
  set(GSV_LAB_VARIANTS starter solution)
endif()
if(NOT DEFINED GSV_LAB_LIBRARY)
  set(GSV_LAB_LIBRARY gsv_support)  # the framework in common/ comes with it
endif()

# The lab's known C++ mistakes in one build, <id>_mistakes (tools/known_mistake_switch.cpp): the reference with each C++
# TODO block switched at run time, so the grader's diagnosis renders each mistake's pictures with GSV_KNOWN_MISTAKE set
# (grader/src/grade/mistake_pictures.cpp). Only where the instructor's lists are (tests/mutants/<id>.json, so not in the
# student edition) and they hold C++ mistakes. Not in a cross-build (Windows with mingw-w64): its sources are written by
# gsv-make-starters, a program of that build the host cannot run, and the grader that uses them is Linux's.
function(gsv_add_lab_mistakes id dir)
  if(CMAKE_CROSSCOMPILING)
    return()
  endif()
  set(list ${PROJECT_SOURCE_DIR}/tests/mutants/${id}.json)
  if(NOT "solution" IN_LIST GSV_LAB_VARIANTS OR NOT EXISTS ${list} OR NOT EXISTS ${GSV_LABS_ROOT}/solutions/${dir})
    return()
  endif()
  file(READ ${list} spec)
  string(JSON count ERROR_VARIABLE none LENGTH "${spec}" cpp_mutants)
  if(none OR count EQUAL 0)
    return()
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${list})
  file(GLOB solution_files CONFIGURE_DEPENDS ${GSV_LABS_ROOT}/solutions/${dir}/*)
  set(out ${CMAKE_BINARY_DIR}/mistakes/${dir})
  set(written ${out}/known_mistake_switch.cpp)
  foreach(file IN LISTS solution_files)
    get_filename_component(name ${file} NAME)
    list(APPEND written ${out}/${name})
  endforeach()
  add_custom_command(OUTPUT ${written}
    COMMAND gsv-make-starters --root ${PROJECT_SOURCE_DIR} --mistakes ${id} --to ${out}
    DEPENDS gsv-make-starters ${solution_files} ${list}
    COMMENT "${id}'s known C++ mistakes switched into ${out}")
  set(sources ${written})
  list(FILTER sources INCLUDE REGEX "\\.cpp$")
  add_executable(${id}_mistakes ${sources})
  target_link_libraries(${id}_mistakes PRIVATE ${GSV_LAB_LIBRARY})
  target_compile_definitions(${id}_mistakes PRIVATE GSV_LAB_DIR="solutions/${dir}" GSV_LAB_VARIANT="solution")
  set_target_properties(${id}_mistakes PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin)
  if(COMMAND gsv_warnings)
    gsv_warnings(${id}_mistakes)
  endif()
endfunction()

function(gsv_add_lab id dir)
  foreach(variant IN LISTS GSV_LAB_VARIANTS)
    if(variant STREQUAL "starter")
      set(src labs/${dir})
      set(target ${id})
    else()
      set(src solutions/${dir})
      set(target ${id}_solution)
    endif()
    # The grader's build of a submission globs once: its sources do not change under it, and each lab is built where
    # only its own folder is there to see (a check of every glob at each build would configure again without the rest).
    if(GSV_GLOB_ONCE)
      file(GLOB lab_sources ${GSV_LABS_ROOT}/${src}/*.cpp)
    else()
      file(GLOB lab_sources CONFIGURE_DEPENDS ${GSV_LABS_ROOT}/${src}/*.cpp)
    endif()
    if(NOT lab_sources)
      # A lab whose starter has not been generated yet: the rest of the kit configures and builds without it.
      if(variant STREQUAL "starter" AND EXISTS ${GSV_LABS_ROOT}/solutions/${dir} AND NOT GSV_GLOB_ONCE)
        message(WARNING "${id}: no starter yet in labs/${dir}/, so no ${id} target: generate it from solutions/${dir}/ "
                        "with `scripts/kit starters` (build/bin/gsv-make-starters --write), which configures again")
      endif()
      continue()
    endif()
    add_executable(${target} ${lab_sources})
    target_link_libraries(${target} PRIVATE ${GSV_LAB_LIBRARY})
    target_compile_definitions(${target} PRIVATE GSV_LAB_DIR="${src}" GSV_LAB_VARIANT="${variant}")
    set_target_properties(${target} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin)
    # The kit's own build warns (cmake/warnings.cmake); the grader's build of a submission has no gsv_warnings and
    # adds no flags: a student's build log holds what the compiler must say, and no warning can fail it.
    if(COMMAND gsv_warnings)
      gsv_warnings(${target})
    endif()
    # The reference's sweeps follow the instructor's sweep plan, reference/<dir>/sweep_plan.cpp (common/app/sweep_plan.h),
    # with its measuring code beside it (which includes the lab's headers, its SweepView among them) and the CPU
    # yardsticks of gsv_reference. None of it is in the student edition or the grader's submission build; there, and
    # for a lab with no plan, the lab's sweeps take the default plan (GSV_HAVE_REFERENCE undefined, common/app/app.h).
    if(variant STREQUAL "solution" AND TARGET gsv_reference AND EXISTS ${PROJECT_SOURCE_DIR}/reference/${dir}/sweep_plan.cpp)
      file(GLOB reference_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/reference/${dir}/*.cpp)
      target_sources(${target} PRIVATE ${reference_sources})
      target_include_directories(${target} PRIVATE ${GSV_LABS_ROOT}/${src})
      target_link_libraries(${target} PRIVATE gsv_reference)
      target_compile_definitions(${target} PRIVATE GSV_HAVE_REFERENCE=1)
    endif()
  endforeach()
  gsv_add_lab_mistakes(${id} ${dir})
  set(GSV_LABS ${GSV_LABS} ${id} CACHE INTERNAL "")
  set(GSV_LAB_DIR_${id} ${dir} CACHE INTERNAL "")
endfunction()

# The list as the build has it, for the tests to read when they run (tests/lab_runner.h): written only when it
# changes, so a lab added relinks the tests (their list of tests is made from it) and recompiles none.
function(gsv_write_lab_list file)
  gsv_lab_list_json(${GSV_KIT_ROOT} json)
  set(old "")
  if(EXISTS ${file})
    file(READ ${file} old)
  endif()
  if(NOT old STREQUAL json)
    file(WRITE ${file} "${json}")
  endif()
endfunction()
