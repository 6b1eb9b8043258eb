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


def web(p, count, spacing, start, diagonal):
    # Three families: `count` parallels each way from `start`, `spacing` apart, and the diagonals through their
    # crossings (a 3-web of triangles, Sec. 4.2), the diagonals in the colour `diagonal`.
    for k in range(count):
        line(p, 2, start + spacing * k, 21, start + spacing * k, INK)
        line(p, start + spacing * k, 2, start + spacing * k, 21, INK)
    for m in range(1, 2 * count - 2):
        for x in range(start, 22):
            if start <= 2 * start + spacing * m - x <= 21:
                dot(p, x, 2 * start + spacing * m - x, diagonal)


def strip_web():
    p = canvas()
    web(p, 4, 6, 3, ACCENT)
    return p


def optimise_web():
    # A 3-web whose vertices (the accent squares) the optimisation moves until each family is exact (Sec. 3.5).
    p = canvas()
    web(p, 3, 7, 4, INK)
    for i in range(3):
        for j in range(3):
            for dx in (-1, 0, 1):
                for dy in (-1, 0, 1):
                    dot(p, 4 + 7 * i + dx, 4 + 7 * j + dy, ACCENT)
    return p


def library():
    p = strip_field()
    curve(p, lambda x: 21, ACCENT)
    return p


for name, draw in [("StripField", strip_field), ("LevelCurves", level_curves), ("RectifyingStrips", rectifying_strips),
                   ("StripQuality", strip_quality), ("TracePCurve", trace_p_curve), ("StripWeb", strip_web), ("OptimiseWeb", optimise_web),
                   ("Lamella", library)]:
    png(name + ".png", draw())
