#!/usr/bin/env python3
"""Tiles with non-vehicles of a vehicle's size (`spinhash scan-scene --sheds
--containers --bushes --heaps`) through `spinhash scene`, against one or
more databases of the same models (for instance built with each
`--calibration-clutter`): per database and point spacing, the flags each
answer level raises on the vehicles (right and wrong) and on the clutter
(every one wrong). An answer goes to the truth object whose footprint
holds its centre (1 m slack); a vehicle's class and group are its model's,
as `spinhash info` gives them.

  scripts/clutter_tiles.py --spinhash build/host-tools/spinhash --meshes MESH_DIR \\
      --db LABEL=DB.shdb [--db LABEL=DB.shdb ...] --out DIR [--spacings 0.1,0.2]
      [--seeds 201-230] [--per-kind 2] [--size 50]

Writes DIR/clutter_tiles.csv (one row per database, spacing and kind of
object) and prints Markdown tables. Tiles and answers are kept in DIR: a
second run only adds what is missing.
"""
import argparse, csv, json, math, os, subprocess, sys
from collections import Counter, defaultdict

LEVELS = ("vehicle", "group", "class", "model")
CLUTTER = ("shed", "container", "bush", "heap")


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("%s: exit %d: %s" % (" ".join(cmd[:2]), r.returncode, r.stderr[-400:]))
    return r.stdout


def truth_of(x, y, truth):
    for t in truth:
        h = math.radians(float(t["heading_deg"]))
        dx, dy = x - float(t["center_x"]), y - float(t["center_y"])
        along, across = dx * math.cos(h) + dy * math.sin(h), -dx * math.sin(h) + dy * math.cos(h)
        if abs(along) <= float(t["length"]) / 2 + 1 and abs(across) <= float(t["width"]) / 2 + 1:
            return t
    return None


def score(answers, truth, models, counts):
    for t in truth:
        counts[t["kind"]]["objects"] += 1
    for a in answers:
        if a.get("kind") != "vehicle":
            continue
        t = truth_of(a["center"][0], a["center"][1], truth)
        kind = t["kind"] if t else "nothing"
        c = counts[kind]
        c["answered"] += 1
        truth_of_level = {}
        if kind == "vehicle":
            m = models[t["model"]]
            truth_of_level = {"vehicle": True, "group": m["group"], "class": m["class"], "model": t["model"]}
        c["flagged"] += any(a["levels"][level]["confident"] for level in LEVELS)
        named = {"vehicle": True, "group": a.get("group"), "class": a.get("class"), "model": a.get("model")}
        for level in LEVELS:
            if not a["levels"][level]["confident"]:
                continue
            right = bool(truth_of_level) and named[level] == truth_of_level[level]
            c[level + (" right" if right else " wrong")] += 1


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--spinhash", required=True)
    ap.add_argument("--meshes", required=True)
    ap.add_argument("--db", action="append", required=True, help="LABEL=DB.shdb")
    ap.add_argument("--out", required=True)
    ap.add_argument("--spacings", default="0.1,0.2")
    ap.add_argument("--seeds", default="201-230")
    ap.add_argument("--per-kind", default="2")
    ap.add_argument("--size", default="50")
    a = ap.parse_args()
    lo, hi = map(int, a.seeds.split("-"))
    dbs = [d.split("=", 1) for d in a.db]
    info = json.loads(run([a.spinhash, "info", "--format", "json", dbs[0][1]]))
    models = {m["name"]: m for m in info["model_list"]}
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for sp in a.spacings.split(","):
        counts = {label: defaultdict(Counter) for label, _ in dbs}
        for seed in range(lo, hi + 1):
            tile = os.path.join(a.out, "t_%s_%d.las" % (sp, seed))
            if not os.path.exists(tile):
                sized = sum(([flag, a.per_kind] for flag in ("--sheds", "--containers", "--bushes", "--heaps")), [])
                run([a.spinhash, "scan-scene", a.meshes, "--size", a.size, "--spacing", sp, "--seed", str(seed),
                     "-o", tile] + sized)
            with open(tile + ".truth.csv") as f:
                truth = list(csv.DictReader(f))
            for label, db in dbs:
                out = os.path.join(a.out, "t_%s_%d.%s.jsonl" % (sp, seed, label))
                if not os.path.exists(out):
                    text = run(["nice", a.spinhash, "scene", "--db", db, tile])
                    with open(out, "w") as f:
                        f.write(text)
                with open(out) as f:
                    answers = [json.loads(l) for l in f if l.strip()]
                score(answers, truth, models, counts[label])
        print("\n%s m spacing (%.0f points per m^2), seeds %s, %s of each kind a tile:\n"
              % (sp, 1 / float(sp) ** 2, a.seeds, a.per_kind))
        print("| database | vehicles | answered | " + " | ".join("%s flag right / wrong" % l for l in LEVELS)
              + " | clutter | answered | " + " | ".join("%s flag" % l for l in LEVELS) + " |")
        print("| --- |" + " ---: |" * (2 + len(LEVELS) + 2 + len(LEVELS)))
        for label, _ in dbs:
            v = counts[label]["vehicle"]
            cl = Counter()
            for k in CLUTTER:
                cl.update(counts[label][k])
            print("| %s | %d | %d | " % (label, v["objects"], v["answered"])
                  + " | ".join("%d / %d" % (v[l + " right"], v[l + " wrong"]) for l in LEVELS)
                  + " | %d | %d | " % (cl["objects"], cl["answered"])
                  + " | ".join("%d" % cl[l + " wrong"] for l in LEVELS) + " |")
        print("\nPer kind, answered as a vehicle / flagged at any level:\n")
        print("| database | " + " | ".join(CLUTTER) + " |")
        print("| --- |" + " ---: |" * len(CLUTTER))
        for label, _ in dbs:
            c = counts[label]
            print("| %s | " % label + " | ".join("%d / %d of %d" % (c[k]["answered"], c[k]["flagged"], c[k]["objects"])
                                                for k in CLUTTER) + " |")
        for label, _ in dbs:
            for kind, c in sorted(counts[label].items()):
                rows.append(dict(database=label, spacing=sp, kind=kind, objects=c["objects"], answered=c["answered"],
                                 flagged=c["flagged"],
                                 **{"%s_%s" % (l, w): c[l + " " + w] for l in LEVELS for w in ("right", "wrong")}))
    with open(os.path.join(a.out, "clutter_tiles.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
