#!/usr/bin/env python3
"""Writes the PNG layouts OpenCV's encoder does not make, for
tests/unit/capture/test_image_file.cpp (onetip decodes PNG with libpng and must
give the grey image cv::imdecode(IMREAD_GRAYSCALE) gives):
  palette_trns.png      8-bit palette with a transparency chunk
  grey2_interlaced.png  2-bit grey, Adam7 interlaced
  rgb16_interlaced.png  16-bit RGB, Adam7 interlaced
  grey_alpha8.png       8-bit grey with alpha
Pixels are a fixed pseudo-random pattern (seed 7), 37x23. Usage: make_png_variants.py [FOLDER]"""
import random
import struct
import sys
import zlib
from pathlib import Path

W, H = 37, 23


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def pack_row(samples, bits):
    if bits >= 8:
        width = bits // 8
        return b"".join(s.to_bytes(width, "big") for s in samples)
    out, acc, n = bytearray(), 0, 0
    for s in samples:
        acc = (acc << bits) | s
        n += bits
        if n == 8:
            out.append(acc)
            acc, n = 0, 0
    if n:
        out.append(acc << (8 - n))
    return bytes(out)


ADAM7 = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)]


def image_data(pixels, channels, bits, interlaced):
    """pixels[y][x] is a tuple of `channels` samples; filter type 0 on every row."""
    raw = bytearray()
    passes = ADAM7 if interlaced else [(0, 0, 1, 1)]
    for x0, y0, dx, dy in passes:
        xs = range(x0, W, dx)
        if not xs:
            continue
        for y in range(y0, H, dy):
            raw.append(0)
            raw += pack_row([s for x in xs for s in pixels[y][x]], bits)
    return zlib.compress(bytes(raw), 9)


def png(colour_type, bits, channels, pixels, interlaced=False, extra=b""):
    ihdr = struct.pack(">IIBBBBB", W, H, bits, colour_type, 0, 0, 1 if interlaced else 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + extra +
            chunk(b"IDAT", image_data(pixels, channels, bits, interlaced)) + chunk(b"IEND", b""))


def main():
    folder = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).parent)
    rnd = random.Random(7)
    grid = lambda f: [[f() for _ in range(W)] for _ in range(H)]
    palette = [(rnd.randrange(256), rnd.randrange(256), rnd.randrange(256)) for _ in range(16)]
    plte = chunk(b"PLTE", b"".join(bytes(c) for c in palette)) + chunk(b"tRNS", bytes(rnd.randrange(256) for _ in range(16)))
    files = {
        "palette_trns.png": png(3, 8, 1, grid(lambda: (rnd.randrange(16),)), extra=plte),
        "grey2_interlaced.png": png(0, 2, 1, grid(lambda: (rnd.randrange(4),)), interlaced=True),
        "rgb16_interlaced.png": png(2, 16, 3, grid(lambda: tuple(rnd.randrange(65536) for _ in range(3))),
                                    interlaced=True),
        "grey_alpha8.png": png(4, 8, 2, grid(lambda: (rnd.randrange(256), rnd.randrange(256)))),
    }
    for name, data in files.items():
        (folder / name).write_bytes(data)
        print(name, len(data), "bytes")


if __name__ == "__main__":
    main()
