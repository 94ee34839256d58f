"""spinhash.SceneRecognizer answers a tile as `spinhash scene` prints it
(the same path: the tile ordered along track, streamed in bands), whole or
pushed in chunks of any order: two vehicles scanned with their ground, side
by side."""
import numpy as np
import pytest

import spinhash
from conftest import json_lines, run_cli

SHIFT_X = 30.0  # m between the two scans: their 24 m ground squares do not overlap


@pytest.fixture(scope="module")
def tile(fleet, tmp_path_factory):
    """A van and a sedan on their scanned ground, as one georeferenced tile in a text file."""
    parts = []
    for k, model in enumerate(("van-00", "sedan-00")):
        scan = fleet.scan(model, f"tile-{model}.las", "--ground", 12, "--random-pose", "--seed", 3 + k,
                          "--noise", 0.03, "--offset", 500000, 4000000, 100)
        part = spinhash.read_cloud(scan)
        part[:, 0] += k * SHIFT_X
        parts.append(part)
    points = np.vstack(parts)
    path = tmp_path_factory.mktemp("scene") / "tile.xyz"
    np.savetxt(path, points, fmt="%.17g")
    return path, spinhash.read_cloud(path)


def test_the_scene_matches_the_cli(fleet, tile):
    path, points = tile
    lines = json_lines(run_cli("scene", "--db", fleet.db, path))
    scene = spinhash.SceneRecognizer(spinhash.Database(fleet.db))
    objects = scene.recognize(points)
    assert scene.last_status == "ok"
    assert len(objects) == len(lines) >= 2
    for obj, line in zip(objects, lines):
        assert (obj.kind, obj.status, obj.model, obj.confident, obj.group_size, obj.points) == \
            (line["kind"], line["status"], line["model"], line["confident"], line["group_size"],
             line["points"])
        assert (obj.vehicle_class, obj.class_confident) == (line["class"], line["class_confident"])
        assert [(c, m) for c, _, m in obj.class_ranking] == \
            [(entry["class"], entry["model"]) for entry in line["class_ranking"]]
        assert (obj.group, obj.level) == (line["group"], line["level"])
        assert {name: level["confident"] for name, level in obj.levels.items()} == \
            {name: level["confident"] for name, level in line["levels"].items()}
        assert obj.levels["model"]["confident"] == obj.confident
        assert obj.levels["class"]["confident"] == obj.class_confident
        assert [name for name, _ in obj.ranking] == [entry["model"] for entry in line["ranking"]]
        for (_, score), entry in zip(obj.ranking, line["ranking"]):
            assert score == pytest.approx(entry["score"], rel=1e-6)
        np.testing.assert_allclose(obj.center, line["center"], rtol=0, atol=1e-6)  # as the CLI prints it
        np.testing.assert_allclose(obj.extent, line["extent"], rtol=0, atol=1e-3)  # the CLI prints 4 digits
        if line["ground_gap"] is None:
            assert obj.ground_gap is None
        else:
            assert obj.ground_gap == pytest.approx(line["ground_gap"], abs=1e-3)
            if obj.kind == "vehicle" and obj.confident:
                assert obj.ground_gap > -0.15  # max_ground_sink: the model rests on the terrain
        if line["pose"] is None:
            assert obj.pose is None
        else:
            np.testing.assert_allclose(obj.pose, np.reshape(line["pose"], (4, 4)), rtol=0, atol=1e-6)
    vehicles = {obj.model for obj in objects if obj.kind == "vehicle" and obj.confident}
    assert vehicles == {"van-00", "sedan-00"}
    assert scene.last_stats["points_ground"] > len(points) // 3


def test_scene_settings_and_refusals(fleet, tile):
    _, points = tile
    db = spinhash.Database(fleet.db)
    default = spinhash.SceneRecognizer(db)
    assert default.config.ground_clearance == 0.0  # as `spinhash scene`: the terrain classifier takes the ground
    assert (default.top_n, default.max_tile_points, default.max_objects) == (5, 0, 256)  # 0: from the density
    assert spinhash.SceneRecognizer(db, ground_clearance=0.2, seed=3).config.seed == 3
    top_two = spinhash.SceneRecognizer(db, top_n=2, mode="bran").recognize(points)
    assert all(len(obj.ranking) <= 2 for obj in top_two)
    small = spinhash.SceneRecognizer(db, max_tile_points=1000)
    with pytest.raises(ValueError, match="scene: window_overflow"):
        small.recognize(points)
    assert small.last_status == "window_overflow"
    with pytest.warns(RuntimeWarning, match="too_many_objects"):
        one = spinhash.SceneRecognizer(db, max_objects=1).recognize(points)
    assert len(one) == 1
    with pytest.raises(ValueError, match="top_n is out of range"):
        spinhash.SceneRecognizer(db, top_n=0)
    with pytest.raises(ValueError, match="sigma must be in"):
        spinhash.SceneRecognizer(db, sigma=-1.0)
    empty = spinhash.SceneRecognizer(db)
    assert empty.recognize(np.zeros((0, 3))) == [] and empty.last_status == "empty_cloud"


def test_chunks_pushed_as_they_come_give_the_whole_tile(fleet, tile):
    """iter_cloud's chunks, pushed in the file's order or any other: the
    tile's objects, as recognize() gives them for the whole cloud."""
    path, points = tile
    db = spinhash.Database(fleet.db)
    whole = spinhash.SceneRecognizer(db).recognize(points)
    scene = spinhash.SceneRecognizer(db)
    for chunk in spinhash.iter_cloud(path, chunk_points=997):
        assert scene.push(chunk) is None
    chunked = scene.flush()
    assert scene.last_status == "ok"
    answers = [(o.kind, o.model, o.confident, o.points, tuple(o.center)) for o in whole]
    assert [(o.kind, o.model, o.confident, o.points, tuple(o.center)) for o in chunked] == answers
    backwards = spinhash.SceneRecognizer(db)
    for start in reversed(range(0, len(points), 4096)):
        backwards.push(points[start:start + 4096])
    vehicles = sorted(o.model for o in backwards.flush() if o.kind == "vehicle")
    assert vehicles == sorted(o.model for o in whole if o.kind == "vehicle")
    assert scene.flush() == [] and scene.last_status == "empty_cloud"  # a flush starts a new tile
