#!/usr/bin/env python3
"""Sparse airborne tiles (`spinhash scan-scene`, 4 oblique views, points per
m^2 of level ground = 1 / spacing^2) through `spinhash scene`: each vehicle
of the truth list matched to the scene object nearest its centre (within
2 m), scored at model and class level, vehicles of the database and unknown
ones (procedural members not in it) apart.

  scripts/sparse_tiles.py --spinhash build/host-tools/spinhash --db DB.shdb \
      --meshes DB_MESH_DIR --unknown UNKNOWN_MESH_DIR --out DIR [--spacings 0.2,0.3] [--seeds 1-8]

Run scripts/sparse_unknowns.py first: it makes DB.shdb and both mesh folders.
"""
import argparse, csv, json, math, os, subprocess, sys
from collections import defaultdict


def family(name):
    return name.split("-")[0].split("_")[0]


def run(cmd, ok=(0,)):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode not in ok:
        sys.exit("%s: exit %d: %s" % (" ".join(cmd[:3]), r.returncode, r.stderr[-400:]))
    return r.stdout


def pct(n, d):
    return "%d/%d (%.1f%%)" % (n, d, 100.0 * n / d) if d else "0/0"


def main():
    ap = argparse.ArgumentParser()
    for k in ("--spinhash", "--db", "--meshes", "--unknown", "--out"):
        ap.add_argument(k, required=True)
    ap.add_argument("--spacings", default="0.2,0.3")
    ap.add_argument("--seeds", default="1-8")
    a = ap.parse_args()
    lo, hi = map(int, a.seeds.split("-"))
    known = {f[:-4] for f in os.listdir(a.meshes)}
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for sp in a.spacings.split(","):
        for seed in range(lo, hi + 1):
            tile = os.path.join(a.out, "t_%s_%d.las" % (sp, seed))
            if not os.path.exists(tile):
                run([a.spinhash, "scan-scene", a.meshes, "--unknown", a.unknown, "--vehicles", "6",
                     "--unknown-vehicles", "6", "--size", "60", "--spacing", sp, "--seed", str(seed), "-o", tile])
            objects = [json.loads(l) for l in run(["nice", a.spinhash, "scene", "--db", a.db, tile]).splitlines()]
            with open(tile + ".truth.csv") as f:
                truth = [t for t in csv.DictReader(f) if t["kind"] in ("vehicle", "unknown_vehicle")]
            for t in truth:
                cx, cy = float(t["center_x"]), float(t["center_y"])
                best = min(objects, key=lambda o: math.hypot(o["center"][0] - cx, o["center"][1] - cy))
                found = math.hypot(best["center"][0] - cx, best["center"][1] - cy) < 2.0 and best["kind"] == "vehicle"
                rows.append(dict(spacing=sp, seed=seed, truth=t["model"], known=t["model"] in known,
                                 truth_class=family(t["model"]), found=found, points=int(t["points"]),
                                 model=best["model"] if found else None, confident=found and best["confident"],
                                 cls=best["class"] if found else None,
                                 class_confident=found and best["class_confident"]))
    with open(os.path.join(a.out, "rows.jsonl"), "w") as f:
        for r in rows:
            f.write(json.dumps(r) + "\n")
    lines = ["| points per m^2 | vehicles | n | points per vehicle p10-p90 | found | class right first | class confident | "
             "class confident right | model right first | model confident | model confident right |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    groups = defaultdict(list)
    for r in rows:
        groups[(r["spacing"], r["known"])].append(r)
    for (sp, k), rs in sorted(groups.items(), key=lambda g: (g[0][0], not g[0][1])):
        n = len(rs)
        pts = sorted(r["points"] for r in rs)
        cc = [r for r in rs if r["class_confident"]]
        mc = [r for r in rs if r["confident"]]
        lines.append("| %.0f | %s | %d | %d-%d | %s | %s | %s | %s | %s | %s | %s |" % (
            1.0 / float(sp) ** 2, "in database" if k else "unknown", n, pts[n // 10], pts[(9 * n) // 10],
            pct(sum(r["found"] for r in rs), n), pct(sum(r["cls"] == r["truth_class"] for r in rs), n),
            pct(len(cc), n), pct(sum(r["cls"] == r["truth_class"] for r in cc), len(cc)),
            pct(sum(r["model"] == r["truth"] for r in rs), n) if k else "-", pct(len(mc), n),
            pct(sum(r["model"] == r["truth"] for r in mc), len(mc))))
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(a.out, "summary.md"), "w") as f:
        f.write(text + "\n")


if __name__ == "__main__":
    main()
