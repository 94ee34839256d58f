#!/usr/bin/env python3
"""A synthetic airborne tile for `spinhash scene`: sloped terrain with a bump
and a curb (0.1 m spacing, 5 cm noise), the given vehicle scans (x y z text in
the model frame, e.g. from `spinhash scan ... -o v.las` and
las_class_filter.py) rested on it side by side and apart, a building, a wall,
a crate and a tree over the last vehicle; the ground under roofs is hidden.

make_scene_tile.py OUT.xyz TRUTH.csv SLOPE_DEG SIZE_M VEHICLE.xyz...
Writes x y z lines (UTM-like offsets) and a truth CSV: kind,name,x,y,yaw."""
import math
import random
import sys

E0, N0, U0 = 512000.0, 5400000.0, 300.0
out, truth_path, slope, size = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
vehicles = sys.argv[5:]
rng = random.Random(7)
k = math.tan(math.radians(slope))


def terrain(x, y):
    bump = 0.4 * math.exp(-((x + 8) ** 2 + (y - 8) ** 2) / (2 * 2.0 ** 2))
    return k * x + bump + (0.15 if y > -10 else 0.0)


pts = []
roofs = []  # (cx, cy, yaw, hx, hy)
truth = []


def box(cx, cy, yaw, sx, sy, sz, clearance, spacing, kind):
    c, s = math.cos(yaw), math.sin(yaw)
    roofs.append((cx, cy, yaw, sx / 2, sy / 2))
    truth.append((kind, kind, cx, cy, yaw))
    faces = []
    nx, ny, nz = int(sx / spacing) + 1, int(sy / spacing) + 1, int(sz / spacing) + 1
    for i in range(nx):
        for j in range(ny):
            faces.append((i * spacing - sx / 2, j * spacing - sy / 2, sz))
    for i in range(nx):
        for h in range(nz):
            faces += [(i * spacing - sx / 2, -sy / 2, h * spacing), (i * spacing - sx / 2, sy / 2, h * spacing)]
    for j in range(ny):
        for h in range(nz):
            faces += [(-sx / 2, j * spacing - sy / 2, h * spacing), (sx / 2, j * spacing - sy / 2, h * spacing)]
    for u, v, z in faces:
        x, y = cx + c * u - s * v, cy + s * u + c * v
        pts.append((x, y, terrain(x, y) + clearance + z))


def vehicle(path, cx, cy, yaw):
    model = [tuple(map(float, line.split())) for line in open(path)]
    mx = sum(p[0] for p in model) / len(model)
    my = sum(p[1] for p in model) / len(model)
    z0 = min(p[2] for p in model)
    xs = [p[0] - mx for p in model]
    ys = [p[1] - my for p in model]
    roofs.append((cx, cy, yaw, (max(xs) - min(xs)) / 2, (max(ys) - min(ys)) / 2))
    a = math.atan(k)
    ca, sa, c, s = math.cos(a), math.sin(a), math.cos(yaw), math.sin(yaw)
    base = terrain(cx, cy)
    for (x, y, z) in model:
        x1, y1, z1 = c * (x - mx) - s * (y - my), s * (x - mx) + c * (y - my), z - z0
        pts.append((cx + ca * x1 - sa * z1, cy + y1, base + sa * x1 + ca * z1))
    name = path.rsplit("/", 1)[-1].split(".")[0].split("_")[0]
    truth.append(("vehicle", name, cx, cy, yaw))


half = size / 2
def width(path):
    ys = [float(line.split()[1]) for line in open(path)]
    return max(ys) - min(ys)


places = [(-half + 8, -half + 8, 0.0), None, (0.0, 0.0, 1.1),
          (half - 9, 4.0, 2.0), (6.0, -half + 9, 0.5), (-6.0, 5.0, -0.7), (10.0, 12.0, 0.3)]
if len(vehicles) > 1:  # the second parked beside the first, 0.7 m apart
    places[1] = (-half + 8, -half + 8 + (width(vehicles[0]) + width(vehicles[1])) / 2 + 0.7, 0.0)
for path, (cx, cy, yaw) in zip(vehicles, places):
    vehicle(path, cx, cy, yaw)
box(-half + 10, half - 9, 0.0, 12.0, 9.0, 6.0, 0.0, 0.2, "building")
box(half - 10, half - 4, 0.2, 14.0, 0.25, 2.0, 0.0, 0.1, "wall")
box(half - 4, -half + 4, 0.0, 1.0, 1.0, 0.8, 0.0, 0.1, "crate")
# Tree over the vehicle at `places[-1]` of the ones given: crown 4-9 m.
tx, ty = places[len(vehicles) - 1][:2]
for i in range(3000):
    zc = rng.uniform(-1, 1)
    t = rng.uniform(0, 2 * math.pi)
    r = math.sqrt(1 - zc * zc)
    pts.append((tx + 0.5 + 2.5 * r * math.cos(t), ty + 0.5 + 2.5 * r * math.sin(t), terrain(tx, ty) + 6.5 + 2.5 * zc))
truth.append(("tree", "tree", tx + 0.5, ty + 0.5, 0.0))


def under_roof(x, y):
    for cx, cy, yaw, hx, hy in roofs:
        dx, dy = x - cx, y - cy
        u = math.cos(yaw) * dx + math.sin(yaw) * dy
        v = -math.sin(yaw) * dx + math.cos(yaw) * dy
        if abs(u) < hx and abs(v) < hy:
            return True
    return False


steps = int(size / 0.1)
for j in range(steps + 1):
    for i in range(steps + 1):
        x = -half + i * 0.1 + rng.uniform(-0.025, 0.025)
        y = -half + j * 0.1 + rng.uniform(-0.025, 0.025)
        if under_roof(x, y):
            continue
        pts.append((x, y, terrain(x, y) + rng.gauss(0, 0.05)))
with open(out, "w") as f:
    for x, y, z in pts:
        f.write("%.3f %.3f %.3f\n" % (x + E0, y + N0, z + U0))
with open(truth_path, "w") as f:
    f.write("kind,name,x,y,yaw\n")
    for kind, name, x, y, yaw in truth:
        f.write("%s,%s,%.3f,%.3f,%.3f\n" % (kind, name, x + E0, y + N0, yaw))
print(len(pts), "points", file=sys.stderr)
