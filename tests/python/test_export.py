"""Surfaces leaving ensil from Python: PreprocessResult.export and Mesh.save, read back by VTK's
own Python readers (what ParaView uses), and Mesh.coordinates in the data's axes."""

import os

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataReader, vtkXMLPolyDataReader

import ensil


@pytest.fixture(scope="module")
def ensemble():
    return ensil.demo(members=5)


@pytest.fixture(scope="module")
def result(ensemble):
    return ensemble.preprocess(iso=30, clusters=2)


def test_export_writes_a_block_per_surface_with_its_triangles_and_cluster(result, tmp_path):
    files = result.export(tmp_path / "out")
    assert files[0].endswith("wind_speed_iso30.vtm")
    reader = vtkXMLMultiBlockDataReader()
    reader.SetFileName(files[0])
    reader.Update()
    blocks = reader.GetOutput()
    members = len(result.meshes)
    assert blocks.GetNumberOfBlocks() >= members + 1
    for i, mesh in enumerate(result.meshes):
        poly = blocks.GetBlock(i)
        assert poly.GetNumberOfPolys() == len(mesh.triangles)
        cluster = vtk_to_numpy(poly.GetPointData().GetArray("cluster"))
        assert set(cluster) == {result.clusters[i]}
        # The vertices are the mesh's coordinates in the data's axes.
        points = vtk_to_numpy(poly.GetPoints().GetData())
        np.testing.assert_allclose(points, mesh.coordinates, rtol=1e-12)
    assert blocks.GetMetaData(members).Get(vtkCompositeDataSet.NAME()) == "mean"


def test_coordinates_are_the_axes_values_at_the_grid_indices(ensemble, result):
    mesh = result.meshes[0]
    index = mesh.vertices.astype(np.float64)
    coordinates = mesh.coordinates
    _, z, y, x = ensemble.dims
    for a, name in enumerate((x, y, z)):
        values = np.asarray(ensemble.axes[name])
        expected = np.interp(index[:, a], np.arange(len(values)), values)
        np.testing.assert_allclose(coordinates[:, a], expected, rtol=1e-6, atol=1e-6)


def test_a_mesh_saves_to_the_format_its_suffix_names(result, tmp_path):
    mesh = result.meshes[1]
    assert mesh.save(tmp_path / "second.vtp") == 0
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(str(tmp_path / "second.vtp"))
    reader.Update()
    assert reader.GetOutput().GetNumberOfPolys() == len(mesh.triangles)
    member = vtk_to_numpy(reader.GetOutput().GetPointData().GetArray("member"))
    assert set(member) == {2}
    assert result.mean_mesh.save(tmp_path / "mean.ply") == 0
    header = (tmp_path / "mean.ply").read_bytes().split(b"end_header")[0].decode()
    assert "property float outlyingness" in header
    assert f"element face {len(result.mean_mesh.triangles)}" in header
    # In the workbench's box the sides are in proportion: about 1 across, not 120 degrees.
    assert mesh.save(tmp_path / "box.vtp", coordinates="display") == 0
    reader.SetFileName(str(tmp_path / "box.vtp"))
    reader.Update()
    lon_min, lon_max = reader.GetOutput().GetBounds()[:2]
    assert 0 <= lon_min < lon_max < 10
    with pytest.raises(ensil.Error, match="data or display"):
        mesh.save(tmp_path / "x.vtp", coordinates="screen")
    with pytest.raises(ensil.Error, match=r"\.vtp, \.ply, \.obj or \.stl"):
        mesh.save(tmp_path / "second.xyz")
    with pytest.raises(ensil.Error, match="vtp, ply, obj, stl"):
        result.export(tmp_path / "bad", format="vtk")


def test_a_time_series_exports_a_pvd_whose_steps_paraview_reads(tmp_path):
    """`ensil preprocess --times all --export`: the .pvd lists every step's .vtm (parsed here
    with ElementTree), each read by VTK's reader with that step's clusters from --json."""
    import json
    import subprocess
    import xml.etree.ElementTree as ElementTree

    executable = os.environ.get("ENSIL_EXECUTABLE")
    assert executable, "run under CTest, which names the ensil built beside the module"
    data = tmp_path / "steps.nc"
    subprocess.run([executable, "generate", "--members", "4", "--grid", "48x32x8", "--times",
                    "3", "--out", str(data)], check=True, capture_output=True)
    said = subprocess.run([executable, "preprocess", str(data), "--times", "all", "--iso", "30",
                           "--no-cache", "--json", "--quiet", "--export", str(tmp_path / "out")],
                          check=True, capture_output=True, text=True).stdout
    result = json.loads(said)
    pvd = result["export"]["files"][0]
    assert pvd.endswith("wind_speed_iso30.pvd")
    entries = ElementTree.parse(pvd).getroot().find("Collection").findall("DataSet")
    assert [int(e.get("timestep")) for e in entries] == [0, 1, 2]
    for entry, step in zip(entries, result["steps"]):
        assert entry.get("name") == step["time"]
        reader = vtkXMLMultiBlockDataReader()
        reader.SetFileName(os.path.join(os.path.dirname(pvd), entry.get("file")))
        reader.Update()
        blocks = reader.GetOutput()
        for member in range(4):
            poly = blocks.GetBlock(member)
            cluster = vtk_to_numpy(poly.GetPointData().GetArray("cluster"))
            assert set(cluster) == {step["clusters"][member]}
