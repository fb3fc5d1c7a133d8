#!/usr/bin/env python3
"""Writes the fuzzers' seed corpus in corpus/<fuzzer>/: small valid inputs of every format and
layout each fuzzer reads (so libFuzzer starts from the parsers' deep paths, not from random
bytes), and copies of the small bad files of tests/data/bad/. Every file stays well under
64 KiB. Run it again after adding a case; the files are committed beside it. The reproducers
of findings (fixed bugs, and the library leaks lsan.supp ignores) are committed in the same
folders by hand, named finding_*, and are left alone here.

Needs ncgen (Debian netcdf-bin), h5import (Debian hdf5-tools) and grib_set and codes_info
(Debian libeccodes-tools)."""
import pathlib
import shutil
import struct
import subprocess
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
CORPUS = HERE / "corpus"
BAD = HERE.parent / "data" / "bad"


def folder(name):
    path = CORPUS / name
    path.mkdir(parents=True, exist_ok=True)
    return path


# --- legacy VTK: every section kind the header scanner knows ---------------------------------

def vtk_text(dataset, geometry, data):
    return ("# vtk DataFile Version 3.0\nseed\nASCII\nDATASET " + dataset + "\n" + geometry +
            data).encode()


POINTS = "DIMENSIONS 2 2 2\nORIGIN 0 0 0\nSPACING 1 1 1\n"
EIGHT = " ".join(str(i) for i in range(8)) + "\n"
VTK_SEEDS = {
    "points.vtk": vtk_text("STRUCTURED_POINTS", POINTS,
                           "POINT_DATA 8\nSCALARS v float 1\nLOOKUP_TABLE default\n" + EIGHT),
    "rectilinear.vtk": vtk_text(
        "RECTILINEAR_GRID",
        "DIMENSIONS 2 2 2\nX_COORDINATES 2 float\n0 1\nY_COORDINATES 2 double\n0 2\n"
        "Z_COORDINATES 2 int\n0 3\n",
        "POINT_DATA 8\nSCALARS v double\nLOOKUP_TABLE default\n" + EIGHT),
    "attributes.vtk": vtk_text(
        "STRUCTURED_POINTS", POINTS,
        "CELL_DATA 1\nSCALARS c int 1\nLOOKUP_TABLE default\n7\n"
        "POINT_DATA 8\nSCALARS my%20name float 1\nLOOKUP_TABLE table\n" + EIGHT +
        "METADATA\nINFORMATION 0\n\nLOOKUP_TABLE table 2\n0 0 0 1\n1 1 1 1\n"
        "COLOR_SCALARS rgb 3\n" + "0.5 0.5 0.5\n" * 8 +
        "VECTORS vel float\n" + "1 0 0\n" * 8 +
        "NORMALS n float\n" + "0 0 1\n" * 8 +
        "TEXTURE_COORDINATES uv 2 float\n" + "0 1\n" * 8 +
        "TENSORS6 t6 float\n" + "1 2 3 4 5 6\n" * 8 +
        "FIELD extra 2\nw 1 8 float\n" + EIGHT +
        "u 2 8 unsigned_char\n" + EIGHT + EIGHT),
    "field_geometry.vtk": vtk_text(
        "STRUCTURED_POINTS", "FIELD FieldData 1\ntime 1 1 double\n3.5\n" + POINTS,
        "POINT_DATA 8\nFIELD f 1\nonly 1 8 short\n" + EIGHT),
    "polydata.vtk": vtk_text("POLYDATA", "POINTS 1 float\n0 0 0\n", ""),
    # What VTK 5.1+ writers put after arrays: METADATA blocks, with component names (an empty
    # line for an unnamed component) and INFORMATION keys.
    "metadata.vtk": vtk_text(
        "STRUCTURED_POINTS",
        "FIELD FieldData 1\ntime 1 1 double\n3.5\nMETADATA\nINFORMATION 0\n\n" + POINTS,
        "POINT_DATA 8\nSCALARS v float\nLOOKUP_TABLE default\n" + EIGHT +
        "METADATA\nINFORMATION 0\n\nFIELD FieldData 2\nw 3 8 float\n" + "1 0 0\n" * 8 +
        "METADATA\nCOMPONENT_NAMES\neast\n\n\nINFORMATION 1\n"
        "NAME L2_NORM_RANGE LOCATION vtkDataArray\nDATA 2 1 1\n\n"
        "s 1 8 short\n" + EIGHT + "METADATA\nINFORMATION 0\n\n"),
}


def vtk_binary_points():
    header = ("# vtk DataFile Version 3.0\nseed\nBINARY\nDATASET STRUCTURED_POINTS\n" + POINTS +
              "POINT_DATA 8\nSCALARS v float 1\nLOOKUP_TABLE default\n").encode()
    return header + struct.pack(">8f", *range(8)) + b"\n"


def vtk_binary_rectilinear():
    def axis(name, kind, fmt):
        return f"{name}_COORDINATES 2 {kind}\n".encode() + struct.pack(fmt, 0, 1) + b"\n"
    return (b"# vtk DataFile Version 3.0\nseed\nBINARY\nDATASET RECTILINEAR_GRID\n"
            b"DIMENSIONS 2 2 2\n" + axis("X", "float", ">2f") + axis("Y", "double", ">2d") +
            axis("Z", "short", ">2h") +
            b"POINT_DATA 8\nSCALARS v unsigned_short 1\nLOOKUP_TABLE default\n" +
            struct.pack(">8H", *range(8)) + b"\nSCALARS bits bit 1\nLOOKUP_TABLE default\n\xff\n")


VTK_SEEDS["binary_points.vtk"] = vtk_binary_points()
VTK_SEEDS["binary_rectilinear.vtk"] = vtk_binary_rectilinear()

VTI = b"""<?xml version="1.0"?>
<VTKFile type="ImageData" version="0.1" byte_order="LittleEndian">
  <ImageData WholeExtent="0 1 0 1 0 1" Origin="0 0 0" Spacing="1 1 1">
    <Piece Extent="0 1 0 1 0 1">
      <PointData Scalars="v">
        <DataArray type="Float32" Name="v" format="ascii">0 1 2 3 4 5 6 7</DataArray>
      </PointData>
    </Piece>
  </ImageData>
</VTKFile>
"""


# --- NetCDF (classic, 64-bit offset, CDF-5, NetCDF-4) and HDF5 --------------------------------

MEMBERS_CDL = """netcdf members {{
dimensions:
  number = 2 ; time = 2 ; plev = 2 ; lat = 2 ; lon = 3 ;
variables:
  int number(number) ; number:standard_name = "realization" ;
  double time(time) ; time:units = "hours since 2017-01-01 00:00:00" ;
    time:calendar = "gregorian" ;
  float plev(plev) ; plev:units = "Pa" ; plev:positive = "down" ;
  float lat(lat) ; lat:units = "degrees_north" ;
  float lon(lon) ; lon:units = "degrees_east" ;
  short t(number, time, plev, lat, lon) ; t:units = "K" ; t:long_name = "Temperature" ;
    t:scale_factor = 0.5 ; t:add_offset = 200.0 ; t:_FillValue = -32767s ;
    t:valid_range = 0s, 1000s ;
  float u(time, plev, lat, lon) ; u:missing_value = 1e20f ;
  float v(time, plev, lat, lon) ;
data:
  number = 0, 1 ; time = 0, 6 ; plev = 85000, 50000 ; lat = 10, 20 ; lon = 0, 10, 20 ;
  t = {t} ;
  u = {u} ;
  v = {u} ;
}}
"""

PER_MEMBER_CDL = """netcdf wrf {
dimensions:
  Time = UNLIMITED ; bottom_top = 2 ; south_north = 2 ; west_east = 2 ; west_east_stag = 3 ;
  south_north_stag = 3 ;
variables:
  float U(Time, bottom_top, south_north, west_east_stag) ;
  float V(Time, bottom_top, south_north_stag, west_east) ;
  float T(Time, bottom_top, south_north, west_east) ; T:_FillValue = -999.f ;
data:
  U = 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11 ;
  V = 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11 ;
  T = 0, 1, 2, _, 4, 5, 6, 7 ;
}
"""

# netCDF-C names the dimensions of plain HDF5 datasets phony_dim_N; the NetCDF reader leaves
# such files to the HDF5 reader, so this is how attributes reach the HDF5 path.
PHONY_CDL = """netcdf phony {
dimensions:
  phony_dim_0 = 2 ; phony_dim_1 = 2 ; phony_dim_2 = 2 ; phony_dim_3 = 2 ;
variables:
  float field(phony_dim_0, phony_dim_1, phony_dim_2, phony_dim_3) ;
    field:origin = 0., 0., 0. ; field:spacing = 1., 2., 3. ; field:units = "m" ;
    field:long_name = "a field" ; field:_FillValue = -1.f ; field:missing_value = 99.f ;
data:
  field = 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, -1 ;
}
"""


def ncgen(cdl, kind, out):
    subprocess.run(["ncgen", "-k", kind, "-o", str(out)], input=cdl.encode(), check=True)


def h5import(out, datasets):
    """datasets: (path inside the file, dimension sizes) written as 32-bit floats."""
    out.unlink(missing_ok=True)  # h5import adds to an existing file
    with tempfile.TemporaryDirectory() as tmp:
        args = ["h5import"]
        for i, (path, dims) in enumerate(datasets):
            values = pathlib.Path(tmp, f"v{i}.txt")
            count = 1
            for d in dims:
                count *= d
            values.write_text(" ".join(str(v) for v in range(count)) + "\n")
            config = pathlib.Path(tmp, f"c{i}.txt")
            config.write_text(f"PATH {path}\nINPUT-CLASS TEXTFP\nRANK {len(dims)}\n"
                              f"DIMENSION-SIZES {' '.join(map(str, dims))}\n"
                              "OUTPUT-CLASS FP\nOUTPUT-SIZE 32\nOUTPUT-ARCHITECTURE IEEE\n"
                              "OUTPUT-BYTE-ORDER LE\n")
            args += [str(values), "-c", str(config)]
        subprocess.run(args + ["-o", str(out)], check=True, stdout=subprocess.DEVNULL)


def ensemble_reader_seeds():
    out = folder("ensemble_reader")
    t = ", ".join(str(i % 50) for i in range(2 * 2 * 2 * 2 * 3))
    u = ", ".join(str(i) for i in range(2 * 2 * 2 * 3))
    members = MEMBERS_CDL.format(t=t, u=u)
    ncgen(members, "classic", out / "members_classic.nc")
    ncgen(members, "64-bit-offset", out / "members_64bit.nc")
    ncgen(members, "cdf5", out / "members_cdf5.nc")
    ncgen(members, "nc4", out / "members_nc4.nc")
    ncgen(PER_MEMBER_CDL, "classic", out / "wrf_classic.nc")
    ncgen(PER_MEMBER_CDL, "nc4", out / "wrf_nc4.nc")
    ncgen(PHONY_CDL, "nc4", out / "hdf5_attributes.h5")
    h5import(out / "hdf5_4d.h5", [("ensemble", (2, 2, 2, 2))])
    # A dataset in the root too: with every dataset below it, netCDF-C invents no phony
    # dimension there and the NetCDF reader takes (and refuses) the file.
    h5import(out / "hdf5_group.h5", [("members/run_01", (2, 2, 3)),
                                     ("members/run_02", (2, 2, 3)), ("mean", (2, 2, 3))])
    grib_seeds(out)
    (out / "points.vtk").write_bytes(VTK_SEEDS["points.vtk"])
    (out / "binary_rectilinear.vtk").write_bytes(VTK_SEEDS["binary_rectilinear.vtk"])
    (out / "image.vti").write_bytes(VTI)
    for bad in sorted(BAD.glob("*.nc")) + sorted(BAD.glob("*.vtk"))[:2]:
        shutil.copy(bad, out / ("bad_" + bad.name))


def grib_seeds(out):
    """Two members on two pressure levels, from ecCodes's smallest samples (16 x 31 lat-lon),
    in GRIB 1 (ECMWF local definition 1 for the member number) and GRIB 2 (an ensemble
    template), the second with a bitmap; and both again in packings that group the values."""
    samples = subprocess.run(["codes_info", "-s"], check=True, capture_output=True,
                             text=True).stdout.strip()
    editions = {
        "grib1_members_levels.grib1": ("regular_ll_pl_grib1.tmpl",
                                       "setLocalDefinition=1,localDefinitionNumber=1,"
                                       "indicatorOfParameter=130,number={m},level={l}"),
        "grib2_members_levels_bitmap.grib2": ("regular_ll_pl_grib2.tmpl",
                                              "productDefinitionTemplateNumber=1,"
                                              "perturbationNumber={m},level={l},"
                                              "bitmapPresent=1"),
    }
    with tempfile.TemporaryDirectory() as tmp:
        for name, (sample, keys) in editions.items():
            parts = []
            for member in (0, 1):
                for level in (500, 850):
                    part = pathlib.Path(tmp, "part")
                    part.unlink(missing_ok=True)
                    subprocess.run(["grib_set", "-s", keys.format(m=member, l=level),
                                    str(pathlib.Path(samples, sample)), str(part)], check=True)
                    parts.append(part.read_bytes())
            (out / name).write_bytes(b"".join(parts))
        # Complex packing with spatial differencing (NCEP's GFS and GEFS files) in GRIB 2, and
        # GRIB 1's second-order packing (older ECMWF archives).
        packed = {
            "grib2_members_levels_complex.grib2": (
                "regular_ll_pl_grib2.tmpl", "grid_complex_spatial_differencing",
                "productDefinitionTemplateNumber=1,perturbationNumber={m},level={l}"),
            "grib1_members_levels_second_order.grib1": (
                "regular_ll_pl_grib1.tmpl", "grid_second_order",
                "setLocalDefinition=1,localDefinitionNumber=1,indicatorOfParameter=130,"
                "number={m},level={l}"),
        }
        for name, (sample, packing, keys) in packed.items():
            parts = []
            for member in (0, 1):
                for level in (500, 850):
                    part = pathlib.Path(tmp, "part")
                    part.unlink(missing_ok=True)
                    packed_field(pathlib.Path(samples, sample), packing,
                                 keys.format(m=member, l=level), member, part)
                    parts.append(part.read_bytes())
            (out / name).write_bytes(b"".join(parts))


def packed_field(sample, packing, keys, member, out):
    """One message of `sample` (16 x 31 points) with `keys`, whose field varies (ecCodes packs
    no constant field, the samples', in these packings), at 16 bits and 0.01, then `packing`:
    grib_filter sets the values first, then packs them."""
    values = ",".join(f"{250 + (i % 16) * 0.7 + (i // 16) * 0.3 + member:.2f}"
                      for i in range(16 * 31))
    rules = out.with_suffix(".rules")
    rules.write_text("".join(f"set {k};\n" for k in keys.split(",")) +
                     f"set bitsPerValue=16;\nset decimalScaleFactor=2;\n"
                     f"set values={{{values}}};\nset packingType=\"{packing}\";\nwrite;\n")
    subprocess.run(["grib_filter", "-o", str(out), str(rules), str(sample)], check=True)


def vtk_seeds():
    out = folder("vtk_legacy_header")
    for name, data in VTK_SEEDS.items():
        (out / name).write_bytes(data)
    for bad in sorted(BAD.glob("*.vtk")):
        shutil.copy(bad, out / ("bad_" + bad.name))


# --- mesh cache entries (preprocessing/mesh_cache.h) -----------------------------------------

def fnv1a(data):
    h = 0xcbf29ce484222325
    for b in data:
        h = ((h ^ b) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return h


def mesh(vertices, indices):
    data = struct.pack("<6f", 0, 0, 0, 1, 1, 1) + struct.pack("<f", 1.0)
    data += struct.pack("<QQ", vertices, len(indices))
    for v in range(vertices):
        data += struct.pack("<6H4h", v, v, v, 1, 2, 3, 4, 5, 6, 7)
    return data + struct.pack(f"<{len(indices)}I", *indices)


def mesh_payload(members):
    data = struct.pack("<fI3d3Qf", 0.5, members, 0.1, 0.2, 0.3, 4, 2, 6, 0.25)
    data += mesh(3, [0, 1, 2])
    for m in range(members):
        data += mesh(4, [0, 1, 2, 1, 2, 3][: 3 * (m % 2 + 1)])
    return data


def mesh_cache_seeds():
    # The fuzz target's first byte: even, the entry file as stored; odd, the payload alone.
    out = folder("mesh_cache")
    key = b"fuzz"
    for members in (0, 1, 3):
        payload = mesh_payload(members)
        entry = (b"ENSILMC1" + struct.pack("<II", 1, len(key)) + key +
                 struct.pack("<QQ", len(payload), fnv1a(payload)) + payload)
        (out / f"entry_{members}_members").write_bytes(b"\x00" + entry)
        (out / f"payload_{members}_members").write_bytes(b"\x01" + payload)


# --- projects and command-line values (session/) -------------------------------------

PROJECT = """{
    "format": "ensil project",
    "schema_version": 2,
    "written_by": "ensil 0.1.0",
    "data": {"files": [{"path": "run_01.nc", "absolute_path": "/data/run_01.nc"},
                       {"path": "run_02.nc", "absolute_path": "/data/run_02.nc"}],
             "variable": "t", "member_dimension": "number", "time_index": 1},
    "isovalue": 271.5,
    "camera": {"distance": 2.5, "target": [0.5, 0.5, 0.25], "azimuth": -75, "elevation": 30,
               "projection": "orthographic"},
    "rendering": {"mode": "shaded", "thickness": 0.02, "surface_opacity": 0.3,
                  "show_mean": true, "axis_labels": false, "legend": true,
                  "removal": {"enabled": true, "min": 0.1, "max": 0.9, "group_size": 3},
                  "vertical_exaggeration": 2, "background": [0.1, 0.2, 0.3]},
    "clusters": {"count": 4, "linkage": "ward", "hidden": [1]},
    "cutting_plane": {"enabled": true, "normal": [0, 0, 1], "offset": 0.5, "thickness": 0.05},
    "members": {"hidden": [0, 3], "selected": [2]},
    "layout": {"geometry": "AdnQywADAAA=", "state": "AAAA/wAAAAD9"}
}
"""

DEMO_PROJECT = """{"format": "ensil project", "schema_version": 1,
 "data": {"demo": {"members": 8, "grid": [16, 8, 4], "seed": 7}},
 "camera": {"distance": 3, "target": [0.5, 0.5, 0.5]}}
"""


def project_seeds():
    out = folder("project_file")
    (out / "files.ensil").write_text(PROJECT)
    (out / "demo.ensil").write_text(DEMO_PROJECT)
    (out / "minimal.ensil").write_text(
        '{"format": "ensil project", "schema_version": 2, "data": {"demo": {}}}\n')


# The setting table's order (session/setting_table.cpp), with a typical value each.
SETTINGS = ["shaded", "0.02", "0.3", "true", "false", "true", "false", "0.1", "0.9", "3", "2.5",
            "#1c1f24", "orthographic", "-75", "30", "5", "ward", "true", "0.05"]


def setting_seeds():
    # The fuzz target's first byte: a setting's index, else an even byte for a bounded number
    # (bit 2: whole) and an odd one for an image size.
    out = folder("setting_options")
    for i, text in enumerate(SETTINGS):
        (out / f"setting_{i:02d}").write_bytes(bytes([i]) + text.encode())
    (out / "bounded_number").write_bytes(bytes([32]) + b" 12.5 ")
    (out / "bounded_whole").write_bytes(bytes([36]) + b"24")
    (out / "image_size").write_bytes(bytes([33]) + b"1600x1000")


vtk_seeds()
ensemble_reader_seeds()
mesh_cache_seeds()
project_seeds()
setting_seeds()
