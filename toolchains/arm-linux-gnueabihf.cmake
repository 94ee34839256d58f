# Cross build for 32-bit Armv7 hard-float (little-endian) Linux; tests run under qemu-user (arm) with the target's
# runtime from /usr/arm-linux-gnueabihf (Debian's cross packages put it there).
# cmake -S . -B build-cross-arm -DCMAKE_TOOLCHAIN_FILE=toolchains/arm-linux-gnueabihf.cmake -DSPINHASH_HOST_TOOLS=OFF
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(SPINHASH_TRIPLE arm-linux-gnueabihf)

set(CMAKE_C_COMPILER ${SPINHASH_TRIPLE}-gcc)
set(CMAKE_CXX_COMPILER ${SPINHASH_TRIPLE}-g++)
# GCC notes that std::vector iterators are passed differently since GCC 7.1:
# informational only (everything here is built by one compiler).
set(CMAKE_CXX_FLAGS_INIT "-Wno-psabi")
set(CMAKE_FIND_ROOT_PATH /usr/${SPINHASH_TRIPLE})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
# Header-only host packages (Eigen, doctest) are found through their CMake
# configs under /usr/share and /usr/lib/cmake; they hold no target code.
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)

find_program(SPINHASH_QEMU qemu-arm REQUIRED)
set(CMAKE_CROSSCOMPILING_EMULATOR ${SPINHASH_QEMU} -L /usr/${SPINHASH_TRIPLE})
