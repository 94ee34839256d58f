#!/usr/bin/env python3
"""Which confidence gate withholds right answers (docs/results.md, "Real cars").

Scans every mesh of the given folders (3 views, 0.10 m, random pose, seeds
1-5) clean, with 10 cm noise and 20 % occlusion, and with a 5-degree ground
square as well; recognises them with the defaults and with each gate of
`confident` relaxed in turn (the margin, the extent test, the residual F,
the fit), and lists for every right answer left unflagged the relaxations
that flag it, and how many wrong answers each relaxation would flag.

  scripts/confidence_gates.py SPINHASH OUT_DIR MESH_FOLDER...
"""
import json, os, subprocess, sys, glob
S = sys.argv[1]; out = sys.argv[2]; meshes = sys.argv[3:]
conds = {"clean": [], "ground": ["--noise", "0.1", "--occlusion", "0.2", "--ground", "3.2", "--ground-slope", "5"],
         "noisy": ["--noise", "0.1", "--occlusion", "0.2"]}
relax = {"default": [], "extent": ["--max-extent-shortfall", "1e6", "--max-extent-overhang", "1e6"],
         "residual": ["--max-residual-f", "1e6"], "margin": ["--min-margin", "0"],
         "fit": ["--min-inlier-fraction", "0", "--min-mean-log-likelihood", "-1e6"]}
db = os.path.join(out, "cars.shdb")
if not os.path.exists(db):
    subprocess.run([S, "build", "--quiet", "-o", db] + meshes, check=True)
files = sorted(f for m in meshes for f in glob.glob(m + "/*.obj"))
qs = []
for f in files:
    name = os.path.basename(f)[:-4]
    for c, extra in conds.items():
        for seed in range(1, 6):
            q = os.path.join(out, "%s_%s_%d.ply" % (name, c, seed))
            if not os.path.exists(q):
                subprocess.run([S, "scan", f, "--spacing", "0.1", "--random-pose", "--seed", str(seed), "-o", q] + extra,
                               check=True, capture_output=True)
            qs.append((q, name, c))
res = {}
for r, flags in relax.items():
    lines = subprocess.run([S, "recognize", "--db", db] + flags + [q[0] for q in qs], capture_output=True,
                           text=True).stdout.splitlines()
    res[r] = [json.loads(l) for l in lines]
for c in conds:
    idx = [i for i, q in enumerate(qs) if q[2] == c]
    right = [i for i in idx if res["default"][i]["ranking"] and res["default"][i]["ranking"][0]["model"] == qs[i][1]]
    conf = [i for i in right if res["default"][i]["confident"]]
    wrongconf = [i for i in idx if res["default"][i]["confident"] and i not in right]
    print("%s: %d queries, %d right, %d confident right, %d confident wrong" % (c, len(idx), len(right), len(conf), len(wrongconf)))
    for i in right:
        if res["default"][i]["confident"]: continue
        flips = [r for r in relax if r != "default" and res[r][i]["confident"]]
        print("   %-40s released by %s" % (os.path.basename(qs[i][0]), flips))
    for r in relax:
        if r == "default": continue
        bad = [i for i in idx if res[r][i]["confident"] and not (res[r][i]["ranking"][0]["model"] == qs[i][1])]
        print("   relaxing %s: confident wrong %d" % (r, len(bad)))
