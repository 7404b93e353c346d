# SPDX-License-Identifier: BSD-3-Clause
"""Pickling of bodies, motions, options and results, so that multiprocessing, joblib and dask can
pass them between processes. Each is pickled as its state and rebuilt by the library's own
constructors: a Body from its parameters (checked again), a sampled GroundMotion from its samples,
a synthetic one by the call that made it, structs of settable fields field by field; the results'
read-only structs pickle in C++ (python/src/field_pickle.hpp)."""

import copyreg
import hashlib

from . import _flexrock as _f

# structs whose every field is settable: rebuilt from a default one, field by field
_STRUCTS = (
    _f.BodyParameters,
    _f.Damping,
    _f.InitialState,
    _f.SimulationMethods,
    _f.SimulationOptions,
    _f.ExcitationComponent,
    _f.OutputSettings,
    _f.OutputPaths,
)


def _fields(cls):
    return [n for n in dir(cls) if isinstance(getattr(cls, n, None), property) and getattr(cls, n).fset is not None]


def _rebuild_struct(cls, state):
    obj = cls()
    for name, value in state.items():
        setattr(obj, name, value)
    return obj


def _reduce_struct(obj):
    return _rebuild_struct, (type(obj), {n: getattr(obj, n) for n in _fields(type(obj))})


# --- motions -------------------------------------------------------------------------------------

_scaled = _f.GroundMotion.scaled  # the library's, before the package notes its recipe


def _fingerprint(m, n=64):
    # the motion at n times over its duration: what a rebuilt motion must give again
    d = m.duration
    return tuple(v for k in range(n) for v in m.at(d * k / (n - 1)))


def _build(recipe):
    kind = recipe[0]
    if kind == "pulse":
        _, name, a_p, omega_p, duration, component, keys = recipe
        return _f.make_pulse(name, a_p, omega_p, duration, component, keys)
    if kind == "none":
        return _f.GroundMotion.none(recipe[1])
    if kind == "scaled":
        return _scaled(_build(recipe[1]), recipe[2])
    if kind == "case":
        # a synthetic motion of a case file: read again, and only if it is the same motion
        _, source, digest, fingerprint = recipe
        try:
            with open(source, "rb") as f:
                same_file = hashlib.sha256(f.read()).hexdigest() == digest
            m = _f.load_case(source).motion
        except (OSError, _f.InputError) as e:
            raise ValueError(f"cannot unpickle the motion of case file {source}: {e}") from None
        if not same_file or _fingerprint(m) != fingerprint:
            raise ValueError(
                f"cannot unpickle the motion of case file {source}: the file changed since it was "
                "pickled (its synthetic motion is rebuilt from it)"
            )
        return m
    raise ValueError(f"cannot unpickle a GroundMotion: unknown recipe {kind!r}")


def _rebuild_motion(state, extra):
    m = _f.GroundMotion.sampled(*state) if isinstance(state[0], list) else _build(state)
    for name, value in extra.items():
        setattr(m, name, value)
    if not isinstance(state[0], list):
        m._flexrock_recipe = state
    return m


def motion_state(m, source=""):
    """The state a motion pickles as: its samples, or the recipe that made it; for a synthetic
    motion of a case file (`source`), the file with its digest and the motion's fingerprint."""
    if m.is_sampled:
        return (list(m.times), list(m.horizontal), list(m.vertical) if m.has_vertical else [])
    recipe = getattr(m, "_flexrock_recipe", None)
    if recipe is not None:
        return recipe
    if source:
        with open(source, "rb") as f:
            return ("case", source, hashlib.sha256(f.read()).hexdigest(), _fingerprint(m))
    raise TypeError(
        "cannot pickle a synthetic GroundMotion not made by flexrock's pulse functions "
        "(flexrock.one_sine_pulse(...), free_rocking(...), .scaled(...)) or read from a case file: "
        "its function cannot be saved"
    )


def _reduce_motion(m):
    extra = {k: v for k, v in getattr(m, "__dict__", {}).items() if k != "_flexrock_recipe"}
    return _rebuild_motion, (motion_state(m), extra)


def _noted_scaled(self, factor):
    # the library's scaled(), keeping the recipe of a synthetic motion (for pickling)
    out = _scaled(self, factor)
    recipe = getattr(self, "_flexrock_recipe", None)
    if recipe is not None:
        out._flexrock_recipe = ("scaled", recipe, float(factor))
    return out


_noted_scaled.__doc__ = _scaled.__doc__
_f.GroundMotion.scaled = _noted_scaled


# --- cases ---------------------------------------------------------------------------------------


def case_state(case, motion=None):
    """A Case's fields, its motion (or `motion`, the one it was made from) as motion_state."""
    state = {n: getattr(case, n) for n in _fields(_f.Case) if n != "motion"}
    state["motion"] = motion_state(motion if motion is not None else case.motion, case.source)
    return state


def rebuild_case(state):
    case = _f.Case()
    for name, value in state.items():
        if name != "motion":
            setattr(case, name, value)
    motion = state["motion"]
    case.motion = _f.GroundMotion.sampled(*motion) if isinstance(motion[0], list) else _build(motion)
    return case


def _reduce_case(case):
    return rebuild_case, (case_state(case),)


for _cls in _STRUCTS:
    copyreg.pickle(_cls, _reduce_struct)
copyreg.pickle(_f.GroundMotion, _reduce_motion)
copyreg.pickle(_f.Case, _reduce_case)
