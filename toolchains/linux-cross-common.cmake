# Shared by the Linux cross toolchains: set CMAKE_SYSTEM_PROCESSOR,
# SPINHASH_TRIPLE (the Debian cross prefix) and SPINHASH_QEMU_NAME (the
# qemu-user binary) first, then include this file.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_C_COMPILER ${SPINHASH_TRIPLE}-gcc)
set(CMAKE_CXX_COMPILER ${SPINHASH_TRIPLE}-g++)
set(CMAKE_FIND_ROOT_PATH /usr/${SPINHASH_TRIPLE})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
# Header-only host packages (Eigen, doctest) are found through their CMake
# configs under /usr/share and /usr/lib/cmake; they hold no target code.
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)

find_program(SPINHASH_QEMU ${SPINHASH_QEMU_NAME} REQUIRED)
set(CMAKE_CROSSCOMPILING_EMULATOR ${SPINHASH_QEMU} -L /usr/${SPINHASH_TRIPLE})
