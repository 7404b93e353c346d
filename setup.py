# SPDX-License-Identifier: BSD-3-Clause
"""Builds the compiled parts of the Python package with the project's CMake.

setuptools drives CMake (the pattern of pybind11's cmake_example): `build_ext` configures and
builds the targets `_flexrock` (the extension) and `flexrock` (the command line), then copies the
extension and the command (as flexrock/_bin/flexrock, run by the `flexrock` entry point and by
`python -m flexrock`) into the package. Everything else is declared in pyproject.toml.

Environment:
  FLEXROCK_BUILD_DIR   an existing CMake build directory configured with FLEXROCK_BUILD_PYTHON=ON
                       (e.g. build/release): its targets are brought up to date and used, with no
                       second build; its configuration is left as it is
  CMAKE_ARGS           extra arguments for the CMake configure step (space separated)
  CMAKE_BUILD_PARALLEL_LEVEL   parallel build jobs (default: the number of CPUs)
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE_DIR = Path(__file__).resolve().parent


def missing_for_build(commands: list) -> list:
    """What this interpreter lacks to run the setuptools `commands`, each with the Debian
    package that provides it for /usr/bin/python3. pip runs this file with the interpreter of the
    environment, and a python3 that is not Debian's (pyenv, conda, a venv without
    --system-site-packages) often lacks `wheel`: setuptools before 70.1 then fails with
    "invalid command 'bdist_wheel'", which names neither the cause nor the fix."""
    import importlib.util
    import sysconfig

    missing = []
    # pip's metadata step (dist_info) goes through bdist_wheel too
    if {"bdist_wheel", "dist_info"}.intersection(commands) \
            and importlib.util.find_spec("setuptools.command.bdist_wheel") is None \
            and importlib.util.find_spec("wheel") is None:
        missing.append("the `wheel` package (python3-wheel)")
    compiles = {"bdist_wheel", "build", "build_ext", "install", "develop", "editable_wheel"}
    include = sysconfig.get_paths().get("include", "")
    if compiles.intersection(commands) and not (Path(include) / "Python.h").is_file():
        missing.append(f"the C headers, Python.h in {include} (python3-dev)")
    return missing


_missing = missing_for_build(sys.argv[1:])
if _missing:
    sys.exit(
        f"setup.py: {sys.executable} (Python {sys.version.split()[0]}) cannot build flexrock: it "
        f"lacks {'; '.join(_missing)}.\n"
        "Either make the environment from Debian's interpreter, which has them after "
        "scripts/install-deps.sh:\n"
        "  /usr/bin/python3 -m venv --system-site-packages ~/venv/flexrock\n"
        "  ~/venv/flexrock/bin/pip install --no-build-isolation .\n"
        "or run scripts/pip-install.sh, which picks such an interpreter, or install what is "
        "missing into this one.")


def project_version() -> str:
    """The one version: project(flexrock VERSION x.y.z) in CMakeLists.txt."""
    text = (SOURCE_DIR / "CMakeLists.txt").read_text()
    m = re.search(r"^project\(flexrock VERSION ([0-9]+\.[0-9]+\.[0-9]+)", text, re.M)
    if not m:
        sys.exit("setup.py: no project(flexrock VERSION x.y.z) in CMakeLists.txt")
    return m.group(1)


class CMakeExtension(Extension):
    """An extension built by CMake: no sources of its own for setuptools."""

    def __init__(self, name: str) -> None:
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def run_cmake(self, *args: str) -> None:
        # pip shows this output with -v (scripts/pip-install.sh passes it and keeps the build's
        # progress lines on screen); without -v pip shows a spinner until the end
        print("setup.py:", " ".join(args), flush=True)
        subprocess.run(args, check=True)

    def cmake_build_dir(self) -> Path:
        existing = os.environ.get("FLEXROCK_BUILD_DIR")
        if existing:
            build = Path(existing).resolve()
            cache = build / "CMakeCache.txt"
            if not cache.is_file():
                sys.exit(f"setup.py: FLEXROCK_BUILD_DIR={existing} is not a CMake build "
                         f"directory (no CMakeCache.txt)")
            if not re.search(r"^FLEXROCK_BUILD_PYTHON:BOOL=ON$", cache.read_text(), re.M):
                sys.exit(f"setup.py: FLEXROCK_BUILD_DIR={existing} was configured without "
                         f"FLEXROCK_BUILD_PYTHON=ON (the release preset has it)")
            return build
        build = Path(self.build_temp).resolve() / "cmake"
        build.mkdir(parents=True, exist_ok=True)
        args = ["cmake", "-S", str(SOURCE_DIR), "-B", str(build),
                "-DCMAKE_BUILD_TYPE=Release",
                "-DFLEXROCK_BUILD_PYTHON=ON",
                # the module and the command only: no tests, examples or tools
                "-DFLEXROCK_BUILD_TESTS=OFF", "-DFLEXROCK_BUILD_EXAMPLES=OFF",
                "-DFLEXROCK_BUILD_VALIDATION=OFF", "-DFLEXROCK_BUILD_BENCH=OFF",
                # the interpreter that runs pip: the module is built for its ABI
                f"-DPython3_EXECUTABLE={sys.executable}"]
        if shutil.which("ninja") and "CMAKE_GENERATOR" not in os.environ \
                and not (build / "CMakeCache.txt").exists():
            args += ["-G", "Ninja"]
        args += [a for a in os.environ.get("CMAKE_ARGS", "").split() if a]
        self.run_cmake(*args)
        return build

    def build_extension(self, ext: Extension) -> None:
        build = self.cmake_build_dir()
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        self.run_cmake("cmake", "--build", str(build), "--target", "_flexrock", "flexrock",
                       "-j", jobs)

        # the build lays the extension out in <build>/python/flexrock (python/CMakeLists.txt)
        built = sorted((build / "python" / "flexrock").glob("_flexrock*.so"))
        cli = build / "apps" / "flexrock"
        if not built or not cli.is_file():
            sys.exit(f"setup.py: the build in {build} made no _flexrock module or flexrock "
                     f"command")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built[-1], target)
        bin_dir = target.parent / "_bin"
        bin_dir.mkdir(exist_ok=True)
        shutil.copy2(cli, bin_dir / "flexrock")


setup(
    version=project_version(),
    ext_modules=[CMakeExtension("flexrock._flexrock")],
    cmdclass={"build_ext": CMakeBuild},
)
