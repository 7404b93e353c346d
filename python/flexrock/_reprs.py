# SPDX-License-Identifier: BSD-3-Clause
"""Reprs of the compiled module's value types, written from their bound fields (the binding's
table of properties), so that a new field shows without editing this file. A type with a
default constructor shows only the fields that differ from its defaults."""

import math


def _fields(cls):
    return [n for n in sorted(dir(cls)) if not n.startswith("_")
            and isinstance(getattr(cls, n, None), property)]


def _value(v):
    if isinstance(v, float):
        return repr(v) if math.isfinite(v) else f"float('{v}')"
    if hasattr(type(v), "__members__"):  # a bound enum: its name
        return f"{type(v).__name__}.{v.name}"
    if hasattr(v, "shape") and getattr(v, "size", 0) > 6:  # a long array: its size only
        return f"<array of {v.size}>"
    if isinstance(v, (list, tuple)) and len(v) > 6:
        return f"<{len(v)} values>"
    return repr(v)


def _make(cls, defaults):
    fields = _fields(cls)
    base = cls() if defaults else None

    def __repr__(self):
        shown = []
        for n in fields:
            text = _value(getattr(self, n))
            # compared as shown: arrays and nested value types have no plain ==
            if base is not None and text == _value(getattr(base, n)):
                continue
            shown.append(f"{n}={text}")
        return f"{cls.__name__}({', '.join(shown)})"

    return __repr__


def install(module):
    """Gives Extremes, EnergyBalance, FragilityData, SimulationOptions and the SimulationMethods
    inside it their reprs."""
    for name, defaults in (("Extremes", False), ("EnergyBalance", False),
                           ("FragilityData", False), ("SimulationMethods", True),
                           ("SimulationOptions", True)):
        cls = getattr(module, name)
        if cls.__repr__ is object.__repr__:
            cls.__repr__ = _make(cls, defaults)
