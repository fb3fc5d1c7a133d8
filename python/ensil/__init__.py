"""ensil: ensembles of 3D fields from Python.

The engine of the ensil workbench and command line (readers, isosurface preprocessing,
clustering, the contour boxplot, ensemble statistics, headless rendering, projects) on NumPy
arrays::

    import ensil
    ens = ensil.open("era5_eda_members.nc", var="t")   # or ensil.from_numpy(...), ensil.demo()
    result = ens.preprocess(iso=260, clusters=3)
    result.linkage          # SciPy's linkage convention
    ensil.render(ens, iso=260, size=(640, 400))        # an RGBA picture; shows in a notebook

Errors are ensil.Error (RuntimeError) or ensil.ArgumentError (also a ValueError), with the
command line's messages; warnings are ensil.DataWarning.
"""

import builtins as _builtins
import os as _os
import sys as _sys

import numpy as _np

from ._ensil import (  # noqa: F401  (re-exported)
    ArgumentError,
    DataWarning,
    Ensemble,
    Error,
    Mesh,
    PreprocessResult,
    Section,
    Session,
    Settings,
    TimeStep,
    __version__,
    demo,
)
from . import _ensil
from . import _html
from . import _xarray

# help() and reprs name them where users find them: ensil.Ensemble, not ensil._ensil.Ensemble.
for _type in (Ensemble, Mesh, PreprocessResult, Section, Session, Settings, TimeStep, demo):
    _type.__module__ = __name__

# xarray in and out (python/ensil/_xarray.py); xarray itself is imported only when used.
from_xarray = _xarray.from_xarray
Ensemble.to_xarray = _xarray.ensemble_to_xarray
Ensemble.stats_dataset = _xarray.ensemble_stats_dataset
PreprocessResult.to_xarray = _xarray.result_to_xarray
Ensemble._repr_html_ = _html.ensemble_html
PreprocessResult._repr_html_ = _html.result_html
# da.ensil / ds.ensil, where xarray is already imported (else from the first from_xarray call).
if "xarray" in _sys.modules:
    _xarray.register_accessors()

# Not `open`: `from ensil import *` must not hide the built-in open; use ensil.open.
__all__ = [
    "ArgumentError", "DataWarning", "Ensemble", "Error", "Image", "Mesh", "PreprocessResult",
    "Section", "Session", "Settings", "TimeStep", "demo", "from_numpy", "from_xarray", "render",
]


def _paths(paths):
    if isinstance(paths, (str, bytes)) or hasattr(paths, "__fspath__"):
        paths = [paths]
    return [_os.fsdecode(_os.fspath(p)) for p in paths]


def open(paths, var=None, member_dim=None, time_index=0, levels=None, bbox=None,  # noqa: A001
         progress=None):
    """Reads an ensemble from NetCDF, HDF5, VTK (or GRIB) files, as ``ensil info`` and the
    workbench read it: one file with a member dimension, or one file per member.

    paths       a path or a list of paths
    var         the variable (default: the one with three spatial dimensions and the most
                vertical levels)
    member_dim  the dimension holding the members, when ensil cannot find one
    time_index  the index taken along every other non-spatial dimension, such as time
    levels      the vertical levels kept, 'FROM:TO' with ends included, in any units UDUNITS-2
                converts to the vertical axis's ('1000:100hPa', '0:12km'), or in the axis's own
                (default: every level)
    bbox        the region kept, (lon0, lon1, lat0, lat1) in degrees, edges included, on a regular
                longitude-latitude grid: (-10, 40, 35, 72) is Europe; lon0 > lon1 crosses the
                date line or the 0/360 seam, the longitudes kept then run on eastwards from lon0
                (-10..40 on a 0..360 grid; never past 360) (default: the whole grid)
    progress    called with the fraction read; raising from it, or Ctrl+C, stops reading

    Raises ensil.Error with the command line's message (a missing file, an unknown variable,
    with ``.choices`` listing the usable ones).
    """
    return _ensil._open(_paths(paths), var or "", member_dim or "", int(time_index),
                        levels or "", bbox, progress)


def _is_data_array(values):
    return all(hasattr(values, a) for a in ("values", "dims", "coords"))


def from_numpy(values, axes=None, units=None, names=None, variable=None, grid_mapping=None):
    """An Ensemble from a (member, z, y, x) array (copied into ensil's memory as float32; NaN
    and infinities are missing values).

    axes      the grid's coordinates in (z, y, x) order: a dict {name: coordinates} or
              {name: (coordinates, units)}, or a sequence of three coordinate arrays (named
              z, y, x); strictly monotonic, two values at least
    units     the variable's units
    names     the members' names (default: member 1, member 2, ...)
    variable  the variable's name
    grid_mapping  the horizontal axes' map projection, as a CF grid mapping variable's
              attributes: {"grid_mapping_name": "rotated_latitude_longitude",
              "grid_north_pole_latitude": 37.5, ...} (default: plain longitude/latitude axes,
              or none)

    An xarray.DataArray with dims (member, z, y, x) is taken as it is: its coordinates (with
    their 'units' attributes), its name and 'units' attribute, and its member coordinate's
    values as names, unless given here.
    """
    member_dim = "member"
    if _is_data_array(values):
        array = values
        member_dim = str(array.dims[0])
        if axes is None:
            axes = {}
            for dim in array.dims[1:]:
                coord = array.coords[dim] if dim in array.coords else None
                if coord is None:
                    axes[str(dim)] = (_np.arange(array.sizes[dim], dtype=float), "")
                else:
                    axes[str(dim)] = (_np.asarray(coord.values, dtype=float),
                                      str(getattr(coord, "attrs", {}).get("units", "")))
        if units is None:
            units = str(getattr(array, "attrs", {}).get("units", ""))
        if names is None and member_dim in array.coords:
            names = [str(v) for v in _np.asarray(array.coords[member_dim].values)]
        if variable is None and getattr(array, "name", None) is not None:
            variable = str(array.name)
        values = array.values
    if axes is None:
        raise ArgumentError("give the grid's axes in (z, y, x) order, e.g. "
                            "axes={'level': z, 'lat': y, 'lon': x}")
    if isinstance(axes, dict):
        given = []
        for name, axis in axes.items():
            if isinstance(axis, tuple) and len(axis) == 2 and isinstance(axis[1], str):
                given.append((str(name), _np.asarray(axis[0], dtype=float), axis[1]))
            else:
                given.append((str(name), _np.asarray(axis, dtype=float), ""))
    else:
        given = [(n, _np.asarray(a, dtype=float), "") for n, a in zip(("z", "y", "x"), axes)]
        if len(given) != len(axes):
            raise ArgumentError("give three axes, (z, y, x), not %d" % len(axes))
    array = _np.ascontiguousarray(values, dtype=_np.float32)
    return _ensil._from_numpy(array, given, variable or "values", units or "",
                              [str(n) for n in names] if names is not None else [], member_dim,
                              dict(grid_mapping or {}))


class Image(_np.ndarray):
    """An RGBA picture, (height, width, 4) uint8, as ensil.render draws it. A NumPy array
    that a notebook shows as a picture; ``.session`` is the session as drawn (isovalue and
    camera resolved: ``image.session.save('x.ensil')`` then draws the same picture again),
    ``.facts`` what ``ensil render --json`` says of it."""

    def __new__(cls, rgba, session=None, facts=None):
        image = _np.asarray(rgba).view(cls)
        image.session = session
        image.facts = facts or {}
        return image

    def __array_finalize__(self, obj):
        self.session = getattr(obj, "session", None)
        self.facts = getattr(obj, "facts", {})

    def _repr_png_(self):
        return _ensil._png(_np.ascontiguousarray(self, dtype=_np.uint8))

    def save(self, path):
        """Writes the picture as a PNG file."""
        with _builtins.open(_os.fspath(path), "wb") as f:
            f.write(self._repr_png_())


def render(target, iso=None, size=(1600, 1000), mode=None, view=None, cache=True, **settings):
    """Draws an Ensemble, a Session or a project file (.ensil) as the workbench shows it, with
    no window and no display server (Mesa's EGL surfaceless platform where there is none), and
    returns an ensil.Image, (height, width, 4) RGBA.

    iso       the isovalue (default: the session's, or the workbench's default)
    size      (width, height) in pixels, each from 1 to 16384
    mode      shaded, spaghetti, surfaces or opaque
    view      top, north, south, east, west or default
    cache     whether meshes go through the mesh cache (never for arrays)
    settings  any other setting by id (thickness=0.02, clusters=3, legend=False), with the
              ranges and refusals of ``ensil render``'s options

    Call it from one thread: the one that first rendered, where Qt starts. The GIL is released
    while it draws; Ctrl+C is noticed when it returns. Raises ensil.ArgumentError for a refused
    value, ensil.Error when the data cannot be drawn.
    """
    rgba, session, facts = _ensil._render(target, iso, tuple(size), view, cache, mode=mode,
                                          **settings)
    return Image(rgba, session, facts)


def _ensemble_section(self, level=None, lat=None, lon=None, path=None, fill="mean", iso=None,
                      clusters=None, linkage="average", cache=True, colour_map="automatic",
                      range=None, band=False, vertical_axis="log-pressure"):
    """A map or a cross-section of the ensemble, as ``ensil section`` draws it: the members'
    values and their contours of the isovalue, each member in its cluster's colour (the
    clusters of ``preprocess(iso, clusters, linkage)``, from the mesh cache when it has them).

    level       a map: "500hPa", "5km", "index:3", or a number in the vertical axis's units
    lat, lon    a cross-section along a latitude or a longitude: 45, "45N", "10W"
    path        a cross-section along the great circle: ((lon, lat), (lon, lat))
    fill        mean, spread, probability, member:N, anomaly:N (N from 1) or none
    colour_map  automatic (viridis for values, rdbu centred on 0 for anomalies, ylgnbu for
                probabilities), viridis, greys, rdbu or ylgnbu
    range       (lower, upper): a fixed colour bar; by default the section's own values
    band        the contour boxplot: its 50 % band shaded (.band), the median's contour thick
                (.median_member), the outliers' dashed
    vertical_axis  log-pressure, pressure or height: how a pressure axis goes up a
                cross-section (the 3D view's setting of that name)

    Returns an ensil.Section: .values (members x rows x columns), .fill, .contours,
    .mean_contour, .save("figure.svg"). Raises ensil.ArgumentError for a malformed place and
    ensil.Error for one outside the data, with the command line's messages.
    """
    result = self.preprocess(iso=iso, clusters=clusters, linkage=linkage, cache=cache)
    return result.section(level=level, lat=lat, lon=lon, path=path, fill=fill,
                          colour_map=colour_map, range=range, band=band,
                          vertical_axis=vertical_axis)


Ensemble.section = _ensemble_section
