#!/usr/bin/env python3
"""The CRS table of docs/crs-table.md: every public LAS/LAZ/COPC file of
shared/data through `spinhash scene` and through a survey of that file alone,
with the CRS and units each reports and the objects each finds.

    scripts/crs_table.py --spinhash build/host-tools/spinhash --db fleet.shdb \\
        --data ../shared/data --out docs/crs-table.md

The database is any spinhash database (the README's fleet.shdb); the table's
objects depend on it, its CRS and units do not. Runs every file twice (about
ten minutes on two cores: a few sparse files cover kilometres).
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

STATUS = re.compile(r"spinhash scene: [^:\n]+: ([^;\n]+); CRS (.*?); points (\d+)")
UNKNOWN = "unknown (the file's own coordinates, taken as metres)"


def cloud_files(data):
    out = []
    for root, _, files in os.walk(data):
        for f in files:
            if f.lower().endswith((".las", ".laz")):
                out.append(os.path.join(root, f))
    return sorted(out)


def short(text, n=90):
    text = " ".join(text.split())
    return text if len(text) <= n else text[: n - 1] + "…"


def scene(spinhash, db, path):
    r = subprocess.run([spinhash, "scene", "--db", db, path], capture_output=True, text=True)
    lines = [json.loads(l) for l in r.stdout.splitlines() if l.strip()]
    m = STATUS.search(r.stderr)
    if m:
        crs = "unknown (taken as metres)" if m.group(2) == UNKNOWN else m.group(2)
        note = "" if m.group(1) == "ok" else m.group(1)
        return {"exit": r.returncode, "crs": crs, "objects": len(lines), "note": note}
    why = lines[0].get("error", "") if lines else r.stderr.strip().splitlines()[0] if r.stderr.strip() else ""
    return {"exit": r.returncode, "crs": "", "objects": 0, "note": short(why.replace(path + ": ", ""))}


def survey(spinhash, db, path):
    with tempfile.TemporaryDirectory(prefix="spinhash-crs-table-") as out:
        r = subprocess.run([spinhash, "survey", "--db", db, "--out", out, "--jobs", "1", "--quiet", path],
                           capture_output=True, text=True)
        report = os.path.join(out, "survey.json")
        if not os.path.exists(report):
            return {"exit": r.returncode, "crs": "", "units": "", "objects": 0,
                    "note": short(r.stderr.strip().splitlines()[0] if r.stderr.strip() else "")}
        with open(report, encoding="utf-8") as f:
            s = json.load(f)
    units = s.get("crs_units") or {}
    unit_text = units.get("horizontal", "")
    if units.get("vertical") and units.get("vertical") != unit_text:
        unit_text += "; z " + units["vertical"]
    note = "; ".join(r_["reason"] for r_ in s["refused"]) if s["refused"] else ""
    if not note and any(t["status"] != "ok" for t in s["tiles"]):
        note = ", ".join(sorted({t["status"] for t in s["tiles"]}))
    return {"exit": r.returncode, "crs": s["crs"], "units": unit_text, "objects": sum(s["kinds"].values()),
            "note": short(note)}


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--spinhash", required=True)
    p.add_argument("--db", required=True)
    p.add_argument("--data", required=True, help="shared/data (its las/ and laz/ folders)")
    p.add_argument("--out", required=True, help="the markdown page to write")
    a = p.parse_args()
    rows = []
    files = cloud_files(a.data)
    for i, path in enumerate(files):
        rel = os.path.relpath(path, a.data)
        print(f"[{i + 1}/{len(files)}] {rel}", file=sys.stderr)
        sc, sv = scene(a.spinhash, a.db, path), survey(a.spinhash, a.db, path)
        rows.append((rel, sc, sv))
    with open(a.out, "w", encoding="utf-8") as f:
        f.write("# The CRS and units of the public sample files\n\n")
        f.write("Every LAS/LAZ/COPC file of `shared/data` (PDAL, laz-rs, laspy, laz-perf and LASzip test data;\n"
                "`shared/data/las/README.md` and `shared/data/laz/README.md` say what each is) through\n"
                "`spinhash scene` and through `spinhash survey` of that file alone: the CRS each reports\n"
                "(an EPSG code when the file gives one, else the CRS's own name), its units (x y; z when\n"
                "they differ), the exit status and the objects found. Made by\n\n"
                "    scripts/crs_table.py --spinhash build/host-tools/spinhash --db fleet.shdb \\\n"
                "        --data ../shared/data --out docs/crs-table.md\n\n"
                "with the README's `fleet.shdb`. Files without a CRS are processed in their own\n"
                "coordinates, taken as metres (\"unknown\"); files in degrees are refused with how to\n"
                "reproject them (`--work-crs`); unreadable files are refused with what is wrong.\n\n")
        f.write(f"{len(rows)} files.\n\n")
        f.write("| file | scene: CRS (units) | exit | objects | survey: CRS | units | exit | objects | status, or why refused |\n")
        f.write("|---|---|---|---|---|---|---|---|---|\n")
        for rel, sc, sv in rows:
            why = sc["note"] or sv["note"]
            f.write(f"| `{rel}` | {sc['crs'] or '-'} | {sc['exit']} | {sc['objects']} | {sv['crs'] or '-'} | "
                    f"{sv['units'] or '-'} | {sv['exit']} | {sv['objects']} | {why.replace('|', '/')} |\n")
    print(f"wrote {a.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
