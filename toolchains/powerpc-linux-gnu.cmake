# Cross build for 32-bit PowerPC (big-endian) Linux; tests run under qemu-user (ppc) with the target's
# runtime from /usr/powerpc-linux-gnu (Debian's cross packages put it there).
# cmake -S . -B build-cross-powerpc -DCMAKE_TOOLCHAIN_FILE=toolchains/powerpc-linux-gnu.cmake -DSPINHASH_HOST_TOOLS=OFF
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR powerpc)
set(SPINHASH_TRIPLE powerpc-linux-gnu)

set(CMAKE_C_COMPILER ${SPINHASH_TRIPLE}-gcc)
set(CMAKE_CXX_COMPILER ${SPINHASH_TRIPLE}-g++)
set(CMAKE_FIND_ROOT_PATH /usr/${SPINHASH_TRIPLE})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
# Header-only host packages (Eigen, doctest) are found through their CMake
# configs under /usr/share and /usr/lib/cmake; they hold no target code.
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)

find_program(SPINHASH_QEMU qemu-ppc REQUIRED)
set(CMAKE_CROSSCOMPILING_EMULATOR ${SPINHASH_QEMU} -L /usr/${SPINHASH_TRIPLE})
