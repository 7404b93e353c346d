# SPDX-License-Identifier: BSD-3-Clause
"""The package as delivered: one version (CMake's project(VERSION)) reported by the module, the
command line and the summary; `python -m flexrock` running the command line; type stubs that
match the compiled module."""

import re
import subprocess
import sys

import flexrock as fr


def declared_version(source_dir):
    text = (source_dir / "CMakeLists.txt").read_text()
    m = re.search(r"^project\(flexrock VERSION ([0-9]+\.[0-9]+\.[0-9]+)", text, re.M)
    assert m, "no project(flexrock VERSION x.y.z) in CMakeLists.txt"
    return m.group(1)


def test_module_cli_and_summary_report_the_cmake_version(source_dir, cli):
    version = declared_version(source_dir)
    assert fr.__version__ == version
    out = subprocess.run([str(cli), "--version"], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == f"flexrock {version}"
    # a block left at rest by a weak motion: any run writes the version into its summary
    result = fr.simulate(fr.rigid_block(width=0.4, height=1.8, mass=800.0),
                         fr.motion_from_array([0.0, 0.1, 0.0], 0.01))
    assert result.summary()["flexrock_version"] == version


def test_python_m_flexrock_runs_the_command_line(source_dir, cli):
    version = declared_version(source_dir)
    out = subprocess.run([sys.executable, "-m", "flexrock", "--version"], capture_output=True,
                         text=True)
    assert (out.returncode, out.stdout.strip()) == (0, f"flexrock {version}")
    # exit codes pass through: 2 for a usage error, with the command line's message
    bad = subprocess.run([sys.executable, "-m", "flexrock", "fly"], capture_output=True,
                         text=True)
    assert bad.returncode == 2
    assert "flexrock: error:" in bad.stderr


def test_type_stubs_match_the_compiled_module(source_dir):
    stub = source_dir / "python" / "flexrock" / "_flexrock.pyi"
    assert (source_dir / "python" / "flexrock" / "py.typed").exists()
    out = subprocess.run([sys.executable, str(source_dir / "tools" / "stubgen.py"), "--check",
                          "--output", str(stub)], capture_output=True, text=True)
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr
    # every public name of the module is declared
    text = stub.read_text()
    for name in dir(fr._flexrock):
        if not name.startswith("_"):
            assert re.search(rf"^(class|def) {name}\b", text, re.M), name
