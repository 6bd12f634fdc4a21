# What the framework links against. Included by the kit and by grader/submission, which links the
# kit's exported gsv::common and so must find the same libraries.
find_package(glfw3 3.3 REQUIRED)
find_package(glm REQUIRED)
find_package(ZLIB REQUIRED)  # gzipped volumes (.nii.gz)
find_package(nlohmann_json 3.9 REQUIRED)  # JSON files (header-only; 3.9 brought ordered_json)
find_package(OpenGL REQUIRED COMPONENTS OpenGL OPTIONAL_COMPONENTS EGL)
find_path(STB_INCLUDE_DIR stb_image.h PATH_SUFFIXES stb REQUIRED)

# OSMesa is a fallback headless backend, compiled in only where the library is found
# (Mesa dropped it in 25.1, and macOS and Windows never had it).
find_path(OSMESA_INCLUDE_DIR GL/osmesa.h)
find_library(OSMESA_LIBRARY OSMesa)
if(OSMESA_INCLUDE_DIR AND OSMESA_LIBRARY)
  set(GSV_HAVE_OSMESA ON)
else()
  set(GSV_HAVE_OSMESA OFF)
endif()
if(TARGET OpenGL::EGL)
  set(GSV_HAVE_EGL ON)
else()
  set(GSV_HAVE_EGL OFF)
endif()

# Dear ImGui by its CMake config where the package ships one (vcpkg's port: imgui::imgui, its GLFW and OpenGL 3
# bindings inside), else by pkg-config (Debian's libimgui-dev ships no CMake config). GSV_IMGUI_TARGET is what links it.
set(GSV_HAVE_IMGUI OFF)
if(GSV_WITH_IMGUI)
  find_package(imgui CONFIG QUIET)
  if(TARGET imgui::imgui)
    set(GSV_HAVE_IMGUI ON)
    set(GSV_IMGUI_TARGET imgui::imgui)
  else()
    find_package(PkgConfig QUIET)
    if(PkgConfig_FOUND)
      pkg_check_modules(IMGUI QUIET IMPORTED_TARGET imgui)
      if(IMGUI_FOUND)
        set(GSV_HAVE_IMGUI ON)
        set(GSV_IMGUI_TARGET PkgConfig::IMGUI)
      endif()
    endif()
  endif()
endif()
