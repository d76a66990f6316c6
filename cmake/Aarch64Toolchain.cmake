# Cross-compiles pond for aarch64 (the arm64 preset) with clang-14 --target=aarch64-linux-gnu over
# Debian's architecture-independent cross sysroot (libc6-dev-arm64-cross, libstdc++-12-dev-arm64-cross,
# libgcc-12-dev-arm64-cross; binutils-aarch64-linux-gnu links). Not g++-aarch64-linux-gnu: on
# Debian 12 it conflicts with gcc-multilib, which the IA-32 build needs on the same machine.
# Libraries are linked from that sysroot only; headers and CMake package files also come from the
# host's /usr (the header-only packages pond uses: nlohmann-json, CLI11, stb, glm). The programs run
# here under qemu-aarch64 (Debian's qemu-user) on Debian's own arm64 libc6 and libstdc++6, installed
# beside the native ones (multiarch, scripts/setup.sh): on the sysroot's instead
# (`-L /usr/aarch64-linux-gnu`), qemu 7.2 hangs in the first thread a program starts.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(POND_DEBIAN_ARCHITECTURE arm64)  # the package's (cmake/Package.cmake)
set(POND_AARCH64_TRIPLE aarch64-linux-gnu)
set(POND_AARCH64_SYSROOT /usr/${POND_AARCH64_TRIPLE})
set(CMAKE_C_COMPILER clang-14)
set(CMAKE_CXX_COMPILER clang++-14)
set(CMAKE_C_COMPILER_TARGET ${POND_AARCH64_TRIPLE})
set(CMAKE_CXX_COMPILER_TARGET ${POND_AARCH64_TRIPLE})
find_program(CMAKE_OBJDUMP ${POND_AARCH64_TRIPLE}-objdump)  # the no-FMA test reads its disassembly
set(CMAKE_FIND_ROOT_PATH ${POND_AARCH64_SYSROOT})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
find_program(POND_QEMU_AARCH64 qemu-aarch64)
if(POND_QEMU_AARCH64)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${POND_QEMU_AARCH64})
endif()
