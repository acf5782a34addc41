# Cross-compiling Proxima for 64-bit Windows with MinGW-w64 (docs/install.md,
# "Windows"): cmake -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/mingw-w64-x86_64.cmake
#
# The POSIX-threads flavour of the compilers (Debian:
# g++-mingw-w64-x86-64-posix), which std::thread needs. Libraries are searched
# for only under the MinGW-w64 sysroot and the roots given in
# CMAKE_FIND_ROOT_PATH (-D...), never among the build machine's own.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR AMD64)

set(PROX_MINGW_TRIPLE x86_64-w64-mingw32 CACHE STRING "The MinGW-w64 target triple")
find_program(CMAKE_C_COMPILER NAMES ${PROX_MINGW_TRIPLE}-gcc-posix ${PROX_MINGW_TRIPLE}-gcc REQUIRED)
find_program(CMAKE_CXX_COMPILER NAMES ${PROX_MINGW_TRIPLE}-g++-posix ${PROX_MINGW_TRIPLE}-g++ REQUIRED)
find_program(CMAKE_RC_COMPILER NAMES ${PROX_MINGW_TRIPLE}-windres)
# Makes proxima.lib, MSVC's import library, from the DLL's exports.
find_program(CMAKE_DLLTOOL NAMES ${PROX_MINGW_TRIPLE}-dlltool)

list(APPEND CMAKE_FIND_ROOT_PATH /usr/${PROX_MINGW_TRIPLE})
list(REMOVE_DUPLICATES CMAKE_FIND_ROOT_PATH)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# Programs carry their C++ runtime (libstdc++, libgcc, winpthreads) rather
# than needing MinGW's DLLs beside them; proxima.dll does the same
# (sdk/CMakeLists.txt).
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")
