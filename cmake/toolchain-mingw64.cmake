# SPDX-License-Identifier: GPL-3.0-or-later
# Cross-compiling for 64-bit Windows with Debian's MinGW-w64 (g++-mingw-w64-x86-64),
# the `windows` preset in CMakePresets.json (docs/windows.md). The -posix
# compilers: Tactus uses std::thread and std::mutex, which GCC 12's win32
# thread model lacks. Libraries built for Windows are looked up under
# /usr/x86_64-w64-mingw32 and TACTUS_WINDOWS_DEPS (a prefix the third-party
# libraries are installed into); never in the build machine's own /usr.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(TACTUS_MINGW_TRIPLE x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${TACTUS_MINGW_TRIPLE}-gcc-posix)
set(CMAKE_CXX_COMPILER ${TACTUS_MINGW_TRIPLE}-g++-posix)
set(CMAKE_RC_COMPILER ${TACTUS_MINGW_TRIPLE}-windres)

set(TACTUS_WINDOWS_DEPS "$ENV{TACTUS_WINDOWS_DEPS}" CACHE PATH "Prefix holding the third-party libraries built for Windows")
set(CMAKE_FIND_ROOT_PATH /usr/${TACTUS_MINGW_TRIPLE} ${TACTUS_WINDOWS_DEPS})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# pkg-config reads the Windows libraries' .pc files only.
set(ENV{PKG_CONFIG_LIBDIR} "${TACTUS_WINDOWS_DEPS}/lib/pkgconfig:/usr/${TACTUS_MINGW_TRIPLE}/lib/pkgconfig")
set(ENV{PKG_CONFIG_SYSROOT_DIR} "")
# The third-party libraries are static: their own dependencies (libzip's zlib) come with them.
set(PKG_CONFIG_ARGN "--static" CACHE STRING "Arguments pkg-config is given")

# The executables carry libgcc, libstdc++, winpthread and zlib inside, so they
# run without MinGW's DLLs beside them.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")
# Tests run under Wine when one is installed.
find_program(TACTUS_WINE NAMES wine64 wine)
if(TACTUS_WINE)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${TACTUS_WINE})
endif()
