"""scripts/sparse_segmentation.py on one small sparse tile: both rows per
spacing, the CSV and the Markdown table agree, and the cell grown to the
tile's spacing finds the vehicles that the finest cell leaves in fragments."""
import csv
import subprocess
import sys

from conftest import SOURCE_DIR, cli_path

SCRIPT = SOURCE_DIR / "scripts" / "sparse_segmentation.py"


def test_the_grown_cell_finds_the_vehicles_the_finest_leaves_in_fragments(fleet, tmp_path):
    done = subprocess.run(
        [sys.executable, SCRIPT, "--spinhash", cli_path(), "--meshes", fleet.meshes, "--db", fleet.db,
         "--out", tmp_path, "--spacings", "0.45", "--seeds", "3", "--size", "40", "--vehicles", "6"],
        capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    with open(tmp_path / "sparse_segmentation.csv", newline="") as f:
        rows = {r["cell"]: r for r in csv.DictReader(f)}
    assert set(rows) == {"grown", "0.25 m kept"}
    grown, kept = rows["grown"], rows["0.25 m kept"]
    assert grown["cells_m"] == "0.50" and kept["cells_m"] == "0.25"
    assert 4.0 < float(grown["points_per_m2"]) < 6.0
    assert int(grown["vehicles"]) == int(kept["vehicles"]) == 6
    assert int(grown["found"]) >= 3 and int(kept["found"]) <= 1
    for r in rows.values():
        assert 0 <= int(r["group_right"]) <= int(r["group_flagged"]) <= int(r["found"])
        assert f"| {r['cell']} | {r['cells_m']} | {r['found']} / {r['vehicles']} |" in done.stdout
