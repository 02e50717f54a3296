# Cross-compiling for 64-bit Windows with Debian's mingw-w64 (issue 57): the "posix" thread model
# of g++-mingw-w64-x86-64-posix, whose libstdc++ has std::thread and std::mutex (the win32 model's
# has not). .ci/windows uses it with cmake/cross-dependencies.cmake, which finds the header-only
# dependencies in Debian's /usr/include without putting glibc's C headers before mingw's.
#   cmake -S . -B build-windows -DCMAKE_TOOLCHAIN_FILE=cmake/mingw-w64-x86_64.cmake ...
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(RBSIM_MINGW_TRIPLE x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${RBSIM_MINGW_TRIPLE}-gcc-posix)
set(CMAKE_CXX_COMPILER ${RBSIM_MINGW_TRIPLE}-g++-posix)
set(CMAKE_RC_COMPILER ${RBSIM_MINGW_TRIPLE}-windres)
# Libraries and packages come from mingw's own tree only; the programs run at build time are the
# machine's.
set(CMAKE_FIND_ROOT_PATH /usr/${RBSIM_MINGW_TRIPLE})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# The test programs are linked statically (libstdc++, libgcc, winpthread), so wine or a Windows
# machine runs them without mingw's DLLs beside them; and run under wine when it is installed
# (gtest_discover_tests lists each suite's tests at build time).
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")
find_program(RBSIM_WINE NAMES wine64 wine)
if(RBSIM_WINE)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${RBSIM_WINE})
endif()
