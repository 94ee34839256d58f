"""Shared fixtures of the Python module's tests: the built `spinhash` command
(SPINHASH_CLI, set by scripts/python-tests.sh), a six-vehicle database built
with it, and airborne scans made with `spinhash scan`."""
import json
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[2]


def cli_path():
    path = os.environ.get("SPINHASH_CLI")
    if not path or not os.access(path, os.X_OK):
        pytest.fail("SPINHASH_CLI must name the built spinhash command (scripts/python-tests.sh sets it)")
    return path


def run_cli(*args, check=True, cwd=None):
    """Runs the spinhash command; its stdout, or the CompletedProcess when check is False."""
    done = subprocess.run([cli_path(), *map(str, args)], capture_output=True, text=True, cwd=cwd)
    if check:
        assert done.returncode == 0, f"spinhash {' '.join(map(str, args))}: {done.stderr}"
        return done.stdout
    return done


def assert_same_stats(stats, cli_stats):
    """The module's statistics against the CLI's JSON: counters exactly, a
    float as the CLI prints it (4 significant digits)."""
    assert stats.keys() == cli_stats.keys()
    for key, value in stats.items():
        expected = cli_stats[key]
        assert value == (pytest.approx(expected, rel=5e-4, abs=5e-5) if isinstance(value, float) else expected), key


def json_lines(text):
    return [json.loads(line) for line in text.splitlines() if line.strip()]


class Fleet:
    """Six generated vehicles, their database, and a helper for scans of them."""

    def __init__(self, root):
        self.root = root
        self.meshes = root / "fleet"
        self.db = root / "fleet.shdb"
        run_cli("generate", "--count", 6, "-o", self.meshes)
        run_cli("build", "--quiet", "--no-calibration", "-o", self.db, self.meshes)

    def scan(self, model, name, *options):
        """`spinhash scan` of one vehicle into root/name (the extension picks PLY or LAS)."""
        out = self.root / name
        run_cli("scan", self.meshes / f"{model}.obj", "-o", out, *options)
        return out


@pytest.fixture(scope="session")
def fleet(tmp_path_factory):
    return Fleet(tmp_path_factory.mktemp("fleet"))


@pytest.fixture(scope="session")
def truck_query(fleet):
    """A georeferenced airborne scan of truck-00 in a random pose, as PLY."""
    return fleet.scan("truck-00", "truck.ply", "--noise", 0.05, "--seed", 11, "--random-pose",
                      "--offset", 500000, 4000000, 120)
