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
