#!/usr/bin/env python3
"""Checks on what the ensil package installs, with nothing but the standard library.

  package_checks.py png FILE --size WxH [--min-covered F] [--min-colours N]
      FILE is a PNG of that size in which at least the fraction F of the pixels differ from the
      corner pixel (the background) and at least N distinct colours appear: an image with
      something drawn in it, not a blank or single-colour frame.
  package_checks.py mime-glob MIME_DIR PATTERN TYPE
      the shared-mime-info database in MIME_DIR (its globs2 file) maps PATTERN to TYPE.
  package_checks.py mime-package XML PATTERN TYPE
      the same for one MIME package file, compiled into a throw-away database with
      update-mime-database, as the system's trigger would compile it.
  package_checks.py metainfo-release METAINFO VERSION
      the newest <release> of the AppStream file METAINFO is VERSION.

Exits 0 when the check holds, 1 with a message saying what differs otherwise.
"""

import argparse
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ElementTree
import zlib


class CheckFailed(Exception):
    pass


# --- PNG ------------------------------------------------------------------------------------

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
CHANNELS_BY_COLOUR_TYPE = {0: 1, 2: 3, 4: 2, 6: 4}  # grey, RGB, grey+alpha, RGBA


def read_png(path):
    """Returns (width, height, channels, rows) for an 8-bit, non-interlaced, non-palette PNG."""
    with open(path, "rb") as f:
        data = f.read()
    if not data.startswith(PNG_SIGNATURE):
        raise CheckFailed(f"{path} is not a PNG file (its first bytes are {data[:8]!r})")
    pos, header, compressed = len(PNG_SIGNATURE), None, bytearray()
    while pos + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            compressed += body
        elif kind == b"IEND":
            break
    if header is None:
        raise CheckFailed(f"{path} has no IHDR chunk")
    width, height, depth, colour_type, _, _, interlace = header
    if depth != 8 or colour_type not in CHANNELS_BY_COLOUR_TYPE or interlace != 0:
        raise CheckFailed(f"{path}: only 8-bit, non-interlaced grey/RGB/RGBA PNGs are checked "
                          f"(bit depth {depth}, colour type {colour_type}, interlace {interlace})")
    channels = CHANNELS_BY_COLOUR_TYPE[colour_type]
    try:
        raw = zlib.decompress(bytes(compressed))
    except zlib.error as error:
        raise CheckFailed(f"{path}: the image data does not decompress ({error})") from None
    stride = width * channels
    if len(raw) != height * (stride + 1):
        raise CheckFailed(f"{path}: {len(raw)} bytes of image data, "
                          f"expected {height * (stride + 1)}")
    return width, height, channels, unfilter(raw, height, stride, channels)


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def unfilter(raw, height, stride, bpp):
    """Undoes the per-row PNG filters (specification section 9)."""
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, row = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            left = row[i - bpp] if i >= bpp else 0
            up = previous[i]
            up_left = previous[i - bpp] if i >= bpp else 0
            if kind == 1:
                row[i] = (row[i] + left) & 0xFF
            elif kind == 2:
                row[i] = (row[i] + up) & 0xFF
            elif kind == 3:
                row[i] = (row[i] + (left + up) // 2) & 0xFF
            elif kind == 4:
                row[i] = (row[i] + paeth(left, up, up_left)) & 0xFF
            elif kind != 0:
                raise CheckFailed(f"unknown PNG filter type {kind} in row {y}")
        rows.append(bytes(row))
        previous = row
    return rows


def check_png(path, size, min_covered, min_colours):
    width, height, channels, rows = read_png(path)
    expected = tuple(int(n) for n in size.lower().split("x"))
    if (width, height) != expected:
        raise CheckFailed(f"{path} is {width}x{height}, expected {expected[0]}x{expected[1]}")
    background = rows[0][:channels]
    colours, covered = set(), 0
    for row in rows:
        for x in range(0, len(row), channels):
            pixel = row[x:x + channels]
            colours.add(pixel)
            covered += pixel != background
    fraction = covered / (width * height)
    if fraction < min_covered:
        raise CheckFailed(f"{path}: only {fraction:.1%} of the pixels differ from the background "
                          f"{tuple(background)}, expected at least {min_covered:.1%}")
    if len(colours) < min_colours:
        raise CheckFailed(f"{path}: {len(colours)} distinct colours, "
                          f"expected at least {min_colours}")
    print(f"{path}: {width}x{height}, {fraction:.1%} drawn, {len(colours)} colours")


# --- MIME -----------------------------------------------------------------------------------

def check_mime_glob(mime_dir, pattern, mime_type):
    globs = os.path.join(mime_dir, "globs2")
    try:
        with open(globs, encoding="utf-8") as f:
            lines = [line.strip() for line in f if not line.startswith("#")]
    except OSError as error:
        raise CheckFailed(f"cannot read the MIME database's {globs}: {error.strerror}") from None
    # globs2 lines are weight:type:pattern[:flags]
    types = [line.split(":")[1] for line in lines
             if line.count(":") >= 2 and line.split(":")[2] == pattern]
    if mime_type not in types:
        found = ", ".join(types) if types else "nothing"
        raise CheckFailed(f"{globs} maps {pattern} to {found}, expected {mime_type}")
    print(f"{globs}: {pattern} -> {mime_type}")


def check_mime_package(xml_path, pattern, mime_type):
    if shutil.which("update-mime-database") is None:
        raise CheckFailed("update-mime-database is missing: install shared-mime-info")
    with tempfile.TemporaryDirectory() as data_home:
        mime_dir = os.path.join(data_home, "mime")
        os.makedirs(os.path.join(mime_dir, "packages"))
        shutil.copy(xml_path, os.path.join(mime_dir, "packages"))
        # Inside XDG_DATA_HOME, so update-mime-database does not warn that nobody will look there.
        environment = dict(os.environ, XDG_DATA_HOME=data_home)
        result = subprocess.run(["update-mime-database", mime_dir], capture_output=True, text=True,
                                env=environment)
        # update-mime-database reports a malformed package on stderr but still exits 0.
        if result.returncode != 0 or result.stderr.strip():
            raise CheckFailed(f"update-mime-database rejected {xml_path}: {result.stderr.strip()}")
        check_mime_glob(mime_dir, pattern, mime_type)


# --- AppStream ------------------------------------------------------------------------------

def check_metainfo_release(path, version):
    releases = ElementTree.parse(path).getroot().findall("./releases/release")
    if not releases:
        raise CheckFailed(f"{path} lists no <release>")
    newest = releases[0].get("version")  # AppStream lists releases newest first
    if newest != version:
        raise CheckFailed(f"{path}: the newest release is {newest}, but the project is {version}; "
                          f"add a <release version=\"{version}\" date=\"YYYY-MM-DD\"/> first")
    print(f"{path}: newest release {newest}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    commands = parser.add_subparsers(dest="command", required=True)
    png = commands.add_parser("png")
    png.add_argument("file")
    png.add_argument("--size", required=True, help="WxH")
    png.add_argument("--min-covered", type=float, default=0.0)
    png.add_argument("--min-colours", type=int, default=2)
    for name, first in (("mime-glob", "mime_dir"), ("mime-package", "xml")):
        mime = commands.add_parser(name)
        mime.add_argument(first)
        mime.add_argument("pattern")
        mime.add_argument("type")
    metainfo = commands.add_parser("metainfo-release")
    metainfo.add_argument("metainfo")
    metainfo.add_argument("version")
    args = parser.parse_args()

    try:
        if args.command == "png":
            check_png(args.file, args.size, args.min_covered, args.min_colours)
        elif args.command == "mime-glob":
            check_mime_glob(args.mime_dir, args.pattern, args.type)
        elif args.command == "mime-package":
            check_mime_package(args.xml, args.pattern, args.type)
        else:
            check_metainfo_release(args.metainfo, args.version)
    except (CheckFailed, OSError, ValueError, ElementTree.ParseError) as error:
        print(f"package_checks.py {args.command}: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
