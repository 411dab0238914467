# shellcheck shell=bash
# Shared by the kernel drills (tests/qemu_uinput, tests/qemu_camera): boots
# Debian's own kernel under qemu (TCG, no KVM needed) with a small busybox
# initramfs that holds the kernel modules and programs a drill needs. Source
# it from bash (set -euo pipefail) and call, in order:
#
#   qemu_guest_setup WORK MODULE...   checks qemu, cpio and a static busybox; picks the newest
#                                     /boot/vmlinuz-* whose modules.dep has every MODULE
#                                     (names as modprobe takes them); empties WORK; sets
#                                     QG_KERNEL, QG_VERSION, QG_ROOT (the initramfs tree)
#   qemu_guest_has_module NAME        whether NAME is a loadable module of that kernel
#   qemu_guest_module NAME            copies NAME and every module it depends on (modules.dep,
#                                     decompressed: busybox insmod wants a plain .ko) and writes
#                                     /modules/load-NAME.sh, which inserts the dependencies not
#                                     yet loaded, then NAME with its arguments ("$@")
#   qemu_guest_program FILE DEST      copies a program and every shared library it loads (ldd)
#                                     to the same paths in the guest
#   qemu_guest_boot BODY TIMEOUT [QEMU ARG...]
#                                     writes /init (busybox applets, /proc, /sys, /dev mounted,
#                                     "ONETIP BOOTED <kernel>" printed, then the shell text BODY,
#                                     then power off), packs the initramfs and boots it; the
#                                     console goes to $WORK/guest.log (QG_LOG). Fails when qemu
#                                     runs longer than TIMEOUT seconds. Sets QG_BOOT_SECONDS and
#                                     QG_INITRD_BYTES.
#
# Every missing prerequisite is a skip: "SKIP: <what, and the Debian package>" and exit 77.
# Overrides: ONETIP_QEMU_KERNEL (a vmlinuz whose modules are in /lib/modules/<version>),
# ONETIP_QEMU_BUSYBOX, QG_MEMORY (guest RAM, default 512M); QG_PACKAGES names the
# Debian packages that bring a module from outside the kernel package, for the skip message.

qemu_guest_skip() { echo "SKIP: $*"; exit 77; }

# The path (relative to the module tree) of module NAME in modules.dep, or nothing.
qemu_guest_module_path() {
  local dep=$1 name=${2//-/_}
  awk -F: -v want="$name" '{ base = $1; sub(/.*\//, "", base); sub(/\.ko(\.[a-z]+)?$/, "", base);
                             gsub(/-/, "_", base); if (base == want) { print $1; exit } }' "$dep"
}

# Whether NAME is a loadable module of the chosen kernel (false when built in or absent).
qemu_guest_has_module() { [ -n "$(qemu_guest_module_path "$QG_MODULES/modules.dep" "$1")" ]; }

qemu_guest_setup() {
  QG_WORK=${1:?qemu_guest_setup WORK MODULE...}
  shift
  command -v qemu-system-x86_64 >/dev/null ||
    qemu_guest_skip "qemu-system-x86_64 not installed (apt-get install qemu-system-x86)"
  command -v cpio >/dev/null || qemu_guest_skip "cpio not installed (apt-get install cpio)"
  local busybox=${ONETIP_QEMU_BUSYBOX:-/bin/busybox}
  [ -x "$busybox" ] || qemu_guest_skip "busybox not found (apt-get install busybox-static)"
  if ldd "$busybox" >/dev/null 2>&1; then
    qemu_guest_skip "$busybox is dynamically linked (apt-get install busybox-static)"
  fi

  QG_KERNEL=${ONETIP_QEMU_KERNEL:-}
  local k v m ok
  if [ -z "$QG_KERNEL" ]; then
    for k in $(ls -1 /boot/vmlinuz-* 2>/dev/null | sort -V -r); do
      v=${k#/boot/vmlinuz-}
      [ -r "/lib/modules/$v/modules.dep" ] || continue
      ok=1
      for m in "$@"; do
        [ -n "$(qemu_guest_module_path "/lib/modules/$v/modules.dep" "$m")" ] || { ok=0; break; }
      done
      if [ $ok = 1 ]; then QG_KERNEL=$k; break; fi
    done
  fi
  [ -n "$QG_KERNEL" ] && [ -r "$QG_KERNEL" ] ||
    qemu_guest_skip "no readable /boot/vmlinuz-* whose modules include: $*" \
      "(apt-get install linux-image-amd64${QG_PACKAGES:+ $QG_PACKAGES})"
  QG_VERSION=${QG_KERNEL##*/vmlinuz-}
  QG_MODULES=/lib/modules/$QG_VERSION
  for m in "$@"; do
    [ -n "$(qemu_guest_module_path "$QG_MODULES/modules.dep" "$m")" ] ||
      qemu_guest_skip "module $m is not in $QG_MODULES/modules.dep${QG_PACKAGES:+ (apt-get install $QG_PACKAGES)}"
  done

  rm -rf "$QG_WORK"
  QG_ROOT=$QG_WORK/root
  mkdir -p "$QG_ROOT"/{bin,dev,proc,sys,modules,tmp}
  cp "$busybox" "$QG_ROOT/bin/busybox"
}

# Copies one module file (by its modules.dep path) as /modules/<name>.ko; prints <name>.
qemu_guest_copy_module() {
  local rel=$1 src=$QG_MODULES/$1 base
  base=$(basename "$rel")
  base=${base%%.ko*}
  base=${base//-/_}
  case "$src" in
    *.ko) cp "$src" "$QG_ROOT/modules/$base.ko" ;;
    *.ko.xz) xz -dc "$src" >"$QG_ROOT/modules/$base.ko" ;;
    *.ko.zst) zstd -qdc "$src" >"$QG_ROOT/modules/$base.ko" ;;
    *) qemu_guest_skip "unsupported module compression: $src" ;;
  esac
  echo "$base"
}

qemu_guest_module() {
  local name=${1:?qemu_guest_module NAME} rel deps base i
  rel=$(qemu_guest_module_path "$QG_MODULES/modules.dep" "$name")
  [ -n "$rel" ] || qemu_guest_skip "module $name is not in $QG_MODULES/modules.dep"
  # modules.dep lists every dependency, those needed first last (modprobe inserts them in reverse).
  read -r -a deps <<<"$(grep -m1 "^$rel:" "$QG_MODULES/modules.dep" | cut -d: -f2-)"
  local script=$QG_ROOT/modules/load-${name//-/_}.sh
  echo '#!/bin/busybox sh' >"$script"
  for ((i = ${#deps[@]} - 1; i >= 0; i--)); do
    base=$(qemu_guest_copy_module "${deps[$i]}")
    echo "[ -d /sys/module/$base ] || insmod /modules/$base.ko || exit 1" >>"$script"
  done
  base=$(qemu_guest_copy_module "$rel")
  echo "insmod /modules/$base.ko \"\$@\"" >>"$script"
  chmod +x "$script"
}

qemu_guest_program() {
  local bin=${1:?qemu_guest_program FILE DEST} dest=${2:?qemu_guest_program FILE DEST} lib
  [ -x "$bin" ] || { echo "FAIL: guest program '$bin' missing"; exit 1; }
  mkdir -p "$QG_ROOT$(dirname "$dest")"
  cp "$bin" "$QG_ROOT$dest"
  ldd "$bin" | grep -o '/[^ ]*' | while read -r lib; do
    mkdir -p "$QG_ROOT$(dirname "$lib")"
    cp -L "$lib" "$QG_ROOT$lib"
  done
}

qemu_guest_boot() {
  local body=${1:?qemu_guest_boot BODY TIMEOUT} timeout_s=${2:?qemu_guest_boot BODY TIMEOUT}
  shift 2
  {
    echo '#!/bin/busybox sh'
    echo '/bin/busybox --install -s /bin'
    echo 'mount -t proc proc /proc'
    echo 'mount -t sysfs sysfs /sys'
    echo 'mount -t devtmpfs devtmpfs /dev'
    echo 'echo "ONETIP BOOTED $(uname -r)"'
    echo "$body"
    echo 'poweroff -f'
  } >"$QG_ROOT/init"
  chmod +x "$QG_ROOT/init"
  (cd "$QG_ROOT" && find . | cpio -o -H newc --quiet | gzip -1) >"$QG_WORK/initrd.gz"
  QG_INITRD_BYTES=$(stat -c %s "$QG_WORK/initrd.gz")
  QG_LOG=$QG_WORK/guest.log
  local start rc
  start=$(date +%s.%N)
  set +e
  timeout "$timeout_s" qemu-system-x86_64 -accel tcg -m "${QG_MEMORY:-512M}" -smp 1 -nographic -no-reboot \
    -kernel "$QG_KERNEL" -initrd "$QG_WORK/initrd.gz" \
    -append "console=ttyS0 rdinit=/init panic=-1 quiet loglevel=3" "$@" >"$QG_LOG" 2>&1
  rc=$?
  set -e
  QG_BOOT_SECONDS=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  echo "qemu ($QG_VERSION, TCG) ran $QG_BOOT_SECONDS s, exit $rc, initramfs $QG_INITRD_BYTES bytes; log: $QG_LOG"
  if [ $rc -eq 124 ]; then
    echo "FAIL: qemu ran longer than $timeout_s s"
    tail -n 20 "$QG_LOG"
    exit 1
  fi
}
