"""xarray in and out: ensil.from_xarray, Ensemble.to_xarray, PreprocessResult.to_xarray and the
``.ensil`` accessors of DataArray and Dataset.

Dimensions are found by name and CF attributes, as ensil's NetCDF reader finds them (METHODS.md,
"Reading files"): a member dimension (standard_name realization or ensemble_member_id,
_CoordinateAxisType Ensemble, or a name such as number, member, realization), a vertical one
(axis Z, a 'positive' attribute, a pressure or height standard_name, or a name such as plev,
level, lev, height), latitude or y (axis Y) and longitude or x (axis X). They are put in ensil's
order (member, z, y, x) by name, whatever the order in the array; every other dimension is taken
at one index (``time_index``, as --time-index does). xarray is imported only when used.
"""

import numpy as _np

_MEMBER_NAMES = ("number", "member", "members", "realization", "realisation", "ens", "ens0",
                 "ensemble", "ensemble_member")
_MEMBER_STANDARD_NAMES = ("realization", "ensemble_member_id")
_X_NAMES = ("lon", "longitude", "x", "rlon", "west_east", "grid_longitude", "xc")
_X_STANDARD_NAMES = ("longitude", "grid_longitude", "projection_x_coordinate")
_Y_NAMES = ("lat", "latitude", "y", "rlat", "south_north", "grid_latitude", "yc")
_Y_STANDARD_NAMES = ("latitude", "grid_latitude", "projection_y_coordinate")
_Z_NAMES = ("plev", "level", "lev", "z", "height", "bottom_top", "model_level_number",
            "isobaricinhpa", "pressure", "pressure_level", "altitude", "depth", "hybrid")
_Z_STANDARD_NAMES = ("air_pressure", "height", "altitude", "depth", "model_level_number",
                     "atmosphere_hybrid_sigma_pressure_coordinate", "atmosphere_sigma_coordinate",
                     "atmosphere_hybrid_height_coordinate")


def _attrs(array, dim):
    coord = array.coords[dim] if dim in array.coords else None
    return dict(getattr(coord, "attrs", {}) or {})


def _role(array, dim):
    """'member', 'z', 'y', 'x' or None for one dimension of a DataArray."""
    attrs = _attrs(array, dim)
    name = str(dim).lower()
    standard = str(attrs.get("standard_name", ""))
    axis = str(attrs.get("axis", "")).upper()
    if (standard in _MEMBER_STANDARD_NAMES or attrs.get("_CoordinateAxisType") == "Ensemble"
            or name in _MEMBER_NAMES):
        return "member"
    if axis == "X" or standard in _X_STANDARD_NAMES or name in _X_NAMES:
        return "x"
    if axis == "Y" or standard in _Y_STANDARD_NAMES or name in _Y_NAMES:
        return "y"
    if axis == "Z" or "positive" in attrs or standard in _Z_STANDARD_NAMES or name in _Z_NAMES:
        return "z"
    return None


def _roles(array, member_dim=None):
    roles = {}
    for dim in array.dims:
        role = "member" if member_dim is not None and dim == member_dim else _role(array, dim)
        if role == "member" and member_dim is not None and dim != member_dim:
            role = None  # the caller named another one
        if role is not None and role not in roles:
            roles[role] = dim
    return roles


def _usable(array, member_dim=None):
    return all(r in _roles(array, member_dim) for r in ("member", "z", "y", "x"))


def _choose_variable(dataset, var, member_dim):
    from ._ensil import ArgumentError

    if var is not None:
        if var not in dataset.data_vars:
            raise ArgumentError("the Dataset has no variable %r; its variables: %s"
                                % (var, ", ".join(map(str, dataset.data_vars))))
        return dataset[var]
    usable = [str(name) for name, array in dataset.data_vars.items()
              if _usable(array, member_dim)]
    if len(usable) == 1:
        return dataset[usable[0]]
    if not usable:
        raise ArgumentError("no variable of the Dataset has a member, a vertical and two "
                            "horizontal dimensions; name the member dimension with member_dim=")
    raise ArgumentError("the Dataset holds several ensembles (%s): name one with var="
                        % ", ".join(usable))


def from_xarray(data, var=None, member_dim=None, time_index=0):
    """An Ensemble from an xarray DataArray or Dataset (a variable of it: ``var``, or the only one
    with member, vertical and horizontal dimensions).

    Its dimensions are found by CF attributes and names and put in ensil's (member, z, y, x)
    order by name; ``member_dim`` names the member dimension where ensil cannot find one (a
    time or a month standing in for members). Every other dimension is taken at
    ``time_index``, as --time-index does. The coordinates, their units, the name, 'units' and
    the member coordinate's values (as the members' names) come along.
    """
    from . import from_numpy
    from ._ensil import ArgumentError

    register_accessors()
    array = _choose_variable(data, var, member_dim) if hasattr(data, "data_vars") else data
    roles = _roles(array, member_dim)
    missing = [r for r in ("member", "z", "y", "x") if r not in roles]
    if missing:
        words = {"member": "a member dimension (name it with member_dim=)",
                 "z": "a vertical dimension", "y": "a latitude or y dimension",
                 "x": "a longitude or x dimension"}
        raise ArgumentError("%r %s has no %s; its dimensions: %s"
                            % (str(array.name), "DataArray",
                               " and no ".join(words[m] for m in missing),
                               ", ".join(map(str, array.dims))))
    others = [d for d in array.dims if d not in roles.values()]
    index = int(time_index)
    for dim in others:
        if not 0 <= index < array.sizes[dim]:
            raise ArgumentError("time_index %d lies outside %r, which has %d steps"
                                % (index, str(dim), array.sizes[dim]))
    if others:
        array = array.isel({dim: index for dim in others})
    mapping = _grid_mapping(data, array)
    array = array.transpose(roles["member"], roles["z"], roles["y"], roles["x"])
    return from_numpy(array, names=_member_names(array, roles["member"]), grid_mapping=mapping)


def _grid_mapping(data, array):
    """The attributes of the variable the array's CF ``grid_mapping`` names (in the Dataset given,
    or among the array's coordinates when opened with decode_coords="all"); None when it names
    none, so coastlines and true bounds come with projected and rotated grids as from the file."""
    name = array.attrs.get("grid_mapping") or array.encoding.get("grid_mapping")
    if not name:
        return None
    name = str(name).split(":")[0].strip()  # the CF form "crs: x y" names its axes after a colon
    if hasattr(data, "data_vars") and name in data.variables:
        return dict(data[name].attrs)
    if name in array.coords:
        return dict(array.coords[name].attrs)
    return None


def _member_names(array, dim):
    """The members' names as ensil's NetCDF reader gives them, so that a file opened either way
    has the same members: dates ("2017-01-01T00:00") for times, "member 3" for the values of a
    member dimension (number, realization, ens...), "month 7" for another dimension's, text as it
    is; none without a coordinate (ensil numbers them, "member 1"...)."""
    if dim not in array.coords:
        return None
    values = _np.asarray(array.coords[dim].values)
    if values.dtype.kind == "M":
        return [str(v) for v in _np.datetime_as_string(values, unit="m")]
    if values.dtype.kind in "iuf":
        name = str(dim)
        prefix = ("member" if name in ("number", "realization") or name.startswith("ens")
                  else name)
        return ["%s %g" % (prefix, v) for v in values.tolist()]
    return [str(v) for v in values.tolist()]


def ensemble_to_xarray(ensemble):
    """The ensemble as an xarray DataArray (member, z, y, x), named and with units as in the
    file, its axes as coordinates with their units and the members' names as the member
    coordinate (a copy of the values)."""
    import xarray as xr

    member_dim, z, y, x = ensemble.dims
    member_dim = member_dim or "member"
    units = ensemble.axis_units
    coords = {member_dim: list(ensemble.members)}
    for name, values in ensemble.axes.items():
        coords[name] = xr.Variable(name, _np.array(values), attrs={"units": units[name]}
                                   if units[name] else {})
    attrs = {}
    if ensemble.units:
        attrs["units"] = ensemble.units
    if ensemble.long_name:
        attrs["long_name"] = ensemble.long_name
    return xr.DataArray(_np.array(ensemble.values), dims=(member_dim, z, y, x), coords=coords,
                        name=ensemble.variable, attrs=attrs)


def result_to_xarray(result):
    """One isovalue's preprocessing as an xarray Dataset over the members: their clusters (as
    the workbench numbers them), colours, depth (band depth of the contour boxplot), distances
    to each other (member x member2) and to the mean, outliers, and the merge tree in SciPy's
    linkage convention (merge x column); the isovalue, linkage and cluster count as attributes."""
    import xarray as xr

    members = list(result.members)
    merges = _np.asarray(result.linkage)
    data = {
        "cluster": ("member", _np.asarray(result.clusters)),
        "color": ("member", _np.asarray(result.colors, dtype=object)),
        "depth": ("member", _np.asarray(result.depth, dtype=float)),
        "distance_to_mean": ("member", _np.asarray(result.distances_to_mean, dtype=float)),
        "outlier": ("member", _np.isin(_np.arange(len(members)),
                                       _np.asarray(result.outliers, dtype=int))),
        "distance": (("member", "member2"), _np.array(result.distance_matrix)),
        "linkage": (("merge", "linkage_column"), merges),
    }
    return xr.Dataset(
        data,
        coords={"member": members, "member2": members,
                "linkage_column": ["cluster_a", "cluster_b", "height", "size"]},
        attrs={"isovalue": float(result.isovalue), "linkage_method": result.linkage_method,
               "clusters": int(result.k)})


def ensemble_stats_dataset(ensemble, iso, members=None, progress=None):
    """Ensemble.stats as an xarray Dataset shaped as the NetCDF file ``ensil stats`` writes:
    mean, stddev (n - 1), min, max, range, exceedance_probability and member_count on the grid
    points, level_crossing_probability on the cells (coordinates named <axis>_cell, at the
    cells' midpoints), with the file's units and cell_methods; the variable, isovalue and
    members as attributes. (The file's long names are the command line's; not repeated here.)"""
    import xarray as xr

    stats = ensemble.stats(iso, members=members, progress=progress)
    z, y, x = list(ensemble.axes)
    units = ensemble.axis_units
    coords = {}
    for name in (z, y, x):
        values = _np.asarray(ensemble.axes[name], dtype=float)
        attrs = {"units": units[name]} if units[name] else {}
        coords[name] = xr.Variable(name, values, attrs=attrs)
        coords[name + "_cell"] = xr.Variable(name + "_cell", 0.5 * (values[:-1] + values[1:]),
                                             attrs=attrs)
    value_units = {"units": ensemble.units} if ensemble.units else {}
    fraction = {"units": "1"}

    def on_points(key, attrs, method=None):
        if method:
            attrs = dict(attrs, cell_methods="realization: " + method)
        return xr.Variable((z, y, x), _np.array(stats[key]), attrs=attrs)

    data = {
        "mean": on_points("mean", value_units, "mean"),
        "stddev": on_points("stddev", value_units, "standard_deviation"),
        "min": on_points("minimum", value_units, "minimum"),
        "max": on_points("maximum", value_units, "maximum"),
        "range": on_points("range", value_units, "range"),
        "exceedance_probability": on_points("exceedance_probability", fraction),
        "member_count": on_points("count", fraction),
        "level_crossing_probability": xr.Variable(
            (z + "_cell", y + "_cell", x + "_cell"),
            _np.array(stats["level_crossing_probability"]), attrs=fraction),
    }
    member_names = [ensemble.members[i] for i in _np.asarray(stats["members"], dtype=int)]
    return xr.Dataset(data, coords=coords,
                      attrs={"variable": ensemble.variable, "isovalue": float(stats["isovalue"]),
                             "members": ", ".join(member_names)})


_accessors_registered = False


def register_accessors():
    """``da.ensil.ensemble()`` and ``ds.ensil.ensemble(var=...)``, once, when xarray is
    importable."""
    global _accessors_registered
    if _accessors_registered:
        return
    try:
        import xarray as xr
    except ImportError:
        return
    _accessors_registered = True

    class _Accessor:
        def __init__(self, obj):
            self._obj = obj

        def ensemble(self, var=None, member_dim=None, time_index=0):
            """The ensil Ensemble of this DataArray or Dataset (ensil.from_xarray)."""
            return from_xarray(self._obj, var=var, member_dim=member_dim, time_index=time_index)

    import warnings

    with warnings.catch_warnings():  # a registration after a reload of ensil only warns
        warnings.simplefilter("ignore")
        xr.register_dataarray_accessor("ensil")(_Accessor)
        xr.register_dataset_accessor("ensil")(_Accessor)
