#!/usr/bin/env python3
"""Does a flight line keep up? A queue simulation of the scene stream's rows.

  scripts/flight-keepup.py ROWS.csv [--speed 30] [--swath 100] [--density 100]
      [--window-core 32] [--windows-per-row 4] [--max-lag 16] [--hz 1.2e9] [--ipc 1.0]
      [--per-point 1245] [--per-unit 110] [--window-max-work 0] [--fixed-per-point 520]
      [--overshoot 10e6]

ROWS.csv is what `tests/worst_case/stream_runner run DIR` writes (columns
row, points, objects, recognition_work): per row of windows along track, its
input points and the work units its recognitions spent. A row's
instructions are --per-point times its points (the stream without
recognition, aarch64: docs/budgets.md, "Work per point") plus --per-unit
times its work units (the most aarch64 instructions a unit has cost,
docs/budgets.md, "Time"). The aircraft flies --speed m/s, so a row of
--window-core m is complete every core / speed s; one core of --hz cycles
per second at --ipc instructions per cycle runs the rows in order. A row
waits while the rows before it run: the line keeps up when no row waits
longer than the aircraft takes to fly --max-lag m (the stream's lag).

The configured bound: with --window-max-work W a window's recognitions
spend at most W units, plus what its last query passes its cap by (one LSH
scan, one pair or lent pose, or one step of the refine stage and the upward
surface of the leaders finalised after it: at most --overshoot
instructions, docs/budgets.md), plus what the units do
not count, each query's loading, ground removal and equalising of its
cloud in both passes (--fixed-per-point instructions a point of it; its
points are the row's at most), so a row of --windows-per-row windows at
--density points per m2 costs at most (per-point + fixed-per-point) x
density x core x swath + windows x (per-unit x W + overshoot). Prints the
measured rows, the bound, and whether each keeps up; exit status 0 when
the measured line keeps up, 1 when it does not, 2 on bad input.
"""
import argparse
import csv
import sys


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("rows")
    p.add_argument("--speed", type=float, default=30.0, help="m/s along track")
    p.add_argument("--swath", type=float, default=100.0, help="m across track that one core streams")
    p.add_argument("--density", type=float, default=100.0, help="points per m2, for the bound")
    p.add_argument("--window-core", type=float, default=32.0, help="m: a row of windows along track")
    p.add_argument("--windows-per-row", type=int, default=4, help="windows a row holds across the swath")
    p.add_argument("--max-lag", type=float, default=16.0, help="m a row may wait, as flight")
    p.add_argument("--hz", type=float, default=1.2e9, help="the core's cycles per second")
    p.add_argument("--ipc", type=float, default=1.0, help="instructions per cycle")
    p.add_argument("--per-point", type=float, default=1245.0, help="instructions per input point, recognition aside")
    p.add_argument("--per-unit", type=float, default=110.0, help="instructions per recognition work unit")
    p.add_argument("--window-max-work", type=int, default=0, help="the run's window budget (0: none)")
    p.add_argument("--fixed-per-point", type=float, default=520.0,
                   help="instructions a query point costs that no work unit counts (aarch64, both passes)")
    p.add_argument("--overshoot", type=float, default=10e6,
                   help="instructions a window's last query may pass its cap by (one step of the refine stage)")
    a = p.parse_args()
    try:
        with open(a.rows, newline="") as f:
            rows = [(int(r["points"]), int(r["recognition_work"])) for r in csv.DictReader(f)]
    except (OSError, KeyError, ValueError) as e:
        print(f"flight-keepup: {a.rows}: {e}", file=sys.stderr)
        return 2
    if not rows or a.speed <= 0 or a.hz <= 0 or a.ipc <= 0:
        print("flight-keepup: no rows, or a speed or clock that is not positive", file=sys.stderr)
        return 2

    rate = a.hz * a.ipc  # instructions per second
    period = a.window_core / a.speed  # s between complete rows
    allowed = a.max_lag / a.speed  # s a row may wait
    costs = [a.per_point * points + a.per_unit * work for points, work in rows]
    free_at = 0.0
    worst_wait = 0.0
    for k, cost in enumerate(costs):
        ready = k * period
        start = max(ready, free_at)
        worst_wait = max(worst_wait, start - ready)
        free_at = start + cost / rate
    mean = sum(costs) / len(costs)
    keeps_up = worst_wait <= allowed

    print(f"rows: {len(rows)} of {a.window_core:g} m; one every {period:.2f} s at {a.speed:g} m/s; "
          f"the core runs {rate / 1e9:.2f} G instructions/s ({rate * period / 1e9:.2f} G a row)")
    print(f"measured: mean {mean / 1e9:.2f} G instructions a row (load {mean / (rate * period):.0%}), "
          f"worst {max(costs) / 1e9:.2f} G; the longest wait {worst_wait:.2f} s = "
          f"{worst_wait * a.speed:.1f} m of flight against --max-lag {a.max_lag:g} m: "
          f"{'keeps up' if keeps_up else 'falls behind'}")
    if a.window_max_work > 0:
        row_points = a.density * a.window_core * a.swath
        budget = a.per_unit * a.windows_per_row * a.window_max_work
        overshoot = a.windows_per_row * a.overshoot
        bound = (a.per_point + a.fixed_per_point) * row_points + budget + overshoot
        print(f"bound: at most {bound / 1e9:.2f} G instructions a row at {a.density:g} points/m2 "
              f"(the stream {a.per_point * row_points / 1e9:.2f} G, the queries' loading and equalising "
              f"{a.fixed_per_point * row_points / 1e9:.2f} G, window_max_work {a.window_max_work} a window "
              f"{budget / 1e9:.2f} G, the windows' last queries past their caps {overshoot / 1e9:.2f} G): "
              f"{'keeps up' if bound <= rate * period else 'may fall behind'} whatever the row holds")
    return 0 if keeps_up else 1


if __name__ == "__main__":
    sys.exit(main())
