# The engine's dependencies for the mingw-w64 cross build (issue 57), as a dependency provider
# (CMake 3.24+): .ci/windows passes -DCMAKE_PROJECT_TOP_LEVEL_INCLUDES=cmake/windows-dependencies.cmake
# with the toolchain cmake/mingw-w64-x86_64.cmake. Debian has no mingw builds of them, but the
# engine needs only headers: Eigen, Boost.Math and nlohmann-json are header-only, and tinyobjloader
# is one header that compiles its own implementation. Their Linux configs would put /usr/include on
# the include path, where glibc's C headers would shadow mingw's; so each gets a folder of its own
# holding a link to Debian's headers and nothing else. GoogleTest is the one .ci/windows built
# from Debian's source (/usr/src/googletest) into RBSIM_WINDOWS_GTEST_DIR. oneTBB has no mingw build:
# the engine uses its std::thread pool (RBSIM_WITH_TBB=OFF).
set(RBSIM_WINDOWS_HEADERS ${CMAKE_BINARY_DIR}/windows-headers)

# A folder <name>/ holding links to the given files or folders of /usr/include, for an interface
# target's include path.
function(rbsim_windows_headers name)
  set(folder ${RBSIM_WINDOWS_HEADERS}/${name})
  file(MAKE_DIRECTORY ${folder})
  foreach(entry ${ARGN})
    if(NOT EXISTS /usr/include/${entry})
      message(FATAL_ERROR "cmake/windows-dependencies.cmake: /usr/include/${entry} is missing (.ci/setup installs it)")
    endif()
    if(NOT EXISTS ${folder}/${entry})
      file(CREATE_LINK /usr/include/${entry} ${folder}/${entry} SYMBOLIC)
    endif()
  endforeach()
endfunction()

function(rbsim_windows_interface target folder)
  if(TARGET ${target})
    return()
  endif()
  add_library(${target} INTERFACE IMPORTED GLOBAL)
  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${RBSIM_WINDOWS_HEADERS}/${folder})
endfunction()

# tinyobjloader's implementation (TINYOBJLOADER_IMPLEMENTATION, doubles as Debian's
# tinyobjloader_double) compiled once at configure time into a static library of the build folder.
function(rbsim_windows_tinyobjloader)
  set(dir ${RBSIM_WINDOWS_HEADERS}/tinyobjloader)
  set(library ${dir}/libtinyobjloader_double.a)
  if(TARGET tinyobjloader::tinyobjloader_double)
    return()
  endif()
  if(NOT EXISTS ${library})
    file(WRITE ${dir}/tinyobjloader.cpp
         "#define TINYOBJLOADER_IMPLEMENTATION\n#define TINYOBJLOADER_USE_DOUBLE\n#include <tiny_obj_loader.h>\n")
    execute_process(COMMAND ${CMAKE_CXX_COMPILER} -O2 -std=c++17 -I${dir} -c ${dir}/tinyobjloader.cpp -o ${dir}/tinyobjloader.o
                    COMMAND_ERROR_IS_FATAL ANY)
    execute_process(COMMAND ${CMAKE_AR} rcs ${library} ${dir}/tinyobjloader.o COMMAND_ERROR_IS_FATAL ANY)
  endif()
  add_library(tinyobjloader::tinyobjloader_double STATIC IMPORTED GLOBAL)
  set_target_properties(tinyobjloader::tinyobjloader_double PROPERTIES
                        IMPORTED_LOCATION ${library}
                        INTERFACE_INCLUDE_DIRECTORIES ${dir}
                        INTERFACE_COMPILE_DEFINITIONS TINYOBJLOADER_USE_DOUBLE)
endfunction()

macro(rbsim_windows_find_package method name)
  if("${name}" STREQUAL "Eigen3")
    # Its config points at /usr/include/eigen3, which holds Eigen alone.
    find_package(${name} ${ARGN} PATHS /usr/share/eigen3/cmake NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH BYPASS_PROVIDER)
  elseif("${name}" STREQUAL "Boost")
    rbsim_windows_headers(boost boost)
    rbsim_windows_interface(Boost::headers boost)
    set(Boost_FOUND TRUE)
  elseif("${name}" STREQUAL "nlohmann_json")
    rbsim_windows_headers(nlohmann_json nlohmann)
    rbsim_windows_interface(nlohmann_json::nlohmann_json nlohmann_json)
    set(nlohmann_json_FOUND TRUE)
  elseif("${name}" STREQUAL "tinyobjloader")
    rbsim_windows_headers(tinyobjloader tiny_obj_loader.h)
    rbsim_windows_tinyobjloader()
    set(tinyobjloader_FOUND TRUE)
  elseif("${name}" STREQUAL "GTest")
    find_package(GTest CONFIG REQUIRED PATHS ${RBSIM_WINDOWS_GTEST_DIR} NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH BYPASS_PROVIDER)
  else()
    find_package(${name} ${ARGN} BYPASS_PROVIDER)
  endif()
endmacro()

cmake_language(SET_DEPENDENCY_PROVIDER rbsim_windows_find_package SUPPORTED_METHODS FIND_PACKAGE)
