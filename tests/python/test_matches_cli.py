"""The module gives the CLI's answer on the same query: same ranking (names,
order, scores), pose within 1e-6, same confidence, status and statistics."""
import json

import numpy as np
import pytest

import spinhash
from conftest import assert_same_stats, json_lines, run_cli


def cli_answer(fleet, query, *flags):
    lines = json_lines(run_cli("recognize", "--db", fleet.db, *flags, query))
    assert len(lines) == 1
    return lines[0]


def assert_same_answer(result, line):
    assert result.status == line["status"]
    assert [name for name, _ in result.ranking] == [entry["model"] for entry in line["ranking"]]
    for (_, score), entry in zip(result.ranking, line["ranking"]):
        assert score == pytest.approx(entry["score"], rel=1e-6, abs=1e-9)  # the CLI prints 7 digits
    if line["pose"] is None:
        assert result.pose is None
    else:
        assert result.pose.shape == (4, 4) and result.pose.dtype == np.float64
        np.testing.assert_allclose(result.pose, np.array(line["pose"]).reshape(4, 4), rtol=0, atol=1e-6)
    assert result.confident == line["confident"]
    assert result.group_size == line["group_size"]
    assert result.group_size >= (1 if result.ranking else 0)
    assert_same_classes(result, line)
    assert_same_levels(result, line)
    assert_same_stats(result.stats, line["stats"])


def assert_same_classes(answer, line):
    """The class level: the CLI's class, class_confident and class_ranking."""
    assert answer.vehicle_class == line["class"]
    assert answer.class_confident == line["class_confident"]
    assert [(c, m) for c, _, m in answer.class_ranking] == \
        [(entry["class"], entry["model"]) for entry in line["class_ranking"]]
    for (_, score, _), entry in zip(answer.class_ranking, line["class_ranking"]):
        assert score == pytest.approx(entry["score"], rel=1e-6, abs=1e-9)
    assert all(c in spinhash.CLASS_NAMES for c, _, _ in answer.class_ranking)


def assert_same_levels(answer, line):
    """The answer levels: the CLI's group, group_ranking, levels and level."""
    assert answer.group == line["group"]
    assert [(g, m) for g, _, m in answer.group_ranking] == \
        [(entry["group"], entry["model"]) for entry in line["group_ranking"]]
    assert list(answer.levels) == list(line["levels"]) == ["vehicle", "group", "class", "model"]
    for name, level in answer.levels.items():
        assert level["confident"] == line["levels"][name]["confident"]
        if line["levels"][name]["evidence"] is None:
            assert level["evidence"] is None
        else:
            assert level["evidence"] == pytest.approx(line["levels"][name]["evidence"], rel=1e-5, abs=1e-6)
    assert answer.levels["model"]["confident"] == answer.confident
    assert answer.levels["class"]["confident"] == answer.class_confident
    assert answer.level == line["level"]
    assert answer.level in ("none", "vehicle", "group", "class", "model")


@pytest.mark.parametrize("mode", ["bran", "sran", "sind"])
def test_each_mode_matches_the_cli(fleet, truck_query, mode):
    line = cli_answer(fleet, truck_query, "--mode", mode)
    result = spinhash.Recognizer(spinhash.Database(fleet.db), mode=mode).recognize(
        spinhash.read_cloud(truck_query))
    assert_same_answer(result, line)
    assert result.model == "truck-00"
    assert len(result.ranking) >= 2
    assert result.vehicle_class == "truck"  # the fleet's family


def test_keyword_settings_match_the_cli_flags(fleet, truck_query):
    line = cli_answer(fleet, truck_query, "--seed", 7, "--trials", 300, "-W", 20, "--no-refine",
                      "--ground-clearance", 0.1)
    rec = spinhash.Recognizer(spinhash.Database(fleet.db), seed=7, max_trials=300, top_w=20,
                              refine_poses=False, ground_clearance=0.1)
    assert_same_answer(rec.recognize(spinhash.read_cloud(truck_query)), line)


def test_the_pose_is_georeferenced_like_the_query(fleet, truck_query):
    points = spinhash.read_cloud(truck_query)
    result = spinhash.Recognizer(spinhash.Database(fleet.db)).recognize(points)
    assert result.confident
    # The model's origin lands inside the scan, at UTM-sized coordinates.
    origin = result.pose[:3, 3]
    assert np.all(origin >= points.min(axis=0) - 1.0) and np.all(origin <= points.max(axis=0) + 1.0)
    rotation = result.pose[:3, :3]
    np.testing.assert_allclose(rotation @ rotation.T, np.eye(3), atol=1e-5)
    np.testing.assert_array_equal(result.pose[3], [0, 0, 0, 1])


def test_a_database_from_bytes_answers_as_the_file(fleet, truck_query):
    points = spinhash.read_cloud(truck_query)
    from_file = spinhash.Recognizer(spinhash.Database(fleet.db)).recognize(points)
    from_bytes = spinhash.Recognizer(spinhash.Database.from_bytes(fleet.db.read_bytes())).recognize(points)
    assert from_bytes.ranking == from_file.ranking
    np.testing.assert_array_equal(from_bytes.pose, from_file.pose)


def test_database_describes_itself_as_info_does(fleet):
    db = spinhash.Database(fleet.db)
    assert len(db) == 6
    assert sorted(db.names) == sorted(p.stem for p in fleet.meshes.glob("*.obj"))
    assert db.names == [m["name"] for m in db.models]
    text = run_cli("info", fleet.db)
    for model in db.models:
        assert model["name"] in text and model["features"] > 0
        assert model["group"] == spinhash.CLASS_GROUPS[spinhash.CLASS_NAMES.index(model["class"])]
        assert all(e > 0.5 for e in model["extent"])
    assert f"models        {db.info['models']}" in text
    assert f"features      {db.info['features']}" in text
    assert db.info["bytes"] == fleet.db.stat().st_size
    assert f"{db.info['bins_alpha']}x{db.info['bins_beta']} bins" in text
    field = f"nearest field {db.info['field_cell']:g} m voxels, reach {db.info['field_reach']:g} m, "
    assert field + f"{db.info['field_slots']} slots, {db.info['field_entry_count']} entries" in text
    assert db.info["format_version"] == 5 and db.info["field_entry_count"] > 0


def test_database_gives_a_model_its_own_group_as_info_does(fleet, tmp_path):
    """A model of a class in no group ("other") may carry a group of its own
    (the build manifest's third word); the module and `info` both read it."""
    manifest = tmp_path / "classes.txt"
    manifest.write_text("sedan-00 other light\ntruck-00 other\n")
    db_path = tmp_path / "grouped.shdb"
    run_cli("build", "--quiet", "--no-calibration", "--classes", manifest, "-o", db_path, fleet.meshes)
    models = {m["name"]: m for m in spinhash.Database(db_path).models}
    assert (models["sedan-00"]["class"], models["sedan-00"]["group"]) == ("other", "light")
    assert (models["truck-00"]["class"], models["truck-00"]["group"]) == ("other", "none")
    info = {m["name"]: m for m in json.loads(run_cli("info", "--format", "json", db_path))["model_list"]}
    for name, model in models.items():
        assert (info[name]["class"], info[name]["group"]) == (model["class"], model["group"])
