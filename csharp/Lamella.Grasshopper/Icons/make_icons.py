"""Draws the 24x24 component icons (PNG, RGBA) of Lamella.Grasshopper; run once after editing, commit the PNGs."""
import math
import struct
import zlib

SIZE = 24
INK = (40, 70, 120, 255)
ACCENT = (220, 120, 40, 255)


def png(path, pixels):
    raw = b"".join(b"\x00" + bytes(c for px in row for c in px) for row in pixels)
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", SIZE, SIZE, 8, 6, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def canvas():
    return [[(0, 0, 0, 0)] * SIZE for _ in range(SIZE)]


def dot(p, x, y, colour):
    if 0 <= x < SIZE and 0 <= y < SIZE:
        p[y][x] = colour


def curve(p, f, colour, x0=2, x1=21):
    for i in range(200):
        x = x0 + (x1 - x0) * i / 199
        dot(p, int(round(x)), int(round(f(x))), colour)


def strip_field():
    p = canvas()
    for k in range(4):
        curve(p, lambda x, k=k: 4 + 5 * k + 2.5 * math.cosh((x - 12) / 7) - 2.5, INK if k % 2 else ACCENT)
    return p


def level_curves():
    p = canvas()
    for k in range(5):
        curve(p, lambda x, k=k: 3 + 4 * k + 1.5 * math.sin(x / 3.5), INK)
    return p


def rectifying_strips():
    p = canvas()
    for k in range(2):
        top = 5 + 9 * k
        curve(p, lambda x, t=top: t, INK)
        curve(p, lambda x, t=top: t + 5, INK)
        for x in range(2, 22, 4):
            for y in range(top, top + 6):
                dot(p, x + (y - top) // 3, y, ACCENT)
    return p


def strip_quality():
    p = canvas()
    for i, h in enumerate((8, 14, 5, 18)):
        for x in range(3 + 5 * i, 6 + 5 * i):
            for y in range(21 - h, 21):
                dot(p, x, y, ACCENT if i == 3 else INK)
    curve(p, lambda x: 21, INK)
    return p


def trace_p_curve():
    p = canvas()
    for y in range(2, 22):
        dot(p, 2, y, INK)
    for k, start in enumerate((6, 12)):
        curve(p, lambda x, s=start: s + 2.0 * math.cosh((x - 3) / 6) - 2.0, INK, x0=3, x1=21)
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                dot(p, 2 + dx, start + dy, ACCENT)
    return p


def line(p, x0, y0, x1, y1, colour):
    for i in range(100):
        t = i / 99
        dot(p, int(round(x0 + (x1 - x0) * t)), int(round(y0 + (y1 - y0) * t)), colour)


def strip_web():
    # Three families: two sets of parallels and their diagonals (a 3-web of triangles, Sec. 4.2).
    p = canvas()
    for k in range(4):
        line(p, 2, 3 + 6 * k, 21, 3 + 6 * k, INK)
        line(p, 3 + 6 * k, 2, 3 + 6 * k, 21, INK)
    for k in range(-2, 3):
        for x in range(3, 22):
            if 3 <= 24 + 6 * k - x <= 21:
                dot(p, x, 24 + 6 * k - x, ACCENT)
    return p


def library():
    p = strip_field()
    curve(p, lambda x: 21, ACCENT)
    return p


for name, draw in [("StripField", strip_field), ("LevelCurves", level_curves), ("RectifyingStrips", rectifying_strips),
                   ("StripQuality", strip_quality), ("TracePCurve", trace_p_curve), ("StripWeb", strip_web), ("Lamella", library)]:
    png(name + ".png", draw())
