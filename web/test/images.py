"""RGB images as (width, height, bytes) for the browser test: PPM reading, PNG writing and the
comparisons it reports. Standard library only."""

import struct
import zlib


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    if fields[0] != b"P6" or fields[3] != b"255":
        raise ValueError("%s: not an 8-bit binary PPM" % path)
    width, height = int(fields[1]), int(fields[2])
    return width, height, data[pos + 1:pos + 1 + width * height * 3]


def rgba_to_rgb(rgba):
    out = bytearray(len(rgba) // 4 * 3)
    out[0::3], out[1::3], out[2::3] = rgba[0::4], rgba[1::4], rgba[2::4]
    return bytes(out)


HEAD_ATTRIBUTION = ('"Infinite, 3D Head Scan" by Lee Perry-Smith is licensed under a Creative Commons Attribution 3.0 '
                    'Unported License. Based on a work at www.triplegangers.com. Permissions beyond the scope of this '
                    'license may be available at http://www.ir-ltd.net/')


def write_png(path, width, height, rgb, copyright=HEAD_ATTRIBUTION):
    """An 8-bit RGB PNG; the head scan's attribution in its Copyright text chunk (as the demo's)."""
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)
    rows = b"".join(b"\0" + rgb[y * width * 3:(y + 1) * width * 3] for y in range(height))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
                chunk(b"tEXt", b"Copyright\0" + copyright.encode("latin-1")) +
                chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def pixel_differences(a, b):
    """Per pixel, the largest difference over R, G and B (0..255)."""
    return [max(abs(a[i] - b[i]), abs(a[i + 1] - b[i + 1]), abs(a[i + 2] - b[i + 2])) for i in range(0, len(a), 3)]


def percentile(values, p):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(p / 100.0 * len(ordered)))]


def difference_image(diffs, scale):
    """A grey image of the differences, `scale` times brighter, for looking at where they are."""
    out = bytearray(len(diffs) * 3)
    for i, d in enumerate(diffs):
        out[i * 3] = out[i * 3 + 1] = out[i * 3 + 2] = min(255, d * scale)
    return bytes(out)
