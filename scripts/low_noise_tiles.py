#!/usr/bin/env python3
"""Low noise that a file does not class as noise: tiles from `spinhash
scan-scene` with points added under the ground (multipath returns, 2-20 m
below a real return, one per RATE m^2 of the tile, unclassified) through
`spinhash scene`. Each truth vehicle is matched to the scene's vehicle
nearest its centre (within 2 m). Writes DIR/low_noise.csv and prints, per
rate, the share of points classed ground, the vehicles found and those
named right first, as Markdown; the CSV also has the points the scene
counted as low noise. The scene's low-noise test leaves such
points out of the terrain; --noise-gap 0 switches it off, to compare. A
file that classes such points 7 (low noise) has them left out by the
reader: tests/host/test_tile_stream.cpp holds that case.

  scripts/low_noise_tiles.py --spinhash build/host-tools/spinhash --db DB.shdb \
      --meshes DB_MESH_DIR --out DIR [--rates 0,180,60,18] [--seeds 1-3] [--size 60] [--vehicles 8] \
      [--spacing M] [--noise-gap M]
"""
import argparse, csv, json, math, os, re, subprocess, sys

import numpy as np


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("%s: exit %d: %s" % (" ".join(cmd[:3]), r.returncode, r.stderr[-400:]))
    return r


def read_ply_xyz(path):
    raw = open(path, "rb").read()
    end = raw.index(b"end_header\n") + len(b"end_header\n")
    header = raw[:end].decode()
    if "format binary_little_endian" not in header or "property double x" not in header:
        sys.exit("%s: expected scan-scene's binary PLY of double x y z" % path)
    n = int(re.search(r"element vertex (\d+)", header).group(1))
    return np.frombuffer(raw[end:end + 24 * n], dtype="<f8").reshape(n, 3)


def write_ply_xyz(path, xyz):
    with open(path, "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\n"
                 "property double x\nproperty double y\nproperty double z\nend_header\n" % len(xyz)).encode())
        f.write(np.ascontiguousarray(xyz, dtype="<f8").tobytes())


def main():
    ap = argparse.ArgumentParser()
    for k in ("--spinhash", "--db", "--meshes", "--out"):
        ap.add_argument(k, required=True)
    ap.add_argument("--rates", default="0,180,60,18", help="m^2 of tile per low point (0: none)")
    ap.add_argument("--seeds", default="1-3")
    ap.add_argument("--size", type=float, default=60.0)
    ap.add_argument("--vehicles", type=int, default=8)
    ap.add_argument("--spacing", help="scan-scene's --spacing, m (default: scan-scene's)")
    ap.add_argument("--noise-gap", help="scene's --terrain-noise-gap (0: the low-noise test off; default: scene's)")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    lo, hi = map(int, a.seeds.split("-"))
    rates = [float(r) for r in a.rates.split(",")]
    rows = {r: {"low": 0, "points": 0, "ground": 0, "left_out": 0, "truth": 0, "found": 0, "right": 0} for r in rates}
    for seed in range(lo, hi + 1):
        tile = os.path.join(a.out, "tile%d.ply" % seed)
        spacing = [] if a.spacing is None else ["--spacing", a.spacing]
        run([a.spinhash, "scan-scene", a.meshes, "-o", tile, "--size", str(a.size), "--vehicles",
             str(a.vehicles), "--trees", "4", "--seed", str(seed)] + spacing)
        truth = [t for t in csv.DictReader(open(tile + ".truth.csv")) if t["kind"] == "vehicle"]
        xyz = read_ply_xyz(tile)
        rng = np.random.default_rng(seed)
        for rate in rates:
            n = 0 if rate == 0 else int(round(a.size * a.size / rate))
            under = xyz[rng.choice(len(xyz), n, replace=False)].copy()
            under[:, 2] -= rng.uniform(2.0, 20.0, n)
            noisy = os.path.join(a.out, "tile%d-low%g.ply" % (seed, rate))
            write_ply_xyz(noisy, np.vstack([xyz, under]))
            gap = [] if a.noise_gap is None else ["--terrain-noise-gap", a.noise_gap]
            r = run([a.spinhash, "scene", "--db", a.db, noisy] + gap)
            m = re.search(r"points (\d+), non-finite \d+, ground (\d+)", r.stderr)
            objects = [json.loads(l) for l in r.stdout.splitlines() if l.startswith("{")]
            vehicles = [o for o in objects if o.get("kind") == "vehicle"]
            row = rows[rate]
            row["low"] += n
            row["points"] += int(m.group(1))
            row["ground"] += int(m.group(2))
            left = re.search(r"low noise (\d+)", r.stderr)  # printed when the test left points out
            row["left_out"] += int(left.group(1)) if left else 0
            for t in truth:
                c = (float(t["center_x"]), float(t["center_y"]))
                near = [(math.hypot(o["center"][0] - c[0], o["center"][1] - c[1]), o) for o in vehicles]
                near = [p for p in near if p[0] <= 2.0]
                row["truth"] += 1
                if near:
                    row["found"] += 1
                    best = min(near, key=lambda p: p[0])[1]
                    row["right"] += best.get("model") == t["model"]
    with open(os.path.join(a.out, "low_noise.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["m2_per_low_point", "low_points", "points", "ground_points", "low_noise_points", "vehicles",
                    "found", "right"])
        for rate in rates:
            r = rows[rate]
            w.writerow(["%g" % rate, r["low"], r["points"], r["ground"], r["left_out"], r["truth"], r["found"],
                        r["right"]])
    print("| low points (one per m2) | low points | points classed ground | vehicles found | named right first |")
    print("| --- | ---: | ---: | ---: | ---: |")
    for rate in rates:
        r = rows[rate]
        print("| %s | %d | %.1f %% | %d / %d | %d |" % ("none" if rate == 0 else "%g" % rate, r["low"],
                                                       100.0 * r["ground"] / max(1, r["points"]), r["found"],
                                                       r["truth"], r["right"]))


if __name__ == "__main__":
    main()
