"""ensil.Session: projects loaded, changed and saved; the settings of the one setting table
under their ids with the command line's ranges and refusals."""

import json
import os

import pytest

import ensil


def test_settings_are_the_setting_tables(era5_path):
    session = ensil.Session(era5_path, var="t")
    settings = session.settings
    assert len(settings) == len(list(settings)) == len(settings.keys())
    for id in ("mode", "thickness", "clusters", "linkage", "background", "removal_min", "plane"):
        assert id in settings
    assert "colour" not in settings
    # The defaults are a default session's, as `ensil render --help` states them.
    assert settings["mode"] == "shaded"
    assert settings["clusters"] == 5 and isinstance(settings["clusters"], int)
    assert settings["show_mean"] is True
    assert isinstance(settings["thickness"], float)
    assert settings["background"].startswith("#")
    described = settings.describe("thickness")
    assert described["option"] == "--thickness"
    assert described["allowed"] == "a number from 0.0001 to 0.5"
    assert described["project_key"] == "rendering.thickness"
    assert dict(settings.items())["mode"] == "shaded"


def test_changed_settings_survive_save_and_load(era5_path, tmp_path):
    session = ensil.Session(era5_path, var="t")
    session.settings["thickness"] = 0.02
    session.settings["mode"] = "spaghetti"
    session.settings["legend"] = False
    session.settings["background"] = "#102030"
    session.set(clusters=3, linkage="ward")
    session.isovalue = 255.5
    session.hidden_members = [1, 4]
    path = str(tmp_path / "changed.ensil")
    session.save(path)
    assert session.path == path
    saved = json.load(open(path))
    assert saved["rendering"]["thickness"] == pytest.approx(0.02)
    loaded = ensil.Session.load(path)
    assert loaded.settings["thickness"] == pytest.approx(0.02)
    assert loaded.settings["mode"] == "spaghetti"
    assert loaded.settings["legend"] is False
    assert loaded.settings["background"] == "#102030"
    assert loaded.settings["clusters"] == 3 and loaded.settings["linkage"] == "ward"
    assert loaded.isovalue == pytest.approx(255.5)
    assert loaded.hidden_members == [1, 4]
    assert loaded.variable == "t" and loaded.paths == [era5_path] or \
        loaded.paths[0].endswith("era5_eda_members.nc")
    # save() with no path writes back where it was loaded from.
    loaded.settings["thickness"] = 0.03
    loaded.save()
    assert ensil.Session.load(path).settings["thickness"] == pytest.approx(0.03)


def test_values_outside_the_range_are_refused_as_the_command_line_refuses_them():
    session = ensil.Session()
    assert session.demo
    with pytest.raises(ensil.ArgumentError) as refused:
        session.settings["thickness"] = 5
    assert str(refused.value) == "--thickness '5' is refused: it must be a number from 0.0001 to 0.5"
    with pytest.raises(ensil.ArgumentError, match=r"^--clusters '2.5' is refused: it must be a "
                                                  r"whole number from 1 to \d+$"):
        session.settings["clusters"] = 2.5
    with pytest.raises(ensil.ArgumentError, match=r"^--mean 'maybe' is refused: it must be true "
                                                  r"or false$"):
        session.settings["show_mean"] = "maybe"
    # A setting with no command-line option goes by its id.
    with pytest.raises(ensil.ArgumentError, match=r"^removal_min '-1' is refused: it must be a "
                                                  r"number from 0"):
        session.settings["removal_min"] = -1
    with pytest.raises(ensil.ArgumentError, match="there is no setting 'thicknes'"):
        session.settings["thicknes"] = 0.1
    with pytest.raises(ensil.ArgumentError, match=r"^--iso 'nan' is refused"):
        session.isovalue = float("nan")
    with pytest.raises(ensil.ArgumentError, match=r"^--view 'up' is refused: it must be one of "
                                                  r"top, north"):
        session.look_from("up")
    session.look_from("top")  # the map view: straight down, orthographic
    assert session.settings["elevation"] == 90.0
    assert session.settings["projection"] == "orthographic"
    # Nothing changed, also by a set() whose second value is refused.
    with pytest.raises(ensil.ArgumentError):
        session.set(thickness=0.05, mode="bogus")
    assert session.settings["thickness"] == pytest.approx(ensil.Session().settings["thickness"])


def test_a_bad_project_is_refused_whole(tmp_path):
    path = tmp_path / "bad.ensil"
    path.write_text('{"format": "ensil project", "version": 2,\n "rendering": {"thickness": 9}}')
    with pytest.raises(ensil.Error) as refused:
        ensil.Session.load(str(path))
    assert refused.value.kind == "project"
    with pytest.raises(ensil.Error, match="say where to save"):
        ensil.Session().save()


def test_a_session_keeps_the_levels_it_was_given_in_its_project(era5_path, tmp_path):
    path = os.path.join(os.path.dirname(era5_path), "eraint_uvz.nc")
    project = str(tmp_path / "upper.ensil")
    ensil.Session(path, var="u", member_dim="month", levels="500:200hPa").save(project)
    with open(project) as f:
        assert json.load(f)["data"]["levels"] == "500:200 hPa"
    ensil.Session.load(project).save(project)  # read back and written again, the same
    with open(project) as f:
        assert json.load(f)["data"]["levels"] == "500:200 hPa"
    with pytest.raises(ensil.ArgumentError, match="levels: the level range '500-200'"):
        ensil.Session(path, levels="500-200")
