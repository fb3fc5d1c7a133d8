"""The build of `pip install .` and `python3 -m build --wheel`: the package python/ensil/ with
its extension ensil._ensil, which the project's own CMake builds (pyproject.toml holds the
metadata; docs/python.md, "Installing into your own environment", says why setuptools).

The extension is built for the interpreter that runs this file (pip's, a virtual environment's):
CMake is given -DPython3_EXECUTABLE=sys.executable, where the normal build takes Debian's
/usr/bin/python3 (python/CMakeLists.txt).

Where CMake builds:
  - by default a tree of its own below setuptools' build folder (build/pip/temp.<platform>-<abi>/
    cmake in the source folder) with only the layers the module links and the module
    (-DENSIL_BUILD_APP=OFF: no program, no tests, no manuals): minutes the first time, then only
    what changed;
  - with ENSIL_CMAKE_BUILD_DIR=<tree>, an existing configured tree (build/ci, say): its target
    ensil_python is brought up to date and taken as it is, without configuring the tree again,
    so it must have been configured for this interpreter's ABI (checked below).
CMAKE_ARGS (as scikit-build names it) adds arguments to a fresh tree's configure, e.g.
CMAKE_ARGS="-DCMAKE_BUILD_TYPE=RelWithDebInfo"; CMAKE_BUILD_PARALLEL_LEVEL sets the build's jobs.
"""

import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build import build
from setuptools.command.build_ext import build_ext
from setuptools.command.sdist import sdist

SOURCE = Path(__file__).resolve().parent
REUSED_TREE = None
if os.environ.get("ENSIL_CMAKE_BUILD_DIR"):
    REUSED_TREE = Path(os.environ["ENSIL_CMAKE_BUILD_DIR"]).resolve()
    if not (REUSED_TREE / "CMakeCache.txt").is_file():
        sys.exit(f"setup.py: ENSIL_CMAKE_BUILD_DIR={REUSED_TREE} is not a configured CMake tree "
                 "(no CMakeCache.txt): configure it first (cmake --preset ci, say), or unset "
                 "ENSIL_CMAKE_BUILD_DIR to build a tree of pip's own")


def project_version():
    """The version in CMakeLists.txt's project(ensil VERSION x.y.z): the one place it is set."""
    cmake_lists = SOURCE / "CMakeLists.txt"
    if not cmake_lists.is_file():
        # An sdist holds only what setuptools packs; the C++ layers are built from the source
        # folder itself (python3 -m build --wheel, pip install .), not from an sdist.
        sys.exit(f"setup.py: {cmake_lists} not found: build from the source folder "
                 "(pip install SOURCE, python3 -m build --wheel SOURCE), not from an sdist")
    text = cmake_lists.read_text(encoding="utf-8")
    match = re.search(r"\bproject\(\s*ensil\s+VERSION\s+([0-9]+(?:\.[0-9]+)*)", text)
    if not match:
        sys.exit(f"setup.py: no 'project(ensil VERSION ...)' in {cmake_lists}")
    return match.group(1)


def run(command, **kwargs):
    print("setup.py:", shlex.join(str(part) for part in command), flush=True)
    subprocess.run([str(part) for part in command], check=True, **kwargs)


class CMakeBuild(build_ext):
    """Builds each extension as its CMake target and copies the module where setuptools packs
    it. The module is python/ensil/_ensil<EXT_SUFFIX> in the CMake tree, laid out as installed
    (python/CMakeLists.txt)."""

    def build_extension(self, ext):
        cmake = shutil.which("cmake")
        if not cmake:
            sys.exit("setup.py: cmake not found (packaging/install-deps.sh installs it)")
        if REUSED_TREE:
            tree = REUSED_TREE
        else:
            tree = Path(self.build_temp).resolve() / "cmake"
            self.configure(cmake, tree)

        command = [cmake, "--build", tree, "--target", "ensil_python"]
        if self.parallel:
            command += ["--parallel", str(self.parallel)]
        try:
            run(command)
        except subprocess.CalledProcessError:
            sys.exit(f"setup.py: building ensil_python in {tree} failed (above). The module is "
                     "built only where CMake finds pybind11-dev and python3-dev for this "
                     f"interpreter ({sys.executable}); packaging/install-deps.sh installs them")

        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = tree / "python" / "ensil" / f"_ensil{suffix}"
        if not built.is_file():
            found = sorted(path.name for path in (tree / "python" / "ensil").glob("_ensil*"))
            sys.exit(f"setup.py: {built} was not built: this interpreter ({sys.executable}) "
                     f"loads extensions named _ensil{suffix}, the tree holds "
                     f"{', '.join(found) or 'none'}. Configure the tree with "
                     f"-DPython3_EXECUTABLE={sys.executable}, or unset ENSIL_CMAKE_BUILD_DIR")
        destination = Path(self.get_ext_fullpath(ext.name))
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, destination)

    @staticmethod
    def configure(cmake, tree):
        command = [cmake, "-S", SOURCE, "-B", tree,
                   "-DCMAKE_BUILD_TYPE=Release",
                   "-DENSIL_BUILD_APP=OFF", "-DENSIL_BUILD_TESTS=OFF",
                   "-DENSIL_WITH_PYTHON=ON", "-DENSIL_WITH_MPI=OFF",
                   f"-DPython3_EXECUTABLE={sys.executable}"]
        if not (tree / "CMakeCache.txt").exists() and shutil.which("ninja"):
            command += ["-G", "Ninja"]  # the generator is chosen once, at the first configure
        command += shlex.split(os.environ.get("CMAKE_ARGS", ""))
        run(command)


class CleanBuild(build):
    """Empties the folder the wheel is packed from (build_lib) first: setuptools leaves the last
    build's files there, so a module no longer built, or built elsewhere, would still be packed.
    The CMake tree (below build_temp) is kept."""

    def run(self):
        shutil.rmtree(self.build_lib, ignore_errors=True)
        super().run()


class NoSdist(sdist):
    """An sdist would hold only the Python files: refused, rather than one that cannot build."""

    def run(self):
        sys.exit("setup.py: no sdist: the module is built from the source folder with its C++ "
                 "layers (pip install SOURCE, python3 -m build --wheel SOURCE)")


# setuptools' own folders (build, bdist, egg-info) in one place: below the reused tree, or in
# build/pip beside the CMake presets' folders; not egg-info in python/ of the source folder.
build_base = REUSED_TREE / "pip" if REUSED_TREE else SOURCE / "build" / "pip"
build_base.mkdir(parents=True, exist_ok=True)

setup(
    version=project_version(),
    package_dir={"": "python"},
    packages=["ensil"],
    package_data={"ensil": ["*.pyi", "py.typed"]},
    zip_safe=False,
    ext_modules=[Extension("ensil._ensil", sources=[])],
    cmdclass={"build": CleanBuild, "build_ext": CMakeBuild, "sdist": NoSdist},
    options={"build": {"build_base": str(build_base)},
             "egg_info": {"egg_base": str(build_base)}},
)
