# The browser edition (scripts/kit web, the `web` preset): every lab built with Debian's Emscripten (em++ 3.1.6)
# from the same framework, lab.cpp and GLSL files as the native build, for WebGL 2 (OpenGL ES 3.0), into one
# static folder, build-web/site/. Included by the top-level CMakeLists.txt instead of the native build.
#
# Emscripten's cache is frozen on Debian (no ports download): GLFW, html5, embind and stb_image are there, zlib is
# not, so gzipped volumes are refused in the browser (support/volume/nifti_file.cpp says so in one line).
include(${CMAKE_CURRENT_LIST_DIR}/labs.cmake)

# What each lab's page reads beyond its own package (its folder, the shaders, its case file and golden images): the
# folders of data/ that its code or its cases open (a fixed data_file, a file parameter's default, the public and
# hidden cases' settings), each a package of its own in shared/ (below) that the browser fetches once and keeps for
# every page that reads it. Each lab says which in its lab.json ("data", GSV_LAB_DATA_<id>: cmake/lab_list.cmake). The
# page is told its list (data-packages in its HTML) and fetches only those (web/page/lab.js). A folder read but not
# declared stops the page's lab at "cannot find data file"; the web test's self-check draws every public case, so it
# would show.
# What every page reads whatever its lab: the font of the self-check's comparison labels (compose_comparison).
set(GSV_WEB_PAGE_PACKAGES font)

# Header-only libraries from Debian's /usr/include, reached through links of their own: the whole of /usr/include
# would put glibc's headers before Emscripten's libc.
set(GSV_WEB_INCLUDE ${CMAKE_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${GSV_WEB_INCLUDE})
foreach(header_dir glm nlohmann stb)
  find_path(GSV_WEB_${header_dir}_PARENT ${header_dir} PATHS /usr/include /usr/local/include NO_DEFAULT_PATH
            NO_CMAKE_FIND_ROOT_PATH)
  if(NOT GSV_WEB_${header_dir}_PARENT)
    message(FATAL_ERROR "the web build needs ${header_dir}'s headers in /usr/include (scripts/setup.sh installs them)")
  endif()
  if(NOT EXISTS ${GSV_WEB_INCLUDE}/${header_dir})
    file(CREATE_LINK ${GSV_WEB_${header_dir}_PARENT}/${header_dir} ${GSV_WEB_INCLUDE}/${header_dir} SYMBOLIC)
  endif()
endforeach()

set(GSV_WEB_FLAGS -fexceptions)
add_compile_options(${GSV_WEB_FLAGS})

add_subdirectory(third_party/glad)

# The framework without what a browser has no use for: EGL, OSMesa and GLFW contexts, the window mode and its panel,
# child processes. The web mode (common/app/app_web.cpp) and the WebGL context take their place.
file(GLOB_RECURSE GSV_COMMON_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/common/*.cpp)
list(FILTER GSV_COMMON_SOURCES EXCLUDE REGEX
     "context/context_(egl|osmesa|glfw)\\.cpp$|/window/(image_view|window_panel|legend)|app/(app_window|window_reference|subprocess|app_compare|reference_image)\\.cpp$")
add_library(gsv_common STATIC ${GSV_COMMON_SOURCES})
target_include_directories(gsv_common PUBLIC ${PROJECT_SOURCE_DIR} ${GSV_WEB_INCLUDE} ${GSV_WEB_INCLUDE}/stb)
target_link_libraries(gsv_common PUBLIC glad)
target_compile_definitions(gsv_common PUBLIC GLM_FORCE_CTOR_INIT GSV_WEB=1 PRIVATE GSV_SOURCE_ROOT="/kit")
set_source_files_properties(${PROJECT_SOURCE_DIR}/common/core/version.cpp PROPERTIES COMPILE_DEFINITIONS GSV_VERSION="${PROJECT_VERSION}")
target_compile_options(gsv_common PRIVATE -Wall -Wextra)

file(GLOB_RECURSE GSV_SUPPORT_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/support/*.cpp)
add_library(gsv_support STATIC ${GSV_SUPPORT_SOURCES})
target_link_libraries(gsv_support PUBLIC gsv_common)
target_compile_options(gsv_support PRIVATE -Wall -Wextra)

# The grader's part of the page: its lowest floor (grader/src/core/), its case files, comparison, verdicts and table, and
# the self-check that runs them in the page (grader/src/app/page_self_check.cpp). Not the grader's processes or sandbox:
# the page grades nothing of anyone else's.
file(GLOB GSV_GRADER_CORE_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/grader/src/core/*.cpp)
add_library(gsv_grader_page STATIC ${GSV_GRADER_CORE_SOURCES}
  ${PROJECT_SOURCE_DIR}/grader/src/cases/cases.cpp ${PROJECT_SOURCE_DIR}/grader/src/cases/draw.cpp
  ${PROJECT_SOURCE_DIR}/grader/src/cases/case_row.cpp
  ${PROJECT_SOURCE_DIR}/grader/src/judge/array_compare.cpp ${PROJECT_SOURCE_DIR}/grader/src/judge/image_verdict.cpp
  ${PROJECT_SOURCE_DIR}/grader/src/judge/needs.cpp ${PROJECT_SOURCE_DIR}/grader/src/report/report_table.cpp
  ${PROJECT_SOURCE_DIR}/grader/src/report/report_format.cpp
  ${PROJECT_SOURCE_DIR}/grader/src/diagnose/ranking.cpp ${PROJECT_SOURCE_DIR}/grader/src/diagnose/shipped_diagnosis.cpp)
target_link_libraries(gsv_grader_page PUBLIC gsv_common)
target_compile_options(gsv_grader_page PRIVATE -Wall -Wextra)
# Compiled once for every page (an object library: its EMSCRIPTEN_BINDINGS would be dropped from a static one).
add_library(gsv_page_self_check OBJECT ${PROJECT_SOURCE_DIR}/grader/src/app/page_self_check.cpp)
target_link_libraries(gsv_page_self_check PUBLIC gsv_grader_page)
set(GSV_WEB_PAGE_SOURCES $<TARGET_OBJECTS:gsv_page_self_check>)
set(GSV_WEB_PAGE_LIBRARIES gsv_grader_page)
# compare's composite writes its labels in the kit's font (common/image/ui_font.cpp), at the path it has on Debian.
find_file(GSV_WEB_FONT DejaVuSans.ttf PATHS /usr/share/fonts/truetype/dejavu NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
if(NOT GSV_WEB_FONT)
  message(FATAL_ERROR "the web pages' comparison labels need DejaVu Sans: apt-get install fonts-dejavu-core")
endif()

# Each lab's page: <id>.js, <id>.wasm and <id>.data, the files the lab reads preloaded at the paths the native kit
# has them (the lab's folder, shaders/, its case file and golden images), under /kit, the kit's root there; what it
# reads of data/ comes from the shared packages (below).
# The site gets the student's copy (labs/, the starters: no answer is shipped); the reference solutions are built
# beside it in build-web/lecturer/, the lecturer's site (every page says it is never to be published to students),
# which the tests use too.
set(GSV_WEB_SITE ${CMAKE_BINARY_DIR}/site)
set(GSV_WEB_LECTURER ${CMAKE_BINARY_DIR}/lecturer)
# FULL_ES3: glMapBufferRange for writing (lab 05 writes its particles the seed's way), which WebGL 2 lacks.
set(GSV_WEB_LINK_FLAGS -fexceptions -lembind -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2 -sFULL_ES3=1 -sALLOW_MEMORY_GROWTH=1
    -sFORCE_FILESYSTEM=1 -sENVIRONMENT=web -sINVOKE_RUN=0 --profiling-funcs "-sEXPORTED_RUNTIME_METHODS=[FS,callMain]")

function(gsv_add_web_lab id dir)
  # A lab's C++ files that are the same in labs/ and solutions/ (all but the TODOs in C++, L03-T1 and L05-T1) are
  # compiled once for both pages; lab.cpp is compiled per page (it names its folder). A change to one of them
  # reconfigures, so that the two are compared again.
  file(GLOB solution_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/solutions/${dir}/*.cpp)
  set(shared_sources)
  foreach(source ${solution_sources})
    get_filename_component(name ${source} NAME)
    set(starter_source ${PROJECT_SOURCE_DIR}/labs/${dir}/${name})
    if(NOT name STREQUAL "lab.cpp" AND EXISTS ${starter_source})
      set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${source} ${starter_source})
      file(SHA256 ${source} solution_hash)
      file(SHA256 ${starter_source} starter_hash)
      if(solution_hash STREQUAL starter_hash)
        list(APPEND shared_sources ${source})
      endif()
    endif()
  endforeach()
  set(shared_objects)
  if(shared_sources)
    add_library(${id}_web_shared OBJECT ${shared_sources})
    target_link_libraries(${id}_web_shared PUBLIC gsv_support)
    set(shared_objects $<TARGET_OBJECTS:${id}_web_shared>)
  endif()
  foreach(variant starter solution)
    if(variant STREQUAL "starter")
      set(src labs/${dir})
      set(target ${id}_web)
      set(out ${GSV_WEB_SITE}/${id})
    else()
      set(src solutions/${dir})
      set(target ${id}_solution_web)
      set(out ${GSV_WEB_LECTURER}/${id})
    endif()
    file(GLOB lab_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${src}/*.cpp)
    if(NOT lab_sources)
      continue()
    endif()
    foreach(source ${shared_sources})
      get_filename_component(name ${source} NAME)
      list(REMOVE_ITEM lab_sources ${PROJECT_SOURCE_DIR}/${src}/${name})
    endforeach()
    file(GLOB_RECURSE preloaded CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${src}/* ${PROJECT_SOURCE_DIR}/shaders/*
         ${PROJECT_SOURCE_DIR}/grader/golden/${id}/*)
    add_executable(${target} ${lab_sources} ${shared_objects} ${GSV_WEB_PAGE_SOURCES})
    target_link_libraries(${target} PRIVATE gsv_support ${GSV_WEB_PAGE_LIBRARIES})
    target_compile_definitions(${target} PRIVATE GSV_LAB_DIR="${src}" GSV_LAB_VARIANT="${variant}")
    set(preload)
    # data/ and the font are the shared packages' (below), not each lab's.
    foreach(path ${src} shaders grader/cases/${id}.json grader/golden/${id})
      # SHELL: keeps each option with its value (CMake removes repeated options otherwise).
      list(APPEND preload "SHELL:--preload-file ${PROJECT_SOURCE_DIR}/${path}@/kit/${path}")
    endforeach()
    target_link_options(${target} PRIVATE ${GSV_WEB_LINK_FLAGS} ${preload})
    set_target_properties(${target} PROPERTIES OUTPUT_NAME ${id} SUFFIX ".js" RUNTIME_OUTPUT_DIRECTORY ${out}
                          LINK_DEPENDS "${preloaded};${PROJECT_SOURCE_DIR}/grader/cases/${id}.json")
  endforeach()
endfunction()

foreach(lab IN LISTS GSV_LAB_LIST)
  string(REPLACE ":" ";" lab_pair ${lab})
  gsv_add_web_lab(${lab_pair})
endforeach()

# The packages the pages share, in shared/: one per folder of data/ (flows, meshes, terrain, volumes, images) and one
# for the font, so that a page fetches only what its lab reads (GSV_LAB_DATA_<id>, above) and the browser's cache keeps
# each for every later page that reads it, not again inside each lab's own package. data/README.md is in none: the
# labs never open it. Each package is a .data file and the .js that fetches it and puts its files in the lab's file
# system, at the paths the native kit has them.
find_file(GSV_FILE_PACKAGER file_packager.py PATHS /usr/share/emscripten/tools ${EMSCRIPTEN_ROOT_PATH}/tools
          NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
if(NOT GSV_FILE_PACKAGER)
  message(FATAL_ERROR "the web pages' shared data packages need Emscripten's tools/file_packager.py (apt-get install emscripten)")
endif()
find_package(Python3 REQUIRED COMPONENTS Interpreter)
set(GSV_WEB_SHARED ${GSV_WEB_SITE}/shared)
file(MAKE_DIRECTORY ${GSV_WEB_SHARED})
set(GSV_WEB_PACKAGES)
set(GSV_WEB_PACKAGE_FILES)
# name: the package (shared/<name>.data and shared/<name>.js); preload: what it holds, as file_packager's
# SOURCE@PATH; inputs: the files it is made from.
function(gsv_add_web_package name preload inputs)
  set(outputs ${GSV_WEB_SHARED}/${name}.data ${GSV_WEB_SHARED}/${name}.js)
  add_custom_command(OUTPUT ${outputs}
    COMMAND ${Python3_EXECUTABLE} ${GSV_FILE_PACKAGER} ${name}.data --preload ${preload} --js-output=${name}.js
    DEPENDS ${inputs}
    WORKING_DIRECTORY ${GSV_WEB_SHARED}
    COMMENT "the pages' shared package ${name} into ${GSV_WEB_SHARED}")
  set(GSV_WEB_PACKAGES ${GSV_WEB_PACKAGES} ${name} PARENT_SCOPE)
  set(GSV_WEB_PACKAGE_FILES ${GSV_WEB_PACKAGE_FILES} ${outputs} PARENT_SCOPE)
endfunction()
file(GLOB data_entries LIST_DIRECTORIES true CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/data/*)
foreach(entry ${data_entries})
  if(IS_DIRECTORY ${entry})
    get_filename_component(folder ${entry} NAME)
    file(GLOB_RECURSE folder_files CONFIGURE_DEPENDS ${entry}/*)
    gsv_add_web_package(${folder} ${entry}@/kit/data/${folder} "${folder_files}")
  endif()
endforeach()
gsv_add_web_package(font ${GSV_WEB_FONT}@${GSV_WEB_FONT} ${GSV_WEB_FONT})
# Each lab's list: declared, and of packages there are (a misspelt folder would be a page that never starts).
foreach(lab IN LISTS GSV_LAB_LIST)
  string(REPLACE ":" ";" lab_pair ${lab})
  list(GET lab_pair 0 id)
  foreach(package ${GSV_LAB_DATA_${id}} ${GSV_WEB_PAGE_PACKAGES})
    if(NOT package IN_LIST GSV_WEB_PACKAGES)
      message(FATAL_ERROR "${id} reads the package '${package}' (its lab.json's data), which is none of data/'s folders nor the font: "
                          "${GSV_WEB_PACKAGES}")
    endif()
  endforeach()
endforeach()
add_custom_target(web_shared_data ALL DEPENDS ${GSV_WEB_PACKAGE_FILES}
  COMMAND ${CMAKE_COMMAND} -E copy_directory ${GSV_WEB_SHARED} ${GSV_WEB_LECTURER}/shared)

# The site: an index (each lab with a picture, its first case's golden image, and its title), a page per lab, the
# pages' JavaScript and CSS (web/page/), and the editor and zip code from Debian and npm, copied as they come.
find_path(GSV_CODEMIRROR_DIR lib/codemirror.js PATHS /usr/share/javascript/codemirror NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
find_path(GSV_JSZIP_DIR jszip.min.js PATHS ${PROJECT_SOURCE_DIR}/web/node_modules/jszip/dist NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
find_path(GSV_MARKED_DIR marked.min.js PATHS ${PROJECT_SOURCE_DIR}/web/node_modules/marked NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
if(NOT GSV_CODEMIRROR_DIR)
  message(FATAL_ERROR "the web pages' editor is Debian's CodeMirror: apt-get install libjs-codemirror (scripts/kit web does)")
endif()
if(NOT GSV_JSZIP_DIR)
  message(FATAL_ERROR "the web pages' download and open use JSZip from npm: npm ci --prefix web (scripts/kit web does)")
endif()
if(NOT GSV_MARKED_DIR)
  message(FATAL_ERROR "the web pages' lab sheet is rendered by marked from npm: npm ci --prefix web (scripts/kit web does)")
endif()

# The lecturer's pages say, on each, what they are: the answers to every TODO. The student edition has no solutions/,
# so no lecturer's site.
set(GSV_WEB_HAS_LECTURER OFF)
if(EXISTS ${PROJECT_SOURCE_DIR}/solutions)
  set(GSV_WEB_HAS_LECTURER ON)
endif()
set(GSV_LECTURER_NOTE "<p class=\"lecturer-note\" role=\"note\">The lecturer's site: the reference solutions, to show in lectures. Never publish it where students can reach it: it holds the answer to every TODO (the students' site is build-web/site/).</p>")
set(GSV_WEB_INDEX_ENTRIES "")
foreach(lab IN LISTS GSV_LAB_LIST)
  string(REPLACE ":" ";" lab_pair ${lab})
  list(GET lab_pair 0 id)
  list(GET lab_pair 1 dir)
  file(STRINGS ${PROJECT_SOURCE_DIR}/labs/${dir}/README.md title LIMIT_COUNT 1)
  string(REGEX REPLACE "^# *" "" GSV_LAB_TITLE "${title}")
  set(GSV_LAB_ID ${id})
  set(packages ${GSV_LAB_DATA_${id}} ${GSV_WEB_PAGE_PACKAGES})
  list(JOIN packages " " GSV_LAB_PACKAGES)
  # What the page fetches before its lab can start, asked for as the page opens rather than when lab.js gets to it
  # (measured: lab 05's .data and .wasm began about 0.7 s into the page, after its scripts and the packages' loaders).
  set(GSV_LAB_PRELOADS "<link rel=\"preload\" href=\"${id}.wasm\" as=\"fetch\" crossorigin>\n<link rel=\"preload\" href=\"${id}.data\" as=\"fetch\" crossorigin>")
  foreach(package IN LISTS packages)
    string(APPEND GSV_LAB_PRELOADS "\n<link rel=\"preload\" href=\"../shared/${package}.data\" as=\"fetch\" crossorigin>")
  endforeach()
  string(SUBSTRING ${id} 3 2 number)
  file(GLOB deck RELATIVE ${PROJECT_SOURCE_DIR}/slides ${PROJECT_SOURCE_DIR}/slides/${number}-*.md)
  string(REGEX REPLACE "\\.md$" "" GSV_LAB_DECK "${deck}")
  set(GSV_SITE_NOTE "")
  configure_file(${PROJECT_SOURCE_DIR}/web/lab.html.in ${GSV_WEB_SITE}/${id}/index.html @ONLY)
  # The lab sheet beside the editor (web/page/sheet.js): the student's in the site, the solution's in the lecturer's.
  configure_file(${PROJECT_SOURCE_DIR}/labs/${dir}/README.md ${GSV_WEB_SITE}/${id}/README.md COPYONLY)
  file(READ ${PROJECT_SOURCE_DIR}/grader/cases/${id}.json cases_json)
  string(JSON first_case GET "${cases_json}" cases 0 name)
  configure_file(${PROJECT_SOURCE_DIR}/grader/golden/${id}/${first_case}.png ${GSV_WEB_SITE}/${id}/picture.png COPYONLY)
  if(GSV_WEB_HAS_LECTURER)
    set(GSV_SITE_NOTE "${GSV_LECTURER_NOTE}")
    configure_file(${PROJECT_SOURCE_DIR}/web/lab.html.in ${GSV_WEB_LECTURER}/${id}/index.html @ONLY)
    configure_file(${PROJECT_SOURCE_DIR}/solutions/${dir}/README.md ${GSV_WEB_LECTURER}/${id}/README.md COPYONLY)
    configure_file(${PROJECT_SOURCE_DIR}/grader/golden/${id}/${first_case}.png ${GSV_WEB_LECTURER}/${id}/picture.png COPYONLY)
  endif()
  string(APPEND GSV_WEB_INDEX_ENTRIES
         "<a href=\"${id}/index.html\"><img src=\"${id}/picture.png\" alt=\"${id}'s case ${first_case}\"><strong>${GSV_LAB_TITLE}</strong></a>\n")
endforeach()
set(GSV_SITE_NOTE "")
configure_file(${PROJECT_SOURCE_DIR}/web/index.html.in ${GSV_WEB_SITE}/index.html @ONLY)
if(GSV_WEB_HAS_LECTURER)
  set(GSV_SITE_NOTE "${GSV_LECTURER_NOTE}")
  configure_file(${PROJECT_SOURCE_DIR}/web/index.html.in ${GSV_WEB_LECTURER}/index.html @ONLY)
endif()

add_custom_target(web_site ALL
  COMMAND ${CMAKE_COMMAND} -E copy_directory ${PROJECT_SOURCE_DIR}/web/page ${GSV_WEB_SITE}/page
  COMMAND ${CMAKE_COMMAND} -E copy_directory ${PROJECT_SOURCE_DIR}/web/page ${GSV_WEB_LECTURER}/page
  COMMAND ${CMAKE_COMMAND} -E make_directory ${GSV_WEB_SITE}/vendor/codemirror
  COMMAND ${CMAKE_COMMAND} -E copy ${GSV_CODEMIRROR_DIR}/lib/codemirror.js ${GSV_CODEMIRROR_DIR}/lib/codemirror.css
          ${GSV_CODEMIRROR_DIR}/mode/clike/clike.js ${GSV_WEB_SITE}/vendor/codemirror/
  COMMAND ${CMAKE_COMMAND} -E copy ${GSV_JSZIP_DIR}/jszip.min.js ${GSV_MARKED_DIR}/marked.min.js ${GSV_WEB_SITE}/vendor/
  COMMAND ${CMAKE_COMMAND} -E copy_directory ${GSV_WEB_SITE}/vendor ${GSV_WEB_LECTURER}/vendor
  COMMENT "the web pages' scripts, styles and editor into ${GSV_WEB_SITE}")
