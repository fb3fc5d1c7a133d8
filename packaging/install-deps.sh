#!/usr/bin/env bash
# Installs exactly the Debian 12 packages that ensil's build, tests and app need.
# Idempotent: packages already present are skipped, and `apt-get update` runs only when
# something is missing. Run as root (or with sudo available).
set -euo pipefail

packages=(
    # toolchain
    cmake ninja-build g++ pkg-config
    # Qt 6 (Widgets, OpenGL, OpenGLWidgets, Test, Concurrent, Svg); libqt6opengl6-dev is only
    # a recommendation of qt6-base-dev but Qt6OpenGLWidgets' CMake config needs it.
    qt6-base-dev libqt6opengl6-dev qt6-svg-dev qt6-qpa-plugins
    # maths, meshes, threads
    libglm-dev libopenmesh-dev libmeshoptimizer-dev libtbb-dev libeigen3-dev
    # file formats
    libnetcdf-dev netcdf-bin libhdf5-dev hdf5-tools libvtk9-dev
    # content hashes of input files (the mesh cache key)
    libxxhash-dev
    # map projections (CF grid mappings: rotated pole, Lambert, stereographic, Mercator)
    libproj-dev
    # GRIB 1 and 2 (ECMWF's and NCEP's native format) and its command-line tools
    libeccodes-dev libeccodes-tools
    # unit conversion (UDUNITS-2 and its unit database): level ranges in hPa, km...
    libudunits2-dev
    # the Python module (pybind11) and its tests (pytest, NumPy; VTK's Python readers check the
    # surfaces it exports; cftime is the oracle for the dates of every CF calendar)
    pybind11-dev python3-dev python3-pytest python3-numpy python3-vtk9 python3-cftime
    # xarray in and out (python/ensil/_xarray.py): xarray and its NetCDF engine open the real
    # files as an independent reader; SciPy's linkage is the oracle of the merge tree
    python3-xarray python3-netcdf4 python3-scipy
    # `pip install .` into a virtual environment (pyproject.toml, setup.py) and its test
    # (python.venv_install): venv with pip, the setuptools backend and wheel, and
    # `python3 -m build --wheel`
    python3-venv python3-setuptools python3-wheel python3-build
    # `mpirun -np K ensil preprocess` (the mpi/ front end, ENSIL_WITH_MPI; the ci preset needs it)
    libopenmpi-dev openmpi-bin
    # the tests (the benchmarks are plain programs that print figures; they need nothing more)
    libgtest-dev libgmock-dev
    # the libFuzzer targets (tests/fuzz/, the fuzz preset): clang 14 and its libFuzzer runtime
    clang-14 libfuzzer-14-dev
    # packaging/check-format.sh: the C++ layout of .clang-format, checked before any build
    clang-format-14
    # packaging/check-tidy.py: .clang-tidy's checks on the files changed since their last check
    clang-tidy-14
    # the manual pages, made from ensil's --help at build time (packaging/make-command-help.sh)
    help2man
    # rpmbuild, for the RPM CPack makes beside the .deb (packaging/rpm/cpack.cmake)
    rpm
    # headless OpenGL (Mesa llvmpipe) under Xvfb, and EGL for batch rendering; xcb to check
    # that an X display answers before Qt is started on it
    xvfb xauth libgl1-mesa-dri libegl-mesa0 libegl-dev libgl-dev libxcb1-dev
    # a window manager for the tests of what only one does, such as maximising a window
    # (tests/support/with-window-manager.sh), and wmctrl to know when it has started
    openbox wmctrl
    # packages and desktop integration: dpkg-shlibdeps for CPack's Debian dependencies, the
    # validators of the desktop entry, AppStream metadata and MIME type, and the package checks
    # (x11-utils: xwininfo and xprop read the workbench window's icon)
    dpkg-dev file desktop-file-utils appstream shared-mime-info python3 x11-utils
)

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#packages[@]} packages already installed"
    exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install-deps: done"
