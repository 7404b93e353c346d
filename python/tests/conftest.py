# SPDX-License-Identifier: BSD-3-Clause
"""Shared fixtures: where the sources and the `flexrock` command are.

ctest sets FLEXROCK_SOURCE_DIR and FLEXROCK_CLI (and PYTHONPATH to the build's python dir);
run by hand, the defaults are this checkout and build/release.
"""

import os
import pathlib

import matplotlib
import pytest

matplotlib.use("Agg")  # never a window, even if a test reaches pyplot

SOURCE_DIR = pathlib.Path(os.environ.get("FLEXROCK_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
CLI = pathlib.Path(os.environ.get("FLEXROCK_CLI", SOURCE_DIR / "build" / "release" / "apps" / "flexrock"))
CASES = SOURCE_DIR / "examples" / "cases"
DATA = SOURCE_DIR.parent / "shared" / "data"


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="session")
def cli():
    if not CLI.exists():
        pytest.fail(f"the flexrock command is not at {CLI}: set FLEXROCK_CLI")
    return CLI


@pytest.fixture(scope="session")
def cases():
    return CASES
