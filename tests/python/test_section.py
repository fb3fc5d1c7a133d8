"""Ensemble.section: maps and cross-sections as arrays, against NumPy's own slices and
statistics of the same values; contours on the known circles of sphere fields; the figure in
each format; refusals with the command line's messages."""

import os

import numpy as np
import pytest

import ensil
from conftest import sphere_ensemble

RADII = [4.0, 4.5, 6.0]


@pytest.fixture(scope="module")
def spheres():
    return sphere_ensemble(RADII, n=24)


def test_map_through_grid_points_holds_the_members_own_values(spheres):
    section = spheres.section(level="index:12", iso=0.0, clusters=2)
    # At a grid level the section is the data's own slice, NumPy's indexing as the oracle.
    np.testing.assert_array_equal(section.values, spheres.values[:, 12, :, :])
    np.testing.assert_allclose(section.fill, spheres.values[:, 12, :, :].mean(axis=0), rtol=1e-6)
    assert section.title == "distance at level 12 (z 12)"  # the z axis has no units
    assert len(section.contours) == len(RADII)
    # Each member's cluster number and colour, as preprocess gives them.
    result = spheres.preprocess(iso=0.0, clusters=2)
    assert list(section.clusters) == list(result.clusters)
    assert section.colors == result.colors


def test_contours_are_the_spheres_circles_within_a_twentieth_of_a_cell(spheres):
    section = spheres.section(level="index:14", iso=0.0, fill="none")
    assert section.fill is None
    centre = 23 / 2
    for radius, lines in zip(RADII, section.contours):
        assert len(lines) == 1
        # Plot places (0..1) back to grid indices: 23 cells across each axis.
        points = lines[0] * 23.0
        # The sphere's circle at 2.5 cells above its centre: sqrt(r^2 - 2.5^2).
        expected = np.sqrt(radius ** 2 - (14 - centre) ** 2)
        distances = np.hypot(points[:, 0] - centre, points[:, 1] - centre)
        assert np.max(np.abs(distances - expected)) < 0.05


def test_spread_along_a_latitude_is_numpys_standard_deviation(era5_path):
    era5 = ensil.open(era5_path, var="t")
    section = era5.section(lat="45N", iso=260, fill="spread", cache=False)
    lat = era5.axes["lat"]
    row = int(np.flatnonzero(np.isclose(lat, 45.0))[0])
    values = era5.values[:, :, row, :]  # members x levels x longitudes
    np.testing.assert_allclose(section.values, values, rtol=1e-6)
    np.testing.assert_allclose(section.fill, values.std(axis=0, ddof=1), rtol=1e-4, atol=1e-5)
    assert section.fill_range[0] == 0.0
    assert section.title == "t along 45°N"


def test_the_band_is_between_the_deepest_halfs_union_and_intersection(era5_path, tmp_path):
    era5 = ensil.open(era5_path, var="t")
    result = era5.preprocess(iso=250, cache=False)
    section = result.section(level="500hPa", band=True)
    assert section.median_member == result.median_member
    # The band from its definition, NumPy as the oracle: the ceil(N / 2) deepest members
    # (equals in index order), some above the isovalue at a point but not all.
    deepest = np.argsort(-result.depth, kind="stable")[:(len(result.depth) + 1) // 2]
    inside = section.values[deepest] > 250
    expected = inside.any(axis=0) & ~inside.all(axis=0)
    assert expected.sum() > 20
    np.testing.assert_array_equal(section.band, expected)
    assert result.section(level="500hPa").band is None
    section.save(str(tmp_path / "band.png"))


def test_probability_and_the_figure_in_each_format(era5_path, tmp_path):
    era5 = ensil.open(era5_path, var="t")
    # A bare number is in the axis's own units (Pa here).
    assert era5.section(level=50000, iso=250, cache=False).place == "50000 Pa"
    section = era5.section(level="500hPa", fill="probability", iso=250, cache=False)
    above = (era5.values[:, 0, :, :] > 250).mean(axis=0)
    np.testing.assert_allclose(section.fill, above, atol=1e-6)
    assert (section.colour_map, section.fill_range) == ("ylgnbu", (0.0, 1.0))
    fixed = era5.section(level="500hPa", fill="probability", iso=250, cache=False,
                         colour_map="greys", range=(0.2, 0.8))
    assert (fixed.colour_map, fixed.fill_range) == ("greys", pytest.approx((0.2, 0.8)))
    for suffix in ("png", "svg", "pdf"):
        path = tmp_path / ("map." + suffix)
        section.save(str(path))
        assert path.stat().st_size > 1000
    assert "<text" in (tmp_path / "map.svg").read_text(encoding="utf-8")


def test_a_pressure_axis_goes_up_as_the_vertical_axis_setting_says():
    demo = ensil.demo(members=4)
    plev = demo.to_xarray()["plev"].values  # hPa, from 1000 up to 100, even in log-pressure
    bottom, top = plev.max(), plev.min()
    linear = demo.section(lat=45, vertical_axis="pressure", cache=False)
    np.testing.assert_allclose(linear.row_positions, (bottom - plev) / (bottom - top), atol=1e-6)
    logarithmic = demo.section(lat=45, cache=False)  # the default, as the 3D view's
    np.testing.assert_allclose(logarithmic.row_positions,
                               np.log(bottom / plev) / np.log(bottom / top), atol=1e-6)
    with pytest.raises(ensil.ArgumentError, match="vertical_axis 'linear' is refused"):
        demo.section(lat=45, vertical_axis="linear", cache=False)


def test_refusals_say_what_is_wrong(era5_path):
    era5 = ensil.open(era5_path, var="t")
    result = era5.preprocess(iso=260, cache=False)
    with pytest.raises(ensil.ArgumentError, match="one of level="):
        result.section(level="500hPa", lat=45)
    with pytest.raises(ensil.ArgumentError, match="fill is refused"):
        result.section(level="500hPa", fill="median")
    with pytest.raises(ensil.ArgumentError, match="colour_map 'jet' is refused"):
        result.section(level="500hPa", colour_map="jet")
    with pytest.raises(ensil.ArgumentError, match="lower end must lie below"):
        result.section(level="500hPa", range=(260, 250))
    with pytest.raises(ensil.Error, match="outside the data"):
        result.section(level="1000hPa")
    with pytest.raises(ensil.Error, match="1 to 10"):
        result.section(level="500hPa", fill="member:11")
