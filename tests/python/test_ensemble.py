"""ensil.from_numpy, ensil.open and Ensemble: values, axes and names survive the round trip
NumPy -> ensil -> NumPy; info() says what `ensil info --json` says; bad input is refused with
the command line's messages."""

import os
import subprocess
import warnings

import numpy as np
import pytest

import ensil


def grid_axes():
    return {"plev": (np.array([1000.0, 850.0, 500.0]), "hPa"),
            "lat": (np.array([40.0, 45.0, 50.0, 55.0]), "degrees_north"),
            "lon": (np.array([0.0, 2.0, 4.0, 6.0, 8.0]), "degrees_east")}


def test_values_axes_and_names_round_trip():
    rng = np.random.default_rng(7)
    values = rng.normal(size=(4, 3, 4, 5)).astype(np.float32)
    values[2, 1, 3, 4] = np.nan
    ens = ensil.from_numpy(values, grid_axes(), units="K", names=["a", "b", "c", "d"],
                           variable="t")
    back = ens.values
    assert back.dtype == np.float32 and back.shape == (4, 3, 4, 5)
    np.testing.assert_array_equal(back, values)  # NaN where NaN
    assert not back.flags.writeable
    assert ens.shape == (4, 3, 4, 5) and len(ens) == 4
    assert ens.dims == ("member", "plev", "lat", "lon")
    assert list(ens.axes) == ["plev", "lat", "lon"]
    for name, (coords, units) in grid_axes().items():
        np.testing.assert_array_equal(ens.axes[name], coords)
        assert ens.axis_units[name] == units
    assert ens.members == ["a", "b", "c", "d"]
    assert ens.units == "K" and ens.variable == "t"
    for m in range(4):
        np.testing.assert_array_equal(ens.member_values(m), values[m])
    np.testing.assert_array_equal(ens.member_values(-1), values[3])


def test_member_values_are_views_of_ensils_memory():
    ens = ensil.from_numpy(np.ones((2, 3, 4, 5)), grid_axes())
    view = ens.member_values(1)
    assert not view.flags.writeable and not view.flags.owndata
    # The view keeps the ensemble's memory alive when the ensemble is gone.
    del ens
    assert float(view.sum()) == 60.0


def test_values_are_copied_in_not_shared_with_the_callers_array():
    values = np.zeros((2, 3, 4, 5), dtype=np.float32)
    ens = ensil.from_numpy(values, grid_axes())
    values[:] = 7.0
    assert float(ens.values.max()) == 0.0


def test_default_names_and_sequence_axes():
    ens = ensil.from_numpy(np.zeros((3, 2, 2, 2)), [[0, 1], [0, 1], [0, 1]])
    assert ens.members == ["member 1", "member 2", "member 3"]
    assert ens.dims == ("member", "z", "y", "x")


def test_infinities_become_missing_and_are_said():
    values = np.ones((2, 3, 4, 5), dtype=np.float32)
    values[0, 0, 0, 0] = np.inf
    values[1, 2, 3, 4] = -np.inf
    with pytest.warns(ensil.DataWarning, match="2"):
        ens = ensil.from_numpy(values, grid_axes())
    assert np.isnan(ens.values[0, 0, 0, 0]) and np.isnan(ens.values[1, 2, 3, 4])
    assert ens.info()["infinite"] == 2


class FakeDataArray:
    """What ensil reads of an xarray.DataArray (xarray is not a dependency): values, dims,
    coords (each with values and attrs), sizes, attrs and name."""

    class Coord:
        def __init__(self, values, units=None):
            self.values = np.asarray(values)
            self.attrs = {"units": units} if units else {}

    def __init__(self, values):
        self.values = values
        self.dims = ("number", "level", "latitude", "longitude")
        self.coords = {"number": self.Coord([0, 1]),
                       "level": self.Coord([1000.0, 500.0], "hPa"),
                       "latitude": self.Coord([10.0, 20.0, 30.0], "degrees_north"),
                       "longitude": self.Coord([0.0, 1.0, 2.0, 3.0], "degrees_east")}
        self.sizes = dict(zip(self.dims, values.shape))
        self.attrs = {"units": "m s-1"}
        self.name = "wind"


def test_a_data_array_is_taken_with_its_coordinates_units_and_names():
    values = np.arange(2 * 2 * 3 * 4, dtype=np.float32).reshape(2, 2, 3, 4)
    ens = ensil.from_numpy(FakeDataArray(values))
    np.testing.assert_array_equal(ens.values, values)
    assert ens.dims == ("number", "level", "latitude", "longitude")
    assert ens.axis_units == {"level": "hPa", "latitude": "degrees_north",
                              "longitude": "degrees_east"}
    np.testing.assert_array_equal(ens.axes["latitude"], [10.0, 20.0, 30.0])
    assert ens.members == ["0", "1"]
    assert ens.units == "m s-1" and ens.variable == "wind"


def test_bad_arrays_are_refused_saying_why():
    with pytest.raises(ensil.ArgumentError, match="values must be 4-D"):
        ensil.from_numpy(np.zeros((3, 4, 5)), grid_axes())
    with pytest.raises(ensil.ArgumentError, match="axis 'lat' has 4 coordinates but the values 6"):
        ensil.from_numpy(np.zeros((2, 3, 6, 5)), grid_axes())
    with pytest.raises(ensil.ArgumentError, match="names has 1 entries for 2 members"):
        ensil.from_numpy(np.zeros((2, 3, 4, 5)), grid_axes(), names=["only"])
    axes = grid_axes()
    axes["lon"] = (np.array([0.0, 2.0, 1.0, 6.0, 8.0]), "degrees_east")
    with pytest.raises(ensil.Error, match="lon"):
        ensil.from_numpy(np.zeros((2, 3, 4, 5)), axes)
    # Also a ValueError, as a Python user of a bad argument expects.
    with pytest.raises(ValueError):
        ensil.from_numpy(np.zeros((3, 4, 5)), grid_axes())


def test_open_reads_a_file_as_ensil_info_does(era5_path):
    fractions = []
    ens = ensil.open(era5_path, var="t", progress=fractions.append)
    assert ens.shape == (10, 2, 61, 120)
    assert ens.variable == "t" and ens.units == "K"
    assert fractions and all(0.0 <= f <= 1.0 for f in fractions)
    assert fractions == sorted(fractions)
    info = ens.info()
    assert info["variable"] == "t" and info["members"] == 10
    assert info["grid"] == [120, 61, 2]
    assert info["member_names"] == ens.members
    lo, hi = info["range"]
    assert lo == pytest.approx(float(np.nanmin(ens.values)), rel=1e-6)
    assert hi == pytest.approx(float(np.nanmax(ens.values)), rel=1e-6)
    executable = os.environ.get("ENSIL_EXECUTABLE", "")
    if os.path.exists(executable):  # CTest names the command line built beside the module
        import json
        said = subprocess.run([executable, "info", era5_path, "--var", "t", "--json"],
                              check=True, capture_output=True, text=True).stdout
        assert json.loads(said) == info


def test_open_refuses_what_the_command_line_refuses(era5_path, tmp_path):
    missing = str(tmp_path / "nothing.nc")
    with pytest.raises(ensil.Error, match="nothing.nc") as raised:
        ensil.open(missing)
    assert raised.value.kind == "file_not_found"
    with pytest.raises(ensil.Error) as raised:
        ensil.open(era5_path, var="no_such_variable")
    assert raised.value.kind == "variable_not_found"
    assert "t" in raised.value.choices
    with pytest.raises(ensil.ArgumentError, match="name at least one file"):
        ensil.open([])


def test_what_the_reader_read_around_is_a_data_warning(era5_grib_path, tmp_path):
    # ERA5's GRIB twin cut in the middle of its last message (t at the last time): the first
    # time still reads, with a warning naming where the cut message starts.
    with open(era5_grib_path, "rb") as f:
        data = f.read()
    last = data.rfind(b"GRIB")
    cut = tmp_path / "cut.grib"
    cut.write_bytes(data[:last + (len(data) - last) // 2])
    with pytest.warns(ensil.DataWarning, match=f"byte offset {last}"):
        ens = ensil.open(str(cut), var="t", time_index=0)
    assert ens.shape == (10, 2, 61, 120)
    # And it stays with the ensemble, for a script that reads it later.
    assert any(f"byte offset {last}" in w for w in ens.warnings), ens.warnings
    assert ensil.demo(members=3).warnings == []


def test_demo_is_the_workbenchs():
    ens = ensil.demo(members=3)
    assert ens.shape == (3, 16, 128, 256)
    assert ens.source == "demo"
    with pytest.raises(ensil.ArgumentError, match="members must be a whole number from 1 to 1000"):
        ensil.demo(members=0)


def test_help_and_repr_say_what_things_are():
    ens = ensil.from_numpy(np.zeros((2, 3, 4, 5)), grid_axes(), units="K", variable="t")
    assert repr(ens) == "<ensil.Ensemble 't' [K]: 2 members on 5 x 4 x 3 (lon, lat, plev)>"
    assert "(member, z, y, x)" in ensil.Ensemble.values.__doc__
    assert "SciPy" in ensil.PreprocessResult.linkage.__doc__
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        import pydoc
        assert "preprocess" in pydoc.render_doc(ensil.Ensemble)


def test_a_star_import_leaves_the_builtin_open_alone():
    names = {}
    exec("from ensil import *", names)
    assert "open" not in names and "from_numpy" in names and "render" in names


def test_levels_keep_the_vertical_levels_between_their_ends_in_any_units(era5_path):
    # ERA-Interim's levels are in millibars (200, 500, 850); the range is given in Pa and hPa.
    path = os.path.join(os.path.dirname(era5_path), "eraint_uvz.nc")
    whole = ensil.open(path, var="u", member_dim="month")
    z_name = list(whole.axes)[0]
    z_values = whole.axes[z_name]
    kept_by_numpy = (np.asarray(z_values) >= 200.0) & (np.asarray(z_values) <= 500.0)
    assert kept_by_numpy.sum() == 2
    for levels in ("50000:20000 Pa", "200:500hPa", "500:200 millibars"):
        part = ensil.open(path, var="u", member_dim="month", levels=levels)
        assert part.shape == (2, 2, 241, 480), levels
        assert list(part.axes)[0] == z_name
        np.testing.assert_array_equal(part.axes[z_name], np.asarray(z_values)[kept_by_numpy])
        np.testing.assert_array_equal(part.values, whole.values[:, kept_by_numpy])
    with pytest.raises(ensil.ArgumentError, match="'500-200'"):
        ensil.open(path, var="u", member_dim="month", levels="500-200")
    with pytest.raises(ensil.Error, match="hold 1 level"):
        ensil.open(path, var="u", member_dim="month", levels="600:400hPa")
