#!/usr/bin/env bash
# Boots Debian's kernel under qemu (TCG, no KVM needed) with a small busybox
# initramfs (tests/qemu/qemu_guest.sh) that loads the uinput module, runs
# uinput_guest (onetip's joystick created through /dev/uinput, read back
# through libevdev, classified by udev's input_id builtin) and powers off; then
# checks the guest's output.
#
#   run_qemu_uinput.sh GUEST_BINARY WORK_DIR
#
# Exit: 0 checked, 1 failed, 77 skipped (no qemu, no kernel image with the
# uinput module, no static busybox, no cpio). Overrides: see qemu_guest.sh.
set -euo pipefail

guest=${1:?usage: run_qemu_uinput.sh GUEST_BINARY WORK_DIR}
work=${2:?usage: run_qemu_uinput.sh GUEST_BINARY WORK_DIR}
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=../qemu/qemu_guest.sh
source "$here/../qemu/qemu_guest.sh"

qemu_guest_setup "$work" uinput
evdev_load=true
if qemu_guest_has_module evdev; then  # else built into the kernel
  qemu_guest_module evdev
  evdev_load=/modules/load-evdev.sh
fi
qemu_guest_module uinput
qemu_guest_program "$guest" /uinput_guest
if udevadm=$(command -v udevadm); then qemu_guest_program "$udevadm" /bin/udevadm; fi

qemu_guest_boot "
/uinput_guest --expect-missing
$evdev_load
/modules/load-uinput.sh && echo 'ONETIP MODULE uinput loaded'
/uinput_guest
echo \"ONETIP GUEST-EXIT \$?\"" 240
/usr/bin/python3 "$here/check_guest_output.py" "$QG_LOG"
