"""spinhash.SceneStream: the tile of test_scene.py pushed in scan order, in
chunks of any size, answers as SceneRecognizer does; bad input is counted;
points out of order are dropped with a warning, and AlongTrackOrder orders
iter_cloud's chunks as they come so that nothing is dropped."""
import numpy as np
import pytest

import spinhash
from test_scene import tile  # noqa: F401  (the fixture)


def stream_of(fleet, points, **settings):
    """A stream along +x over the tile, its origin the tile's min corner."""
    frame = dict(heading_deg=0, origin=tuple(points.min(axis=0)), swath_min=-10, swath_max=60, own_min=-10,
                 own_max=60, max_lag=1)
    frame.update(settings)
    return spinhash.SceneStream(spinhash.Database(fleet.db), **frame)


def in_scan_order(points):
    return points[np.argsort(points[:, 0], kind="stable")]


def answers(objects):
    return [(o.kind, o.model, o.confident, o.points) for o in objects]


def test_chunks_of_any_size_give_the_same_objects(fleet, tile):  # noqa: F811
    _, points = tile
    ordered = in_scan_order(points)
    runs = []
    for chunk in (len(ordered), 4096 // 24, 997):
        stream = stream_of(fleet, ordered)
        objects = []
        for i in range(0, len(ordered), chunk):
            objects += stream.push(ordered[i:i + chunk])
        objects += stream.flush()
        assert stream.last_status == "ok"
        runs.append(answers(objects))
        assert stream.stats["points_pushed"] == len(ordered)
    assert runs[0] == runs[1] == runs[2]
    vehicles = {model for kind, model, confident, _ in runs[0] if kind == "vehicle" and confident}
    assert vehicles == {"van-00", "sedan-00"}
    whole = spinhash.SceneRecognizer(spinhash.Database(fleet.db)).recognize(points)
    assert sorted(m for k, m, c, _ in runs[0] if k == "vehicle") == \
        sorted(o.model for o in whole if o.kind == "vehicle")


def test_bad_input_is_counted_and_a_push_after_flush_refused(fleet, tile):  # noqa: F811
    _, points = tile
    ordered = in_scan_order(points)
    stream = stream_of(fleet, ordered)
    glitch = ordered[:3].copy()
    glitch[0, 1] += 10000.0  # 10 km across the track
    glitch[1, 0] = np.nan
    stream.push(glitch)
    stream.push(ordered)
    stream.flush()
    stats = stream.stats
    assert stats["points_outside"] == 1
    assert stats["scene"]["points_nonfinite"] == 1
    with pytest.raises(ValueError, match="stream_flushed"):
        stream.push(ordered[:10])
    assert stream.stats["points_after_flush"] == 10
    stream.reset()
    assert stream.stats["points_pushed"] == 0
    with pytest.raises(ValueError, match="invalid settings"):
        stream_of(fleet, ordered, max_lag=-1.0)


def test_chunks_out_of_order_warn_and_along_track_order_keeps_them(fleet, tile, tmp_path):  # noqa: F811
    _, points = tile
    path = tmp_path / "shuffled.xyz"  # a file whose points come in no particular order
    np.savetxt(path, points[np.random.default_rng(5).permutation(len(points))], fmt="%.17g")
    as_they_come = stream_of(fleet, points)
    with pytest.warns(RuntimeWarning, match="points_late"):
        for chunk in spinhash.iter_cloud(path, chunk_points=4096):
            as_they_come.push(chunk)
    assert as_they_come.last_status == "points_late"
    assert as_they_come.stats["points_late"] > 0
    as_they_come.flush()

    order = spinhash.AlongTrackOrder(heading_deg=0, row_depth=1, memory_points=5000)  # the stream's frame
    for chunk in spinhash.iter_cloud(path, chunk_points=4096):
        order.push(chunk)
    assert order.points == len(points)
    ordered_stream = stream_of(fleet, points)
    objects = []
    for chunk in order.chunks(chunk_points=4096):
        objects += ordered_stream.push(chunk)
    objects += ordered_stream.flush()
    assert ordered_stream.stats["points_late"] == 0 and ordered_stream.last_status == "ok"
    sorted_stream = stream_of(fleet, points)
    reference = sorted_stream.push(in_scan_order(points)) + sorted_stream.flush()
    assert sorted(answers(objects)) == sorted(answers(reference))
    with pytest.raises(ValueError, match="row_depth"):
        spinhash.AlongTrackOrder(row_depth=0)
