"""scripts/flight-keepup.py: the queue of a flight line's rows (a row that
waits longer than the lag falls behind) and the configured bound, whose
terms include what each window's last query passes its cap by."""
import re
import subprocess
import sys

from conftest import SOURCE_DIR

SCRIPT = SOURCE_DIR / "scripts" / "flight-keepup.py"


def keepup(rows, tmp_path, *args):
    path = tmp_path / "rows.csv"
    path.write_text("row,points,objects,recognition_work\n" +
                    "".join(f"{k},{p},1,{w}\n" for k, (p, w) in enumerate(rows)))
    return subprocess.run([sys.executable, SCRIPT, path, *map(str, args)], capture_output=True, text=True)


def test_a_line_keeps_up_while_no_row_waits_longer_than_the_lag(tmp_path):
    # 1 G instructions/s, a 32 m row every 1.6 s at 20 m/s: 1.0 G a row keeps up.
    done = keepup([(0, 10_000_000)] * 5, tmp_path, "--hz", 1e9, "--per-unit", 100, "--speed", 20)
    assert done.returncode == 0, done.stderr
    assert "longest wait 0.00 s" in done.stdout and "keeps up" in done.stdout
    # 2.0 G a row: each waits 0.4 s more than the one before; the fifth 1.6 s = 32 m > 16 m.
    done = keepup([(0, 20_000_000)] * 5, tmp_path, "--hz", 1e9, "--per-unit", 100, "--speed", 20)
    assert done.returncode == 1
    assert "longest wait 1.60 s = 32.0 m" in done.stdout and "falls behind" in done.stdout


def test_the_bound_counts_the_stream_the_fixed_costs_the_budget_and_the_overshoot(tmp_path):
    done = keepup([(1000, 0)], tmp_path, "--density", 100, "--window-core", 32, "--swath", 100,
                  "--per-point", 1000, "--fixed-per-point", 500, "--per-unit", 50, "--windows-per-row", 4,
                  "--window-max-work", 1_000_000, "--overshoot", 10e6, "--speed", 30)
    assert done.returncode == 0, done.stderr
    bound = re.search(r"bound: at most ([\d.]+) G", done.stdout)
    # 320 000 points x 1 500 + 4 x (50 x 1 000 000 + 10 000 000) = 0.48 G + 0.24 G
    assert bound and float(bound.group(1)) == 0.72
    assert "past their caps 0.04 G" in done.stdout and "keeps up whatever the row holds" in done.stdout
    # The same budget with a larger overshoot passes a 30 m/s row's 1.28 G.
    done = keepup([(1000, 0)], tmp_path, "--density", 100, "--per-point", 1000, "--fixed-per-point", 500,
                  "--per-unit", 50, "--window-max-work", 1_000_000, "--overshoot", 200e6, "--speed", 30)
    assert "at most 1.48 G" in done.stdout and "may fall behind" in done.stdout


def test_bad_rows_are_refused_with_status_2(tmp_path):
    path = tmp_path / "rows.csv"
    path.write_text("row,points\n0,12\n")
    done = subprocess.run([sys.executable, SCRIPT, path], capture_output=True, text=True)
    assert done.returncode == 2 and "recognition_work" in done.stderr
