"""ensil.open(bbox=...) against xarray's own selection by coordinate: a small global NetCDF
ensemble written here with xarray and netCDF4 (longitudes 0..357.5, latitudes north to south),
read by ensil as hyperslabs, must give exactly what xarray's sel(lon=..., lat=...) gives, across
the 0/360 seam too (xarray's concat of the two sides, and its roll); Session(bbox=...) keeps
the region in its project; a malformed box or one without grid points is an ArgumentError."""

import json

import numpy as np
import pytest
import xarray as xr

import ensil


@pytest.fixture(scope="module")
def globe(tmp_path_factory):
    """5 members of t on 4 pressure levels, 144 longitudes from 0 and 73 latitudes from 90 N."""
    rng = np.random.default_rng(42)
    lon = np.arange(0.0, 360.0, 2.5)
    lat = np.arange(90.0, -90.1, -2.5)
    plev = np.array([1000.0, 850.0, 500.0, 250.0])
    values = rng.normal(280.0, 10.0, size=(5, plev.size, lat.size, lon.size)).astype(np.float32)
    ds = xr.Dataset(
        {"t": (("number", "plev", "lat", "lon"), values, {"units": "K"})},
        coords={
            "number": ("number", np.arange(5), {"standard_name": "realization"}),
            "plev": ("plev", plev, {"units": "hPa", "positive": "down", "axis": "Z"}),
            "lat": ("lat", lat, {"units": "degrees_north", "standard_name": "latitude"}),
            "lon": ("lon", lon, {"units": "degrees_east", "standard_name": "longitude"}),
        })
    path = tmp_path_factory.mktemp("region") / "globe.nc"
    ds.to_netcdf(path, engine="netcdf4")
    return str(path), ds.t


def assert_same(kept, expected):
    """ensil's ensemble equals xarray's DataArray: values and every axis, exactly."""
    expected = expected.transpose("number", "plev", "lat", "lon")
    assert kept.shape == expected.shape
    np.testing.assert_array_equal(kept.values, expected.values)
    for name in ("plev", "lat", "lon"):
        np.testing.assert_array_equal(kept.axes[name], expected[name].values, err_msg=name)


def test_a_box_within_the_grid_is_xarrays_selection(globe):
    path, t = globe
    kept = ensil.open(path, var="t", bbox=(5, 40, 35, 72))
    assert_same(kept, t.sel(lon=slice(5, 40), lat=slice(72, 35)))
    # Edges on grid points are kept; the latitudes may be given either way round.
    kept = ensil.open(path, var="t", bbox=[5.0, 40.0, 72.5, 35.0])
    assert_same(kept, t.sel(lon=slice(5, 40), lat=slice(72.5, 35)))
    assert kept.axes["lon"][-1] == 40.0 and kept.axes["lat"][0] == 72.5


def test_a_box_across_the_seam_is_xarrays_two_sides_joined(globe):
    path, t = globe
    # -10..40 on 0..357.5: 350..357.5 written as -10..-2.5, then 0..40.
    west = t.sel(lon=slice(350, 360), lat=slice(72, 35))
    east = t.sel(lon=slice(0, 40), lat=slice(72, 35))
    expected = xr.concat([west.assign_coords(lon=west.lon - 360.0), east], dim="lon")
    assert_same(ensil.open(path, var="t", bbox=(-10, 40, 35, 72)), expected)
    assert_same(ensil.open(path, var="t", bbox="-10,40,35,72"), expected)
    # 350..20 is the same box as -10..20, written so (never past 360).
    east = t.sel(lon=slice(0, 20), lat=slice(72, 35))
    expected = xr.concat([west.assign_coords(lon=west.lon - 360.0), east], dim="lon")
    assert_same(ensil.open(path, var="t", bbox=(350, 20, 35, 72)), expected)


def test_the_whole_globe_from_180_west_is_xarrays_roll(globe):
    path, t = globe
    # xarray's roll by half the globe, longitudes written from -180 on.
    rolled = t.roll(lon=72, roll_coords=True)
    rolled = rolled.assign_coords(lon=np.where(rolled.lon >= 180.0, rolled.lon - 360.0, rolled.lon))
    kept = ensil.open(path, var="t", bbox=(-180, 180, -90, 90))
    assert_same(kept, rolled)
    assert kept.axes["lon"][0] == -180.0 and kept.axes["lon"][-1] == 177.5
    assert kept.info()["kept_region"]["column_runs"] == [{"first": 72, "count": 72},
                                                         {"first": 0, "count": 72}]


def test_the_levels_and_the_region_combine(globe):
    path, t = globe
    kept = ensil.open(path, var="t", levels="850:500hPa", bbox=(-10, 40, 35, 72))
    west = t.sel(lon=slice(350, 360), lat=slice(72, 35), plev=[850.0, 500.0])
    east = t.sel(lon=slice(0, 40), lat=slice(72, 35), plev=[850.0, 500.0])
    assert_same(kept, xr.concat([west.assign_coords(lon=west.lon - 360.0), east], dim="lon"))
    info = kept.info()
    assert info["kept_region"]["bbox"] == [-10, 40, 35, 72]
    assert info["kept_region"]["of"] == [144, 73]
    assert info["grid"] == [21, 15, 2]


def test_a_session_keeps_the_region_in_its_project(globe, tmp_path):
    path, _ = globe
    project = str(tmp_path / "europe.ensil")
    ensil.Session(path, var="t", bbox=(350, 40, 35, 72)).save(project)
    with open(project) as f:
        assert json.load(f)["data"]["region"] == "350,40,35,72"
    ensil.Session.load(project).save(project)  # read back and written again, the same
    with open(project) as f:
        assert json.load(f)["data"]["region"] == "350,40,35,72"
    with pytest.raises(ensil.ArgumentError, match="bbox: the region '0,10,95,72' has LAT0 = 95"):
        ensil.Session(path, bbox=(0, 10, 95, 72))


def test_a_malformed_box_or_one_without_grid_points_is_refused(globe):
    path, _ = globe
    with pytest.raises(ensil.ArgumentError, match=r"bbox: \(1, 2, 3\) has 3 numbers, not 4"):
        ensil.open(path, bbox=(1, 2, 3))
    with pytest.raises(ensil.ArgumentError, match="is not four numbers"):
        ensil.open(path, bbox=("west", 2, 3, 4))
    with pytest.raises(ensil.ArgumentError, match="'10,10,35,72' has no width"):
        ensil.open(path, bbox=(10, 10, 35, 72))
    with pytest.raises(ensil.ArgumentError, match="has 'a' for LON0"):
        ensil.open(path, bbox="a,10,35,72")
    with pytest.raises(ensil.ArgumentError,
                       match=r"the region 1,2,35,72 holds no grid point of 't' in .*globe\.nc, "
                             r"whose grid spans longitudes 0 to 357\.5 and latitudes 90 to -90 "
                             r"\(144 x 73 points\)"):
        ensil.open(path, bbox=(1, 2, 35, 72))
