#!/usr/bin/env bash
# Installs the Debian packages onetip needs that are missing, and only those (with sudo when not root).
#   bash .ci/install-deps.sh          the SDK: what building it needs, the `onetip` program and its
#                                     viewer, DDS publishing, and the Python and C# bindings the
#                                     install section of the README uses (.ci/demo.sh);
#   bash .ci/install-deps.sh --tests  the SDK and what the whole test suite needs as well: GoogleTest
#                                     and Google Benchmark, PCL, Doxygen, Xvfb, pytest, Fast DDS and
#                                     network tools, clang with libFuzzer, and qemu with a kernel image,
#                                     busybox and DKMS headers for the camera and uinput drills (.ci/test.sh).
#   --check (or ONETIP_INSTALL_DEPS=check in the environment): install nothing; name what is
#                                     missing and exit with status 1 if anything is.
# It says which set it checks and names the missing packages. Idempotent: when everything is
# there it installs nothing and takes about a second.
set -euo pipefail

usage="usage: install-deps.sh [--tests] [--check]"
tests=0 check=0
[ "${ONETIP_INSTALL_DEPS:-}" = check ] && check=1
for arg in "$@"; do
  case "$arg" in
    --tests) tests=1 ;;
    --check) check=1 ;;
    -h|--help) echo "$usage"; exit 0 ;;
    *) echo "install-deps: unknown argument '$arg'; $usage" >&2; exit 2 ;;
  esac
done

# Building and running the SDK.
sdk=(
  build-essential cmake pkg-config git ccache ninja-build  # ccache, Ninja: every build in .ci/ (.ci/build-env.sh)
  libopencv-dev libeigen3-dev libceres-dev libyaml-cpp-dev libnanoflann-dev
  libturbojpeg0-dev libpng-dev libv4l-dev linux-libc-dev  # frame sources; libpng: PNG frames decoded with its messages caught
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libglfw3-dev libopengl-dev  # the viewer (windowed or headless)
  libasound2-dev  # vibrotactile output (sdk/src/devices)
  cyclonedds-dev cyclonedds-tools  # `onetip publish` and `teleop` (sdk/src/dds): Cyclone DDS and its IDL compiler
  pybind11-dev python3-dev python3-numpy  # the Python module
  mono-mcs mono-runtime  # the C# assembly (and Unity's)
)
# The whole test suite, on top of the SDK.
suite=(
  libgtest-dev libgmock-dev libbenchmark-dev libpcl-dev  # tests and benchmarks (PCL: the pose baselines)
  doxygen  # the API reference: the `docs` target (docs/api), warnings as errors
  xvfb xauth xdotool  # the windowed viewer test: a virtual X display and synthetic input
  libspnav-dev libevdev-dev  # clients of `onetip spnav` and `onetip joystick` in the tests
  python3-matplotlib python3-pytest
  libfastrtps-dev fastddsgen iproute2 nftables  # DDS tests: the Fast DDS subscriber; network namespaces, dropped packets
  openssl  # DDS Security tests: the test PKI of docs/dds/security/make-test-pki.sh
  clang libclang-rt-14-dev  # the sanitizer tree and the libFuzzer harnesses (tests/fuzz)
  qemu-system-x86 linux-image-amd64 busybox-static cpio udev  # camera and uinput drills under qemu
)
# Optional, with the suite: v4l2loopback built by DKMS for the kernel qemu boots (tests/qemu_camera's
# loopback drills). A DKMS build that fails here must not stop the set-up: the drills that need
# the module then skip, saying why.
optional=(linux-headers-amd64 v4l2loopback-dkms)

packages=("${sdk[@]}")
what="the SDK (${#sdk[@]} packages; --tests adds the test suite's)"
if [ $tests -eq 1 ]; then
  packages+=("${suite[@]}")
  what="the SDK and the whole test suite (${#packages[@]} packages, and ${#optional[@]} optional)"
else
  optional=()
fi

missing_of() {  # the packages among "$@" that are not installed
  local p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}
mapfile -t missing < <(missing_of "${packages[@]}")
optional_missing=()
[ ${#optional[@]} -eq 0 ] || mapfile -t optional_missing < <(missing_of "${optional[@]}")

if [ ${#missing[@]} -eq 0 ] && [ ${#optional_missing[@]} -eq 0 ]; then
  echo "install-deps: $what: all present"
  exit 0
fi
echo "install-deps: $what: missing ${#missing[@]}${missing[*]:+: ${missing[*]}}"
[ ${#optional_missing[@]} -eq 0 ] || echo "install-deps: optional, missing: ${optional_missing[*]}"
if [ $check -eq 1 ]; then
  [ ${#missing[@]} -eq 0 ] || { echo "install-deps: --check: nothing installed" >&2; exit 1; }
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}"
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
if [ ${#optional_missing[@]} -gt 0 ]; then
  echo "install-deps: installing the optional ${optional_missing[*]}"
  if ! $SUDO apt-get install -y -qq --no-install-recommends "${optional_missing[@]}" >/dev/null; then
    echo "install-deps: WARNING: ${optional_missing[*]} did not install; the v4l2loopback camera drills will skip"
    $SUDO dpkg --configure -a >/dev/null 2>&1 || true
  fi
fi
echo "install-deps: done"
