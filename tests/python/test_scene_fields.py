"""The Python mirrors of spinhash/scene_fields.h and spinhash/status_list.h,
read from the headers: every scene and stream setting is a keyword (and a
SceneRecognizer property), the statistics dicts hold the listed keys in
order, SceneObject has the listed attributes and no other, and
spinhash.STATUSES is the status list."""
import re

import numpy as np
import pytest

import spinhash
from conftest import SOURCE_DIR

HEADER = (SOURCE_DIR / "include" / "spinhash" / "scene_fields.h").read_text()


PATTERNS = {"X": r"X\((\w+), (\w+),", "S": r'S\((\w+), (\w+), "(\w+)"\)', "K": r'K\("(\w+)", "(\w*)"\)'}


def entries(macro, letter="X"):
    """The entries of one list of scene_fields.h: (kind, name) of a config, (kind, name, key) of
    statistics, (key, attribute) of the object's keys."""
    body = HEADER[HEADER.index(f"#define {macro}("):]
    body = body[:body.index("\n\n")]
    return re.findall(PATTERNS[letter], body)


def test_every_scene_setting_is_a_keyword_and_a_property(fleet):
    db = spinhash.Database(fleet.db)
    fields = entries("SPINHASH_SCENE_CONFIG_FIELDS")
    assert len(fields) > 20
    default = spinhash.SceneRecognizer(db)
    for kind, name in fields:
        value = getattr(default, name)
        assert isinstance(value, int if kind in ("U32", "U64") else float), name
        again = spinhash.SceneRecognizer(db, **{name: value})  # accepted as a keyword, checked by the core
        assert getattr(again, name) == value, name
    with pytest.raises(ValueError, match="max_length is out of range"):
        spinhash.SceneRecognizer(db, max_length=-1.0)
    with pytest.raises(TypeError, match="window_core must be a number"):
        spinhash.SceneRecognizer(db, window_core="64")


def test_every_stream_setting_is_a_keyword(fleet):
    settings = dict(origin=(1.0, 2.0, 3.0), heading_deg=45.0, swath_min=-200.0, swath_max=200.0, own_min=-100.0,
                    own_max=100.0, max_lag=8.0, max_jump=400.0, jump_confirm_points=8, max_z_offset=2000.0,
                    max_buffered_points=100000)
    # BOOLs are set by the setting they name (origin_given: origin)
    assert set(settings) == {name for kind, name in entries("SPINHASH_STREAM_CONFIG_FIELDS") if kind != "BOOL"}
    spinhash.SceneStream(spinhash.Database(fleet.db), **settings)


def test_the_statistics_dicts_hold_the_listed_keys_in_order(fleet):
    db = spinhash.Database(fleet.db)
    scene_keys = [key for _, _, key in entries("SPINHASH_SCENE_STATS_FIELDS", "S")]
    scene = spinhash.SceneRecognizer(db)
    scene.recognize(np.random.default_rng(1).uniform(0, 20, (500, 3)))
    assert list(scene.last_stats) == scene_keys
    assert list(scene.last_stats["objects_by_kind"]) == ["vehicle", "too small", "too large",
                                                        "not vehicle-shaped", "unknown"]
    stream = spinhash.SceneStream(db)
    assert list(stream.stats) == [key for _, _, key in entries("SPINHASH_STREAM_STATS_FIELDS", "S")]
    assert list(stream.stats["scene"]) == scene_keys


def test_scene_object_attributes_are_the_listed_keys():
    listed = {attribute for _, attribute in entries("SPINHASH_SCENE_OBJECT_KEYS", "K") if attribute}
    public = {a for a in dir(spinhash.SceneObject) if not a.startswith("_")}
    assert public == listed


def test_statuses_are_the_status_list():
    text = re.sub(r"\\\n", " ", (SOURCE_DIR / "include" / "spinhash" / "status_list.h").read_text())
    listed = re.findall(r'X\((\w+), (\d+), (\w+), "(\w+)",\s*"([^"]*)"\)', text)
    assert len(listed) == len(spinhash.STATUSES) > 30
    for _, value, _, word, message in listed:
        assert spinhash.STATUSES[word] == (int(value), message)


def test_a_window_work_budget_is_an_unsigned_64_bit_setting(fleet):
    db = spinhash.Database(fleet.db)
    big = spinhash.SceneRecognizer(db, window_max_work=2**40)
    assert big.window_max_work == 2**40
    with pytest.raises(ValueError, match="window_max_work is out of range"):
        spinhash.SceneRecognizer(db, window_max_work=2**40 + 1)
    with pytest.raises(ValueError, match="window_max_work is out of range"):
        spinhash.SceneRecognizer(db, window_max_work=-1)
    with pytest.raises(TypeError, match="window_max_work must be an int"):
        spinhash.SceneRecognizer(db, window_max_work=1.5)
