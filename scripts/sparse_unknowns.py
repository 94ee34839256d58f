#!/usr/bin/env python3
"""Sparse scans (10-30 points per m^2) of vehicles in and out of a database.

Measures, through the spinhash command: class right first, confident model
answers (and how many are right), and how often vehicles that are NOT in the
database are flagged confident at model level or confident in a wrong class.

  scripts/sparse_unknowns.py --spinhash build/host-tools/spinhash --out DIR \
      [--per-family 8] [--spacings 0.35,0.45,0.55] [--seeds 1]

The fleet: `spinhash generate` members 0..per_family-1 of each family go into
the database; members per_family..2*per_family-1 are unknown vehicles of a
known class; stretched and shortened copies of database members (x 1.12,
x 0.90 along the length, x 1.08 across) are unknown vehicles close to known
ones. --extra-unknown adds folders of other meshes as unknown vehicles, each
folder named after the class of its meshes (the real cars of
scripts/prepare-cars.sh: out/cars/meshes/sedan,out/cars/meshes/other);
--only-extra scans only those. Density is the scan's points per m^2 of the
scanned mesh's footprint (the measure of the recognizer's evidence gate,
sides included).
"""
import argparse, json, os, subprocess, sys
from collections import defaultdict

# Scan settings per condition. clean, noisy: the paper's query scans (3 views
# at 45 degrees elevation, 45 degrees apart), whose ground holds far fewer
# points per m^2 than the vehicle. survey: two opposite flight lines at 70
# degrees elevation, the ground at 1.9 / spacing^2 points per m^2 (0.3 m:
# 21, 0.4 m: 12), as an airborne survey; survey_ground with the ground, 5 cm
# noise and a tilt.
CONDITIONS = {
    "clean": lambda a: [],
    "noisy": lambda a: ["--noise", str(a.noise), "--ground", str(a.ground), "--tilt"],
    "survey": lambda a: ["--views", "2", "--elevation", "70", "--azimuth-step", "180"],
    "survey_ground": lambda a: ["--views", "2", "--elevation", "70", "--azimuth-step", "180", "--noise",
                                str(a.noise), "--ground", str(a.ground), "--tilt"],
}
STRETCHES = {"long": (1.12, 1.0), "short": (0.90, 1.0), "wide": (1.0, 1.08)}


def run(cmd, ok_codes=(0,)):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode not in ok_codes:
        sys.exit("%s: exit %d: %s" % (" ".join(cmd[:3]), r.returncode, r.stderr[-500:]))
    return r.stdout


def family(name):
    return name.split("-")[0].split("~")[0]


def stretch_obj(src, dst, sx, sy):
    with open(src) as f, open(dst, "w") as g:
        for line in f:
            if line.startswith("v "):
                x, y, z = map(float, line.split()[1:4])
                line = "v %.6f %.6f %.6f\n" % (x * sx, y * sy, z)
            g.write(line)


def footprint(path):
    xs, ys = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                p = line.split()
                xs.append(float(p[1]))
                ys.append(float(p[2]))
    return (max(xs) - min(xs)) * (max(ys) - min(ys))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--spinhash", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--per-family", type=int, default=8)
    ap.add_argument("--spacings", default="0.35,0.45,0.55")
    ap.add_argument("--seeds", default="1")
    ap.add_argument("--noise", type=float, default=0.05)
    ap.add_argument("--ground", type=float, default=6.0, help="ground square half size with the noisy scans")
    ap.add_argument("--conds", default="clean,noisy", help="of CONDITIONS: clean, noisy, survey, survey_ground")
    ap.add_argument("--extra-unknown", default="", help="comma-separated mesh folders of unknown vehicles, each named after its class")
    ap.add_argument("--recognize-args", default="", help="more flags for spinhash recognize, e.g. '--mode sran'")
    ap.add_argument("--only-extra", action="store_true", help="scan only the --extra-unknown vehicles")
    a = ap.parse_args()
    S, out = a.spinhash, a.out
    os.makedirs(out, exist_ok=True)
    fleet, db_dir, unk_dir = (os.path.join(out, d) for d in ("fleet", "db", "unknown"))
    db = os.path.join(out, "db.shdb")
    if not os.path.exists(db):
        run([S, "generate", "--count", str(14 * a.per_family), "-o", fleet])
        os.makedirs(db_dir, exist_ok=True)
        os.makedirs(unk_dir, exist_ok=True)
        for f in sorted(os.listdir(fleet)):
            idx = int(f.split("-")[1].split(".")[0])
            os.link(os.path.join(fleet, f), os.path.join(db_dir if idx < a.per_family else unk_dir, f))
        for f in sorted(os.listdir(db_dir)):
            for tag, (sx, sy) in STRETCHES.items():
                stretch_obj(os.path.join(db_dir, f), os.path.join(unk_dir, f[:-4] + "_" + tag + ".obj"), sx, sy)
        run([S, "build", "--quiet", "-o", db, db_dir])
    queries = []  # (path of scan, truth model or None, truth class, area, condition)
    qdir = os.path.join(out, "scans")
    os.makedirs(qdir, exist_ok=True)
    sources = [] if a.only_extra else [(True, db_dir, None), (False, unk_dir, None)]
    sources += [(False, d, os.path.basename(d.rstrip("/"))) for d in a.extra_unknown.split(",") if d]
    for known, d, cls in sources:
        for f in sorted(x for x in os.listdir(d) if x.endswith(".obj")):
            mesh = os.path.join(d, f)
            area = footprint(mesh)
            for sp in a.spacings.split(","):
                for seed in a.seeds.split(","):
                    for cond in a.conds.split(","):
                        q = os.path.join(qdir, "%s_%s_%s_%s.ply" % (f[:-4], sp, seed, cond))
                        if not os.path.exists(q):
                            extra = CONDITIONS[cond](a)
                            run([S, "scan", mesh, "--spacing", sp, "--random-pose", "--seed", seed, "-o", q] + extra)
                        queries.append((q, f[:-4] if known else None, cls or family(f), area, cond, sp))
    rows = []
    chunk = 64
    for i in range(0, len(queries), chunk):
        part = queries[i:i + chunk]
        lines = run(["nice", S, "recognize", "--db", db] + a.recognize_args.split() + [q[0] for q in part], ok_codes=(0, 3)).splitlines()
        assert len(lines) == len(part), (len(lines), len(part))
        for q, line in zip(part, lines):
            d = json.loads(line)
            ok = d["status"] == "ok"
            pts = d["stats"]["points"] - d["stats"]["points_ground"]
            rows.append(dict(query=os.path.basename(q[0]), known=q[1] is not None, truth=q[1], truth_class=q[2],
                             cond=q[4], spacing=q[5], density=pts / q[3], points=pts, features=d["stats"]["features"],
                             status=d["status"], model=d["ranking"][0]["model"] if d["ranking"] else None,
                             confident=d["confident"], cls=d.get("class"), class_confident=d.get("class_confident")))
    with open(os.path.join(out, "rows.jsonl"), "w") as f:
        for r in rows:
            f.write(json.dumps(r) + "\n")
    report(rows, out)


def pct(n, d):
    return "%d/%d (%.1f%%)" % (n, d, 100.0 * n / d) if d else "0/0"


def report(rows, out):
    lines = []
    groups = defaultdict(list)
    for r in rows:
        groups[(r["known"], r["cond"])].append(r)
    lines.append("| queries | cond | n | density p10-p90 | class right first | class confident | class confident right | model confident | model confident right |")
    lines.append("|---|---|---|---|---|---|---|---|---|")
    for (known, cond), rs in sorted(groups.items(), key=lambda k: (not k[0][0], k[0][1])):
        n = len(rs)
        dens = sorted(r["density"] for r in rs)
        cr = sum(r["cls"] == r["truth_class"] for r in rs)
        cc = [r for r in rs if r["class_confident"]]
        mc = [r for r in rs if r["confident"]]
        lines.append("| %s | %s | %d | %.0f-%.0f | %s | %s | %s | %s | %s |" % (
            "in database" if known else "unknown", cond, n, dens[n // 10], dens[(9 * n) // 10], pct(cr, n),
            pct(len(cc), n), pct(sum(r["cls"] == r["truth_class"] for r in cc), len(cc)), pct(len(mc), n),
            pct(sum(r["model"] == r["truth"] for r in mc), len(mc))))
    unk = [r for r in rows if not r["known"]]
    lines.append("")
    lines.append("unknown vehicles: model confident %s; confident in a wrong class %s" % (
        pct(sum(r["confident"] for r in unk), len(unk)),
        pct(sum(bool(r["class_confident"]) and r["cls"] != r["truth_class"] for r in unk), len(unk))))
    sparse = [r for r in rows if 10 <= r["density"] <= 30]
    lines.append("density 10-30 per m^2 (all queries): class right first %s; unknown model confident %s; "
                 "unknown wrong-class confident %s" % (
                     pct(sum(r["cls"] == r["truth_class"] for r in sparse), len(sparse)),
                     pct(sum(r["confident"] for r in sparse if not r["known"]), sum(not r["known"] for r in sparse)),
                     pct(sum(bool(r["class_confident"]) and r["cls"] != r["truth_class"] for r in sparse if not r["known"]),
                         sum(not r["known"] for r in sparse))))
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write(text + "\n")


if __name__ == "__main__":
    main()
