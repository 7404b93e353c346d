#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds the API references: C++ from the public headers' comments (Doxygen, docs/api/Doxyfile)
# into build/api/cpp/html/, and Python from the numpydoc strings (Sphinx autodoc with napoleon,
# Debian's python3-sphinx) into build/api/python/. Needs a built module (default build/release).
# Usage: scripts/api-reference.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:-build/release}"
PY=/usr/bin/python3
[ -x "$PY" ] || PY=python3
status=0
if command -v doxygen >/dev/null; then
  mkdir -p build/api/cpp
  doxygen docs/api/Doxyfile
  echo "C++:    build/api/cpp/html/index.html"
else
  echo "api-reference.sh: no doxygen (apt-get install doxygen): C++ reference skipped" >&2
  status=1
fi
if PYTHONPATH="$BUILD/python" "$PY" -c "import sphinx, flexrock" 2>/dev/null; then
  conf="$(mktemp -d "${TMPDIR:-/tmp}/flexrock_api.XXXXXX")"
  trap 'rm -rf "$conf"' EXIT
  cat >"$conf/conf.py" <<'PYCONF'
project = "flexrock"
extensions = ["sphinx.ext.autodoc", "sphinx.ext.napoleon"]
napoleon_numpy_docstring = True
napoleon_google_docstring = False
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": True}
html_theme = "alabaster"
PYCONF
  cat >"$conf/index.rst" <<'RST'
flexrock Python API
===================

Generated from the numpydoc strings (units in brackets). The guide: docs/python.md. The
compiled module's classes and functions appear under ``flexrock``, which re-exports them.

.. automodule:: flexrock

Studies
-------

.. automodule:: flexrock.studies
   :noindex:

Plots
-----

.. automodule:: flexrock.plots
   :noindex:
RST
  PYTHONPATH="$BUILD/python" MPLBACKEND=Agg "$PY" -m sphinx -b html -q "$conf" build/api/python
  echo "Python: build/api/python/index.html"
else
  echo "api-reference.sh: no sphinx or no built flexrock module in $BUILD/python: Python" \
    "reference skipped (apt-get install python3-sphinx; cmake --build --preset release)" >&2
  status=1
fi
exit "$status"
