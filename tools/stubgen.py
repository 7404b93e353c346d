#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the type stubs of the compiled module (python/flexrock/_flexrock.pyi) from the module
itself: pybind11 puts each function's signature in the first line of its docstring.

    PYTHONPATH=build/release/python python3 tools/stubgen.py           write the stub file
    PYTHONPATH=build/release/python python3 tools/stubgen.py --check   exit 1 if it is stale

Debian 12 has no pybind11-stubgen; this covers what the bindings use (functions, overloads,
classes with methods, static methods and properties, enums, the exception).
"""
import argparse
import difflib
import importlib
import inspect
import re
import sys
from pathlib import Path

MODULE = "flexrock._flexrock"
STUB = Path(__file__).resolve().parent.parent / "python" / "flexrock" / "_flexrock.pyi"
HEADER = f"""# SPDX-License-Identifier: BSD-3-Clause
# Type stubs of the compiled module {MODULE}, written by tools/stubgen.py from the module.
# Do not edit: after changing the bindings, rebuild and run the tool (a test checks they agree).
from __future__ import annotations

from typing import Any, Callable, ClassVar, Iterator, Optional, overload

import numpy
import numpy.typing
"""
SKIPPED_DUNDERS = {"__getstate__", "__setstate__", "__ne__", "__str__", "__new__",
                   "__init_subclass__", "__subclasshook__", "__dir__", "__format__",
                   "__reduce__", "__reduce_ex__", "__sizeof__"}
OPEN, CLOSE = "([{<", ")]}>"


def split_top(text, sep=","):
    """Splits at `sep` outside brackets and quotes."""
    parts, depth, quote, cur = [], 0, None, ""
    for ch in text:
        if quote:
            quote = None if ch == quote else quote
        elif ch in "'\"":
            quote = ch
        elif ch in OPEN:
            depth += 1
        elif ch in CLOSE:
            depth -= 1
        elif ch == sep and depth == 0:
            parts.append(cur)
            cur = ""
            continue
        cur += ch
    if cur.strip():
        parts.append(cur)
    return [p.strip() for p in parts]


def closing_paren(text, start):
    depth = 0
    for i in range(start, len(text)):
        if text[i] in OPEN:
            depth += 1
        elif text[i] in CLOSE:
            depth -= 1
            if depth == 0:
                return i
    raise ValueError(f"unbalanced signature: {text!r}")


def py_type(t):
    """A pybind11 type name as a stub annotation."""
    t = t.strip().replace(MODULE + ".", "")
    t = re.sub(r"numpy\.ndarray\[numpy\.(\w+)(\[[^\]]*\])?\]", r"numpy.typing.NDArray[numpy.\1]", t)
    for old, new in (("List[", "list["), ("Dict[", "dict["), ("Tuple[", "tuple["),
                     ("Set[", "set[")):
        t = t.replace(old, new)
    t = re.sub(r"\bhandle\b", "Any", t)
    t = re.sub(r"\bfunction\b", "Callable[..., Any]", t)
    t = re.sub(r"\biterator\b", "Iterator[Any]", t)
    return t or "Any"


def parse_signature(line):
    """'name(a: T = d, ...) -> R' as (name, [(arg, type, has_default, default_is_none)], R)."""
    open_at = line.index("(")
    close_at = closing_paren(line, open_at)
    name = line[:open_at].strip()
    rest = line[close_at + 1:].strip()
    ret = py_type(rest[2:]) if rest.startswith("->") else "None"
    params = []
    for p in split_top(line[open_at + 1:close_at]):
        default = None
        parts = p.split(" = ", 1) if "=" in p else [p]
        head = parts[0]
        if len(parts) == 2:
            default = parts[1].strip()
        if p.startswith("*"):
            params.append((head, None, False, False))
            continue
        arg, _, typ = head.partition(":")
        params.append((arg.strip(), py_type(typ) if typ else None, default is not None,
                       default == "None"))
    return name, params, ret


def format_def(name, params, ret, method, indent, decorators=()):
    args = []
    for i, (arg, typ, has_default, default_none) in enumerate(params):
        if method and i == 0:
            args.append("self")
            continue
        if typ is None:
            args.append(arg)
            continue
        if default_none and not typ.startswith("Optional[") and typ != "None":
            typ = f"Optional[{typ}]"
        args.append(f"{arg}: {typ}" + (" = ..." if has_default else ""))
    lines = [f"{indent}@{d}" for d in decorators]
    lines.append(f"{indent}def {name}({', '.join(args)}) -> {ret}: ...")
    return lines


def doc_text(doc, signature_lines):
    """The docstring without pybind11's signature lines."""
    lines = (doc or "").splitlines()
    body = [ln for ln in lines[signature_lines:]]
    text = "\n".join(body).strip()
    return text


def docstring(text, indent):
    if not text:
        return []
    text = text.replace("\\", "\\\\").replace('"""', '\\"\\"\\"')
    lines = text.splitlines()
    if len(lines) == 1:
        return [f'{indent}"""{lines[0]}"""']
    return [f'{indent}"""{lines[0]}'] + [(indent + ln) if ln else "" for ln in lines[1:]] + \
        [f'{indent}"""']


def function_stub(name, obj, indent="", method=False, static=False):
    doc = obj.__doc__ or ""
    first = doc.splitlines()[0] if doc else ""
    decorators = ["staticmethod"] if static else []
    if "Overloaded function." in doc.splitlines()[1:2]:
        out = []
        sigs = re.findall(rf"^\d+\. ({re.escape(name)}\(.*)$", doc, re.M)
        for sig in sigs:
            _, params, ret = parse_signature(sig)
            out += format_def(name, params, ret, method, indent, decorators + ["overload"])
        return out
    if not first.startswith(name + "("):
        if name == "__init__":
            return []  # a class without a constructor
        # no signature (a plain Python callable): accept anything
        args = "self, *args: Any, **kwargs: Any" if method else "*args: Any, **kwargs: Any"
        return [f"{indent}@{d}" for d in decorators] + [f"{indent}def {name}({args}) -> Any: ..."]
    _, params, ret = parse_signature(first)
    lines = format_def(name, params, ret, method, indent, decorators)
    body = docstring(doc_text(doc, 1), indent + "    ")
    if body:
        lines[-1] = lines[-1][:-len(" ...")]
        lines += body
    return lines


def property_type(prop):
    doc = (prop.fget.__doc__ or "") if prop.fget else ""
    m = re.search(r"\)\s*->\s*(.+)$", doc.splitlines()[0] if doc else "")
    return py_type(m.group(1)) if m else "Any"


def enum_stub(cls, indent=""):
    name = cls.__qualname__
    i = indent + "    "
    out = [f"{indent}class {cls.__name__}:"]
    out += docstring(class_doc(cls), i)
    for member in cls.__members__:
        out.append(f"{i}{member}: ClassVar[{name}]")
    out.append(f"{i}__members__: ClassVar[dict[str, {name}]]")
    out += [f"{i}{line}" for line in ("def __init__(self, value: int) -> None: ...",
                                      "def __eq__(self, other: object) -> bool: ...",
                                      "def __hash__(self) -> int: ...",
                                      "def __index__(self) -> int: ...",
                                      "def __int__(self) -> int: ...",
                                      "@property",
                                      "def name(self) -> str: ...",
                                      "@property",
                                      "def value(self) -> int: ...")]
    return out


def class_doc(cls):
    doc = cls.__dict__.get("__doc__")
    return doc.strip() if isinstance(doc, str) and not doc.startswith("Members:") else ""


def class_stub(cls, indent=""):
    if hasattr(cls, "__members__") and "__entries" in cls.__dict__:
        return enum_stub(cls, indent)
    i = indent + "    "
    bases = [b.__qualname__ for b in cls.__bases__ if b.__module__ == MODULE]
    out = [f"{indent}class {cls.__name__}{'(' + ', '.join(bases) + ')' if bases else ''}:"]
    out += docstring(class_doc(cls), i)
    members = []
    for name, obj in sorted(cls.__dict__.items()):
        if name.startswith("__") and (name in SKIPPED_DUNDERS or not callable(obj)):
            continue
        if name.startswith("_") and not name.startswith("__"):
            continue
        if inspect.isclass(obj):
            members += class_stub(obj, i)
        elif isinstance(obj, property):
            typ = property_type(obj)
            if obj.fset is None:
                members += [f"{i}@property", f"{i}def {name}(self) -> {typ}: ..."]
            else:
                members.append(f"{i}{name}: {typ}")
        elif isinstance(obj, staticmethod):
            members += function_stub(name, obj.__func__, i, static=True)
        elif callable(obj):
            members += function_stub(name, obj, i, method=True)
    return out + (members or [f"{i}..."])


def generate():
    module = importlib.import_module(MODULE)
    out = [HEADER]
    out.append(f"__version__: str\n")
    names = sorted(n for n in dir(module) if not n.startswith("_"))
    for name in names:
        obj = getattr(module, name)
        if inspect.isclass(obj) and issubclass(obj, BaseException):
            base = obj.__bases__[0].__name__
            out.append(f"class {name}({base}): ...\n")
    for name in names:
        obj = getattr(module, name)
        if inspect.isclass(obj) and not issubclass(obj, BaseException):
            out.append("\n".join(class_stub(obj)) + "\n")
    for name in names:
        obj = getattr(module, name)
        if not inspect.isclass(obj) and callable(obj):
            out.append("\n".join(function_stub(name, obj)) + "\n")
        elif not inspect.isclass(obj) and not callable(obj) and not inspect.ismodule(obj):
            out.append(f"{name}: {type(obj).__name__}\n")
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true",
                        help="compare with the committed stub file; exit 1 if they differ")
    parser.add_argument("--output", type=Path, default=STUB, help=f"default: {STUB}")
    args = parser.parse_args()
    text = generate()
    if args.check:
        old = args.output.read_text() if args.output.exists() else ""
        if old != text:
            sys.stdout.writelines(difflib.unified_diff(old.splitlines(True), text.splitlines(True),
                                                       str(args.output), "generated"))
            print(f"{args.output} does not match the module: run tools/stubgen.py with the "
                  f"build's python directory on PYTHONPATH", file=sys.stderr)
            return 1
        return 0
    args.output.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
