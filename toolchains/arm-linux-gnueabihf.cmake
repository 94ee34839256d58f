# Cross build for 32-bit Armv7 hard-float (little-endian) Linux; tests run under qemu-user (arm) with the target's
# runtime from /usr/arm-linux-gnueabihf (Debian's cross packages put it there).
# cmake -S . -B build-cross-arm -DCMAKE_TOOLCHAIN_FILE=toolchains/arm-linux-gnueabihf.cmake
# builds the core and its tests: host tools (SPINHASH_HOST_TOOLS) default to OFF when cross-compiling.
set(CMAKE_SYSTEM_PROCESSOR arm)
set(SPINHASH_TRIPLE arm-linux-gnueabihf)
set(SPINHASH_QEMU_NAME qemu-arm)
# GCC notes that std::vector iterators are passed differently since GCC 7.1:
# informational only (everything here is built by one compiler).
set(CMAKE_CXX_FLAGS_INIT "-Wno-psabi")
include(${CMAKE_CURRENT_LIST_DIR}/linux-cross-common.cmake)
