# Bare-metal Cortex-M7 with double-precision FPU (newlib nano, no OS): proves
# the core compiles and links for a microcontroller and measures its size.
# Nothing runs: scripts/stages/21-bare-metal.sh reports arm-none-eabi-size.
# cmake -S . -B build-cross-cortex-m7 -DCMAKE_TOOLCHAIN_FILE=toolchains/arm-none-eabi.cmake
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR cortex-m7)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
# No OS to run a test program on: check the compilers with a static library.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# Cortex-M has no NEON: the scalar reference kernels (firmware-lib/kernels/),
# stated rather than left to the absence of __ARM_NEON.
set(SPINHASH_KERNELS_REFERENCE ON CACHE BOOL "scalar reference kernels on bare metal")
set(SPINHASH_CPU_FLAGS "-mcpu=cortex-m7 -mfpu=fpv5-d16 -mfloat-abi=hard -mthumb")
set(CMAKE_C_FLAGS_INIT "${SPINHASH_CPU_FLAGS} -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "${SPINHASH_CPU_FLAGS} -ffunction-sections -fdata-sections")
set(CMAKE_EXE_LINKER_FLAGS_INIT "--specs=nano.specs --specs=nosys.specs -Wl,--gc-sections")

set(CMAKE_FIND_ROOT_PATH /usr/lib/arm-none-eabi)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)  # header-only Eigen from the host
