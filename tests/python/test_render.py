"""ensil.render: an RGBA picture of the size asked, the members drawn in their cluster colours
over the session's background, with no display server; the PNG a notebook shows; the session
as drawn draws the same picture again; refusals with `ensil render`'s messages."""

import os
import struct
import subprocess
import sys
import threading
import zlib

import numpy as np
import pytest

import ensil
from conftest import sphere_ensemble

BACKGROUND = np.array([0.11, 0.12, 0.14]) * 255


@pytest.fixture(scope="module")
def spheres():
    # Two pairs of spheres side by side: two clusters, each in sight.
    return sphere_ensemble([3.5, 3.8, 3.6, 3.9], n=24,
                           centres=[(6, 12, 12), (6.3, 12, 12), (17, 12, 12), (17.3, 12, 12)])


def near(image, rgb, tolerance=3):
    return np.all(np.abs(image[..., :3].astype(int) - np.asarray(rgb, dtype=int)) <= tolerance,
                  axis=-1)


def hex_rgb(color):
    return [int(color[i:i + 2], 16) for i in (1, 3, 5)]


def shaded_like(image, rgb, tolerance=0.06):
    """Pixels of colour `rgb` under some light: the same channel proportions, not dark."""
    pixels = image[..., :3].astype(float)
    brightest = pixels.max(axis=-1, keepdims=True)
    rgb = np.asarray(rgb, dtype=float)
    return (brightest[..., 0] > 60) & np.all(
        np.abs(pixels / np.maximum(brightest, 1) - rgb / rgb.max()) <= tolerance, axis=-1)


def test_a_picture_of_the_size_asked_with_the_members_colours(spheres):
    image = ensil.render(spheres, iso=0.0, size=(240, 160), mode="opaque", clusters=2,
                         axis_labels=False, legend=False, title=False, floor="none")
    assert isinstance(image, ensil.Image) and isinstance(image, np.ndarray)
    assert image.shape == (160, 240, 4) and image.dtype == np.uint8
    assert np.all(image[..., 3] == 255)
    # Background in the corners, where no surface reaches.
    for corner in (image[0, 0], image[0, -1], image[-1, 0], image[-1, -1]):
        np.testing.assert_allclose(corner[:3], BACKGROUND, atol=2)
    # Each cluster's colour (as preprocess gives it), shaded, covers part of the picture.
    colors = spheres.preprocess(iso=0.0, clusters=2).colors
    assert len(set(colors)) == 2
    for color in set(colors):
        assert shaded_like(image, hex_rgb(color)).mean() > 0.01, color
    # Most of the frame is background.
    assert near(image, BACKGROUND).mean() > 0.5
    assert image.facts["members"] == 4 and image.facts["isovalue"] == 0.0


def test_without_a_display_server_it_draws_through_egl(tmp_path):
    script = ("import ensil, numpy as np\n"
              "from conftest import sphere_ensemble\n"
              "image = ensil.render(sphere_ensemble([4.0, 6.0]), iso=0.0, size=(64, 48))\n"
              "print(image.shape, image.facts['display'])\n")
    env = {k: v for k, v in os.environ.items()
           if k not in ("DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM")}
    env["PYTHONPATH"] = os.pathsep.join([os.path.dirname(__file__), env.get("PYTHONPATH", "")])
    said = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True,
                          text=True, timeout=240)
    assert said.returncode == 0, said.stderr
    assert "(48, 64, 4) none (EGL surfaceless)" in said.stdout


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def png_size_and_pixels(png):
    """Width, height and RGBA rows of an 8-bit RGBA PNG without interlacing (what Qt writes),
    decoded here so the test needs nothing beyond NumPy."""
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    pos, data, header = 8, b"", None
    while pos < len(png):
        length, kind = struct.unpack(">I4s", png[pos:pos + 8])
        body = png[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            data += body
        pos += 12 + length
    width, height, depth, color_type = header[:4]
    channels = {6: 4, 2: 3}[color_type]
    assert depth == 8
    raw = zlib.decompress(data)
    stride = width * channels
    rows, previous = [], np.zeros(stride, dtype=np.int32)
    for y in range(height):
        filt = raw[y * (stride + 1)]
        line = np.frombuffer(raw, np.uint8, stride, y * (stride + 1) + 1).astype(np.int32)
        out = np.zeros(stride, dtype=np.int32)
        for i in range(stride):
            a = out[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            predictor = {0: 0, 1: a, 2: b, 3: (a + b) // 2, 4: paeth(a, b, c)}[filt]
            out[i] = (line[i] + predictor) & 0xFF
        rows.append(out)
        previous = out
    return width, height, np.array(rows, dtype=np.uint8).reshape(height, width, channels)


def test_a_notebook_shows_the_picture(spheres):
    image = ensil.render(spheres, iso=0.0, size=(32, 24), legend=False, axis_labels=False,
                         title=False)
    png = image._repr_png_()
    width, height, pixels = png_size_and_pixels(png)
    assert (width, height) == (32, 24)
    np.testing.assert_array_equal(pixels[..., :3], np.asarray(image)[..., :3])


def test_the_session_as_drawn_draws_the_same_picture(era5_path, tmp_path):
    ens = ensil.open(era5_path, var="t")
    first = ensil.render(ens, size=(200, 120), view="top", thickness=0.01)
    assert first.session.isovalue == pytest.approx(first.facts["isovalue"])
    project = str(tmp_path / "drawn.ensil")
    first.session.save(project)
    again = ensil.render(project, size=(200, 120))
    np.testing.assert_array_equal(np.asarray(again), np.asarray(first))
    session = ensil.Session.load(project)
    assert session.settings["thickness"] == pytest.approx(0.01)
    from_session = ensil.render(session, size=(200, 120))
    np.testing.assert_array_equal(np.asarray(from_session), np.asarray(first))
    # A setting changed in the session changes the picture.
    session.settings["mode"] = "opaque"
    assert not np.array_equal(np.asarray(ensil.render(session, size=(200, 120))),
                              np.asarray(first))


def test_refusals_say_what_ensil_render_says(spheres, tmp_path):
    with pytest.raises(ensil.ArgumentError, match=r"^--size '0x10' is refused: it must be "
                                                  r"WIDTHxHEIGHT in pixels, each from 1 to 16384"):
        ensil.render(spheres, iso=0.0, size=(0, 10))
    with pytest.raises(ensil.ArgumentError, match=r"^--mode 'bogus' is refused: it must be "
                                                  r"shaded, spaghetti, surfaces or opaque$"):
        ensil.render(spheres, iso=0.0, mode="bogus")
    with pytest.raises(ensil.ArgumentError, match=r"^--thickness '5' is refused: it must be a "
                                                  r"number from 0.0001 to 0.5$"):
        ensil.render(spheres, iso=0.0, thickness=5)
    with pytest.raises(ensil.ArgumentError, match=r"^--view 'up' is refused: it must be one of "):
        ensil.render(spheres, iso=0.0, view="up")
    with pytest.raises(ensil.ArgumentError, match="there is no setting 'colour'"):
        ensil.render(spheres, iso=0.0, colour="red")
    with pytest.raises(ensil.Error, match="outside the values"):
        ensil.render(spheres, iso=100.0, size=(16, 16))
    with pytest.raises(ensil.ArgumentError, match="not a project"):
        ensil.render(str(tmp_path / "data.nc"))


def test_another_thread_is_told_why_it_cannot_render(spheres):
    ensil.render(spheres, iso=0.0, size=(16, 16))  # Qt starts on this thread
    raised = []

    def render_here():
        try:
            ensil.render(spheres, iso=0.0, size=(16, 16))
        except ensil.Error as e:
            raised.append(str(e))

    worker = threading.Thread(target=render_here)
    worker.start()
    worker.join()
    assert raised == ["ensil.render must be called from the thread Qt started on "
                      "(the first picture's)"]
