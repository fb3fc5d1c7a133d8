#!/usr/bin/env python3
"""Writes the bad-input corpus in this folder: small files that once crashed, hung or misled
ensil. Each is read by tests/app/bad_input_test.cpp, which checks the exit status and a phrase
of the message. Run it again after adding a case; the files are committed beside it.

Needs ncgen (Debian netcdf-bin) for the NetCDF cases."""
import pathlib
import subprocess

HERE = pathlib.Path(__file__).resolve().parent


def vtk_points(name, dimensions, values="0 " * 8):
    (HERE / name).write_text(
        "# vtk DataFile Version 3.0\nbad\nASCII\nDATASET STRUCTURED_POINTS\n"
        f"DIMENSIONS {dimensions}\nORIGIN 0 0 0\nSPACING 1 1 1\n"
        "POINT_DATA 8\nSCALARS v float 1\nLOOKUP_TABLE default\n" + values + "\n")


def vtk_rectilinear(name, x_count):
    (HERE / name).write_text(
        "# vtk DataFile Version 3.0\nbad\nASCII\nDATASET RECTILINEAR_GRID\n"
        "DIMENSIONS 2 2 2\n"
        f"X_COORDINATES {x_count} float\n0 1\n"
        "Y_COORDINATES 2 float\n0 1\nZ_COORDINATES 2 float\n0 1\n"
        "POINT_DATA 8\nSCALARS v float 1\nLOOKUP_TABLE default\n" + "0 " * 8 + "\n")


def ensemble_cdl(name, values):
    """A CF ensemble t(number=4, level=3, lat=4, lon=5) in K; values(m, z, y, x) gives each value
    as CDL text."""
    data = ", ".join(values(m, z, y, x) for m in range(4) for z in range(3) for y in range(4)
                     for x in range(5))
    return (f"netcdf {name} {{\ndimensions:\n  number = 4 ;\n  level = 3 ;\n  lat = 4 ;\n"
            "  lon = 5 ;\nvariables:\n  int number(number) ;\n"
            "    number:standard_name = \"realization\" ;\n"
            "  double level(level) ;\n    level:units = \"hPa\" ;\n"
            "  double lat(lat) ;\n    lat:units = \"degrees_north\" ;\n"
            "  double lon(lon) ;\n    lon:units = \"degrees_east\" ;\n"
            "  float t(number, level, lat, lon) ;\n    t:units = \"K\" ;\n"
            "    t:_FillValue = -999.f ;\n"
            "data:\n  number = 0, 1, 2, 3 ;\n  level = 850, 700, 500 ;\n"
            "  lat = 50, 51, 52, 53 ;\n  lon = 0, 1, 2, 3, 4 ;\n"
            f"  t = {data} ;\n}}\n")


def smooth(m, z, y, x):
    return f"{x + y + z + 0.5 * m:g}"


def ensemble(name, values):
    cdl = ensemble_cdl(name.split('.')[0], values)
    subprocess.run(["ncgen", "-o", str(HERE / name)], input=cdl.encode(), check=True)


def truncated(name, cut):
    """A classic ensemble file with its last `cut` bytes cut off: fewer than its header holds, so
    the file still has more bytes than all its values need together."""
    ensemble(name, smooth)
    path = HERE / name
    data = path.read_bytes()
    path.write_bytes(data[:len(data) - cut])


def netcdf(name, variable):
    cdl = (f"netcdf {name.split('.')[0]} {{\ndimensions:\n  z = 2 ;\n  y = 2 ;\n  x = 2 ;\n"
           f"variables:\n  float {variable}(z, y, x) ;\ndata:\n"
           f"  {variable} = 0, 1, 2, 3, 4, 5, 6, 7 ;\n}}\n")
    subprocess.run(["ncgen", "-o", str(HERE / name)], input=cdl.encode(), check=True)


vtk_points("vtk_negative_dimensions.vtk", "-5 8 8")
vtk_points("vtk_negative_last_dimension.vtk", "8 8 -1")
vtk_points("vtk_all_negative_dimensions.vtk", "-1 -1 -1")
vtk_points("vtk_zero_dimension.vtk", "2 0 2")
vtk_points("vtk_huge_dimensions.vtk", "100000 100000 100000")
vtk_rectilinear("vtk_negative_coordinate_count.vtk", "-4")
vtk_rectilinear("vtk_billion_coordinates.vtk", "1000000000")
netcdf("member_u.nc", "u")
netcdf("member_t.nc", "t")
# A classic file cut inside its data: once read with zeros for the missing end, exit 0.
truncated("netcdf_truncated_data.nc", 100)
# Member 2 has no valid value (all _FillValue): its distances and the linkage heights were null.
ensemble("member_without_data.nc", lambda m, z, y, x: "-999" if m == 2 else smooth(m, z, y, x))
# Infinities among the values: the range in `ensil info --json` was null.
ensemble("infinite_values.nc",
         lambda m, z, y, x: {(1, 0, 0, 0): "Infinityf", (3, 2, 3, 4): "-Infinityf"}.get(
             (m, z, y, x), smooth(m, z, y, x)))
# Members 0 and 1 are valid in different halves of the grid, so no point holds both: their
# distance was infinite, and null in `ensil preprocess --json`.
ensemble("members_without_overlap.nc",
         lambda m, z, y, x: "-999" if (m == 0 and x >= 2) or (m == 1 and x < 3)
         else smooth(m, z, y, x))
