"""CTest python.venv_install: `pip install .` into a new virtual environment, then ensil used
from it as a user would (README-like line, then this folder's pytest suite), and the same build
as a wheel (`python3 -m build --no-isolation --wheel`).

    python3 check_venv_install.py --source SRC --build TREE --work DIR

The environment is made with the interpreter running this script (CMake's Python3_EXECUTABLE)
and --system-site-packages, for NumPy, pytest and the suite's oracles from Debian. pip builds
offline (--no-index, --no-build-isolation, --no-deps) from TREE, an existing configured tree
(ENSIL_CMAKE_BUILD_DIR: seconds, where a fresh tree takes minutes; setup.py says more). The
module is then used from DIR, outside the source folder, without PYTHONPATH, and must come
from the environment's site-packages: the build tree's module next to the source cannot pass.
HOME, the XDG folders and pip's configuration are DIR's own, so the user's settings, cache and
pip.conf are neither read nor written. Not a pytest file (no test_ prefix): CTest runs it.
"""

import argparse
import os
import shutil
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

# The README's line, and what the test checks of it: where ensil came from, and that the
# version pip recorded (setup.py, from CMakeLists.txt) is the module's own (session/version.h).
SMOKE = """
import importlib.metadata, ensil
ensil.demo(members=4).preprocess(iso=30)
assert importlib.metadata.version("ensil") == ensil.__version__, (
    importlib.metadata.version("ensil"), ensil.__version__)
print(ensil.__file__)
"""

# The suite, then which ensil its tests imported (conftest.py imports it after its set-up).
SUITE = """
import sys, pytest
code = pytest.main(sys.argv[1:])
import ensil
print(ensil.__file__)
sys.exit(code)
"""


def fail(message):
    sys.exit(f"check_venv_install: {message}")


def run(command, **kwargs):
    print("+", " ".join(str(part) for part in command), flush=True)
    return subprocess.run([str(part) for part in command], check=False, **kwargs)


def last_line(text):
    lines = text.strip().splitlines()
    return lines[-1] if lines else ""


def check_from_venv(module_file, venv, what):
    """Fails unless module_file (ensil/__init__.py as imported) lies inside the venv."""
    path = Path(module_file).resolve()
    if not path.is_relative_to(venv.resolve()):
        fail(f"{what} imported ensil from {path}, not from the virtual environment {venv}")
    print(f"{what}: ensil from {path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True, type=Path, help="the source folder")
    parser.add_argument("--build", required=True, type=Path, help="a configured CMake tree")
    parser.add_argument("--work", required=True, type=Path, help="this test's folder, emptied")
    args = parser.parse_args()
    source, work = args.source.resolve(), args.work.resolve()
    if work.is_relative_to(source) and not work.is_relative_to(source / "build"):
        fail(f"{work} lies in the source folder outside build/: the test must run elsewhere")

    shutil.rmtree(work, ignore_errors=True)
    home = work / "home"
    env = {name: value for name, value in os.environ.items()
           if not name.startswith(("PYTHON", "PIP_", "VIRTUAL_ENV"))}
    env.update(HOME=str(home), XDG_CONFIG_HOME=str(home / "config"),
               XDG_DATA_HOME=str(home / "data"), XDG_CACHE_HOME=str(home / "cache"),
               PIP_CONFIG_FILE=os.devnull, PIP_DISABLE_PIP_VERSION_CHECK="1",
               PIP_NO_INPUT="1", PYTHONNOUSERSITE="1", PYTHONDONTWRITEBYTECODE="1")
    for name in ("HOME", "XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME"):
        Path(env[name]).mkdir(parents=True, exist_ok=True)

    venv = work / "venv"
    python = venv / "bin" / "python"
    if run([sys.executable, "-m", "venv", "--system-site-packages", venv],
           env=env, cwd=work).returncode:
        fail("python3 -m venv failed (Debian: python3-venv)")
    if run([python, "-m", "pip", "install", "--no-build-isolation", "--no-deps", "--no-index",
            source], env=dict(env, ENSIL_CMAKE_BUILD_DIR=str(args.build.resolve())),
           cwd=work).returncode:
        fail("pip install failed")

    smoke = run([python, "-c", SMOKE], env=env, cwd=work, capture_output=True, text=True)
    print(smoke.stdout, smoke.stderr, sep="", end="")
    if smoke.returncode:
        fail("the README's line failed in the virtual environment")
    check_from_venv(last_line(smoke.stdout), venv, "the README's line")

    # As python/CMakeLists.txt runs the suite, but in one process from the environment; the
    # shared data and the command line (some tests compare with it) come from CTest.
    suite = run([python, "-X", "faulthandler", "-c", SUITE, "-q", "-p", "no:cacheprovider",
                 source / "tests" / "python"],
                env=dict(env, ENSIL_TEST_OUTPUT_DIR=str(work / "pytest")), cwd=work,
                capture_output=True, text=True)
    print(suite.stdout, suite.stderr, sep="", end="")
    if suite.returncode:
        fail(f"tests/python failed in the virtual environment (pytest's status {suite.returncode})")
    check_from_venv(last_line(suite.stdout), venv, "tests/python")

    # The same build as a wheel file (Debian's python3-build), holding the package and the
    # module for this interpreter.
    dist = work / "dist"
    if run([python, "-m", "build", "--no-isolation", "--wheel", "--outdir", dist, source],
           env=dict(env, ENSIL_CMAKE_BUILD_DIR=str(args.build.resolve())), cwd=work).returncode:
        fail("python3 -m build --no-isolation --wheel failed")
    wheels = list(dist.glob("ensil-*.whl"))
    tag = f"cp{sys.version_info.major}{sys.version_info.minor}"  # the venv's Python is ours
    if len(wheels) != 1 or f"-{tag}-{tag}-linux_" not in wheels[0].name:
        fail(f"python3 -m build wrote {[wheel.name for wheel in wheels]}, not one {tag} wheel")
    with zipfile.ZipFile(wheels[0]) as wheel:
        names = set(wheel.namelist())
    wanted = {"ensil/__init__.py", "ensil/py.typed",
              f"ensil/_ensil{sysconfig.get_config_var('EXT_SUFFIX')}"}
    if not wanted <= names:
        fail(f"{wheels[0].name} lacks {sorted(wanted - names)}")
    print(f"{wheels[0].name}: {len(names)} files")


if __name__ == "__main__":
    main()
