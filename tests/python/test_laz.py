"""spinhash.read_cloud reads LAZ and COPC through the same decoder as the CLI,
read_cloud_header gives a header and its CRS without the points, iter_cloud
hands out the points in chunks, and points a file marks as noise are left
out and counted (tests skip when ../shared/data/laz is absent)."""
import pathlib

import numpy as np
import pytest

import spinhash

LAZ = pathlib.Path(__file__).resolve().parents[2].parent / "shared" / "data" / "laz"
pytestmark = pytest.mark.skipif(not LAZ.is_dir(), reason="LAZ samples live in shared/, beside the clone")


def test_a_laz_tile_reads_as_its_las_twin():
    laz = spinhash.read_cloud(LAZ / "twins" / "autzen_trim.laz")
    las = spinhash.read_cloud(LAZ / "twins" / "autzen_trim.las")
    assert laz.shape == (110000, 3)
    np.testing.assert_array_equal(laz, las)


def test_copc_holds_the_points_of_its_twin_in_another_order():
    copc = spinhash.read_cloud(LAZ / "twins" / "simple-rgb.copc.laz")
    las = spinhash.read_cloud(LAZ / "twins" / "simple-rgb.las")
    key = lambda a: np.round(a, 2)[np.lexsort(np.round(a, 2).T)]
    np.testing.assert_allclose(key(copc), key(las), atol=1e-6)


def test_the_header_and_crs_come_without_the_points():
    h = spinhash.read_cloud_header(LAZ / "twins" / "1815.laz")
    assert h["format"] == "laz" and h["point_count"] == 1247 and h["las_point_format"] == 1
    assert h["crs"]["epsg"] == 6580 and h["crs"]["vertical_epsg"] == 5703
    wkt = spinhash.read_cloud_header(LAZ / "crs" / "file_with_both_wkt_and_geotiff_vlrs.las")["crs"]
    assert wkt["source"] == "wkt" and wkt["name"] == "NAD83_2011_Nebraska_ft"
    us_foot = 1200 / 3937  # the WKT's unit: US survey feet, metres per unit for x y and z
    assert wkt["metres_per_unit"] == pytest.approx((us_foot, us_foot)) and wkt["unit_notes"]
    assert h["crs"]["metres_per_unit"] == (1.0, 1.0) and h["crs"]["unit_notes"] == []
    assert spinhash.read_cloud_header(LAZ / "crs" / "epsg_4326.las")["crs"]["metres_per_unit"] is None
    bad = spinhash.read_cloud_header(LAZ / "crs" / "bad-geotiff-keys.las")["crs"]
    assert bad["epsg"] == 32617 and len(bad["warnings"]) == 1


@pytest.mark.parametrize("chunk", [1, 7, 4096, 200000])
def test_chunks_give_the_whole_cloud(chunk):
    path = LAZ / "twins" / "1_4_w_evlr.laz"
    chunks = spinhash.iter_cloud(path, chunk_points=chunk)
    assert chunks.header["point_count"] == 1000
    parts = list(chunks)
    assert all(1 <= len(p) <= chunk for p in parts)
    np.testing.assert_array_equal(np.concatenate(parts), spinhash.read_cloud(path))


def test_points_the_file_marks_as_noise_are_left_out_and_counted():
    path = LAZ / "crs" / "file_with_both_wkt_and_geotiff_vlrs.las"  # format 6, 25 points of class 7
    chunks = spinhash.iter_cloud(path, chunk_points=4096)
    assert chunks.points_noise == 0  # nothing read yet
    points = np.concatenate(list(chunks))
    assert chunks.points_noise == 25
    assert len(points) == chunks.header["point_count"] - 25
    np.testing.assert_array_equal(points, spinhash.read_cloud(path))


def test_classes_named_in_drop_classes_are_left_out_and_counted_with_the_noise():
    path = LAZ / "no-twin" / "format8-nir-extrabytes.laz"  # its producer put 539 low artefacts in class 65
    everything = spinhash.read_cloud(path)
    chunks = spinhash.iter_cloud(path, chunk_points=4096, drop_classes=[65])
    kept = np.concatenate(list(chunks))
    assert len(kept) == len(everything) - 539 and chunks.points_noise == 539
    np.testing.assert_array_equal(kept, spinhash.read_cloud(path, drop_classes=[65]))
    np.testing.assert_array_equal(spinhash.read_cloud(path, drop_classes=[200]), everything)  # no such point
    with pytest.raises(ValueError, match="256 is not a LAS class"):
        spinhash.read_cloud(path, drop_classes=[65, 256])


def test_broken_laz_raises_naming_the_problem():
    with pytest.raises(ValueError, match="compressor 16"):
        spinhash.read_cloud(LAZ / "broken" / "broken_compressor.laz")
    with pytest.raises(ValueError, match="coder 15"):
        list(spinhash.iter_cloud(LAZ / "broken" / "broken_coder.laz"))


def test_units_and_reprojection_through_the_reading_door():
    autzen = LAZ / "twins" / "autzen_trim.laz"
    crs = spinhash.read_cloud_header(autzen)["crs"]
    assert crs["name"] == "NAD_1983_HARN_Lambert_Conformal_Conic" and crs["units"] == ("foot", "foot")
    feet, metres = spinhash.read_cloud(autzen), spinhash.read_cloud(autzen, metres=True)
    np.testing.assert_allclose(metres, feet * 0.3048, rtol=1e-12)
    with pytest.raises(ValueError, match="degrees"):
        spinhash.read_cloud(LAZ / "crs" / "epsg_4326.las", metres=True)
    utm = spinhash.read_cloud(LAZ / "crs" / "epsg_4326.las", work_crs="EPSG:32615")
    assert utm[:, 0].min() == pytest.approx(339337, abs=50) and utm[:, 1].min() == pytest.approx(3434860, abs=100)
    chunks = np.concatenate(list(spinhash.iter_cloud(autzen, 4096, metres=True)))
    np.testing.assert_array_equal(chunks, metres)

