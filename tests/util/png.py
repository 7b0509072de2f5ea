"""tests/util/png.py - the PNG reader the picture checks share.

A test looks at the pixels qdot drew (plots by Cairo, the animation page by
Chromium); Debian's python3 has no imaging library, and the files are plain:
8-bit RGB or RGBA, not interlaced (RFC 2083), which zlib and the five
filters decode in a few lines.  Imported by tests/cli/check_*.py with
tests/util on sys.path.
"""
import struct
import zlib
from pathlib import Path


def _paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else b if pb <= pc else c


def _unfilter(raw, w, h, bpp):
    stride = w * bpp
    out = bytearray(h * stride)
    prev = bytearray(stride)
    pos = 0
    for y in range(h):
        ft = raw[pos]
        line = bytearray(raw[pos + 1:pos + 1 + stride])
        pos += 1 + stride
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            line[i] = (line[i] + (0, a, b, (a + b) // 2, _paeth(a, b, c))[ft]) & 255
        out[y * stride:(y + 1) * stride] = line
        prev = line
    return out


def read_png(path):
    """(width, height, px) with px(x, y) the (r, g, b) at column x, row y."""
    data = Path(path).read_bytes()
    assert data[:8] == b'\x89PNG\r\n\x1a\n', 'not a PNG'
    pos, idat, hdr = 8, b'', None
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b'IHDR':
            hdr = struct.unpack('>IIBBBBB', body)
        elif kind == b'IDAT':
            idat += body
        pos += 12 + n
    w, h, depth, ctype, _, _, interlace = hdr
    assert depth == 8 and ctype in (2, 6) and interlace == 0, 'PNG kind %r' % (hdr,)
    bpp = 3 if ctype == 2 else 4
    px = _unfilter(zlib.decompress(idat), w, h, bpp)
    return w, h, lambda x, y: tuple(px[(y * w + x) * bpp:(y * w + x) * bpp + 3])
