"""spinhash.survey on a real Dask cluster: a `dask-scheduler` and two
`dask-worker` processes on 127.0.0.1 (nothing beyond loopback). A generated
scene cut into 2 x 2 tiles gives the same files as `spinhash survey`; a
worker killed in the middle of a run loses and duplicates nothing."""
import json
import os
import signal
import socket
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import spinhash
from spinhash import survey

from conftest import run_cli

pytest.importorskip("distributed")
pytest.importorskip("geopandas")

CENTRE = (512000.0, 5400000.0)  # scan-scene's default offset: the scene's centre, where the tiles meet
OUTPUTS = ("detections.jsonl", "detections.geojson")
STARTUP_S = 60  # a scheduler and its workers come up within this on a loaded 2-core CI machine
PROCESSES_EXIT_S = 10


@pytest.fixture(scope="module")
def tiles(fleet, tmp_path_factory):
    """A 64 m scene of 10 vehicles cut into 2 x 2 text tiles at its centre (millimetres, as LAS keeps)."""
    root = tmp_path_factory.mktemp("survey")
    scene = root / "scene.las"
    run_cli("scan-scene", fleet.meshes, "-o", scene, "--size", 64, "--vehicles", 10, "--trees", 2, "--seed", 5)
    points = spinhash.read_cloud(str(scene))
    folder = root / "tiles"
    folder.mkdir()
    for i in range(2):
        for j in range(2):
            keep = ((points[:, 0] >= CENTRE[0]) == bool(i)) & ((points[:, 1] >= CENTRE[1]) == bool(j))
            np.savetxt(folder / f"t{i}{j}.xyz", points[keep], fmt="%.3f")
    return folder


@pytest.fixture(scope="module")
def cli_out(fleet, tiles, tmp_path_factory):
    out = tmp_path_factory.mktemp("cli") / "out"
    run_cli("survey", "--quiet", "--jobs", 2, "--db", fleet.db, "--out", out, tiles)
    assert len(vehicles(out)) >= 8
    return out


def vehicles(out):
    lines = [json.loads(line) for line in (out / "detections.jsonl").read_text().splitlines()]
    return [o for o in lines if o["kind"] == "vehicle"]


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Cluster:
    """A scheduler and two workers (no nanny: a killed worker stays dead), as separate processes."""

    def __init__(self, log_dir):
        self.address = f"tcp://127.0.0.1:{free_port()}"
        self.logs = []
        self.scheduler = self._start(log_dir, "scheduler", ["dask-scheduler", "--host", "127.0.0.1", "--port",
                                                            self.address.rsplit(":", 1)[1], "--no-dashboard"])
        self.workers = [self._start(log_dir, f"worker{k}",
                                    ["dask-worker", self.address, "--host", "127.0.0.1", "--nthreads", "1",
                                     "--no-nanny", "--no-dashboard", "--name", f"w{k}"]) for k in range(2)]
        from distributed import Client
        self.client = Client(self.address, timeout=STARTUP_S)
        self.client.wait_for_workers(2, timeout=STARTUP_S)

    def _start(self, log_dir, name, argv):
        log = open(log_dir / f"{name}.log", "w")
        self.logs.append(log)
        return subprocess.Popen(argv, stdout=log, stderr=subprocess.STDOUT, env=os.environ.copy())

    def close(self):
        self.client.close()
        for p in self.workers + [self.scheduler]:
            if p.poll() is None:
                p.send_signal(signal.SIGINT)
        for p in self.workers + [self.scheduler]:
            try:
                p.wait(PROCESSES_EXIT_S)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()
        for log in self.logs:
            log.close()


@pytest.fixture
def cluster(tmp_path):
    c = Cluster(tmp_path)
    yield c
    c.close()


def test_the_module_on_a_real_scheduler_gives_the_cli_files(fleet, tiles, cli_out, cluster, tmp_path):
    out = tmp_path / "dask"
    status = survey.main(["--db", str(fleet.db), "--out", str(out), "--scheduler", cluster.address, "--quiet",
                          str(tiles)])
    assert status == 0
    for name in OUTPUTS:
        assert (out / name).read_bytes() == (cli_out / name).read_bytes(), name
    report = json.loads((out / "survey.json").read_text())
    assert report["tiles_done"] == 4 and report["refused"] == []


def test_a_worker_killed_mid_run_loses_and_duplicates_nothing(fleet, tiles, cli_out, cluster, tmp_path):
    out = tmp_path / "dask"
    result = {}

    def run():
        result["frame"] = survey.run(str(fleet.db), [str(tiles)], str(out), cluster.client, progress=False)

    runner = threading.Thread(target=run)
    runner.start()
    victim = cluster.workers[0]
    deadline = time.monotonic() + STARTUP_S
    while time.monotonic() < deadline:  # kill it while it works on a tile
        busy = cluster.client.processing()
        if any(tasks for address, tasks in busy.items() if cluster.client.scheduler_info()["workers"]
               .get(address, {}).get("name") == "w0"):
            break
        time.sleep(0.05)
    else:
        pytest.fail("worker w0 never got a tile")
    victim.kill()
    victim.wait()
    runner.join(timeout=300)
    assert not runner.is_alive()
    for name in OUTPUTS:
        assert (out / name).read_bytes() == (cli_out / name).read_bytes(), name
    frame = result["frame"]
    assert frame.crs is not None  # the tiles declare none: the local engineering CRS, not WGS 84
    assert len(frame) == len(json.loads((out / "detections.geojson").read_text())["features"])
    assert frame.attrs["exit_status"] == 0
    centres = [tuple(np.round(v["center"][:2], 3)) for v in vehicles(out)]
    assert len(centres) == len(set(centres))  # each vehicle once


def test_bad_input_is_refused_with_a_clear_error(fleet, tmp_path):
    with pytest.raises(ValueError, match="no such file"):
        survey.run(str(fleet.db), [str(tmp_path / "missing.las")], str(tmp_path / "out"), client=object())
    assert survey.main(["--db", str(fleet.db), "--out", str(tmp_path / "o"), str(tmp_path / "missing.las")]) == 1
    with pytest.raises(SystemExit):
        survey.main(["--db", "x", "--out", "y", "--workers", "2", "--scheduler", "tcp://127.0.0.1:1", "t.las"])
    with pytest.raises(SystemExit):
        survey.main(["--db", "x", "--out", "y", "--drop-class", "65,x", "t.las"])
    with pytest.raises(ValueError, match="drop_classes: 300 is not a LAS class"):
        survey.run(str(fleet.db), [str(tmp_path)], str(tmp_path / "out"), client=object(), drop_classes=[300])


def test_classes_to_leave_out_reach_every_worker_in_its_task(fleet, tiles, tmp_path):
    prepared = survey._spinhash._survey_prepare(str(fleet.db), [str(tiles)], str(tmp_path / "out"),
                                                drop_classes=[65, 66])
    for name, path, task in prepared.pending():
        assert "drop_classes 7,18,65,66" in task.splitlines()


def test_a_worker_s_order_memory_moves_no_answer_and_is_bounded(fleet, tiles, tmp_path):
    """A tile ordered within 4 096 points (spilling to its temporary file
    many times) gives the result of one ordered in memory, times aside."""
    prepared = survey._spinhash._survey_prepare(str(fleet.db), [str(tiles)], str(tmp_path / "out"))
    name, path, task = prepared.pending()[0]

    def answers(result):
        return [line for line in result.splitlines() if not line.startswith("times ")]

    held = survey.run_tile(str(fleet.db), task)
    spilled = survey.run_tile(str(fleet.db), task, order_memory=4096)
    assert any(line.startswith("line ") for line in held.splitlines())
    assert answers(spilled) == answers(held)
    with pytest.raises(ValueError, match="order_memory"):
        survey.run_tile(str(fleet.db), task, order_memory=100)


def test_the_package_keeps_the_extension_s_names():
    assert spinhash.Database is spinhash._spinhash.Database
    assert spinhash.__version__ == spinhash._spinhash.__version__
    assert callable(survey.run) and sys.modules["spinhash.survey"] is survey


def test_results_are_stored_as_they_come_with_the_progress_line_on(fleet, tiles, tmp_path, monkeypatch, capfd):
    """The default mode (progress shown): three tiles' results are stored while
    the fourth still runs, so an interruption then keeps them."""
    from distributed import Client
    release = threading.Event()
    real = survey._spinhash._survey_run_task

    def held(db, task, top_n, max_objects, order_memory):
        if any(line.startswith("tile ") and line.endswith("t11.xyz") for line in task.splitlines()):
            release.wait(STARTUP_S * 2)  # the last tile waits until the others are stored
        return real(db, task, top_n, max_objects, order_memory)

    monkeypatch.setattr(survey._spinhash, "_survey_run_task", held)
    out = tmp_path / "dask"
    client = Client(processes=False, n_workers=2, threads_per_worker=1, dashboard_address=None)
    try:
        runner = threading.Thread(target=lambda: survey.run(str(fleet.db), [str(tiles)], str(out), client,
                                                            progress=True, geodataframe=False))
        runner.start()
        results = out / "tile-results"
        deadline = time.monotonic() + STARTUP_S
        while time.monotonic() < deadline and len(list(results.glob("*.result"))) < 3:
            time.sleep(0.1)
        stored = sorted(p.name for p in results.glob("*.result"))
        release.set()
        runner.join(timeout=300)
        assert not runner.is_alive()
    finally:
        client.close()
    assert stored == ["t00.result", "t01.result", "t10.result"]
    report = json.loads((out / "survey.json").read_text())
    assert report["jobs"] == 2  # the workers that ran the tasks
    err = capfd.readouterr().err
    assert "[survey] 4/4 tiles" in err  # on stderr


def test_the_command_line_matches_the_cli_s_options_and_help_is_plain_text(capsys):
    with pytest.raises(SystemExit):
        survey.main(["--help"])
    text = capsys.readouterr().out
    assert "``" not in text
    for option in ("--top", "--max-objects", "--work-crs", "--drop-class", "--order-memory", "--quiet"):
        assert option in text

