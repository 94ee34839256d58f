"""scripts/clutter_tiles.py on one small tile: every object of the truth is
counted by its kind, flags on the vehicle-sized clutter count only as
wrong, and a second database is scored on the same tile."""
import csv
import subprocess
import sys

from conftest import SOURCE_DIR, cli_path

SCRIPT = SOURCE_DIR / "scripts" / "clutter_tiles.py"


def test_each_kind_is_counted_and_clutter_flags_are_wrong(fleet, tmp_path):
    out = tmp_path / "tiles"
    done = subprocess.run(
        [sys.executable, SCRIPT, "--spinhash", cli_path(), "--meshes", fleet.meshes, "--db", f"a={fleet.db}",
         "--db", f"b={fleet.db}", "--out", out, "--spacings", "0.2", "--seeds", "3-3", "--per-kind", "1",
         "--size", "45"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "| a | 5 |" in done.stdout and "| b | 5 |" in done.stdout  # the tile's 5 vehicles, for each database
    with open(out / "clutter_tiles.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    by = {(r["database"], r["kind"]): r for r in rows}
    for db in ("a", "b"):
        assert int(by[(db, "vehicle")]["objects"]) == 5
        for kind in ("shed", "container", "bush", "heap"):
            row = by[(db, kind)]
            assert int(row["objects"]) == 1
            assert int(row["answered"]) <= 1
            for level in ("vehicle", "group", "class", "model"):
                assert int(row[f"{level}_right"]) == 0
        vehicles = by[(db, "vehicle")]
        assert 0 < int(vehicles["answered"]) <= 5
        assert int(vehicles["vehicle_wrong"]) == 0  # a vehicle is one, whatever else is named
    # The same database twice: the same counts.
    assert {k: v for k, v in by[("a", "vehicle")].items() if k != "database"} == \
        {k: v for k, v in by[("b", "vehicle")].items() if k != "database"}
    # Answers are kept: a second run scores them again without running scene.
    again = subprocess.run(done.args, capture_output=True, text=True)
    assert again.returncode == 0 and again.stdout == done.stdout
