#!/usr/bin/env bash
# Installs the Debian packages onetip needs, and only those that are missing.
# Idempotent: a second run installs nothing and takes about a second.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git ccache ninja-build  # ccache, Ninja: every build in .ci/ (.ci/build-env.sh)
  doxygen  # the API reference: the `docs` target (docs/api), warnings as errors
  libopencv-dev libeigen3-dev libceres-dev libpcl-dev
  libturbojpeg0-dev libpng-dev libv4l-dev linux-libc-dev  # libpng: PNG frames decoded with its messages caught
  libgtest-dev libgmock-dev libbenchmark-dev
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libglfw3-dev libopengl-dev
  xvfb xauth xdotool  # the windowed viewer test: a virtual X display and synthetic input
  libnanoflann-dev libspnav-dev libevdev-dev libasound2-dev
  libyaml-cpp-dev  # configuration files (pattern, options, scenarios) as plain YAML
  pybind11-dev python3-dev python3-numpy python3-matplotlib python3-pytest
  mono-mcs mono-runtime
  qemu-system-x86 linux-image-amd64 busybox-static cpio udev
  cyclonedds-dev cyclonedds-tools  # the DDS link (sdk/src/dds, issue 19): Cyclone DDS and its IDL compiler
  libfastrtps-dev fastddsgen iproute2 nftables  # DDS tests: the Fast DDS subscriber; network namespaces, dropped packets
  clang libclang-rt-14-dev  # libFuzzer harnesses (tests/fuzz, issue 17)
)
# Optional: v4l2loopback built by DKMS for the kernel qemu boots (tests/qemu_camera's
# loopback drills). A DKMS build that fails here must not stop the set-up: the
# drills that need the module then skip, saying why.
optional=(linux-headers-amd64 v4l2loopback-dkms)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

optional_missing=()
for p in "${optional[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    optional_missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ] && [ ${#optional_missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${#missing[@]} missing packages: ${missing[*]}"
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
if [ ${#optional_missing[@]} -gt 0 ]; then
  echo "install-deps: installing optional packages: ${optional_missing[*]}"
  if ! $SUDO apt-get install -y -qq --no-install-recommends "${optional_missing[@]}" >/dev/null; then
    echo "install-deps: WARNING: ${optional_missing[*]} did not install; the v4l2loopback camera drills will skip"
    $SUDO dpkg --configure -a >/dev/null 2>&1 || true
  fi
fi
echo "install-deps: done"
