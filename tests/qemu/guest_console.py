"""The qemu drills' guest output (tests/qemu/qemu_guest.sh): the lines a guest
program printed with the prefix "ONETIP ", without it, in order, from the
serial console log (which may put escape codes and kernel messages around them)."""


def console_lines(path):
    lines = []
    with open(path, errors="replace") as f:
        for raw in f:
            raw = raw.replace("\r", "").rstrip("\n")
            at = raw.find("ONETIP ")
            if at >= 0:
                lines.append(raw[at + len("ONETIP "):])
    return lines
