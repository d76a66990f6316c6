# The arm64-gpu preset: the arm64 toolchain (Aarch64Toolchain.cmake) plus Debian's arm64 Vulkan
# loader, GLFW and ImGui (libvulkan-dev:arm64, ...; scripts/setup.sh). Those live in the multiarch
# directory /usr/lib/aarch64-linux-gnu, outside the cross sysroot, so it is searched too.
include(${CMAKE_CURRENT_LIST_DIR}/Aarch64Toolchain.cmake)
list(APPEND CMAKE_FIND_ROOT_PATH /)
set(CMAKE_LIBRARY_ARCHITECTURE ${POND_AARCH64_TRIPLE})
# The libraries those need in turn (libglfw.so.3: libX11.so.6, ...) are there as well, not in the sysroot.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-Wl,-rpath-link,/usr/lib/${POND_AARCH64_TRIPLE}")
# pkg-config (ImGui) reads the arm64 .pc files, not the host's.
set(ENV{PKG_CONFIG_LIBDIR} "/usr/lib/${POND_AARCH64_TRIPLE}/pkgconfig:/usr/share/pkgconfig")
