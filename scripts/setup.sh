#!/usr/bin/env bash
# Installs every Debian package pond needs to build, run and test. Idempotent: when everything is
# already installed it only checks (no apt-get update), so it is quick to run before every build.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  mesa-vulkan-drivers libvulkan-dev vulkan-tools vulkan-validationlayers
  glslang-tools spirv-tools
  libglfw3-dev libglm-dev libimgui-dev libstb-dev
  nlohmann-json3-dev libcli11-dev libgtest-dev libbenchmark-dev libmeshoptimizer-dev
  xvfb xauth twm time gcc-multilib g++-multilib
  x11-utils  # tests/demo/storm_test.sh: xwininfo, to wait until the window manager runs
  qemu-user  # tests/cli/ia32_golden_test.sh on kernels that cannot run 32-bit programs; the arm64 tests
  # The arm64 preset (cmake/Aarch64Toolchain.cmake): clang-14 (below) over Debian's cross sysroot, not
  # g++-aarch64-linux-gnu (it conflicts with gcc-multilib); GoogleTest's sources for its tests.
  libc6-dev-arm64-cross libstdc++-12-dev-arm64-cross libgcc-12-dev-arm64-cross binutils-aarch64-linux-gnu googletest
  # Debian's arm64 runtime, beside the native one (multiarch): the arm64 tests run on it under
  # qemu-aarch64, and the arm64 .deb's Depends come from its symbols files (dpkg-shlibdeps).
  libc6:arm64 libstdc++6:arm64 libgcc-s1:arm64
  # The arm64-gpu preset (cmake/Aarch64GpuToolchain.cmake): arm64 Vulkan loader, GLFW and ImGui to
  # link, and arm64 lavapipe and validation layer for its pond under qemu-aarch64.
  libvulkan-dev:arm64 libglfw3-dev:arm64 libimgui-dev:arm64 mesa-vulkan-drivers:arm64 vulkan-validationlayers:arm64
  gnuplot-nox
  clang-14 libclang-rt-14-dev  # scripts/fuzz.sh: libFuzzer and clang's ASan/UBSan runtimes
  dpkg-dev file  # cpack -G DEB (tests/install): dpkg-shlibdeps computes Depends; CPack finds ELF files with `file`
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "setup: installing ${missing[*]}" >&2
# The :arm64 packages come from Debian's arm64 archive, beside the native ones (multiarch).
add_arm64=
dpkg --print-foreign-architectures | grep -qx arm64 || add_arm64=1
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO=sudo; else
    echo "setup: need root to install: ${missing[*]}" >&2; exit 1
  fi
else
  SUDO=
fi
export DEBIAN_FRONTEND=noninteractive
[ -z "$add_arm64" ] || $SUDO dpkg --add-architecture arm64
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
