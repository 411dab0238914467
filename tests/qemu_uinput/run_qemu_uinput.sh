#!/usr/bin/env bash
# Boots Debian's kernel under qemu (TCG, no KVM needed) with a small busybox
# initramfs that loads the uinput module, runs uinput_guest (onetip's joystick
# created through /dev/uinput, read back through libevdev, classified by
# udev's input_id builtin) and powers off; then checks the guest's output.
#
#   run_qemu_uinput.sh GUEST_BINARY WORK_DIR
#
# Exit: 0 checked, 1 failed, 77 skipped (no qemu, no kernel image with the
# uinput module, no static busybox, no cpio). Overrides: ONETIP_QEMU_KERNEL
# (a vmlinuz whose modules are in /lib/modules/<version>), ONETIP_QEMU_BUSYBOX.
set -euo pipefail

guest=${1:?usage: run_qemu_uinput.sh GUEST_BINARY WORK_DIR}
work=${2:?usage: run_qemu_uinput.sh GUEST_BINARY WORK_DIR}
here=$(cd "$(dirname "$0")" && pwd)

skip() { echo "SKIP: $*"; exit 77; }

command -v qemu-system-x86_64 >/dev/null || skip "qemu-system-x86_64 not installed (apt-get install qemu-system-x86)"
command -v cpio >/dev/null || skip "cpio not installed"
[ -x "$guest" ] || { echo "FAIL: guest program '$guest' missing"; exit 1; }

# A kernel image whose module tree has uinput (and evdev unless built in).
kernel=${ONETIP_QEMU_KERNEL:-}
if [ -z "$kernel" ]; then
  for k in $(ls -1 /boot/vmlinuz-* 2>/dev/null | sort -V -r); do
    v=${k#/boot/vmlinuz-}
    if ls /lib/modules/"$v"/kernel/drivers/input/misc/uinput.ko* >/dev/null 2>&1; then kernel=$k; break; fi
  done
fi
[ -n "$kernel" ] && [ -r "$kernel" ] || skip "no readable /boot/vmlinuz-* with a uinput module (apt-get install linux-image-amd64)"
version=${kernel##*/vmlinuz-}
moddir=/lib/modules/$version/kernel/drivers/input

busybox=${ONETIP_QEMU_BUSYBOX:-/bin/busybox}
[ -x "$busybox" ] || skip "busybox not found (apt-get install busybox-static)"
if ldd "$busybox" >/dev/null 2>&1; then skip "$busybox is dynamically linked (apt-get install busybox-static)"; fi

rm -rf "$work"
root=$work/root
mkdir -p "$root"/{bin,dev,proc,sys,modules,tmp}
cp "$busybox" "$root/bin/busybox"

# Copies a module, decompressing .xz/.zst (busybox insmod wants a plain .ko).
copy_module() {
  local base=$1 src
  src=$(ls -1 "$moddir/$base".ko* 2>/dev/null | head -n1 || true)
  [ -n "$src" ] || return 0  # built into the kernel
  case "$src" in
    *.ko) cp "$src" "$root/modules/$(basename "$base").ko" ;;
    *.ko.xz) xz -dc "$src" >"$root/modules/$(basename "$base").ko" ;;
    *.ko.zst) zstd -qdc "$src" >"$root/modules/$(basename "$base").ko" ;;
    *) skip "unsupported module compression: $src" ;;
  esac
}
copy_module evdev
copy_module misc/uinput
[ -f "$root/modules/uinput.ko" ] || skip "uinput is not a module of $version"

# The programs and every shared library they load, at the same paths.
copy_with_libs() {
  local bin=$1 dest=$2
  mkdir -p "$root$(dirname "$dest")"
  cp "$bin" "$root$dest"
  ldd "$bin" | grep -o '/[^ ]*' | while read -r lib; do
    mkdir -p "$root$(dirname "$lib")"
    cp -L "$lib" "$root$lib"
  done
}
copy_with_libs "$guest" /uinput_guest
if udevadm=$(command -v udevadm); then copy_with_libs "$udevadm" /bin/udevadm; fi

cat >"$root/init" <<'INIT'
#!/bin/busybox sh
/bin/busybox --install -s /bin
mount -t proc proc /proc
mount -t sysfs sysfs /sys
mount -t devtmpfs devtmpfs /dev
echo "ONETIP BOOTED $(uname -r)"
/uinput_guest --expect-missing
[ -f /modules/evdev.ko ] && insmod /modules/evdev.ko
insmod /modules/uinput.ko && echo "ONETIP MODULE uinput loaded"
/uinput_guest
echo "ONETIP GUEST-EXIT $?"
poweroff -f
INIT
chmod +x "$root/init"
(cd "$root" && find . | cpio -o -H newc --quiet | gzip -1) >"$work/initrd.gz"

log=$work/guest.log
start=$(date +%s)
set +e
timeout 240 qemu-system-x86_64 -accel tcg -m 512M -smp 1 -nographic -no-reboot \
  -kernel "$kernel" -initrd "$work/initrd.gz" \
  -append "console=ttyS0 rdinit=/init panic=-1 quiet loglevel=3" >"$log" 2>&1
qemu_rc=$?
set -e
echo "qemu ($version, TCG) ran $(( $(date +%s) - start )) s, exit $qemu_rc; log: $log"
[ $qemu_rc -eq 124 ] && { echo "FAIL: qemu timed out"; tail -n 20 "$log"; exit 1; }
/usr/bin/python3 "$here/check_guest_output.py" "$log"
