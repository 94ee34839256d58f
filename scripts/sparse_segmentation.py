#!/usr/bin/env python3
"""Vehicles found on sparse simulated tiles (`spinhash scan-scene`, 4 oblique
views, points per m^2 of level ground = 1 / spacing^2) by `spinhash scene`
with the segmentation cell grown to the tile's point spacing (the default)
and with the finest cell kept at 0.25 m (`--segment-cell 0.0625`: its two
doublings stop at 0.25 m on any tile under 64 points per m^2). Each truth
vehicle is matched to the scene object nearest its centre (within 2 m):
found when that object is a vehicle candidate; flagged when the answer's
level is the group or finer; right when the flagged group is the truth's
(include/spinhash/vehicle_classes.h: light, heavy, armoured).

  scripts/sparse_segmentation.py --spinhash build/host-tools/spinhash --db DB.shdb \\
      --meshes DB_MESH_DIR [--unknown MESH_DIR ...] --out DIR [--spacings 0.3,0.35,0.5,0.7] [--seeds 1-3]

With --unknown the tiles hold only those vehicles (none of them in the
database: a world left out), each folder's name its class; else the
database's own, their class the family of their name (`spinhash generate`'s
`sedan-03`). A class outside GROUP_OF (other) counts as found only. Writes DIR/sparse_segmentation.csv and prints a Markdown
table.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

GROUP_OF = {"sedan": "light", "suv": "light", "van": "light", "pickup": "light", "truck": "heavy",
            "bus": "heavy", "apc": "armoured", "tracked": "armoured"}
FINEST_KEPT = "0.0625"  # two doublings reach 0.25 m only


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode not in (0, 3):
        sys.exit("%s: exit %d: %s" % (" ".join(cmd[:2]), r.returncode, r.stderr[-400:]))
    return r


def seeds_of(text):
    lo, _, hi = text.partition("-")
    return list(range(int(lo), int(hi or lo) + 1))


def group_of_mesh(unknown_dirs):
    """Mesh stem -> "light", "heavy" or None, from the folder it lies in."""
    groups = {}
    for d in unknown_dirs:
        cls = os.path.basename(os.path.normpath(d))
        for f in os.listdir(d):
            stem = os.path.splitext(f)[0]
            groups[stem] = GROUP_OF.get(cls)
    return groups


def truth_group(model, groups):
    if model in groups:
        return groups[model]
    for stem, g in groups.items():  # scan-scene may shorten a stem
        if stem.startswith(model) or model.startswith(stem):
            return g
    return GROUP_OF.get(model.split("-")[0])


def score(tile, objs, groups):
    found = flagged = right = total = 0
    rows = list(csv.DictReader(open(tile + ".truth.csv", newline="")))
    for t in rows:
        if t["kind"] not in ("vehicle", "unknown_vehicle"):
            continue
        total += 1
        cx, cy = float(t["center_x"]), float(t["center_y"])
        near = [(math.hypot(o["center"][0] - cx, o["center"][1] - cy), o) for o in objs if "center" in o]
        near = [n for n in near if n[0] < 2.0]
        if not near:
            continue
        o = min(near, key=lambda n: n[0])[1]
        if o.get("kind") != "vehicle":
            continue
        found += 1
        if o.get("level") in ("group", "class", "model"):
            flagged += 1
            right += o.get("group") == truth_group(t["model"], groups)
    return total, found, flagged, right


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--spinhash", required=True)
    ap.add_argument("--db", required=True)
    ap.add_argument("--meshes", required=True, help="the database's meshes (scan-scene's MESHES)")
    ap.add_argument("--unknown", nargs="*", default=[], help="class folders of vehicles not in the database")
    ap.add_argument("--out", required=True)
    ap.add_argument("--spacings", default="0.3,0.35,0.5,0.7")
    ap.add_argument("--seeds", default="1-3")
    ap.add_argument("--size", type=float, default=80.0)
    ap.add_argument("--vehicles", type=int, default=16)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    groups = group_of_mesh(a.unknown)
    rows = []
    for spacing in [float(s) for s in a.spacings.split(",")]:
        for label, extra in (("grown", []), ("0.25 m kept", ["--segment-cell", FINEST_KEPT])):
            sums = [0, 0, 0, 0]
            density, cells = [], set()
            for seed in seeds_of(a.seeds):
                tile = os.path.join(a.out, f"tile-{spacing}-{seed}.las")
                if not os.path.exists(tile + ".truth.csv"):
                    who = (["--vehicles", "0", "--unknown", *a.unknown, "--unknown-vehicles", str(a.vehicles)]
                           if a.unknown else ["--vehicles", str(a.vehicles)])
                    run([a.spinhash, "scan-scene", a.meshes, "-o", tile, "--size", str(a.size), "--trees", "4",
                         "--spacing", str(spacing), "--seed", str(seed), *who])
                r = run([a.spinhash, "scene", "--db", a.db, *extra, tile])
                for line in r.stderr.splitlines():
                    if "segmentation cell" in line:
                        head = line.split(" points per m2, segmentation cell ")
                        density.append(float(head[0].rsplit(" ", 1)[1]))
                        cells.add(head[1].split(" m;")[0])
                objs = [json.loads(l) for l in r.stdout.splitlines() if l.startswith("{")]
                for k, v in enumerate(score(tile, objs, groups)):
                    sums[k] += v
            rows.append({"spacing_m": spacing, "points_per_m2": round(sum(density) / max(1, len(density)), 1),
                         "cell": label, "cells_m": "/".join(sorted(cells)), "vehicles": sums[0],
                         "found": sums[1], "group_flagged": sums[2], "group_right": sums[3]})
    with open(os.path.join(a.out, "sparse_segmentation.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print("| points per m2 | segmentation cell | cell used (m) | found / vehicles | group flag raised | right |")
    print("| ---: | --- | --- | ---: | ---: | ---: |")
    for r in rows:
        print(f"| {r['points_per_m2']} | {r['cell']} | {r['cells_m']} | {r['found']} / {r['vehicles']} "
              f"| {r['group_flagged']} | {r['group_right']} |")


if __name__ == "__main__":
    main()
