# Cross build for 32-bit PowerPC (big-endian) Linux; tests run under qemu-user (ppc) with the target's
# runtime from /usr/powerpc-linux-gnu (Debian's cross packages put it there).
# cmake -S . -B build-cross-powerpc -DCMAKE_TOOLCHAIN_FILE=toolchains/powerpc-linux-gnu.cmake
# builds the core and its tests: host tools (SPINHASH_HOST_TOOLS) default to OFF when cross-compiling.
set(CMAKE_SYSTEM_PROCESSOR powerpc)
set(SPINHASH_TRIPLE powerpc-linux-gnu)
set(SPINHASH_QEMU_NAME qemu-ppc)
include(${CMAKE_CURRENT_LIST_DIR}/linux-cross-common.cmake)
