"""spinhash.Config mirrors SPINHASH_CONFIG_FIELDS (include/spinhash/config_fields.h)
and each stage's SPINHASH_PARAMS_<id> (stage_fields.h): every field is an
attribute and a keyword argument, with the core's range."""
import math
import re

import pytest

import spinhash
from conftest import SOURCE_DIR, json_lines, run_cli

FIELDS_HEADER = SOURCE_DIR / "include" / "spinhash" / "config_fields.h"
STAGES_HEADER = SOURCE_DIR / "include" / "spinhash" / "stage_fields.h"


def header_entries(macro, letter, header=FIELDS_HEADER):
    """(kind, name, rest) of each entry of one X-macro list of config_fields.h (or `header`)."""
    text = header.read_text()
    body = text[text.index(f"#define {macro}("):]
    body = body[:body.index("\n\n")]
    return re.findall(rf"\b{letter}\((\w+), (\w+),([^\n]*)", body)


def config_entries():
    """(kind, Python name, rest) of every field: the top-level list, then each stage's in run order
    (a stage's switch, `enabled`, is <stage>_enabled in Python)."""
    entries = header_entries("SPINHASH_CONFIG_FIELDS", "X")
    for stage, _, _ in header_entries("SPINHASH_STAGES", "S", STAGES_HEADER):
        for kind, name, rest in header_entries(f"SPINHASH_PARAMS_{stage}", "X", STAGES_HEADER):
            entries.append((kind, f"{stage}_enabled" if name == "enabled" else name, rest))
    return entries


def test_every_config_field_and_only_those():
    names = [name for _, name, _ in config_entries()]
    assert len(names) >= 100
    assert list(spinhash.Config.fields) == names
    assert len(set(names)) == len(names)


def test_a_stage_field_also_goes_by_its_key():
    config = spinhash.Config(**{"draws.max_trials": 800, "focus.enabled": False})
    assert config.max_trials == 800 and not config.focus_enabled
    assert spinhash.Config.keys["max_trials"] == "draws.max_trials"
    assert spinhash.Config.keys["focus_enabled"] == "focus.enabled"
    assert spinhash.Config.keys["seed"] == "seed"


def test_every_stats_field_under_its_json_key(fleet, truck_query):
    keys = [re.search(r'"(\w+)"', rest).group(1) for _, _, rest in header_entries("SPINHASH_STATS_FIELDS", "S")]
    assert len(keys) >= 20
    result = spinhash.Recognizer(spinhash.Database(fleet.db)).recognize(spinhash.read_cloud(truck_query))
    assert list(result.stats) == keys
    assert list(json_lines(run_cli("recognize", "--db", fleet.db, truck_query))[0]["stats"]) == keys


def a_value_inside(name, default):
    """A valid value other than the default, from the field's kind and range."""
    if name == "mode":
        return "sind"
    if name == "viewpoint":
        return (1.5, -2.0, 30.0)
    if isinstance(default, bool):
        return not default
    lo, hi = spinhash.Config.ranges[name]
    if isinstance(default, int):
        return default + 1 if default < hi else default - 1
    return (lo + hi) / 2 if (lo + hi) / 2 != default else lo


@pytest.mark.parametrize("name", spinhash.Config.fields)
def test_each_field_is_a_keyword_and_an_attribute(name):
    default = getattr(spinhash.Config(), name)
    value = a_value_inside(name, default)
    by_keyword = spinhash.Config(**{name: value})
    assert getattr(by_keyword, name) == pytest.approx(value, rel=1e-6)
    by_attribute = spinhash.Config()
    setattr(by_attribute, name, value)
    assert by_attribute == by_keyword
    others = [f for f in spinhash.Config.fields if f not in (name, "has_viewpoint")]
    assert all(getattr(by_keyword, f) == getattr(spinhash.Config(), f) for f in others)


@pytest.mark.parametrize("name", sorted(spinhash.Config.ranges))
def test_each_range_is_the_cores(name):
    lo, hi = spinhash.Config.ranges[name]
    spinhash.Config(**{name: lo})
    spinhash.Config(**{name: hi})
    below, above = (lo - 1, hi + 1) if isinstance(lo, int) else (lo - abs(lo) * 0.01 - 1e-3, hi * 1.01 + 1e-3)
    for bad in (below, above):
        with pytest.raises(ValueError, match=rf"^{name} must be in \["):
            spinhash.Config(**{name: bad})
        config = spinhash.Config()
        with pytest.raises(ValueError, match=name):
            setattr(config, name, bad)
        assert getattr(config, name) == getattr(spinhash.Config(), name)  # unchanged after the error


def test_the_cli_refuses_what_the_module_refuses(fleet, truck_query):
    # Same bounds: the CLI's flags and the module both come from the one list.
    lo, hi = spinhash.Config.ranges["top_w"]
    assert run_cli("recognize", "--db", fleet.db, "-W", hi + 1, truck_query, check=False).returncode == 2
    assert run_cli("recognize", "--db", fleet.db, "-W", hi, "--trials", 10, truck_query, check=False).returncode == 0
    with pytest.raises(ValueError):
        spinhash.Recognizer(spinhash.Database(fleet.db), top_w=hi + 1)


def test_the_mode_is_named_as_on_the_command_line():
    assert spinhash.Config.modes == ("bran", "sran", "sind")
    assert spinhash.Config().mode == "bran"
    assert spinhash.Config(mode="SRAN").mode == "sran"
    with pytest.raises(ValueError, match="mode must be one of bran, sran, sind"):
        spinhash.Config(mode="ransac")
    with pytest.raises(TypeError, match="mode must be a str"):
        spinhash.Config(mode=1)


def test_values_of_the_wrong_type_are_type_errors():
    with pytest.raises(TypeError, match="max_points must be an int"):
        spinhash.Config(max_points=1.5)
    with pytest.raises(TypeError, match="max_points must be an int"):
        spinhash.Config(max_points=True)
    with pytest.raises(TypeError, match="sigma must be a number"):
        spinhash.Config(sigma="0.1")
    with pytest.raises(TypeError, match="refine_poses must be True or False"):
        spinhash.Config(refine_poses=1)
    with pytest.raises(TypeError, match="unknown recognizer setting 'sigmaa'"):
        spinhash.Config(sigmaa=0.1)
    with pytest.raises(ValueError, match="sigma must be in"):
        spinhash.Config(sigma=math.nan)
    with pytest.raises(ValueError, match="seed must be in"):
        spinhash.Config(seed=-1)
    with pytest.raises(ValueError, match="seed must be in"):
        spinhash.Config(seed=2**64)
    assert spinhash.Config(seed=2**64 - 1).seed == 2**64 - 1


def test_the_viewpoint_turns_on_and_off_as_the_cli_flag():
    config = spinhash.Config(viewpoint=(1, 2, 3))
    assert config.has_viewpoint and config.viewpoint == (1.0, 2.0, 3.0)
    config.viewpoint = None
    assert not config.has_viewpoint
    with pytest.raises(ValueError, match="viewpoint must be finite"):
        spinhash.Config(viewpoint=(0, math.inf, 0))
    with pytest.raises(TypeError, match="viewpoint must be 3 numbers"):
        spinhash.Config(viewpoint=(0, 0))


def test_rules_joining_fields_are_checked_when_a_recognizer_is_made(fleet):
    db = spinhash.Database(fleet.db)
    with pytest.raises(ValueError, match="delta_max .* must be at least delta"):
        spinhash.Recognizer(db, delta=0.5, delta_max=0.4)
    with pytest.raises(ValueError, match="recognizer: "):  # the database has more models than the workspace holds
        spinhash.Recognizer(db, max_models=2)


def test_a_recognizer_takes_a_config_and_keywords_over_it(fleet):
    db = spinhash.Database(fleet.db)
    config = spinhash.Config(mode="sran", seed=5)
    rec = spinhash.Recognizer(db, config, seed=9)
    assert rec.config.mode == "sran" and rec.config.seed == 9
    assert config.seed == 5  # the caller's Config is not changed
    assert rec.workspace_bytes > 0
    with pytest.raises(TypeError, match="config must be a spinhash.Config"):
        spinhash.Recognizer(db, {"seed": 1})


def test_defaults_and_ranges_are_the_clis():
    """Each numeric flag of `spinhash recognize --help` shows the module's range and default."""
    help_text = run_cli("recognize", "--help")
    checked = 0
    for kind, name, rest in config_entries():
        flag = re.search(r'"(?:-\w,)?(--[\w-]+)"', rest)
        if kind not in ("U32", "U64", "F32") or not flag:
            continue
        shown = re.search(re.escape(flag.group(1)) + r" \w+:\w+ in \[([-\d.e+]+) - ([-\d.e+]+)\]=([-\d.e+]+)",
                          help_text)
        assert shown, flag.group(1)
        lo, hi, default = (float(v) for v in shown.groups())
        assert spinhash.Config.ranges[name] == (pytest.approx(lo, rel=1e-6), pytest.approx(hi, rel=1e-6)), name
        assert getattr(spinhash.Config(), name) == pytest.approx(default, rel=1e-6), name
        checked += 1
    assert checked >= 25


def test_a_config_copies_and_pickles_with_every_setting():
    import copy
    import pickle
    config = spinhash.Config(mode="sran", seed=2**63, sigma=0.2, refine_poses=False, viewpoint=(1, 2, 3))
    for twin in (copy.copy(config), copy.deepcopy(config), config.copy(), pickle.loads(pickle.dumps(config))):
        assert twin == config and twin is not config
        assert twin.to_dict() == config.to_dict()
    default = spinhash.Config()
    for twin in (pickle.loads(pickle.dumps(default)), spinhash.Config(**default.to_dict())):
        assert twin == default and not twin.has_viewpoint  # the viewpoint's value does not turn it on here
    twin = config.copy()
    twin.seed = 1
    assert config.seed == 2**63 and twin != config
