#!/usr/bin/env python3
"""Renders an ASCII PLY with per-face colors (as written by `disk_uv --colored`)
to a PNG: orthographic view, software z-buffer, flat (Lambert) shading, thin
dark edges between faces of different colors. Standard library only.

usage: render_ply.py IN.ply OUT.png [--size 512] [--yaw DEG] [--pitch DEG]
"""
import argparse
import math
import struct
import sys
import zlib


def read_ply(path):
    with open(path, "r") as f:
        header = []
        while True:
            line = f.readline()
            if not line:
                sys.exit("render_ply: unexpected end of header in " + path)
            line = line.strip()
            header.append(line)
            if line == "end_header":
                break
        if "format ascii 1.0" not in header:
            sys.exit("render_ply: only ASCII PLY is supported")
        nv = nf = 0
        for h in header:
            parts = h.split()
            if parts[:2] == ["element", "vertex"]:
                nv = int(parts[2])
            elif parts[:2] == ["element", "face"]:
                nf = int(parts[2])
        tokens = f.read().split()
    pos = 0
    verts = []
    for _ in range(nv):
        verts.append((float(tokens[pos]), float(tokens[pos + 1]), float(tokens[pos + 2])))
        pos += 3
    faces = []
    for _ in range(nf):
        n = int(tokens[pos])
        idx = [int(t) for t in tokens[pos + 1:pos + 1 + n]]
        pos += 1 + n
        rgb = (int(tokens[pos]), int(tokens[pos + 1]), int(tokens[pos + 2]))
        pos += 3
        for i in range(1, n - 1):  # fan triangulation of polygons
            faces.append((idx[0], idx[i], idx[i + 1], rgb))
    return verts, faces


def write_png(path, width, height, rgb_rows):
    raw = b"".join(b"\x00" + bytes(row) for row in rgb_rows)

    def chunk(tag, data):
        c = struct.pack(">I", len(data)) + tag + data
        return c + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n"
    png += chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9))
    png += chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def render(verts, faces, size, yaw, pitch):
    cy, sy = math.cos(math.radians(yaw)), math.sin(math.radians(yaw))
    cp, sp = math.cos(math.radians(pitch)), math.sin(math.radians(pitch))
    # Rotate about y (yaw) then about x (pitch); the camera looks along -z.
    rv = []
    for x, y, z in verts:
        x1, z1 = cy * x + sy * z, -sy * x + cy * z
        y2, z2 = cp * y - sp * z1, sp * y + cp * z1
        rv.append((x1, y2, z2))
    xs = [p[0] for p in rv]
    ys = [p[1] for p in rv]
    span = max(max(xs) - min(xs), max(ys) - min(ys)) or 1.0
    margin = 0.05 * size
    scale = (size - 2 * margin) / span
    ox = (size - (max(xs) - min(xs)) * scale) / 2 - min(xs) * scale
    oy = (size - (max(ys) - min(ys)) * scale) / 2 - min(ys) * scale
    sv = [(p[0] * scale + ox, size - (p[1] * scale + oy), p[2]) for p in rv]

    light = (0.35, 0.45, 0.82)
    ln = math.sqrt(sum(c * c for c in light))
    light = tuple(c / ln for c in light)
    depth = [-1e300] * (size * size)
    color = [(255, 255, 255)] * (size * size)
    face_id = [-1] * (size * size)
    for fi, (a, b, c, rgb) in enumerate(faces):
        pa, pb, pc = rv[a], rv[b], rv[c]
        ux, uy, uz = pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]
        vx, vy, vz = pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]
        nx, ny, nz = uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx
        nl = math.sqrt(nx * nx + ny * ny + nz * nz)
        if nl == 0.0:
            continue
        lam = abs(nx * light[0] + ny * light[1] + nz * light[2]) / nl  # two-sided
        shade = 0.25 + 0.75 * lam
        col = tuple(min(255, int(ch * shade)) for ch in rgb)
        (x0, y0, z0), (x1, y1, z1), (x2, y2, z2) = sv[a], sv[b], sv[c]
        area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
        if area == 0.0:
            continue
        xmin = max(0, int(math.floor(min(x0, x1, x2))))
        xmax = min(size - 1, int(math.ceil(max(x0, x1, x2))))
        ymin = max(0, int(math.floor(min(y0, y1, y2))))
        ymax = min(size - 1, int(math.ceil(max(y0, y1, y2))))
        inv = 1.0 / area
        for py in range(ymin, ymax + 1):
            fy = py + 0.5
            row = py * size
            for px in range(xmin, xmax + 1):
                fx = px + 0.5
                w0 = ((x1 - fx) * (y2 - fy) - (x2 - fx) * (y1 - fy)) * inv
                w1 = ((x2 - fx) * (y0 - fy) - (x0 - fx) * (y2 - fy)) * inv
                w2 = 1.0 - w0 - w1
                if w0 < 0 or w1 < 0 or w2 < 0:
                    continue
                z = w0 * z0 + w1 * z1 + w2 * z2
                i = row + px
                if z > depth[i]:
                    depth[i] = z
                    color[i] = col
                    face_id[i] = fi
    # Darken pixels where the visible chart color changes (chart borders).
    out = list(color)
    for py in range(1, size - 1):
        row = py * size
        for px in range(1, size - 1):
            i = row + px
            f = face_id[i]
            if f < 0:
                continue
            rgb = faces[f][3]
            for j in (i + 1, i + size):
                g = face_id[j]
                if g >= 0 and faces[g][3] != rgb:
                    out[i] = (30, 30, 30)
                    break
    rows = []
    for py in range(size):
        r = bytearray()
        for px in range(size):
            r.extend(out[py * size + px])
        rows.append(r)
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("--size", type=int, default=512)
    ap.add_argument("--yaw", type=float, default=-35.0)
    ap.add_argument("--pitch", type=float, default=20.0)
    args = ap.parse_args()
    verts, faces = read_ply(args.input)
    write_png(args.output, args.size, args.size, render(verts, faces, args.size, args.yaw, args.pitch))


if __name__ == "__main__":
    main()
