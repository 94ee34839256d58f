#!/usr/bin/env python3
"""Writes the x y z of the points of one ASPRS class of a LAS 1.x file (point
formats 0-5) as text: las_class_filter.py IN.las CLASS OUT.xyz"""
import struct
import sys

data = open(sys.argv[1], "rb").read()
want = int(sys.argv[2])
offset, = struct.unpack_from("<I", data, 96)
fmt, rec_len, count = struct.unpack_from("<BHI", data, 104)
scale = struct.unpack_from("<3d", data, 131)
origin = struct.unpack_from("<3d", data, 155)
assert fmt <= 5, "point formats 0-5 only"
with open(sys.argv[3], "w") as out:
    for i in range(count):
        at = offset + i * rec_len
        x, y, z = struct.unpack_from("<3i", data, at)
        if data[at + 15] & 0x1F != want:
            continue
        out.write("%.4f %.4f %.4f\n" % (x * scale[0] + origin[0], y * scale[1] + origin[1], z * scale[2] + origin[2]))
