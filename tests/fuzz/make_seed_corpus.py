#!/usr/bin/env python3
"""Writes the committed seed corpus of the libFuzzer targets (tests/fuzz/corpus/<target>/): a few
well-formed inputs per entry point, so that fuzzing starts from the valid shapes and mutates out
of them. Run from anywhere; rewrites the seed files (never the inputs a fuzzing run adds)."""
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
SETTINGS_SIZE = 4 + 4 + 12 + 12 + 4 + 4  # sizeof(sss_settings)


def write(target, name, data):
    folder = os.path.join(HERE, "corpus", target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "seed-" + name), "wb") as f:
        f.write(data)


def settings(width=0.0015, strength=(0.78, 0.70, 0.75), falloff=(0.57, 0.13, 0.08), samples=17, flags=1):
    return struct.pack("<If3f3fiI", SETTINGS_SIZE, width, *strength, *falloff, samples, flags)


def perspective(fovy, aspect, near, far):
    f = 1.0 / math.tan(math.radians(fovy) / 2)
    m = [0.0] * 16
    m[0], m[5], m[11] = f / aspect, f, -1.0
    if far == math.inf:
        m[10], m[14] = -1.0, -2.0 * near
    else:
        m[10], m[14] = (far + near) / (near - far), 2 * far * near / (near - far)
    return m


def orthographic(half, near, far):
    m = [0.0] * 16
    m[0] = m[5] = 1.0 / half
    m[10], m[14], m[15] = -2.0 / (far - near), -(far + near) / (far - near), 1.0
    return m


def floats(values):
    return struct.pack("<%df" % len(values), *values)


# sss_fuzz_validation: selector byte (0 settings, 1 camera, 2 kernel), then the argument bytes.
write("validation", "settings-default", b"\x00" + settings() + b"\x01")
write("validation", "settings-edges", b"\x00" + settings(1e6, (0, 1, 0), (1, 0, 1), 65, 0) + b"\x01")
write("validation", "settings-zero-width", b"\x00" + settings(0.0, samples=3) + b"\x00")
write("validation", "camera-perspective", b"\x01" + floats(perspective(45, 1.5, 0.1, 100)) + struct.pack("<HH", 1920, 1080))
write("validation", "camera-infinite", b"\x01" + floats(perspective(60, 1.0, 0.01, math.inf)) + struct.pack("<HH", 64, 64))
write("validation", "camera-ortho", b"\x01" + floats(orthographic(2.0, 0.1, 10)) + struct.pack("<HH", 1, 8192))
write("validation", "kernel", b"\x02" + struct.pack("<i", 25) + floats([1, 0.5, 0]) + floats([0, 0.5, 1]) + b"\x00")

# sss_fuzz_kernel: tap-count byte, then six (mode byte + value) unit values.
write("kernel", "default", bytes([7]) + b"".join(b"\x00" + struct.pack("<H", int(v * 65535)) for v in (0.78, 0.7, 0.75, 0.57, 0.13, 0.08)))
write("kernel", "ends", bytes([31]) + b"\x03\x07\x03\x02\x01" + struct.pack("<f", 0.5) + b"\x03\x03\x07")

# sss_fuzz_cpu_model: dims byte, 16 camera floats, colours, depths, mask bits, then settings bytes.
def cpu_case(w, h, camera, color, depth, mask_bits=0, width_units=150, encoding=0):
    dims = (w - 1) + 6 * (h - 1)
    data = bytes([dims]) + floats(camera) + floats(color) + floats(depth) + struct.pack("<Q", mask_bits)
    data += struct.pack("<HB", width_units, 1) + struct.pack("<6H", *([40000] * 6)) + bytes([8, 0, encoding, 0, 20])
    return data

cam = perspective(40, 1.0, 0.1, 10)
n = 16
colour = []
for i in range(n):
    colour += [0.2 + 0.05 * i, 0.5, 1.0 - 0.05 * i, 1.0]
write("cpu_model", "plane-4x4", cpu_case(4, 4, cam, colour, [0.9] * n))
colour[5 * 4] = float("nan")
colour[9 * 4 + 1] = float("inf")
write("cpu_model", "nonfinite-4x4", cpu_case(4, 4, cam, colour, [0.9] * n, mask_bits=0x8001))
write("cpu_model", "linear-6x6", cpu_case(6, 6, cam, [65504.0, 0.0, 1.0, 1.0] * 36, [1.5] * 35 + [float("nan")], encoding=2))
print("seed corpus written under", os.path.join(HERE, "corpus"))
