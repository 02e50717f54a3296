# The engine's dependencies for the cross builds, as a dependency provider (CMake 3.24+): the
# mingw-w64 build for Windows (issue 57: .ci/windows, with the toolchain cmake/mingw-w64-x86_64.cmake)
# and the WebAssembly build (issue 59: the "web" preset of CMakePresets.json, with Emscripten's
# toolchain) pass -DCMAKE_PROJECT_TOP_LEVEL_INCLUDES=cmake/cross-dependencies.cmake. Debian has no
# mingw or wasm builds of them, but the engine needs only headers: Eigen, Boost.Math and
# nlohmann-json are header-only, and tinyobjloader is one header that compiles its own
# implementation. Their Linux configs would put /usr/include on the include path, where glibc's C
# headers would shadow mingw's (or Emscripten's musl); so each gets a folder of its own holding a
# link to Debian's headers and nothing else. GoogleTest is the one .ci/windows built from Debian's
# source (/usr/src/googletest) into RBSIM_CROSS_GTEST_DIR. oneTBB has neither build: the engine
# uses its std::thread pool (RBSIM_WITH_TBB=OFF).
set(RBSIM_CROSS_HEADERS ${CMAKE_BINARY_DIR}/cross-headers)

# A folder <name>/ holding links to the given files or folders of /usr/include, for an interface
# target's include path.
function(rbsim_cross_headers name)
  set(folder ${RBSIM_CROSS_HEADERS}/${name})
  file(MAKE_DIRECTORY ${folder})
  foreach(entry ${ARGN})
    if(NOT EXISTS /usr/include/${entry})
      message(FATAL_ERROR "cmake/cross-dependencies.cmake: /usr/include/${entry} is missing (.ci/setup installs it)")
    endif()
    if(NOT EXISTS ${folder}/${entry})
      file(CREATE_LINK /usr/include/${entry} ${folder}/${entry} SYMBOLIC)
    endif()
  endforeach()
endfunction()

function(rbsim_cross_interface target folder)
  if(TARGET ${target})
    return()
  endif()
  add_library(${target} INTERFACE IMPORTED GLOBAL)
  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${RBSIM_CROSS_HEADERS}/${folder})
endfunction()

# tinyobjloader's implementation (TINYOBJLOADER_IMPLEMENTATION, doubles as Debian's
# tinyobjloader_double) compiled once at configure time into a static library of the build folder.
function(rbsim_cross_tinyobjloader)
  set(dir ${RBSIM_CROSS_HEADERS}/tinyobjloader)
  set(library ${dir}/libtinyobjloader_double.a)
  if(TARGET tinyobjloader::tinyobjloader_double)
    return()
  endif()
  if(NOT EXISTS ${library})
    file(WRITE ${dir}/tinyobjloader.cpp
         "#define TINYOBJLOADER_IMPLEMENTATION\n#define TINYOBJLOADER_USE_DOUBLE\n#include <tiny_obj_loader.h>\n")
    separate_arguments(flags UNIX_COMMAND "${CMAKE_CXX_FLAGS}")  # the build's own (Emscripten's -fexceptions)
    execute_process(COMMAND ${CMAKE_CXX_COMPILER} ${flags} -O2 -std=c++17 -I${dir} -c ${dir}/tinyobjloader.cpp -o ${dir}/tinyobjloader.o
                    COMMAND_ERROR_IS_FATAL ANY)
    execute_process(COMMAND ${CMAKE_AR} rcs ${library} ${dir}/tinyobjloader.o COMMAND_ERROR_IS_FATAL ANY)
  endif()
  add_library(tinyobjloader::tinyobjloader_double STATIC IMPORTED GLOBAL)
  set_target_properties(tinyobjloader::tinyobjloader_double PROPERTIES
                        IMPORTED_LOCATION ${library}
                        INTERFACE_INCLUDE_DIRECTORIES ${dir}
                        INTERFACE_COMPILE_DEFINITIONS TINYOBJLOADER_USE_DOUBLE)
endfunction()

macro(rbsim_cross_find_package method name)
  if("${name}" STREQUAL "Eigen3")
    # Its config points at /usr/include/eigen3, which holds Eigen alone.
    find_package(${name} ${ARGN} PATHS /usr/share/eigen3/cmake NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH BYPASS_PROVIDER)
    if(EMSCRIPTEN AND TARGET Eigen3::Eigen)
      # The same Eigen as x86-64's: its SSE2 kernels (quaternion product, packet sums), whose order
      # of operations the native build's results carry, compiled to wasm SIMD through Emscripten's
      # SSE headers, with 16-byte aligned fixed-size types as on x86-64 (Eigen turns both off for
      # an architecture it does not know). Eigen also includes MMX's <mmintrin.h>, which it never
      # uses and Emscripten does not have: an empty one stands in. Two of Eigen's GCC workarounds
      # are x86 assembly, which wasm cannot compile: SSE's min and max (for GCC before 6.3, and
      # clang calls itself GCC 4.2) and empty register hints in its matrix kernel (for GCC 6 and
      # later). As GCC 6.3 it takes the intrinsics for the first, as GCC 12 does natively, and the
      # hints (`__asm__("" : "+x,m" (A0))`, which compute nothing) are defined away. No other code
      # of the engine's, of Eigen's or of Emscripten's headers it includes writes __asm__.
      file(WRITE ${RBSIM_CROSS_HEADERS}/wasm-sse/mmintrin.h
           "// Empty: Eigen includes MMX's header but uses none of it (cmake/cross-dependencies.cmake).\n")
      set_property(TARGET Eigen3::Eigen APPEND PROPERTY INTERFACE_INCLUDE_DIRECTORIES ${RBSIM_CROSS_HEADERS}/wasm-sse)
      set_property(TARGET Eigen3::Eigen APPEND PROPERTY INTERFACE_COMPILE_OPTIONS -msimd128 -msse2 -fgnuc-version=6.3 "-D__asm__(...)=")
      set_property(TARGET Eigen3::Eigen APPEND PROPERTY INTERFACE_COMPILE_DEFINITIONS EIGEN_MAX_STATIC_ALIGN_BYTES=16)
    endif()
  elseif("${name}" STREQUAL "Boost")
    rbsim_cross_headers(boost boost)
    rbsim_cross_interface(Boost::headers boost)
    set(Boost_FOUND TRUE)
  elseif("${name}" STREQUAL "nlohmann_json")
    rbsim_cross_headers(nlohmann_json nlohmann)
    rbsim_cross_interface(nlohmann_json::nlohmann_json nlohmann_json)
    set(nlohmann_json_FOUND TRUE)
  elseif("${name}" STREQUAL "tinyobjloader")
    rbsim_cross_headers(tinyobjloader tiny_obj_loader.h)
    rbsim_cross_tinyobjloader()
    set(tinyobjloader_FOUND TRUE)
  elseif("${name}" STREQUAL "GTest")
    find_package(GTest CONFIG REQUIRED PATHS ${RBSIM_CROSS_GTEST_DIR} NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH BYPASS_PROVIDER)
  else()
    find_package(${name} ${ARGN} BYPASS_PROVIDER)
  endif()
endmacro()

cmake_language(SET_DEPENDENCY_PROVIDER rbsim_cross_find_package SUPPORTED_METHODS FIND_PACKAGE)
