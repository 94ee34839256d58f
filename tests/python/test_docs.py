"""docs/python.md as run: its install commands (into a temporary prefix), its
example's commands and every Python block, and its table of settings."""
import ast
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig

import pytest

import spinhash
from conftest import SOURCE_DIR, cli_path, run_cli

DOC = (SOURCE_DIR / "docs" / "python.md").read_text()


def blocks(language, section=None):
    """Fenced blocks of one language, in order; only those under `## section` when given."""
    text = DOC
    if section:
        text = text[text.index(f"\n## {section}\n"):]
        text = text[:text.find("\n## ", 1)]
    return re.findall(rf"```{language}\n(.*?)```", text, re.S)


def commands(block):
    return [line.split("#")[0].strip() for line in block.splitlines() if line.split("#")[0].strip()]


def test_the_install_commands_install_an_importable_module(tmp_path):
    install = commands(blocks("sh", "Install")[0])
    assert "cmake --install build" in " ".join(install)
    assert 'python3 -c "import spinhash; print(spinhash.__version__)"' in install
    build = os.environ.get("SPINHASH_BUILD_DIR") or pytest.fail("SPINHASH_BUILD_DIR: scripts/python-tests.sh sets it")
    prefix = tmp_path / "prefix"
    subprocess.run([shutil.which("cmake"), "--install", build, "--prefix", prefix, "--component", "python"],
                   check=True, capture_output=True)
    installed = list(prefix.rglob("spinhash/_spinhash*.so"))
    assert len(installed) == 1
    assert (installed[0].parent / "__init__.py").is_file() and (installed[0].parent / "survey.py").is_file()
    site = installed[0].parent.parent
    # Where this interpreter looks under a prefix: lib/python3.X/<dist-packages on Debian, else site-packages>.
    version = f"python{sys.version_info.major}.{sys.version_info.minor}"
    assert site.relative_to(prefix) == pathlib.Path("lib", version, pathlib.Path(sysconfig.get_path("platlib")).name)
    done = subprocess.run([sys.executable, "-c", "import spinhash; print(spinhash.__version__)"],
                          env={**os.environ, "PYTHONPATH": str(site)}, cwd=tmp_path, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == spinhash.__version__
    assert run_cli("--version").strip() == spinhash.__version__  # both are CMake's PROJECT_VERSION


def test_the_example_runs_as_written(tmp_path, capsys, monkeypatch):
    for command in commands(blocks("sh", "A complete example")[0]):
        argv = shlex.split(command)
        assert argv[0] == "spinhash"
        subprocess.run([cli_path(), *argv[1:]], cwd=tmp_path, check=True, capture_output=True)
    monkeypatch.chdir(tmp_path)
    namespace = {}
    python_blocks = blocks("python")
    assert len(python_blocks) >= 2
    for code in python_blocks:
        exec(compile(code, "docs/python.md", "exec"), namespace)
    out = capsys.readouterr().out
    result = namespace["result"]
    assert result.model == "truck-00" and result.confident
    assert result.stats["points_ground"] > 0  # the scan has ground, the recogniser dropped it
    assert re.search(r"^  truck-00 ", out, re.M)
    assert re.search(r"^vehicle truck-00 (True|False) ", out, re.M)  # found, and named right
    assert "['truck-00', 'truck-00', 'truck-00']" in out


def test_the_settings_table_is_the_config():
    rows = re.findall(r"^\| `(\w+)` \| ([^|]+) \| ([^|]+) \|", DOC, re.M)
    assert [name for name, _, _ in rows] == list(spinhash.Config.fields)
    config = spinhash.Config()
    for name, default, valid in rows:
        assert ast.literal_eval(default.strip().strip("`")) == getattr(config, name), name
        if name in spinhash.Config.ranges:
            lo, hi = (ast.literal_eval(v) for v in valid.split(" - "))
            assert (lo, hi) == spinhash.Config.ranges[name], name


def test_the_class_level_is_documented_and_every_class_named():
    """docs/python.md names the class attributes; CLASS_NAMES is vehicle_classes.h's list, in id order."""
    for attribute in ("vehicle_class", "class_confident", "class_ranking", "group", "group_ranking", "levels",
                      "level", "CLASS_NAMES"):
        assert f"`{attribute}`" in DOC or f"`spinhash.{attribute}`" in DOC
        if attribute != "CLASS_NAMES":
            assert hasattr(spinhash.Result, attribute) and hasattr(spinhash.SceneObject, attribute)
    header = (SOURCE_DIR / "include" / "spinhash" / "vehicle_classes.h").read_text()
    listed = re.findall(r'C\((\d+), \w+, "([a-z]+)"', header)
    assert [int(i) for i, _ in listed] == list(range(len(listed)))
    assert spinhash.CLASS_NAMES == tuple(name for _, name in listed)


def test_every_group_is_named_and_every_class_has_its_listed_group():
    """GROUP_NAMES is vehicle_classes.h's group list in id order; CLASS_GROUPS its class list's group column."""
    header = (SOURCE_DIR / "include" / "spinhash" / "vehicle_classes.h").read_text()
    groups = re.findall(r'G\((\d+), (\w+), "([a-z]+)"', header)
    assert [int(i) for i, _, _ in groups] == list(range(len(groups)))
    assert spinhash.GROUP_NAMES == tuple(name for _, _, name in groups)
    group_name = {symbol: name for _, symbol, name in groups}
    classes = re.findall(r'C\((\d+), \w+, "[a-z]+", (\w+),', header)
    assert spinhash.CLASS_GROUPS == tuple(group_name[symbol] for _, symbol in classes)
    assert len(spinhash.CLASS_GROUPS) == len(spinhash.CLASS_NAMES)
    assert spinhash.CLASS_GROUPS[spinhash.CLASS_NAMES.index("suv")] == "light"
    assert spinhash.CLASS_GROUPS[spinhash.CLASS_NAMES.index("bus")] == "heavy"
    for attribute in ("GROUP_NAMES", "CLASS_GROUPS"):
        assert f"`spinhash.{attribute}`" in DOC


def test_the_readme_python_snippet_reads_files_the_readme_makes():
    readme = (SOURCE_DIR / "README.md").read_text()
    snippet = readme[readme.index("From Python"):]
    snippet = re.findall(r"```python\n(.*?)```", snippet, re.S)[0]
    read = re.findall(r"(?:read_cloud|Database)\(\"([^\"]+)\"\)", snippet)
    assert read, "the snippet reads no file"
    made = set(re.findall(r"\$ build/host-tools/spinhash \w+[^\n]*?-o (\S+)", readme))
    for name in read:
        assert name in made, f"README's Python snippet reads {name}, which no README command makes"

