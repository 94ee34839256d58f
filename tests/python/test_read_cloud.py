"""spinhash.read_cloud reads what the CLI reads: LAS from `spinhash scan -o x.las`,
PLY, text; unreadable files raise with the reason."""
import numpy as np
import pytest

import spinhash
from conftest import json_lines, run_cli


def test_las_and_ply_scans_read_the_same_points(fleet):
    options = ("--seed", 4, "--random-pose", "--offset", 500000, 4000000, 100, "--ground", 6)
    las = fleet.scan("sedan-00", "sedan.las", *options)
    ply = fleet.scan("sedan-00", "sedan.ply", *options)
    assert las.read_bytes()[:4] == b"LASF"
    from_las, from_ply = spinhash.read_cloud(las), spinhash.read_cloud(ply)
    assert from_las.dtype == np.float64 and from_las.flags.c_contiguous
    assert from_las.shape == from_ply.shape and from_las.shape[0] > 1000
    np.testing.assert_allclose(from_las, from_ply, rtol=0, atol=0.0006)  # LAS stores millimetres
    assert from_las[:, 0].mean() == pytest.approx(500000, abs=100)  # georeferenced, in double


def test_a_las_query_gives_the_clis_answer(fleet):
    las = fleet.scan("pickup-00", "pickup.las", "--seed", 8, "--random-pose", "--offset", 300000, 5000000, 50)
    line = json_lines(run_cli("recognize", "--db", fleet.db, las))[0]
    result = spinhash.Recognizer(spinhash.Database(fleet.db)).recognize(spinhash.read_cloud(las))
    assert result.model == line["ranking"][0]["model"] == "pickup-00"
    np.testing.assert_allclose(result.pose, np.reshape(line["pose"], (4, 4)), rtol=0, atol=1e-6)


def test_text_clouds_are_read(tmp_path):
    text = tmp_path / "three.xyz"
    text.write_text("1 2 3\n4 5 6\n7.5 8 9e2\n")
    np.testing.assert_array_equal(spinhash.read_cloud(str(text)), [[1, 2, 3], [4, 5, 6], [7.5, 8, 900]])


def test_unreadable_files_raise_with_the_reason(tmp_path):
    with pytest.raises(FileNotFoundError, match="nothing.las: no such file"):
        spinhash.read_cloud(tmp_path / "nothing.las")
    truncated = tmp_path / "truncated.las"
    truncated.write_bytes(b"LASF" + bytes(100))
    with pytest.raises(ValueError, match="truncated.las"):
        spinhash.read_cloud(truncated)
    zipped = tmp_path / "cloud.laz"
    zipped.write_bytes(b"PK\x03\x04" + bytes(100))
    with pytest.raises(ValueError):
        spinhash.read_cloud(zipped)
    with pytest.raises(ValueError):
        spinhash.read_cloud(tmp_path)  # a directory
