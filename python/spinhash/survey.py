"""A whole survey of adjacent tiles on Dask: one task per tile, with its
neighbours' buffer, each object reported by the tile that owns it; the same
outputs as `spinhash survey` (docs/survey.md).

    python3 -m spinhash.survey --db DB.shdb --out DIR [--workers N | --scheduler tcp://HOST:8786] TILE...

Paths travel to the workers, points do not: every worker reads its tiles
itself (they must be readable at the same paths there) and opens the
database once. The client stores each tile's result in DIR/tile-results/ as it
comes (atomically), whether or not the progress line is shown, so an
interrupted run loses nothing; `resume=True` skips the tiles done. The
outputs (detections.jsonl, detections.geojson, detections.gpkg, survey.json)
are written by the same C++ code as the CLI's.
"""
import argparse
import json
import os
import sys
import time
import uuid
import warnings

from . import _spinhash

DEFAULT_BUFFER = 40.0  # m: half the longest vehicle + the terrain filter's reach (docs/survey.md)
DEFAULT_RETRIES = 3  # a task that raises is tried again this many times (a worker that dies: Dask reschedules)
EXIT_OK, EXIT_ERROR, EXIT_USAGE, EXIT_CHECK_FAILED = 0, 1, 2, 3  # as `spinhash survey` (docs/cli.md)

_databases = {}  # per worker process: path -> spinhash.Database, opened once


def _database(path):
    db = _databases.get(path)
    if db is None:
        db = _databases[path] = _spinhash.Database(path)
    return db


DEFAULT_TOP_N, DEFAULT_MAX_OBJECTS = 5, 256  # as `spinhash survey`'s --top and --max-objects
DEFAULT_ORDER_MEMORY = _spinhash._ORDER_MEMORY_POINTS  # points, `spinhash survey`'s --order-memory default


def run_tile(db_path, task, top_n=DEFAULT_TOP_N, max_objects=DEFAULT_MAX_OBJECTS, order_memory=DEFAULT_ORDER_MEMORY):
    """One tile's task on a worker: its result as text (stored by the client)."""
    return _spinhash._survey_run_task(_database(db_path), task, top_n, max_objects, order_memory)


def _local_client(workers):
    from distributed import Client, LocalCluster
    cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1, processes=True,
                           dashboard_address=None)
    return Client(cluster)


def _progress_line(done, total, resumed, start):
    """The CLI's progress line ([survey] k/n tiles, ...), on stderr."""
    secs = time.monotonic() - start
    ran = done - resumed
    eta = secs / ran * (total - done) if ran > 0 else 0.0
    print(f"[survey] {done}/{total} tiles, {secs:.1f} s, ETA {eta:.0f} s", file=sys.stderr, flush=True)


def _collect(survey, futures, names, show_progress):
    """Stores each result as it comes (and, when shown, says so on stderr);
    (name, path, reason) of the tiles that failed for good."""
    from distributed import as_completed
    total, resumed = survey.tiles_planned, survey.tiles_planned - len(futures)
    start = time.monotonic()
    failed = []
    for done, future in enumerate(as_completed(futures), start=resumed + 1):
        name, path = names[future.key]
        try:
            survey.store(future.result())
        except Exception as error:  # noqa: BLE001  (an unreadable tile, a worker lost too often)
            failed.append((name, path, f"{type(error).__name__}: {error}"))
        if show_progress:
            _progress_line(done, total, resumed, start)
    return sorted(failed, key=lambda f: f[1])


def _workers(client):
    try:
        return len(client.scheduler_info().get("workers", {}))
    except Exception:  # noqa: BLE001  (a client that cannot say: recorded as 0)
        return 0


def run(db_path, tiles, out_dir, client=None, *, workers=None, buffer=DEFAULT_BUFFER, resume=False,
        top_n=DEFAULT_TOP_N, max_objects=DEFAULT_MAX_OBJECTS, retries=DEFAULT_RETRIES, progress=True,
        geodataframe=True, work_crs=None, order_memory=DEFAULT_ORDER_MEMORY, drop_classes=()):
    """Runs the survey of `tiles` (files or folders) into `out_dir`.

    client: a distributed.Client (None: a local cluster of `workers` processes).
    work_crs: a projected CRS to work in ("EPSG:32610", a WKT or a PROJ
    string), as the CLI's --work-crs: tiles in other CRSs, or in degrees,
    are reprojected into it. drop_classes: LAS classes every tile's reader
    leaves out besides noise (7, 18) and withheld points, as --drop-class
    (a producer's own artefact class). order_memory: points of a tile each worker holds
    in memory while ordering it, as --order-memory (the rest wait in a
    temporary file; the answers do not depend on it). progress: a line per
    tile on stderr.
    Returns the detections as a geopandas GeoDataFrame with the CRS set (the
    tiles' CRS; a local engineering CRS when they declare none), with
    ``attrs["survey"]`` (survey.json) and ``attrs["exit_status"]`` (0, or 3
    when tiles were refused or failed: survey.json says why); None when
    geodataframe is False. ValueError for inputs the survey refuses (tiles
    that do not share a CRS, no tile, ...)."""
    db_path = os.path.abspath(db_path)
    out_dir = os.path.abspath(out_dir)
    os.makedirs(out_dir, exist_ok=True)
    survey = _spinhash._survey_prepare(db_path, [os.path.abspath(t) for t in tiles], out_dir, buffer, resume,
                                       top_n, max_objects, work_crs or "", list(drop_classes))
    if survey.kept:
        print(f"spinhash.survey: kept {len(survey.kept)} tiles a previous run finished: {', '.join(survey.kept)}",
              file=sys.stderr)
    own_client = client is None
    if own_client:
        client = _local_client(workers)
    try:
        token = uuid.uuid4().hex[:8]
        names, futures = {}, []
        for name, path, task in survey.pending():
            key = f"spinhash-tile-{name}-{token}"
            names[key] = (name, path)
            futures.append(client.submit(run_tile, db_path, task, top_n, max_objects, order_memory, key=key,
                                         retries=retries, pure=False))
        workers_used = _workers(client)
        failed = _collect(survey, futures, names, progress)
    finally:
        if own_client:
            cluster = client.cluster
            client.close()
            cluster.close()
    status = survey.finish(failed, workers_used)
    for name, path, reason in failed + list(survey.refused):
        warnings.warn(f"spinhash.survey: {path}: {reason}", RuntimeWarning, stacklevel=2)
    if not geodataframe:
        return None
    return _geodataframe(out_dir, status)


def _geodataframe(out_dir, status):
    import geopandas
    frame = geopandas.read_file(os.path.join(out_dir, "detections.gpkg"), layer="detections")
    with open(os.path.join(out_dir, "survey.json"), encoding="utf-8") as f:
        frame.attrs["survey"] = json.load(f)
    frame.attrs["exit_status"] = status
    return frame


def _class_list(text):
    """"65" or "65,66": LAS classes, as the CLI's --drop-class."""
    try:
        classes = [int(item) for item in text.split(",")]
    except ValueError:
        classes = [-1]
    if any(c < 0 or c > 255 for c in classes):
        raise argparse.ArgumentTypeError(f"{text!r} is not a list of LAS classes (whole numbers 0 to 255)")
    return classes


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m spinhash.survey",
                                     description=" ".join(__doc__.split("\n\n")[0].split()))
    parser.add_argument("--db", required=True, help="database file (readable by every worker at this path)")
    parser.add_argument("--out", required=True, help="output folder, on the client")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, help="local worker processes (default: every core)")
    where.add_argument("--scheduler", help="a running Dask scheduler, tcp://HOST:8786")
    parser.add_argument("--buffer", type=float, default=DEFAULT_BUFFER, help="m of the neighbours' points (40)")
    parser.add_argument("--resume", action="store_true", help="keep the tiles a previous run in OUT finished")
    parser.add_argument("--retries", type=int, default=DEFAULT_RETRIES, help="tries again for a failed task")
    parser.add_argument("--top", type=int, default=DEFAULT_TOP_N, help="models ranked per vehicle (5)")
    parser.add_argument("--max-objects", type=int, default=DEFAULT_MAX_OBJECTS,
                        help="objects reported per window at most (256)")
    parser.add_argument("--work-crs", help="a projected CRS to work in (EPSG:n, WKT or PROJ string)")
    parser.add_argument("--drop-class", type=_class_list, action="extend", default=[], metavar="N[,N...]",
                        help="LAS classes to leave out besides noise (7, 18) and withheld points")
    parser.add_argument("--order-memory", type=int, default=DEFAULT_ORDER_MEMORY,
                        help=f"points of a tile each worker holds in memory while ordering it ({DEFAULT_ORDER_MEMORY})")
    parser.add_argument("--quiet", action="store_true", help="no progress line")
    parser.add_argument("tiles", nargs="+", help="tiles (LAS, LAZ, PLY, text) or folders of them")
    args = parser.parse_args(argv)
    if args.workers is not None and args.workers < 1:
        parser.error("--workers must be at least 1")
    client = None
    try:
        if args.scheduler:
            from distributed import Client
            client = Client(args.scheduler)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            frame = run(args.db, args.tiles, args.out, client, workers=args.workers, buffer=args.buffer,
                        resume=args.resume, retries=args.retries, progress=not args.quiet, top_n=args.top,
                        max_objects=args.max_objects, work_crs=args.work_crs, order_memory=args.order_memory,
                        drop_classes=args.drop_class)
    except (ValueError, OSError, RuntimeError) as error:
        print(f"spinhash.survey: {error}", file=sys.stderr)
        return EXIT_ERROR
    finally:
        if client is not None:
            client.close()
    report = frame.attrs["survey"]
    for refused in report["refused"]:
        print(f"spinhash.survey: refused {refused['path']}: {refused['reason']}", file=sys.stderr)
    print(f"spinhash.survey: {len(frame)} vehicle candidates from {report['tiles_done']} of "
          f"{report['tiles_total']} tiles; wrote {args.out}/detections.gpkg and the rest", file=sys.stderr)
    return frame.attrs["exit_status"]


if __name__ == "__main__":
    sys.exit(main())
