"""xarray in and out (python/ensil/_xarray.py), against xarray itself: xarray opens the real files
with its own NetCDF engine and ensil must see the same ensemble; the merge tree equals SciPy's
linkage of ensil's distances."""

import os
import subprocess

import numpy as np
import pytest
import scipy.cluster.hierarchy
import scipy.spatial.distance
import xarray as xr

import ensil
from conftest import SHARED_DATA


@pytest.fixture
def era5(era5_path):
    with xr.open_dataset(era5_path) as ds:
        yield ds.load()


def assert_same_ensemble(a, b):
    assert a.shape == b.shape
    assert a.dims[1:] == b.dims[1:]
    np.testing.assert_array_equal(a.values, b.values)
    for name in a.axes:
        np.testing.assert_array_equal(a.axes[name], b.axes[name])
    assert a.members == b.members
    assert a.units == b.units


def test_a_dataset_read_by_xarray_is_the_ensemble_ensil_reads(era5, era5_path):
    from_xr = ensil.from_xarray(era5, var="t")
    assert_same_ensemble(from_xr, ensil.open(era5_path, var="t"))
    assert from_xr.dims == ("number", "plev", "lat", "lon")
    assert from_xr.axis_units["plev"] == "Pa"
    # Another time step, as --time-index takes it.
    assert_same_ensemble(ensil.from_xarray(era5, var="z", time_index=3),
                         ensil.open(era5_path, var="z", time_index=3))


def test_dimensions_are_found_by_name_and_attributes_in_any_order(era5):
    da = era5["t"].transpose("lon", "time", "number", "lat", "plev")
    assert_same_ensemble(ensil.from_xarray(da), ensil.from_xarray(era5["t"]))
    # Names ensil does not know, found by their CF attributes.
    renamed = era5["t"].rename({"plev": "p", "lat": "j", "lon": "i", "number": "ens_id"})
    renamed = renamed.assign_coords(
        p=renamed.p.assign_attrs(axis="Z"), j=renamed.j.assign_attrs(axis="Y"),
        i=renamed.i.assign_attrs(axis="X"),
        ens_id=renamed.ens_id.assign_attrs(standard_name="realization"))
    got = ensil.from_xarray(renamed)
    assert got.dims == ("ens_id", "p", "j", "i")
    np.testing.assert_array_equal(got.values, ensil.from_xarray(era5["t"]).values)


def test_a_dimension_standing_in_for_members_is_named(era5_path):
    path = os.path.join(os.path.dirname(era5_path), "eraint_uvz.nc")
    with xr.open_dataset(path) as ds:
        got = ensil.from_xarray(ds.load(), var="u", member_dim="month")
    assert_same_ensemble(got, ensil.open(path, var="u", member_dim="month"))


def test_what_cannot_be_an_ensemble_is_refused_saying_why(era5):
    with pytest.raises(ensil.ArgumentError, match="several ensembles \\(z, t\\)"):
        ensil.from_xarray(era5)
    with pytest.raises(ensil.ArgumentError, match="no variable 'q'"):
        ensil.from_xarray(era5, var="q")
    with pytest.raises(ensil.ArgumentError, match="has no a vertical dimension|no a vertical"):
        ensil.from_xarray(era5["t"].isel(plev=0))
    with pytest.raises(ensil.ArgumentError, match="time_index 9 lies outside 'time'"):
        ensil.from_xarray(era5["t"], time_index=9)


def test_an_ensemble_goes_out_as_a_data_array_and_comes_back_the_same(era5_path):
    ens = ensil.open(era5_path, var="t")
    da = ens.to_xarray()
    assert da.dims == ("number", "plev", "lat", "lon")
    assert da.name == "t" and da.attrs["units"] == "K"
    assert list(da["number"].values) == ens.members
    assert da["plev"].attrs["units"] == "Pa"
    np.testing.assert_array_equal(da.values, ens.values)
    assert_same_ensemble(ensil.from_xarray(da), ens)
    # The accessor, once xarray and ensil have met.
    assert_same_ensemble(da.ensil.ensemble(), ens)


def test_a_result_goes_out_as_a_dataset_whose_tree_is_scipys(era5_path):
    result = ensil.open(era5_path, var="t").preprocess(iso=260, clusters=3)
    ds = result.to_xarray()
    assert list(ds["member"].values) == result.members
    np.testing.assert_array_equal(ds["cluster"].values, result.clusters)
    np.testing.assert_array_equal(ds["distance"].values, result.distance_matrix)
    np.testing.assert_array_equal(ds["depth"].values, result.depth)
    assert ds.attrs["clusters"] == 3 and ds.attrs["isovalue"] == 260.0
    scipys = scipy.cluster.hierarchy.linkage(
        scipy.spatial.distance.squareform(result.distance_matrix, checks=False),
        method=result.linkage_method)
    np.testing.assert_allclose(ds["linkage"].values[:, 2], scipys[:, 2], rtol=1e-12)
    np.testing.assert_array_equal(ds["linkage"].values[:, 3], scipys[:, 3])
    # The clusters SciPy cuts from its own tree are ensil's, up to their numbering.
    cut = scipy.cluster.hierarchy.fcluster(scipys, t=3, criterion="maxclust")
    pairs = set(zip(cut.tolist(), ds["cluster"].values.tolist()))
    assert len(pairs) == 3


def test_the_statistics_dataset_is_what_ensil_stats_writes(era5_path, tmp_path):
    executable = os.environ.get("ENSIL_EXECUTABLE", "")
    assert os.path.exists(executable), "CTest names the command line built beside the module"
    out = str(tmp_path / "stats.nc")
    subprocess.run([executable, "stats", era5_path, "--var", "t", "--iso", "260", "--members",
                    "1,3,6", "--out", out], check=True, capture_output=True)  # numbers from 1
    ens = ensil.open(era5_path, var="t")
    ours = ens.stats_dataset(260, members=[0, 2, 5])
    with xr.open_dataset(out) as written:
        assert set(ours.data_vars) == set(written.data_vars)
        for name in written.data_vars:
            assert ours[name].dims == written[name].dims, name
            np.testing.assert_array_equal(ours[name].values, written[name].values)
            for key in ("units", "cell_methods"):
                assert ours[name].attrs.get(key) == written[name].attrs.get(key), (name, key)
        for name in written.coords:
            np.testing.assert_allclose(ours[name].values, written[name].values, rtol=1e-12)
        assert ours.attrs["members"] == written.attrs["members"]
        assert ours.attrs["isovalue"] == written.attrs["isovalue"]


def test_a_grid_mapping_comes_through_as_from_the_file():
    """A rotated-pole file through xarray has the file's map projection: the same grid mapping
    and true longitude/latitude bounds as ensil.open gives (coastlines and bounds depend on
    them), from the Dataset or from a DataArray whose mapping xarray kept as a coordinate."""
    path = os.path.join(SHARED_DATA, "uk_hires.nc")
    from_file = ensil.open(path, member_dim="time").info()
    assert from_file["grid_mapping"] == "rotated_latitude_longitude"
    with xr.open_dataset(path) as ds:
        through = ensil.from_xarray(ds, member_dim="time").info()
    assert through["grid_mapping"] == from_file["grid_mapping"]
    np.testing.assert_allclose(through["lon_lat_bounds"], from_file["lon_lat_bounds"], atol=1e-9)
    with xr.open_dataset(path, decode_coords="all") as ds:
        array = ds["air_potential_temperature"]
        assert ensil.from_xarray(array, member_dim="time").info()["grid_mapping"] == \
            from_file["grid_mapping"]
    with pytest.raises(ensil.ArgumentError, match="grid_mapping_name"):
        ensil.from_numpy(np.zeros((2, 2, 2, 2), np.float32),
                         axes=[[0.0, 1.0], [0.0, 1.0], [0.0, 1.0]],
                         grid_mapping={"grid_north_pole_latitude": 37.5})
