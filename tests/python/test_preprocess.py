"""Ensemble.preprocess: meshes, distances, SciPy's linkage convention, clusters, colours, the
contour boxplot and the statistics, against figures worked out here from the definitions;
refusals with the command line's messages; cancelling with Ctrl+C or from the progress
callable; other Python threads run meanwhile."""

import os
import signal
import sys
import threading
import time

import numpy as np
import pytest

import ensil
from conftest import sphere_ensemble

# Two groups of spheres: radii 4.0-4.4 and 7.0-7.3, around the grid's centre.
RADII = [4.0, 4.2, 4.4, 7.0, 7.3, 7.1]


@pytest.fixture(scope="module")
def spheres():
    return sphere_ensemble(RADII)


@pytest.fixture(scope="module")
def result(spheres):
    return spheres.preprocess(iso=0.0, clusters=2)


def average_linkage(d):
    """SciPy's linkage(squareform(d), 'average') by its definition (the naive O(n^3) way):
    rows [a, b, height, size], a < b, new clusters numbered n, n+1, ..."""
    n = len(d)
    clusters = {i: [i] for i in range(n)}
    rows = []
    for step in range(n - 1):
        best = None
        ids = sorted(clusters)
        for i, a in enumerate(ids):
            for b in ids[i + 1:]:
                h = np.mean([d[p, q] for p in clusters[a] for q in clusters[b]])
                if best is None or h < best[0] - 1e-12:
                    best = (h, a, b)
        h, a, b = best
        clusters[n + step] = clusters.pop(a) + clusters.pop(b)
        rows.append([a, b, h, len(clusters[n + step])])
    return np.array(rows)


def cut(z, k):
    """Members' clusters when the last k - 1 merges of linkage `z` are undone (SciPy's fcluster
    with 'maxclust'), as sets of members."""
    n = len(z) + 1
    groups = {i: {i} for i in range(n)}
    for step, (a, b, _, _) in enumerate(z[: n - k]):
        groups[n + step] = groups.pop(int(a)) | groups.pop(int(b))
    return sorted(sorted(g) for g in groups.values())


def test_distance_matrix_is_a_read_only_metric_matrix(result):
    d = result.distance_matrix
    assert d.shape == (6, 6) and d.dtype == np.float64
    np.testing.assert_array_equal(d, d.T)
    np.testing.assert_array_equal(np.diag(d), 0.0)
    assert not d.flags.writeable
    # Members of one group are closer to each other than to the other group's.
    assert d[:3, :3].max() < d[:3, 3:].min()


def test_linkage_is_scipys_on_the_same_distances(result):
    z = result.linkage
    assert z.shape == (5, 4) and z.dtype == np.float64
    expected = average_linkage(np.asarray(result.distance_matrix))
    np.testing.assert_allclose(z[:, 2], expected[:, 2], rtol=1e-12)
    np.testing.assert_array_equal(z[:, [0, 1, 3]], expected[:, [0, 1, 3]])
    assert result.linkage_method == "average"


def test_a_hand_computed_linkage_in_scipys_convention():
    # Four members on a line at 0, 1, 5 and 7 would give these distances; ensil's merge tree of
    # them (the same code clusters every ensemble) must be SciPy's average-linkage matrix:
    #   0 and 1 at 1 -> 4;  2 and 3 at 2 -> 5;  4 and 5 at mean(5, 7, 4, 6) = 5.5
    d = np.array([[0, 1, 5, 7], [1, 0, 4, 6], [5, 4, 0, 2], [7, 6, 2, 0]], dtype=float)
    np.testing.assert_array_equal(average_linkage(d),
                                  [[0, 1, 1, 2], [2, 3, 2, 2], [4, 5, 5.5, 4]])


def test_clusters_and_colours_follow_the_tree(result):
    clusters = result.clusters
    # Numbered as the legend numbers them: the larger part of a split keeps the number (ties:
    # the part holding the lowest member), so from one tree the numbers are 1..k.
    assert list(clusters) == [1, 1, 1, 2, 2, 2]
    groups = sorted(sorted(np.flatnonzero(clusters == c).tolist()) for c in range(1, result.k + 1))
    assert groups == cut(result.linkage, 2)
    colors = result.colors
    assert all(len(c) == 7 and c.startswith("#") for c in colors)
    assert len(set(colors[:3])) == 1 and len(set(colors[3:])) == 1 and colors[0] != colors[3]


def test_meshes_lie_on_the_spheres(result):
    meshes = result.meshes
    assert len(meshes) == 6
    for radius, mesh in zip(RADII, meshes):
        v, t = mesh.vertices, mesh.triangles
        assert v.shape[1] == 3 and t.shape[1] == 3 and len(t) > 50
        assert t.max() < len(v) and not t.flags.writeable
        r = np.linalg.norm(v - 9.5, axis=1)
        # Decimation keeps every vertex within its error bound (0.25 cells) of the surface;
        # marching cubes' linear interpolation of a distance field adds little to it.
        assert np.abs(r - radius).max() < 0.3
        attributes = mesh.attributes
        normals = attributes["normal"]
        np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-3)
        # Normals point down the field's gradient, to lower values: inwards here.
        assert np.mean(np.sum(normals * (v - 9.5), axis=1) / r) < -0.95
        for name in ("kappa1", "kappa2", "outlyingness"):
            assert attributes[name].shape == (len(v),)
    assert len(result.mean_mesh.vertices) > 0


def test_contour_boxplot_follows_its_definition(result):
    depth = result.depth
    assert depth.shape == (6,) and np.all((depth >= 0) & (depth <= 1))
    assert result.median_member == int(np.argmax(depth))
    q1, q3 = np.percentile(depth, [25, 75])
    fence = q1 - 1.5 * (q3 - q1)
    assert list(result.outliers) == np.flatnonzero(depth < fence).tolist()


def test_statistics_are_those_of_the_members(spheres, result):
    values = spheres.values
    stats = result.stats()
    assert stats["isovalue"] == 0.0
    np.testing.assert_allclose(stats["mean"], values.mean(axis=0), rtol=1e-5, atol=1e-5)
    np.testing.assert_allclose(stats["stddev"], values.std(axis=0, ddof=1), rtol=1e-4,
                               atol=1e-5)
    np.testing.assert_array_equal(stats["minimum"], values.min(axis=0))
    np.testing.assert_array_equal(stats["count"], 6)
    np.testing.assert_allclose(stats["exceedance_probability"], (values > 0).mean(axis=0),
                               atol=1e-6)
    assert stats["level_crossing_probability"].shape == (19, 19, 19)
    some = spheres.stats(iso=1.0, members=[0, 4])
    np.testing.assert_allclose(some["mean"], values[[0, 4]].mean(axis=0), rtol=1e-5, atol=1e-5)
    np.testing.assert_allclose(some["exceedance_probability"], (values[[0, 4]] > 1).mean(axis=0))
    with pytest.raises(ensil.ArgumentError, match="9"):
        spheres.stats(iso=1.0, members=[0, 9])


def test_refusals_say_what_the_command_line_says(spheres):
    lo, hi = float(spheres.values.min()), float(spheres.values.max())
    with pytest.raises(ensil.Error) as refused:
        spheres.preprocess(iso=1000)
    # Numbers as the command line writes them: 6 significant digits.
    assert str(refused.value) == (
        "isovalue 1000 is outside the values of 'distance' (%g .. %g cells): no member has a "
        "surface there. Choose an isovalue inside that range" % (lo, hi))
    with pytest.raises(ensil.ArgumentError, match=r"^--clusters 7 is more than the 6 members of "
                                                  r"this ensemble; give at most 6$"):
        spheres.preprocess(iso=0.0, clusters=7)
    with pytest.raises(ensil.ArgumentError, match=r"^--clusters '0' is refused: it must be a "
                                                  r"whole number from 1 to"):
        spheres.preprocess(iso=0.0, clusters=0)
    with pytest.raises(ensil.ArgumentError, match=r"^--linkage 'median' is refused: it must be "
                                                  r"average, single, complete or ward$"):
        spheres.preprocess(iso=0.0, linkage="median")
    with pytest.raises(ensil.ArgumentError, match=r"^--error '20' is refused: it must be a number "
                                                  r"from 0.001 to 10$"):
        spheres.preprocess(iso=0.0, error=20)


def test_the_default_number_of_clusters_is_about_half_the_members():
    # Not one cluster per member: a cluster of one says nothing of where members agree.
    assert sphere_ensemble([4.0, 5.0, 6.0]).preprocess(iso=0.0).k == 2
    assert sphere_ensemble([4.0, 4.2, 4.4, 5.0, 5.2, 6.0]).preprocess(iso=0.0).k == 3
    assert sphere_ensemble([4.0, 5.0, 6.0]).preprocess(iso=0.0, clusters=3).k == 3


def test_ctrl_c_stops_the_work_at_its_next_check(tmp_path):
    # The demo's meshes go through the mesh cache, which a finished run writes: an empty cache
    # afterwards shows that the work stopped, not only that the call raised.
    ens = ensil.demo(members=2)
    cache = tmp_path / "cache"
    fractions = []

    def press_ctrl_c(fraction):
        fractions.append(fraction)
        if len(fractions) == 1:
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        ens.preprocess(cache_dir=str(cache), progress=press_ctrl_c)
    assert len(fractions) == 1 and fractions[0] < 1.0
    assert not cache.exists() or not any(cache.iterdir())
    # And the next call runs as usual, storing its meshes.
    assert not ens.preprocess(cache_dir=str(cache)).from_cache
    assert any(cache.iterdir())


def test_an_exception_from_the_progress_callable_stops_the_work(spheres):
    calls = []

    def give_up(fraction):
        calls.append(fraction)
        raise ValueError("enough")

    with pytest.raises(ValueError, match="enough"):
        spheres.preprocess(iso=0.25, progress=give_up)
    assert len(calls) == 1


def test_progress_rises_to_the_end(spheres):
    fractions = []
    spheres.preprocess(iso=0.75, progress=fractions.append)
    assert fractions == sorted(fractions) and 0.0 <= fractions[0] and fractions[-1] <= 1.0
    assert len(fractions) >= 6  # a report per member at least


def test_other_python_threads_run_while_it_works():
    # With a switch interval longer than the test, a thread holding the GIL keeps it until it
    # lets it go itself: the count below moves while the other thread preprocesses only if
    # preprocess lets the GIL go while it works. time.sleep(0) is no wait: it hands the GIL to
    # the worker whenever the worker asks for it.
    ens = sphere_ensemble([3.0 + 0.1 * i for i in range(12)], n=40)
    count = [0]
    seen = {}
    done = threading.Event()

    def work():
        seen["before"] = count[0]
        ens.preprocess(iso=0.0, cache=False)
        seen["after"] = count[0]
        done.set()

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    try:
        worker = threading.Thread(target=work)
        worker.start()
        while not done.is_set():
            count[0] += 1
            time.sleep(0)
        worker.join()
    finally:
        sys.setswitchinterval(interval)
    # Held through the work, at most the final join would let the count move once or twice.
    assert seen["after"] - seen["before"] > 20


def test_members_without_data_are_left_out_and_said():
    values = np.stack([np.full((3, 4, 5), np.nan), *[np.indices((3, 4, 5))[2] - 2.0 + 0.1 * k
                                                   for k in range(3)]]).astype(np.float32)
    axis = {"z": np.arange(3.0), "y": np.arange(4.0), "x": np.arange(5.0)}
    with pytest.warns(ensil.DataWarning, match="'member 1' of 'values' has no valid value"):
        ens = ensil.from_numpy(values, axis)
    with pytest.warns(ensil.DataWarning, match="it is left out of the clustering"):
        result = ens.preprocess(iso=0.5, cache=False)
    assert result.members_without_data == ["member 1"]
    assert result.members == ["member 2", "member 3", "member 4"]
    assert result.distance_matrix.shape == (3, 3) and len(result.clusters) == 3
