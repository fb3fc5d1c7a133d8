"""Shared set-up of the Python module's tests.

Before ensil is imported, each test process gets its own empty settings, data and cache
folders (XDG_CONFIG_HOME, XDG_DATA_HOME, XDG_CACHE_HOME) below its CTest output folder, or a
temporary folder when pytest runs by hand, so no test reads or writes the user's mesh cache or
settings, or another test's (as tests/support/gui_test_main.cpp does for the C++ suites).
"""

import os
import shutil
import tempfile

import numpy as np
import pytest

_output = os.environ.get("ENSIL_TEST_OUTPUT_DIR") or tempfile.mkdtemp(prefix="ensil-pytest-")
_home = os.path.join(_output, "home")
shutil.rmtree(_home, ignore_errors=True)
for _name in ("XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME"):
    _folder = os.path.join(_home, _name.lower())
    os.makedirs(_folder)
    os.environ[_name] = _folder

import ensil  # noqa: E402  (after the folders are set)

SHARED_DATA = os.environ.get(
    "ENSIL_SHARED_DATA_DIR",
    os.path.join(os.path.dirname(__file__), "..", "data", "real"))


@pytest.fixture
def era5_path():
    """ERA5 ensemble of data assimilations: 10 members of t (and others) on 120 x 61 x 2."""
    return os.path.join(SHARED_DATA, "era5_eda_members.nc")


@pytest.fixture
def era5_grib_path():
    """The same ensemble as GRIB 2 from ECMWF: 160 messages (z and t, 2 levels, 4 times)."""
    return os.path.join(SHARED_DATA, "era5-levels-members.grib")


def spheres(radii, n=20, centres=None):
    """A (member, z, y, x) ensemble of distance fields: member m's isosurface at 0 is the sphere
    of radius radii[m] around centres[m] (x, y, z in grid index units; default the grid's
    centre), on axes 0..n-1."""
    z, y, x = np.meshgrid(np.arange(n), np.arange(n), np.arange(n), indexing="ij")
    centres = centres or [((n - 1) / 2,) * 3] * len(radii)
    return np.stack([np.sqrt((x - c[0]) ** 2 + (y - c[1]) ** 2 + (z - c[2]) ** 2) - radius
                     for radius, c in zip(radii, centres)]).astype(np.float32)


def sphere_ensemble(radii, n=20, centres=None):
    axis = np.arange(n, dtype=float)
    return ensil.from_numpy(spheres(radii, n, centres), axes={"z": axis, "y": axis, "x": axis},
                            units="cells", variable="distance")
