"""Ensemble.time_series: `ensil preprocess --times` from Python. Each step is the step read on
its own (ensil.open(time_index=k)) preprocessed at the same isovalue: the same clusters, up to
their numbering, which follows groups of members from step to step."""

import pytest

import ensil


def _groups(clusters):
    """The partition of the members, whatever the clusters' numbers."""
    groups = {}
    for member, number in enumerate(clusters):
        groups.setdefault(int(number), set()).add(member)
    return sorted(sorted(g) for g in groups.values())


def test_each_step_is_the_step_read_on_its_own(era5_path):
    era5 = ensil.open(era5_path, var="t")
    steps = era5.time_series(iso=260, clusters=3, cache=False)
    labels = era5.info()["time_steps"]["labels"]
    assert [s.index for s in steps] == list(range(len(labels)))
    assert [s.time for s in steps] == labels
    for step in steps:
        alone = ensil.open(era5_path, var="t", time_index=step.index).preprocess(
            iso=260, clusters=3, cache=False)
        assert step.result.isovalue == pytest.approx(260)
        assert _groups(step.result.clusters) == _groups(alone.clusters), step
        # A member's identity is its cluster's: members of one cluster share it.
        for number in set(step.result.clusters):
            inside = {int(step.identities[m]) for m, c in enumerate(step.result.clusters)
                      if c == number}
            assert len(inside) == 1


def test_a_range_and_its_refusals(era5_path):
    era5 = ensil.open(era5_path, var="t")
    steps = era5.time_series(times="1:2", iso=260, cache=False)
    assert [s.index for s in steps] == [1, 2]
    with pytest.raises(ensil.ArgumentError, match="4 time steps, 0 to 3"):
        era5.time_series(times="2:7")
    with pytest.raises(ensil.ArgumentError, match="opened from files"):
        ensil.demo(members=4).time_series()
