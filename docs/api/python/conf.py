# SPDX-License-Identifier: BSD-3-Clause
# The Python API reference: Sphinx autodoc over the built package, numpydoc-style docstrings read
# by napoleon (Sphinx's own extension: nothing outside Debian's python3-sphinx). Built by
# scripts/api-docs.sh, which puts the build's package on the path.
project = "flexrock"
extensions = ["sphinx.ext.autodoc", "sphinx.ext.napoleon"]
napoleon_google_docstring = False
napoleon_numpy_docstring = True
# the Parameters sections as napoleon's own lists, not :param: fields: the types there are written
# for readers ("AccelUnit or str, optional"), which the field syntax would parse as markup
napoleon_use_param = False
autodoc_member_order = "bysource"
autodoc_typehints = "signature"
html_theme = "alabaster"
html_show_sourcelink = False
html_last_updated_fmt = None  # no date: the same bytes on regeneration
exclude_patterns = []


import re  # noqa: E402

_BARS = re.compile(r"\|([^|\s][^|]*?)\|")


def _plain_docstrings(app, what, name, obj, options, lines):
    # The docstrings are numpydoc written for help() and editors, not reST with substitutions:
    # |theta| is an absolute value, not a substitution; pybind11's enum docstrings list their
    # members bare ("Members:"), which reST would read as markup. Shown as written, in literals.
    for k, line in enumerate(lines):
        lines[k] = _BARS.sub(lambda m: "``|" + m.group(1) + "|``", line)
    if "Members:" in (x.strip() for x in lines):
        at = [x.strip() for x in lines].index("Members:")
        items = []
        for x in lines[at + 1:]:
            if not x.strip():
                continue
            member, _, doc = x.strip().partition(" : ")
            items.append(f"- ``{member}``" + (f": {doc}" if doc else ""))
        lines[at:] = ["Members:", ""] + items


def setup(app):
    app.connect("autodoc-process-docstring", _plain_docstrings)
