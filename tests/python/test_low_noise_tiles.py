"""scripts/low_noise_tiles.py on one small tile: each rate adds its count of
low points, every truth vehicle is counted once per rate, and the CSV and
the Markdown table agree; the scene's low-noise test keeps the ground
that the same tile without it loses."""
import csv
import subprocess
import sys

from conftest import SOURCE_DIR, cli_path

SCRIPT = SOURCE_DIR / "scripts" / "low_noise_tiles.py"


def measure(fleet, out, *extra):
    done = subprocess.run(
        [sys.executable, SCRIPT, "--spinhash", cli_path(), "--meshes", fleet.meshes, "--db", fleet.db,
         "--out", out, "--rates", "0,50", "--seeds", "2-2", "--size", "40", "--vehicles", "4", *extra],
        capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    with open(out / "low_noise.csv", newline="") as f:
        return done, {r["m2_per_low_point"]: r for r in csv.DictReader(f)}


def ground_share(row):
    return int(row["ground_points"]) / int(row["points"])


def test_each_rate_adds_its_low_points_and_counts_every_vehicle(fleet, tmp_path):
    done, rows = measure(fleet, tmp_path / "tiles")
    assert set(rows) == {"0", "50"}
    assert int(rows["0"]["low_points"]) == 0
    assert int(rows["50"]["low_points"]) == 32  # 40 x 40 m / 50 m2
    assert int(rows["50"]["points"]) == int(rows["0"]["points"]) + 32
    for r in rows.values():
        assert int(r["vehicles"]) == 4
        assert 0 <= int(r["right"]) <= int(r["found"]) <= 4
        assert 0 < int(r["ground_points"]) < int(r["points"])
    assert int(rows["0"]["found"]) >= 3  # the clean tile: a real comparison
    for rate, r in rows.items():
        label = "none" if rate == "0" else rate
        assert f"| {label} | {r['low_points']} |" in done.stdout


def test_the_low_noise_test_keeps_the_ground_the_tile_loses_without_it(fleet, tmp_path):
    _, rows = measure(fleet, tmp_path / "with")
    _, off = measure(fleet, tmp_path / "without", "--noise-gap", "0")
    assert int(rows["0"]["low_noise_points"]) == 0  # the clean tile: nothing left out
    # Most of the 32 copies lie under the ground (some copy a crown or a
    # roof, and stay above it).
    assert 16 <= int(rows["50"]["low_noise_points"]) <= 32
    assert int(off["50"]["low_noise_points"]) == 0
    assert abs(ground_share(rows["50"]) - ground_share(rows["0"])) < 0.01
    assert ground_share(off["50"]) < ground_share(rows["0"]) - 0.05
    assert rows["0"]["ground_points"] == off["0"]["ground_points"]  # off changes nothing on a clean tile
