"""A screenshot of the X root window without ImageMagick (the Debian roots stay small): `xwd`
(x11-apps) writes the XWD format, read here into the RGB bytes that tests/host/gui.py's Image
works on (px, count)."""
import struct
import subprocess
import sys
import os

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "host"))
import gui  # noqa: E402


def _shift(mask):
    return (mask & -mask).bit_length() - 1


class XwdImage(gui.Image):
    def __init__(self, path):
        raw = open(path, "rb").read()
        h = struct.unpack(">25I", raw[:100])
        header_size, fmt, depth, w, ht = h[0], h[2], h[3], h[4], h[5]
        byte_order, bpp, bpl = h[7], h[11], h[12]
        rmask, gmask, bmask, ncolors = h[14], h[15], h[16], h[19]
        if fmt != 2 or bpp not in (24, 32):
            raise ValueError("unsupported XWD: format %d, %d bits per pixel" % (fmt, bpp))
        off = header_size + 12 * ncolors
        order = "little" if byte_order == 0 else "big"
        rs, gs, bs = _shift(rmask), _shift(gmask), _shift(bmask)
        n = bpp // 8
        out = bytearray(3 * w * ht)
        for y in range(ht):
            row = raw[off + y * bpl:off + y * bpl + n * w]
            o = 3 * w * y
            for x in range(w):
                p = int.from_bytes(row[n * x:n * x + n], order)
                out[o + 3 * x] = (p & rmask) >> rs
                out[o + 3 * x + 1] = (p & gmask) >> gs
                out[o + 3 * x + 2] = (p & bmask) >> bs
        self.w, self.h, self.data = w, ht, bytes(out)


def screenshot(name):
    """The root window to WORK/name (XWD) and its image."""
    path = os.path.join(gui.WORK, name)
    subprocess.run(["xwd", "-root", "-silent", "-out", path], check=True)
    return XwdImage(path)
