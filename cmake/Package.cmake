# `cpack -G DEB` in the build tree: pond_<version>_<arch>.deb holding what cmake/Install.cmake
# installs, under /usr. Its Depends are computed by dpkg-shlibdeps (dpkg-dev; CPack finds the ELF
# files with `file`, so scripts/setup.sh installs both), plus libvulkan1; mesa-vulkan-drivers is only
# Recommends, so a machine with its own GPU driver need not take it. docs/install.md says more.
set(POND_PACKAGE_MAINTAINER "pond maintainers <pond@localhost>" CACHE STRING
    "The Debian package's Maintainer field, Name <email>")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME pond)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT ${POND_PACKAGE_MAINTAINER})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "spring-mass water and a tree in the wind on Vulkan compute")
string(JOIN "\n" CPACK_PACKAGE_DESCRIPTION  # the control file's lines, each under 80 columns
  "A C++20 Vulkan compute-and-render sample: water as a spring-mass grid"
  "integrated in compute shaders, bit for bit equal to its CPU solvers, and a"
  "fractal tree swaying in the wind. Commands: a windowed demo, headless"
  "simulate and render, and `pond check`, which says whether a GPU gives the"
  "CPU's bits. Runs without a GPU on Mesa's lavapipe (mesa-vulkan-drivers).")
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # pond_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)  # GLFW, stb, libstdc++, ... at the versions linked
if(POND_WITH_VULKAN)
  # pond loads libvulkan.so.1 at run time (src/gpu/vulkan.h), so dpkg-shlibdeps cannot see it: named
  # here and merged with the computed list. A Vulkan 1.3 loader, for the 1.3 entry points pond calls.
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "libvulkan1 (>= 1.3)")
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS mesa-vulkan-drivers)
  set(CPACK_DEBIAN_PACKAGE_SUGGESTS vulkan-validationlayers)  # for --validation
endif()
# A cross build's package is for its target: the arm64 preset's, pond_<version>_arm64.deb. Its
# Depends come from the target's libraries as Debian packages them, libc6:arm64 and the like
# beside the native ones (multiarch; scripts/setup.sh): dpkg-shlibdeps finds them by the
# architecture's library path, and their symbols files give the versions.
if(POND_DEBIAN_ARCHITECTURE)  # set by the toolchain file
  set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE ${POND_DEBIAN_ARCHITECTURE})
endif()
include(CPack)
