"""Bad input gets a clear Python error or the core's status, never a crash:
arrays of the wrong type or shape, NaN rows, empty clouds, bad databases."""
import numpy as np
import pytest

import spinhash
from conftest import assert_same_stats, json_lines, run_cli


@pytest.fixture(scope="module")
def recognizer(fleet):
    return spinhash.Recognizer(spinhash.Database(fleet.db))


@pytest.mark.parametrize("points, message", [
    ([[0.0, 0.0, 0.0]] * 10, "points must be a numpy array of shape \\(N, 3\\), dtype float64 or float32; got list"),
    (np.zeros((10, 3), np.int64), "points must have dtype float64 or float32, got int64"),
    (np.zeros((10, 3), np.dtype(">f8")), "points must have dtype float64 or float32, got >f8"),
])
def test_wrong_types_are_type_errors(recognizer, points, message):
    with pytest.raises(TypeError, match=message):
        recognizer.recognize(points)


@pytest.mark.parametrize("shape", [(30,), (10, 2), (10, 4), (3, 10), (2, 10, 3)])
def test_wrong_shapes_are_value_errors(recognizer, shape):
    with pytest.raises(ValueError, match=r"points must have shape \(N, 3\), got \("):
        recognizer.recognize(np.zeros(shape))


def test_strided_and_fortran_arrays_give_the_contiguous_answer(recognizer, truck_query):
    points = spinhash.read_cloud(truck_query)
    every_other = points[::2]
    assert not every_other.flags.c_contiguous
    expected = recognizer.recognize(np.ascontiguousarray(every_other))
    for view in (every_other, np.asfortranarray(every_other), np.hstack([every_other, every_other])[:, :3]):
        got = recognizer.recognize(view)
        assert got.ranking == expected.ranking
        np.testing.assert_array_equal(got.pose, expected.pose)
    assert recognizer.recognize(points).ranking != expected.ranking  # the rows taken matter


def test_nan_rows_are_dropped_and_counted_as_the_cli_does(fleet, recognizer, truck_query, tmp_path):
    # Within the recognizer's max_points, so that every row is read and counted.
    points = spinhash.read_cloud(truck_query)[: spinhash.Config().max_points]
    points[::7] = np.nan
    points[3::7, 2] = np.inf
    text = tmp_path / "holes.xyz"
    np.savetxt(text, points, fmt="%.17g")
    line = json_lines(run_cli("recognize", "--db", fleet.db, text))[0]
    result = recognizer.recognize(points)
    assert result.status == "ok" == line["status"]
    assert result.stats["points_nonfinite"] == np.count_nonzero(~np.isfinite(points).all(axis=1))
    assert_same_stats(result.stats, line["stats"])
    assert [name for name, _ in result.ranking] == [entry["model"] for entry in line["ranking"]]
    assert result.model == "truck-00"


def test_empty_and_degenerate_clouds_get_the_cores_status(recognizer):
    empty = recognizer.recognize(np.zeros((0, 3)))
    assert (empty.status, empty.error, empty.ranking, empty.pose, empty.confident) == \
        ("empty_cloud", "empty cloud", [], None, False)
    all_nan = recognizer.recognize(np.full((10, 3), np.nan))
    assert all_nan.status == "empty_cloud" and all_nan.stats["points_nonfinite"] == 10
    one_point = recognizer.recognize(np.zeros((1, 3)))
    assert one_point.status == "not_enough_features" and one_point.error
    assert one_point.model is None


def test_a_cloud_above_max_points_is_refused_when_thinning_is_off(fleet, truck_query):
    points = spinhash.read_cloud(truck_query)
    refused = spinhash.Recognizer(spinhash.Database(fleet.db), max_points=1000,
                                  thin_large_clouds=False).recognize(points)
    assert refused.status == "too_many_points" and refused.ranking == []
    thinned = spinhash.Recognizer(spinhash.Database(fleet.db), max_points=5000).recognize(points)
    assert thinned.status == "ok" and thinned.stats["points_thinned"] > 0


def test_bad_databases_are_refused_with_the_reason(fleet, tmp_path):
    with pytest.raises(FileNotFoundError, match="no such file"):
        spinhash.Database(tmp_path / "missing.shdb")
    blob = fleet.db.read_bytes()
    with pytest.raises(ValueError, match="empty"):
        spinhash.Database.from_bytes(b"")
    with pytest.raises(ValueError, match="Database.from_bytes: "):
        spinhash.Database.from_bytes(blob[: len(blob) // 2])
    flipped = bytearray(blob)
    flipped[len(blob) // 2] ^= 0xFF
    with pytest.raises(ValueError, match="Database.from_bytes: "):
        spinhash.Database.from_bytes(flipped)
    corrupt = tmp_path / "corrupt.shdb"
    corrupt.write_bytes(bytes(flipped))
    with pytest.raises(ValueError, match="corrupt.shdb: "):
        spinhash.Database(corrupt)
    assert len(spinhash.Database.from_bytes(memoryview(blob))) == 6
    with pytest.raises(TypeError):
        spinhash.Database.from_bytes("not bytes")
    with pytest.raises(TypeError, match="contiguous"):
        spinhash.Database.from_bytes(memoryview(blob)[::2])


def test_a_recognizer_keeps_its_database_alive(fleet, truck_query):
    rec = spinhash.Recognizer(spinhash.Database.from_bytes(fleet.db.read_bytes()))
    import gc
    gc.collect()
    assert rec.recognize(spinhash.read_cloud(truck_query)).model == "truck-00"
    assert len(rec.db) == 6


def test_float32_clouds_are_read_and_warned_where_float32_cannot_hold_the_coordinates(fleet):
    points = spinhash.read_cloud(fleet.scan("sedan-00", "f32.ply", "--seed", 3))  # local coordinates
    recognizer = spinhash.Recognizer(spinhash.Database(fleet.db))
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # small coordinates: float32 holds them, nothing to say
        small = recognizer.recognize(points.astype(np.float32))
    assert small.model == recognizer.recognize(points.astype(np.float32).astype(np.float64)).model
    utm = points + np.array([500000.0, 4000000.0, 100.0])
    with pytest.warns(UserWarning, match="float32 points: coordinates up to .* steps of"):
        recognizer.recognize(utm.astype(np.float32))


def test_a_python_without_numpy_fails_at_import_with_a_clear_message():
    import subprocess
    import sys
    code = "import sys; sys.modules['numpy'] = None\ntry:\n    import spinhash\nexcept ImportError as e:\n    print(e)\n"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert "spinhash needs numpy" in done.stdout, done.stdout + done.stderr

