# Cross build for 64-bit Arm (little-endian) Linux; tests run under qemu-user (aarch64) with the target's
# runtime from /usr/aarch64-linux-gnu (Debian's cross packages put it there).
# cmake -S . -B build-cross-aarch64 -DCMAKE_TOOLCHAIN_FILE=toolchains/aarch64-linux-gnu.cmake
# builds the core and its tests: host tools (SPINHASH_HOST_TOOLS) default to OFF when cross-compiling.
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(SPINHASH_TRIPLE aarch64-linux-gnu)
set(SPINHASH_QEMU_NAME qemu-aarch64)
include(${CMAKE_CURRENT_LIST_DIR}/linux-cross-common.cmake)
