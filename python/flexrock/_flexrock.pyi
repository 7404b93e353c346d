# SPDX-License-Identifier: BSD-3-Clause
# Type stubs of the compiled module flexrock._flexrock, written by tools/stubgen.py from the module.
# Do not edit: after changing the bindings, rebuild and run the tool (a test checks they agree).
from __future__ import annotations

from typing import Any, Callable, ClassVar, Iterator, Optional, overload

import numpy
import numpy.typing

__version__: str

class InputError(ValueError): ...

class AccelUnit:
    g: ClassVar[AccelUnit]
    m_per_s2: ClassVar[AccelUnit]
    cm_per_s2: ClassVar[AccelUnit]
    __members__: ClassVar[dict[str, AccelUnit]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class AxisymmetricBody:
    """A rigid body of revolution standing on the circular rim of its flat base (docs/theory.md §27); the c.g. on the axis, inertia diag(A, A, C) about it."""
    def __init__(self, mass: float, height: float, radius: float, inertia_diameter: float, inertia_axis: float, gravity: float = ...) -> None:
        """A body of revolution from its parameters.

        Parameters
        ----------
        mass : float
            M [kg].
        height : float
            h [m], the c.g. above the base centre.
        radius : float
            R [m], radius of the base rim.
        inertia_diameter : float
            A [kg m^2], about a diameter through the c.g.
        inertia_axis : float
            C [kg m^2], about the axis (C <= 2 A).
        gravity : float
            g [m/s^2].

        Raises
        ------
        InputError
            A value that is not positive and finite, or C > 2 A.
        """
    def __repr__(self) -> str: ...
    @property
    def alpha(self) -> float: ...
    @property
    def gravity(self) -> float: ...
    @property
    def height(self) -> float: ...
    @property
    def inertia_axis(self) -> float: ...
    @property
    def inertia_diameter(self) -> float: ...
    @property
    def mass(self) -> float: ...
    def planar_equivalent(self) -> BodyParameters:
        """The planar rigid body of the section through the axis (BodyParameters): M, I_cg = A, h, b1 = b2 = R, what the planar engine runs."""
    @property
    def planar_landing_ratio(self) -> float: ...
    @property
    def radius(self) -> float: ...
    @property
    def rocking_frequency(self) -> float: ...

class Body:
    """A validated body; bad parameters raise InputError."""
    def __init__(self, params: BodyParameters) -> None: ...
    def __repr__(self) -> str: ...
    @property
    def alpha1(self) -> float: ...
    @property
    def alpha2(self) -> float: ...
    @property
    def damping_matrix(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def damping_ratios(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def g(self) -> float: ...
    @property
    def modes(self) -> int: ...
    @property
    def mu_inverse(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def natural_frequencies(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def params(self) -> BodyParameters: ...
    @property
    def rocking_frequency(self) -> float: ...
    @property
    def static_deformation(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def stiffness(self) -> numpy.typing.NDArray[numpy.float64]: ...
    def tipping_angle(self, edge: int) -> float:
        """static overturning angle about edge 1 or 2 [rad], positive"""

class BodyKey:
    """One key of a body type."""
    def __repr__(self) -> str: ...
    @property
    def default(self) -> Optional[float]: ...
    @property
    def default_text(self) -> str: ...
    @property
    def doc(self) -> str: ...
    @property
    def name(self) -> str: ...
    @property
    def required(self) -> bool: ...
    @property
    def rule(self) -> BodyKeyRule: ...
    @property
    def unit(self) -> str: ...
    @property
    def value(self) -> BodyKeyValue: ...

class BodyKeyRule:
    finite: ClassVar[BodyKeyRule]
    positive: ClassVar[BodyKeyRule]
    nonnegative: ClassVar[BodyKeyRule]
    __members__: ClassVar[dict[str, BodyKeyRule]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class BodyKeyValue:
    number: ClassVar[BodyKeyValue]
    integer: ClassVar[BodyKeyValue]
    array: ClassVar[BodyKeyValue]
    matrix: ClassVar[BodyKeyValue]
    path: ClassVar[BodyKeyValue]
    __members__: ClassVar[dict[str, BodyKeyValue]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class BodyKind:
    """One body type of the case file."""
    def __repr__(self) -> str: ...
    @property
    def doc(self) -> str: ...
    @property
    def function(self) -> str: ...
    @property
    def keys(self) -> list[BodyKey]: ...
    @property
    def name(self) -> str: ...
    @property
    def numbers(self) -> bool: ...

class BodyParameters:
    """The paper's parameters of a deformable body on two tipping points (SI units; mu, kappa, ... dimensionless)."""
    def __init__(self) -> None: ...
    def __repr__(self) -> str: ...
    b1: float
    b2: float
    beta: numpy.typing.NDArray[numpy.float64]
    damping: Damping
    delta: numpy.typing.NDArray[numpy.float64]
    gamma: numpy.typing.NDArray[numpy.float64]
    gravity: float
    height: float
    kappa: numpy.typing.NDArray[numpy.float64]
    mass: float
    @property
    def modes(self) -> int: ...
    mu: numpy.typing.NDArray[numpy.float64]
    psi_x: numpy.typing.NDArray[numpy.float64]
    psi_y: numpy.typing.NDArray[numpy.float64]
    @staticmethod
    def rectangular_block(mass: float, half_width: float, half_height: float) -> BodyParameters: ...
    @staticmethod
    def rigid(mass: float, height: float, b1: float, b2: float, zeta2: float) -> BodyParameters: ...
    zeta2: float

class Case:
    """A case: everything a run needs (see load_case)."""
    def __init__(self) -> None: ...
    azimuth_deg: Optional[float]
    azimuth_step_deg: float
    body: BodyParameters
    @property
    def body3d(self) -> Optional[AxisymmetricBody]: ...
    body_type: str
    description: str
    excitation_scale: float
    @property
    def has_pair(self) -> bool: ...
    horizontal: ExcitationComponent
    horizontal2: ExcitationComponent
    initial: InitialState
    motion: GroundMotion
    name: str
    options: SimulationOptions
    output: OutputSettings
    restraints: list[Restraint]
    rigid: bool
    source: str
    stem: str
    @property
    def support(self) -> Optional[SupportParameters]: ...
    vertical: ExcitationComponent

class Component:
    horizontal: ClassVar[Component]
    vertical: ClassVar[Component]
    __members__: ClassVar[dict[str, Component]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class ContactForceLaw:
    linear: ClassVar[ContactForceLaw]
    hunt_crossley: ClassVar[ContactForceLaw]
    __members__: ClassVar[dict[str, ContactForceLaw]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class ContactIntegrator:
    auto: ClassVar[ContactIntegrator]
    explicit: ClassVar[ContactIntegrator]
    implicit: ClassVar[ContactIntegrator]
    __members__: ClassVar[dict[str, ContactIntegrator]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class ContactModel:
    impulsive: ClassVar[ContactModel]
    compliant: ClassVar[ContactModel]
    __members__: ClassVar[dict[str, ContactModel]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class CsvTable:
    @property
    def columns(self) -> list[str]: ...
    @property
    def rows(self) -> list[list[str]]: ...
    @property
    def source(self) -> str: ...

class DamageState:
    """A damage state: an outcome and its level."""
    def __init__(self, outcome: FragilityOutcome, level: float = ..., label: str = ...) -> None: ...
    def __repr__(self) -> str: ...
    @property
    def label(self) -> str: ...
    @property
    def level(self) -> float: ...
    @property
    def outcome(self) -> FragilityOutcome: ...

class Damping:
    """Material damping of the deformation modes."""
    def __init__(self) -> None: ...
    kind: DampingKind
    modal_ratios: numpy.typing.NDArray[numpy.float64]
    rayleigh_mass: float
    rayleigh_stiffness: float

class DampingKind:
    none: ClassVar[DampingKind]
    rayleigh: ClassVar[DampingKind]
    modal: ClassVar[DampingKind]
    __members__: ClassVar[dict[str, DampingKind]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class Distribution:
    uniform: ClassVar[Distribution]
    normal: ClassVar[Distribution]
    lognormal: ClassVar[Distribution]
    __members__: ClassVar[dict[str, Distribution]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class EnergyBalance:
    def __repr__(self, *args: Any, **kwargs: Any) -> Any: ...
    @property
    def chatter_loss(self) -> float: ...
    @property
    def damping_loss(self) -> float: ...
    @property
    def friction_loss(self) -> float: ...
    @property
    def impact_loss(self) -> float: ...
    @property
    def input_work(self) -> float: ...
    @property
    def kinetic_change(self) -> float: ...
    @property
    def potential_change(self) -> float: ...
    @property
    def residual(self) -> float: ...
    @property
    def scale(self) -> float: ...

class Event:
    """Something that happened; fields not meaningful are zero."""
    def __repr__(self) -> str: ...
    @property
    def edge(self) -> int: ...
    @property
    def energy_loss(self) -> float: ...
    @property
    def force_estimate(self) -> float: ...
    @property
    def friction_demand(self) -> float: ...
    @property
    def impulse_x(self) -> float: ...
    @property
    def impulse_y(self) -> float: ...
    @property
    def kind(self) -> EventKind: ...
    @property
    def offset(self) -> float: ...
    @property
    def theta(self) -> float: ...
    @property
    def theta_dot_after(self) -> float: ...
    @property
    def theta_dot_before(self) -> float: ...
    @property
    def time(self) -> float: ...

class EventKind:
    uplift: ClassVar[EventKind]
    impact: ClassVar[EventKind]
    rocking_ended: ClassVar[EventKind]
    chatter_cutoff: ClassVar[EventKind]
    peak: ClassVar[EventKind]
    overturn: ClassVar[EventKind]
    lift_off: ClassVar[EventKind]
    landing: ClassVar[EventKind]
    tensile_landing: ClassVar[EventKind]
    pivot_tension: ClassVar[EventKind]
    friction_exceeded: ClassVar[EventKind]
    impact_gained_energy: ClassVar[EventKind]
    stopped: ClassVar[EventKind]
    energy_unbalanced: ClassVar[EventKind]
    slip_start: ClassVar[EventKind]
    stick: ClassVar[EventKind]
    slip_reversal: ClassVar[EventKind]
    impact_law_fallback: ClassVar[EventKind]
    __members__: ClassVar[dict[str, EventKind]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class ExcitationComponent:
    """One component of the excitation, as a case describes it."""
    def __init__(self) -> None: ...
    amplitude: float
    file: str
    format: str
    scale: float
    type: str
    units: str

class Extremes:
    def __repr__(self, *args: Any, **kwargs: Any) -> Any: ...
    @property
    def chatter_cutoffs(self) -> int: ...
    @property
    def first_uplift_edge(self) -> int: ...
    @property
    def first_uplift_time(self) -> float: ...
    @property
    def flight_time(self) -> float: ...
    @property
    def impact_law_fallbacks(self) -> int: ...
    @property
    def impacts(self) -> int: ...
    @property
    def lift_offs(self) -> int: ...
    @property
    def max_abs_q(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def max_base_shear(self) -> float: ...
    @property
    def max_contact_force(self) -> float: ...
    @property
    def max_flight_height(self) -> float: ...
    @property
    def max_friction_demand(self) -> float: ...
    @property
    def max_impact_energy_loss(self) -> float: ...
    @property
    def max_impact_force(self) -> float: ...
    @property
    def max_impulse(self) -> float: ...
    @property
    def max_offset(self) -> float: ...
    @property
    def max_overturning_moment(self) -> float: ...
    @property
    def max_pivot_pull(self) -> float: ...
    @property
    def max_tensile_impulse(self) -> float: ...
    @property
    def max_theta_edge1(self) -> float: ...
    @property
    def max_theta_edge2(self) -> float: ...
    @property
    def max_uplift(self) -> float: ...
    @property
    def overturn_edge(self) -> int: ...
    @property
    def overturn_time(self) -> float: ...
    @property
    def sliding_time(self) -> float: ...
    @property
    def slips(self) -> int: ...
    @property
    def tensile_landings(self) -> int: ...
    @property
    def tension_episodes(self) -> int: ...
    @property
    def tension_time(self) -> float: ...

class FragilityAnalysis:
    runs: ClassVar[FragilityAnalysis]
    msa: ClassVar[FragilityAnalysis]
    ida: ClassVar[FragilityAnalysis]
    __members__: ClassVar[dict[str, FragilityAnalysis]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class FragilityData:
    def __repr__(self, *args: Any, **kwargs: Any) -> Any: ...
    @property
    def body(self) -> str: ...
    @property
    def excluded(self) -> int: ...
    @property
    def failed(self) -> list[int]: ...
    @property
    def im(self) -> list[float]: ...
    @property
    def im_name(self) -> str: ...
    @property
    def im_unit(self) -> str: ...
    @property
    def record(self) -> list[str]: ...

class FragilityFit:
    """Lognormal fragility P = Phi(ln(x/theta)/beta)."""
    def __repr__(self) -> str: ...
    @property
    def beta(self) -> float: ...
    @property
    def beta_lower(self) -> float: ...
    @property
    def beta_upper(self) -> float: ...
    @property
    def confidence(self) -> float: ...
    @property
    def cov_ab(self) -> tuple: ...
    @property
    def cov_ln_theta_beta(self) -> float: ...
    @property
    def failures(self) -> int: ...
    @property
    def iterations(self) -> int: ...
    @property
    def log_likelihood(self) -> float: ...
    @property
    def samples(self) -> int: ...
    @property
    def se_beta(self) -> float: ...
    @property
    def se_ln_theta(self) -> float: ...
    @property
    def theta(self) -> float: ...
    @property
    def theta_lower(self) -> float: ...
    @property
    def theta_upper(self) -> float: ...

class FragilityMeasure:
    """An intensity measure of a fit: kind, sweep column, unit."""
    @property
    def column(self) -> str: ...
    @property
    def kind(self) -> FragilityMeasureKind: ...
    @property
    def name(self) -> str: ...
    @property
    def unit(self) -> str: ...

class FragilityMeasureKind:
    pga: ClassVar[FragilityMeasureKind]
    pga_g: ClassVar[FragilityMeasureKind]
    pgv: ClassVar[FragilityMeasureKind]
    scale: ClassVar[FragilityMeasureKind]
    requested_level: ClassVar[FragilityMeasureKind]
    intensity: ClassVar[FragilityMeasureKind]
    __members__: ClassVar[dict[str, FragilityMeasureKind]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class FragilityOrderNote:
    """Two damage states of a body out of order."""
    @property
    def body(self) -> int: ...
    @property
    def crossing(self) -> float: ...
    @property
    def latter_likelier_above(self) -> bool: ...
    @property
    def medians_cross(self) -> bool: ...
    @property
    def state(self) -> int: ...

class FragilityOutcome:
    overturned: ClassVar[FragilityOutcome]
    uplift: ClassVar[FragilityOutcome]
    theta: ClassVar[FragilityOutcome]
    energy: ClassVar[FragilityOutcome]
    offset: ClassVar[FragilityOutcome]
    residual_offset: ClassVar[FragilityOutcome]
    __members__: ClassVar[dict[str, FragilityOutcome]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class FragilityQuery:
    def __init__(self) -> None: ...
    body: str
    im: str
    level: float
    outcome: str
    worst_azimuth: bool

class FragilitySession:
    """The fits of every damage state and body of a sweep CSV,
    as ``flexrock fragility`` makes them (the same checks, observations, fits and fit CSV).
    """
    def __init__(self, path: str, im: str = ..., im_given: bool = ..., states: list[DamageState] = ..., outcome: FragilityOutcome = ..., level: float = ..., analysis: FragilityAnalysis = ..., body: str = ..., confidence: float = ..., worst_azimuth: bool = ...) -> None: ...
    @property
    def bodies(self) -> int: ...
    def data(self, state: int, body: int) -> FragilityData: ...
    def fit(self, state: int, body: int) -> FragilityFit:
        """The fit of a state and body; raises InputError with the reason if it has none."""
    def fit_csv(self) -> str:
        """The fit CSV's text, as ``flexrock fragility -o`` writes it."""
    def fitted(self, state: int, body: int) -> bool:
        """Whether a state and body could be fitted."""
    @property
    def measure(self) -> FragilityMeasure: ...
    def not_fitted(self) -> list[tuple[int, int, str]]:
        """The states and bodies that could not be fitted: (state, body, reason) each."""
    def order_notes(self) -> list[FragilityOrderNote]: ...
    @property
    def several(self) -> bool: ...
    @property
    def states(self) -> list[DamageState]: ...
    def stripes(self, state: int, body: int) -> list[tuple[float, int, int]]:
        """The stripes of a body's observations: (IM, runs, failures) per level."""
    @property
    def unit(self) -> str: ...

class GridUnits:
    """The units a physical spectrum grid is given in: its cells and boundary keep them and get columns in them (a_p_g, f_p_hz)."""
    @overload
    def __init__(self) -> None: ...
    @overload
    def __init__(self, amplitude: str, amplitude_si: float, frequency: str, frequency_si: float) -> None: ...
    def __repr__(self) -> str: ...
    amplitude: str
    amplitude_si: float
    frequency: str
    frequency_si: float

class GroundMotion:
    """Base accelerations [m/s^2]: sampled (linear between samples) or analytic."""
    def __repr__(self) -> str: ...
    def at(self, t: float) -> tuple:
        """(x, y) base acceleration at time t [m/s^2]"""
    @property
    def duration(self) -> float: ...
    @property
    def has_vertical(self) -> bool: ...
    @property
    def horizontal(self) -> list[float]: ...
    @property
    def is_sampled(self) -> bool: ...
    @staticmethod
    def none(duration: float) -> GroundMotion: ...
    @staticmethod
    def sampled(time: list[float], horizontal: list[float], vertical: list[float] = ...) -> GroundMotion: ...
    @property
    def samples(self) -> int: ...
    def scaled(self, factor: float) -> GroundMotion:
        """The motion with every acceleration times `factor` [-]."""
    @property
    def times(self) -> list[float]: ...
    @staticmethod
    def uniform(dt: float, horizontal: list[float], vertical: list[float] = ..., start: float = ...) -> GroundMotion: ...
    @property
    def vertical(self) -> list[float]: ...

class History:
    """Time history at the output times; each a numpy copy."""
    def __len__(self) -> int: ...
    @property
    def base_acc_x(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def base_acc_y(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def damping_loss(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def friction_demand(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def impact_loss(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def input_work(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def kinetic(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def lift(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def modes(self) -> int: ...
    @property
    def offset(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def phase(self) -> numpy.typing.NDArray[numpy.int32]: ...
    @property
    def potential(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def q(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def q_dot(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def reaction_x(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def reaction_y(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def resultant(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def theta(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def theta_dot(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def time(self) -> numpy.typing.NDArray[numpy.float64]: ...

class ImpactLaw:
    paper: ClassVar[ImpactLaw]
    rigid_body: ClassVar[ImpactLaw]
    restitution: ClassVar[ImpactLaw]
    __members__: ClassVar[dict[str, ImpactLaw]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class InitialState:
    """Where the body starts."""
    def __init__(self, theta: float = ..., theta_dot: float = ..., q: numpy.typing.NDArray[numpy.float64] = ..., q_dot: numpy.typing.NDArray[numpy.float64] = ...) -> None: ...
    q: numpy.typing.NDArray[numpy.float64]
    q_dot: numpy.typing.NDArray[numpy.float64]
    theta: float
    theta_dot: float

class Intensity:
    @property
    def measures(self) -> list[float]: ...
    @property
    def pga(self) -> float: ...
    @property
    def pgv(self) -> float: ...

class LumpedModel:
    """A lumped-mass modal model (pinned-base modes) from a finite-element program."""
    def __init__(self) -> None: ...
    damping: Damping
    frequencies: numpy.typing.NDArray[numpy.float64]
    gravity: float
    nodes: list[LumpedNode]
    phi_x: numpy.typing.NDArray[numpy.float64]
    phi_y: numpy.typing.NDArray[numpy.float64]
    stiffness: numpy.typing.NDArray[numpy.float64]
    tip1_x: float
    tip2_x: float

class LumpedNode:
    def __init__(self, x: float, y: float, mass: float, rotary_inertia: float = ...) -> None: ...
    mass: float
    rotary_inertia: float
    x: float
    y: float

class MeasureRequest:
    def __init__(self, name: str, period: float = ..., zeta: float = ..., *, unit: str = ...) -> None: ...
    name: str
    period: float
    unit: str
    zeta: float

class Outcome:
    no_uplift: ClassVar[Outcome]
    rocking: ClassVar[Outcome]
    overturned_after_impacts: ClassVar[Outcome]
    overturned_without_impact: ClassVar[Outcome]
    stopped: ClassVar[Outcome]
    __members__: ClassVar[dict[str, Outcome]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class OutputPaths:
    def __init__(self) -> None: ...
    events: str
    summary: str
    time_history: str

class OutputSettings:
    def __init__(self) -> None: ...
    dt: float
    events: str
    summary: str
    time_history: str

class OverturnBoundary:
    class Kind:
        found: ClassVar[OverturnBoundary.Kind]
        below_grid: ClassVar[OverturnBoundary.Kind]
        none: ClassVar[OverturnBoundary.Kind]
        __members__: ClassVar[dict[str, OverturnBoundary.Kind]]
        def __init__(self, value: int) -> None: ...
        def __eq__(self, other: object) -> bool: ...
        def __hash__(self) -> int: ...
        def __index__(self) -> int: ...
        def __int__(self) -> int: ...
        @property
        def name(self) -> str: ...
        @property
        def value(self) -> int: ...
    @property
    def bisection_runs(self) -> int: ...
    @property
    def column(self) -> int: ...
    @property
    def computed(self) -> bool: ...
    @property
    def frequency(self) -> float: ...
    @property
    def kind(self) -> OverturnBoundary.Kind: ...
    @property
    def mode(self) -> Outcome: ...
    @property
    def overturning(self) -> float: ...
    @property
    def safe(self) -> float: ...

class OverturnCriterion:
    static_instability: ClassVar[OverturnCriterion]
    half_pi: ClassVar[OverturnCriterion]
    __members__: ClassVar[dict[str, OverturnCriterion]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class Phase:
    full_contact: ClassVar[Phase]
    rocking_edge1: ClassVar[Phase]
    rocking_edge2: ClassVar[Phase]
    flight: ClassVar[Phase]
    sliding_plus: ClassVar[Phase]
    sliding_minus: ClassVar[Phase]
    rocking_edge1_sliding_plus: ClassVar[Phase]
    rocking_edge1_sliding_minus: ClassVar[Phase]
    rocking_edge2_sliding_plus: ClassVar[Phase]
    rocking_edge2_sliding_minus: ClassVar[Phase]
    __members__: ClassVar[dict[str, Phase]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class PulseKey:
    """One key of a pulse type besides amplitude and frequency."""
    def __repr__(self) -> str: ...
    @property
    def argument(self) -> str: ...
    @property
    def default(self) -> Optional[float]: ...
    @property
    def default_text(self) -> str: ...
    @property
    def doc(self) -> str: ...
    @property
    def name(self) -> str: ...
    @property
    def required(self) -> bool: ...
    @property
    def rule(self) -> PulseKeyRule: ...
    @property
    def unit(self) -> str: ...

class PulseKeyRule:
    finite: ClassVar[PulseKeyRule]
    positive: ClassVar[PulseKeyRule]
    nonnegative: ClassVar[PulseKeyRule]
    count: ClassVar[PulseKeyRule]
    __members__: ClassVar[dict[str, PulseKeyRule]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class PulseKind:
    """One synthetic motion type of the case file."""
    def __repr__(self) -> str: ...
    @property
    def doc(self) -> str: ...
    @property
    def ends(self) -> bool: ...
    @property
    def frequency(self) -> bool: ...
    @property
    def function(self) -> str: ...
    @property
    def keys(self) -> list[PulseKey]: ...
    @property
    def name(self) -> str: ...
    @property
    def spectrum(self) -> bool: ...

class QualifySession:
    """A qualification from its file to
    its report (flexrock qualify): the design-level runs and the IDA as journaled study sessions in
    `work_dir`, resumed from there after an interruption.
    """
    def __init__(self, path: str, work_dir: str) -> None: ...
    @property
    def design_runs(self) -> int: ...
    def finish(self) -> tuple:
        """The report: (JSON text, pelicun demand CSV text, passes)."""
    @property
    def ida_sessions(self) -> int: ...
    @property
    def resumed(self) -> int: ...
    def run(self, threads: int = ...) -> None:
        """Runs what is left (the GIL is released); Ctrl-C stops it between runs and raises
        KeyboardInterrupt, every finished run journaled.
        """

class Record:
    """An acceleration record, values in the file's units."""
    def __repr__(self) -> str: ...
    @property
    def dt(self) -> float: ...
    @property
    def duration(self) -> float: ...
    @property
    def header(self) -> list[str]: ...
    @property
    def npts(self) -> int: ...
    @property
    def source(self) -> str: ...
    @property
    def time(self) -> numpy.typing.NDArray[numpy.float64]: ...
    def to_motion(self, scale: float = ...) -> GroundMotion:
        """The record as a horizontal ground motion [m/s^2] times `scale`."""
    def to_si(self, scale: float = ...) -> list[float]: ...
    @property
    def units(self) -> AccelUnit: ...
    @property
    def values(self) -> numpy.typing.NDArray[numpy.float64]: ...

class RecordFormat:
    """A record format of the table of formats."""
    def __repr__(self) -> str: ...
    @property
    def doc(self) -> str: ...
    @property
    def name(self) -> str: ...
    @property
    def needs_dt(self) -> bool: ...
    @property
    def needs_units(self) -> bool: ...
    @property
    def publisher(self) -> str: ...
    @property
    def suffixes(self) -> list[str]: ...

class RecordSpectrumSpec:
    """One record x scale factors."""
    def __init__(self) -> None: ...
    bisect: bool
    bisection_tolerance: float
    free_periods: float
    motion: GroundMotion
    scales: list[float]
    solver: SimulationOptions

class Regime:
    none: ClassVar[Regime]
    sliding: ClassVar[Regime]
    rocking: ClassVar[Regime]
    sliding_rocking: ClassVar[Regime]
    __members__: ClassVar[dict[str, Regime]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class RestrainedResult:
    """A restrained run: the body's result and the restraints'."""
    @property
    def elongation(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def energy(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def events(self) -> list[RestraintEvent]: ...
    @property
    def force(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def fracture_work(self) -> float: ...
    @property
    def plastic_work(self) -> float: ...
    @property
    def restraints(self) -> list[RestraintSummary]: ...
    @property
    def result(self) -> SimulationResult: ...
    @property
    def stored_energy_change(self) -> float: ...

class Restraint:
    """A tie from the floor point (floor_x, floor_y) to the body point (body_x, body_y) [m]: stiffness [N/m], prestress [N], slack [m], yield_force [N], fracture_elongation [m] (docs/theory.md §26)."""
    def __init__(self, *, kind: RestraintKind = ..., body_x: float = ..., body_y: float = ..., floor_x: float = ..., floor_y: float = ..., stiffness: float = ..., prestress: float = ..., slack: float = ..., yield_force: float = ..., fracture_elongation: float = ...) -> None: ...
    body_x: float
    body_y: float
    floor_x: float
    floor_y: float
    fracture_elongation: float
    kind: RestraintKind
    prestress: float
    slack: float
    stiffness: float
    yield_force: float

class RestraintEvent:
    """A restraint's yield, unloading or fracture."""
    @property
    def elongation(self) -> float: ...
    @property
    def energy(self) -> float: ...
    @property
    def force(self) -> float: ...
    @property
    def kind(self) -> RestraintEventKind: ...
    @property
    def plastic_elongation(self) -> float: ...
    @property
    def restraint(self) -> int: ...
    @property
    def time(self) -> float: ...

class RestraintEventKind:
    yield_: ClassVar[RestraintEventKind]
    unload: ClassVar[RestraintEventKind]
    fracture: ClassVar[RestraintEventKind]
    __members__: ClassVar[dict[str, RestraintEventKind]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class RestraintKind:
    tendon: ClassVar[RestraintKind]
    anchor: ClassVar[RestraintKind]
    __members__: ClassVar[dict[str, RestraintKind]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class RestraintSummary:
    """What one restraint did over a run."""
    @property
    def final_force(self) -> float: ...
    @property
    def fracture_time(self) -> float: ...
    @property
    def fracture_work(self) -> float: ...
    @property
    def fractured(self) -> bool: ...
    @property
    def max_elongation(self) -> float: ...
    @property
    def max_force(self) -> float: ...
    @property
    def plastic_elongation(self) -> float: ...
    @property
    def plastic_work(self) -> float: ...
    @property
    def yield_time(self) -> float: ...
    @property
    def yielded(self) -> bool: ...

class RimEvent:
    """One event of a 3D run."""
    def __repr__(self) -> str: ...
    @property
    def azimuth(self) -> float: ...
    @property
    def energy_loss(self) -> float: ...
    @property
    def kind(self) -> RimEventKind: ...
    @property
    def rate_after(self) -> float: ...
    @property
    def rate_before(self) -> float: ...
    @property
    def tilt(self) -> float: ...
    @property
    def time(self) -> float: ...
    @property
    def value(self) -> float: ...

class RimEventKind:
    uplift: ClassVar[RimEventKind]
    landing: ClassVar[RimEventKind]
    rest: ClassVar[RimEventKind]
    overturn: ClassVar[RimEventKind]
    lift_off: ClassVar[RimEventKind]
    rim_slip: ClassVar[RimEventKind]
    full_sliding: ClassVar[RimEventKind]
    stopped: ClassVar[RimEventKind]
    __members__: ClassVar[dict[str, RimEventKind]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class RimHistory:
    """A 3D run's time history at the output times; each a numpy copy."""
    def __len__(self) -> int: ...
    @property
    def azimuth(self) -> numpy.typing.NDArray[numpy.float64]: ...
    def columns(self) -> dict:
        """The time-history CSV's columns (name with unit to numpy array), as `flexrock run` writes them."""
    @property
    def contact_angle(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def friction_demand(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def impact_loss(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def input_work(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def kinetic(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def mode(self) -> numpy.typing.NDArray[numpy.int32]: ...
    @property
    def potential(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def reaction_x(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def reaction_y(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def reaction_z(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def tilt(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def time(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def x(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def y(self) -> numpy.typing.NDArray[numpy.float64]: ...

class RimInitialState:
    """Where a body of revolution starts: upright at rest by default; with a tilt or rates, rolling on the rim point toward `azimuth_deg`."""
    def __init__(self) -> None: ...
    azimuth_deg: float
    precession: float
    spin: float
    tilt: float
    tilt_rate: float

class RimMode:
    full_contact: ClassVar[RimMode]
    rolling: ClassVar[RimMode]
    pivoting: ClassVar[RimMode]
    __members__: ClassVar[dict[str, RimMode]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class RimResult:
    """A 3D run of a body of revolution: outcome, extremes, events, energy."""
    def __repr__(self) -> str: ...
    @property
    def closest_pass(self) -> object: ...
    @property
    def energy(self) -> EnergyBalance: ...
    @property
    def events(self) -> list[RimEvent]: ...
    @property
    def final_mode(self) -> RimMode: ...
    @property
    def final_tilt(self) -> float: ...
    @property
    def history(self) -> RimHistory: ...
    @property
    def landings(self) -> int: ...
    @property
    def max_friction_demand(self) -> float: ...
    @property
    def max_offset(self) -> float: ...
    @property
    def max_tilt(self) -> float: ...
    @property
    def max_tilt_azimuth(self) -> float: ...
    @property
    def message(self) -> str: ...
    @property
    def min_normal_force(self) -> object: ...
    @property
    def rhs_evaluations(self) -> int: ...
    @property
    def status(self) -> RimStatus: ...
    @property
    def steps(self) -> int: ...
    @property
    def t_end(self) -> float: ...
    @property
    def uplifts(self) -> int: ...

class RimStatus:
    completed: ClassVar[RimStatus]
    overturned: ClassVar[RimStatus]
    unmodelled: ClassVar[RimStatus]
    stopped: ClassVar[RimStatus]
    __members__: ClassVar[dict[str, RimStatus]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class RunSummary:
    """What a study keeps of one simulation."""
    @property
    def energy_lost(self) -> float: ...
    @property
    def final_offset(self) -> float: ...
    @property
    def first_uplift_time(self) -> float: ...
    @property
    def impacts(self) -> int: ...
    @property
    def max_friction_demand(self) -> float: ...
    @property
    def max_impulse(self) -> float: ...
    @property
    def max_offset(self) -> float: ...
    @property
    def max_pivot_pull(self) -> float: ...
    @property
    def max_tensile_impulse(self) -> float: ...
    @property
    def max_theta(self) -> float: ...
    @property
    def max_theta_over_alpha(self) -> float: ...
    @property
    def max_uplift(self) -> float: ...
    @property
    def outcome(self) -> Outcome: ...
    @property
    def overturn_edge(self) -> int: ...
    @property
    def overturn_time(self) -> float: ...
    @property
    def regime(self) -> Regime: ...
    @property
    def sliding_time(self) -> float: ...
    @property
    def slips(self) -> int: ...
    @property
    def status(self) -> Status: ...
    @property
    def t_end(self) -> float: ...
    @property
    def tensile_landings(self) -> int: ...
    @property
    def tension_episodes(self) -> int: ...
    @property
    def tension_time(self) -> float: ...

class SampleDesign:
    """The samples of a study: each a pure function of the seed and its index."""
    def __init__(self, uncertainty: Uncertainty, samples: int) -> None: ...
    @property
    def dimensions(self) -> int: ...
    @property
    def samples(self) -> int: ...
    def uniform(self, sample: int, parameter: int) -> float:
        """The uniform in (0, 1) of a sample and parameter (Latin hypercube: inside its stratum)."""
    def values(self, sample: int) -> list[float]:
        """The values of a sample, one per parameter."""

class Sampling:
    """How a study samples its uncertain parameters."""
    def __init__(self, seed: int = ..., method: SamplingMethod = ..., scope: SamplingScope = ...) -> None: ...
    method: SamplingMethod
    scope: SamplingScope
    seed: int

class SamplingMethod:
    random: ClassVar[SamplingMethod]
    lhs: ClassVar[SamplingMethod]
    __members__: ClassVar[dict[str, SamplingMethod]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class SamplingScope:
    run: ClassVar[SamplingScope]
    record: ClassVar[SamplingScope]
    __members__: ClassVar[dict[str, SamplingScope]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class ScaleKind:
    factor: ClassVar[ScaleKind]
    target_pga: ClassVar[ScaleKind]
    target_measure: ClassVar[ScaleKind]
    __members__: ClassVar[dict[str, ScaleKind]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class SimulationMethods:
    """How the engine steps, for tests and comparisons only: each switch picks between two methods that give the same answer within the tolerances, at different cost."""
    def __init__(self) -> None: ...
    def __repr__(self, *args: Any, **kwargs: Any) -> Any: ...
    closed_form_free_rocking: bool
    contact_integrator: ContactIntegrator
    exact_full_contact: bool
    full_contact_walk: bool
    high_order_rocking: bool
    rocking_integrator: ContactIntegrator
    series_rocking: bool
    stiff_switch_scale: float

class SimulationOptions:
    """Solver options (SI units)."""
    def __init__(self) -> None: ...
    def __repr__(self, *args: Any, **kwargs: Any) -> Any: ...
    atol: float
    chatter_ratio: float
    contact_damping_ratio: float
    contact_exponent: float
    contact_force_law: ContactForceLaw
    contact_model: ContactModel
    contact_restitution: float
    contact_stiffness: float
    contact_tangential_stiffness: float
    event_samples: int
    friction_coefficient: float
    impact_duration: float
    impact_law: ImpactLaw
    kinetic_friction_coefficient: float
    max_impacts: int
    max_step: float
    max_steps: int
    methods: SimulationMethods
    output_dt: float
    overturn: OverturnCriterion
    restitution_factor: float
    restitution_ratio_edge1: float
    restitution_ratio_edge2: float
    rtol: float
    t_end: float

class SimulationResult:
    @property
    def chatter_cut_off(self) -> bool: ...
    @property
    def energy(self) -> EnergyBalance: ...
    @property
    def energy_unbalanced(self) -> bool: ...
    @property
    def events(self) -> list[Event]: ...
    @property
    def extremes(self) -> Extremes: ...
    @property
    def final_offset(self) -> float: ...
    @property
    def final_phase(self) -> Phase: ...
    @property
    def final_q(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def final_q_dot(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def final_theta(self) -> float: ...
    @property
    def final_theta_dot(self) -> float: ...
    @property
    def friction_exceeded(self) -> bool: ...
    @property
    def history(self) -> History: ...
    @property
    def impact_gained_energy(self) -> bool: ...
    @property
    def message(self) -> str: ...
    @property
    def pivot_tension(self) -> bool: ...
    @property
    def rejected_steps(self) -> int: ...
    @property
    def rhs_evaluations(self) -> int: ...
    @property
    def status(self) -> Status: ...
    @property
    def steps(self) -> int: ...
    @property
    def t_end(self) -> float: ...

class SpectrumCell:
    @property
    def amplitude(self) -> float: ...
    @property
    def amplitude_si(self) -> float: ...
    @property
    def column(self) -> int: ...
    @property
    def computed(self) -> bool: ...
    @property
    def frequency(self) -> float: ...
    @property
    def omega_si(self) -> float: ...
    @property
    def row(self) -> int: ...
    @property
    def run(self) -> RunSummary: ...

class SpectrumFile:
    """A spectrum spec file, loaded and checked."""
    @property
    def body(self) -> BodyParameters: ...
    @property
    def body_source(self) -> str: ...
    @property
    def is_record(self) -> bool: ...
    @property
    def name(self) -> str: ...
    @property
    def pulse(self) -> SpectrumSpec: ...
    @property
    def record(self) -> RecordSpectrumSpec: ...
    @property
    def record_name(self) -> str: ...
    @property
    def source(self) -> str: ...

class SpectrumResult:
    """Every cell of a spectrum and the minimum overturning of each column."""
    def __repr__(self) -> str: ...
    @property
    def alpha(self) -> float: ...
    @property
    def boundary(self) -> list[OverturnBoundary]: ...
    @property
    def cells(self) -> list[SpectrumCell]: ...
    @property
    def p(self) -> float: ...
    @property
    def sliding(self) -> bool: ...
    @property
    def tan_alpha(self) -> float: ...
    @property
    def units(self) -> GridUnits: ...

class SpectrumSession:
    """A spectrum from its spec file to its CSVs.

    Opening it checks every run and opens (or resumes) the journal ``output + ".partial"``, the one
    ``flexrock spectrum`` keeps: a spectrum the command line started and that was interrupted goes on
    here, and the CSVs have the same bytes as an uninterrupted run.
    """
    def __init__(self, file: SpectrumFile, output: str, boundary_output: str, bisect: bool = ...) -> None: ...
    @property
    def bisect(self) -> bool: ...
    @property
    def cells(self) -> int: ...
    def finish(self) -> SpectrumResult:
        """Writes the CSVs from every cell and boundary and deletes the journal. Raises
        RuntimeError, the journal kept, when a cell or boundary is not finished (run() not called, or
        stopped): call run() first; and when called again (the session is over).

        Returns
        -------
        SpectrumResult
            Every cell and boundary, read back as data.
        """
    @property
    def grid(self) -> SpectrumResult: ...
    @property
    def journal_path(self) -> str: ...
    @property
    def resumed(self) -> int: ...
    def run(self, threads: int = ..., *, progress: object = ..., callback: Optional[object] = ...) -> None:
        """Runs the cells and bisections left, journaling each as it finishes (the GIL is
        released). Ctrl-C stops it between runs and raises KeyboardInterrupt; the journal keeps every
        finished cell and boundary and run() again, or a new session on the same file and outputs, goes
        on from there. Raises RuntimeError after finish().

        Parameters
        ----------
        threads : int
            0: every core.
        progress : bool
            A progress bar on stderr while it runs longer than a second (tqdm where it is installed,
            a plain line otherwise); False: none.
        callback : callable, optional
            Called as callback(done, total) (cells left at the start; a bisection's runs come on top) on the calling thread while the runs go (every 20 ms at
            most, when the count moved) and once at the end: for a notebook's own display. An
            exception it raises stops the runs between two, as Ctrl-C does, and is raised here.
        """
    @property
    def runs(self) -> int: ...

class SpectrumSpec:
    """A pulse spectrum: pulse x amplitude x frequency."""
    def __init__(self) -> None: ...
    amplitudes: list[float]
    bisect: bool
    bisection_tolerance: float
    free_periods: float
    frequencies: list[float]
    normalized: bool
    pulse: str
    solver: SimulationOptions
    units: GridUnits

class Status:
    completed: ClassVar[Status]
    overturned: ClassVar[Status]
    stopped: ClassVar[Status]
    __members__: ClassVar[dict[str, Status]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class SupportParameters:
    """The support under a rigid block: a mass on a horizontal spring and dashpot to the ground (docs/theory.md §24)."""
    def __init__(self) -> None: ...
    damping: float
    displacement: float
    @staticmethod
    def from_frequency(mass: float, body_mass: float, frequency_hz: float, damping_ratio: float) -> SupportParameters:
        """From the frequency [Hz] and damping ratio of the support with the body as a rigid mass of `body_mass` [kg] on it."""
    mass: float
    stiffness: float
    velocity: float

class SupportRunResult:
    """The block's result on the support and the support's own."""
    @property
    def body(self) -> SimulationResult: ...
    @property
    def max_support_displacement(self) -> float: ...
    @property
    def support_acceleration(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def support_displacement(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def support_force(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def support_velocity(self) -> numpy.typing.NDArray[numpy.float64]: ...

class SweepBody:
    def __init__(self, name: str, body: BodyParameters) -> None: ...
    body: BodyParameters
    friction_coefficient: Optional[float]
    kinetic_friction_coefficient: Optional[float]
    name: str

class SweepManifest:
    @property
    def hash(self) -> int: ...
    @property
    def source(self) -> str: ...
    @property
    def spec(self) -> SweepSpec: ...

class SweepRecord:
    def __init__(self, name: str, motion: GroundMotion) -> None: ...
    motion: GroundMotion
    name: str

class SweepRow:
    @property
    def body(self) -> int: ...
    @property
    def duration(self) -> float: ...
    @property
    def index(self) -> int: ...
    @property
    def measures(self) -> list[float]: ...
    @property
    def message(self) -> str: ...
    @property
    def pga(self) -> float: ...
    @property
    def pgv(self) -> float: ...
    @property
    def record(self) -> int: ...
    @property
    def run(self) -> RunSummary: ...
    @property
    def sampled(self) -> list[float]: ...
    @property
    def scale(self) -> float: ...
    @property
    def scale_index(self) -> int: ...

class SweepSession:
    """A sweep from its manifest to its CSV.

    Opening it checks every run and opens (or resumes) the journal ``output + ".partial"``, the one
    ``flexrock sweep`` keeps: a sweep the command line started and that was interrupted goes on here,
    and the CSV has the same bytes as an uninterrupted run.
    """
    def __init__(self, manifest: SweepManifest, output: str) -> None: ...
    def finish(self) -> list[SweepRow]:
        """Writes the CSV from every row and deletes the journal. Raises RuntimeError, the
        journal kept, when a run is not finished (run() not called, or stopped): call run() first; and
        when called again (the session is over).

        Returns
        -------
        list of SweepRow
            Every run's row, in index order.
        """
    @property
    def journal_path(self) -> str: ...
    @property
    def manifest(self) -> SweepManifest: ...
    @property
    def output(self) -> str: ...
    @property
    def remaining(self) -> int: ...
    @property
    def resumed(self) -> int: ...
    def run(self, threads: int = ..., *, progress: object = ..., callback: Optional[object] = ...) -> None:
        """Runs the runs left, journaling each as it finishes (the GIL is released).
        Ctrl-C stops it between runs and raises KeyboardInterrupt; the journal keeps every finished run
        and run() again, or a new session on the same manifest and output, goes on from there. Raises
        RuntimeError after finish().

        Parameters
        ----------
        threads : int
            0: every core.
        progress : bool
            A progress bar on stderr while it runs longer than a second (tqdm where it is installed,
            a plain line otherwise); False: none.
        callback : callable, optional
            Called as callback(done, total) (the runs left at the start) on the calling thread while the runs go (every 20 ms at
            most, when the count moved) and once at the end: for a notebook's own display. An
            exception it raises stops the runs between two, as Ctrl-C does, and is raised here.
        """
    @property
    def runs(self) -> int: ...

class SweepSpec:
    """Bodies x records x scale factors."""
    def __init__(self) -> None: ...
    bodies: list[SweepBody]
    free_periods: float
    level_units: str
    levels: list[float]
    measures: list[MeasureRequest]
    records: list[SweepRecord]
    scale_kind: ScaleKind
    scales: list[float]
    solver: SimulationOptions
    target: MeasureRequest
    uncertainty: Uncertainty

class UncertainKind:
    friction: ClassVar[UncertainKind]
    restitution_factor: ClassVar[UncertainKind]
    restitution_ratio: ClassVar[UncertainKind]
    size_scale: ClassVar[UncertainKind]
    base_width_scale: ClassVar[UncertainKind]
    cg_height_scale: ClassVar[UncertainKind]
    mass_scale: ClassVar[UncertainKind]
    frequency_scale: ClassVar[UncertainKind]
    damping_ratio: ClassVar[UncertainKind]
    __members__: ClassVar[dict[str, UncertainKind]]
    def __init__(self, value: int) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __index__(self) -> int: ...
    def __int__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class UncertainParameter:
    """A distribution of an uncertain parameter, as a manifest's [[uncertain]] table gives it."""
    def __init__(self, parameter: str, distribution: str, *, minimum: Optional[float] = ..., maximum: Optional[float] = ..., mean: Optional[float] = ..., standard_deviation: Optional[float] = ..., median: Optional[float] = ..., beta: Optional[float] = ..., lower: Optional[float] = ..., upper: Optional[float] = ...) -> None:
        """A distribution of a parameter, checked as the manifest's are.

        Parameters
        ----------
        parameter : str
            A name of ``uncertain_parameters()``: "friction", "size_scale", ...
        distribution : str
            "uniform" (``minimum``, ``maximum``), "normal" (``mean``, ``standard_deviation``) or
            "lognormal" (``median``, ``beta``: the standard deviation of ln x).
        lower, upper : float, optional
            Truncation of a normal or lognormal distribution.

        Raises
        ------
        ValueError
            A bad number, a key the distribution does not take, or values outside the parameter's
            domain (a normal friction without ``lower`` > 0).
        """
    @property
    def a(self) -> float: ...
    @property
    def b(self) -> float: ...
    @property
    def distribution(self) -> Distribution: ...
    @property
    def kind(self) -> UncertainKind: ...
    @property
    def lower(self) -> float: ...
    @property
    def upper(self) -> float: ...

class Uncertainty:
    """The uncertain parameters of a study (SweepSpec.uncertainty)."""
    def __init__(self, parameters: list[UncertainParameter] = ..., sampling: Sampling = ...) -> None: ...
    parameters: list[UncertainParameter]
    sampling: Sampling

def azimuth_motion(case: Case, azimuth_deg: float) -> GroundMotion:
    """The ground motion of a case with a record pair at one azimuth: H1 cos(beta) + H2
    sin(beta), beta [deg] from H1 toward H2, scaled and with the vertical as the case says.
    """

def body_kinds() -> list[BodyKind]:
    """Every body type, in the order of the docs.

    Returns
    -------
    list of BodyKind
    """

def boundary_arrays(result: SpectrumResult, normalized: bool = ..., g: float = ...) -> dict:
    """The boundary CSV's columns as numpy arrays of their types, from the result itself (no
    CSV text): int64, float64 (nan where the CSV is empty) and str objects.

    Parameters
    ----------
    result : SpectrumResult
    normalized : bool
        The grid's axes (``min_overturning`` in a_p/(g tan alpha), else in m/s^2).
    g : float
        [m/s^2]

    Returns
    -------
    dict of str to numpy.ndarray
    """

def boundary_columns(units: GridUnits = ...) -> list[str]:
    """Columns of the minimum-overturning CSV.

    Parameters
    ----------
    units : GridUnits
        As for :func:`spectrum_columns` (``min_overturning_g``, ``f_p_hz``).

    Returns
    -------
    list of str
    """

def boundary_csv(result: SpectrumResult, normalized: bool, g: float) -> str:
    """The minimum-overturning CSV text (one row per frequency column).

    Parameters
    ----------
    result : SpectrumResult
    normalized : bool
        Whether the spectrum's grid was normalised (the units of ``frequency``, ``min_overturning``).
    g : float
        [m/s^2]

    Returns
    -------
    str
    """

def capacity_intervals(im: list[float], failed: list[int], record: list[str]) -> tuple:
    """Each record's capacity interval (lower, upper] from an incremental dynamic analysis.

    Parameters
    ----------
    im, failed, record : lists
        One IM, outcome (0/1) and record name per run.

    Returns
    -------
    (list of float, list of float)
        lower (0: failed at its lowest run) and upper (inf: never failed, truncated at lower), one
        per record in order of first appearance.
    """

def combine(horizontal: Record, vertical: Optional[Record] = ..., scale: float = ...) -> GroundMotion:
    """A horizontal record and an optional vertical one as one ground motion.

    Parameters
    ----------
    horizontal : Record
    vertical : Record, optional
        Resampled onto the horizontal's times.
    scale : float
        [-] factor on both.

    Returns
    -------
    GroundMotion
        Accelerations in m/s^2.
    """

def compute_record_spectrum(body: Body, spec: RecordSpectrumSpec, threads: int = ..., *, progress: object = ..., callback: Optional[object] = ...) -> SpectrumResult:
    """One record times scale factors, and the minimum overturning scale.

    Parameters
    ----------
    body : Body
    spec : RecordSpectrumSpec
    threads : int
        0: every core.
    progress : bool
        A progress bar on stderr while it runs longer than a second (tqdm where it is installed,
        a plain line otherwise); False: none.
    callback : callable, optional
        Called as callback(done, total) on the calling thread while the runs go (every 20 ms at
        most, when the count moved) and once at the end: for a notebook's own display. An
        exception it raises stops the runs between two, as Ctrl-C does, and is raised here.

    Returns
    -------
    SpectrumResult
    """

def compute_spectrum(body: Body, spec: SpectrumSpec, threads: int = ..., *, progress: object = ..., callback: Optional[object] = ...) -> SpectrumResult:
    """Every cell of a pulse spectrum, then the minimum overturning amplitude of each column.

    Parameters
    ----------
    body : Body
    spec : SpectrumSpec
        Amplitudes and frequencies normalised (a_p/(g tan alpha), omega_p/p) or in m/s^2 and rad/s.
    threads : int
        0: every core. The GIL is released.
    progress : bool
        A progress bar on stderr while it runs longer than a second (tqdm where it is installed,
        a plain line otherwise); False: none.
    callback : callable, optional
        Called as callback(done, total) on the calling thread while the cells go (every 20 ms at
        most, when the count moved) and once at the end: for a notebook's own display. An
        exception it raises stops the runs between two, as Ctrl-C does, and is raised here.

    Returns
    -------
    SpectrumResult
    """

def critical_stiffness(body: Body, restraints: list[Restraint], which: int, edge: int) -> float:
    """The stiffness [N/m] of restraint `which` at which the post-uplift branch stops softening."""

def crossing_intensity(a: FragilityFit, b: FragilityFit) -> float:
    """The IM at which two fitted fragility curves cross (nan for equal betas).

    Parameters
    ----------
    a, b : FragilityFit

    Returns
    -------
    float
    """

def cycloidal_c_phase(n: int) -> float:
    """The phase phi_n [rad] of the type-C_n cycloidal pulse.

    Parameters
    ----------
    n : int
        [-] the pulse's index, >= 1.

    Returns
    -------
    float
        [rad]
    """

def cycloidal_pulse_a(a_p: float, omega_p: float, duration: float, component: Component = ...) -> GroundMotion:
    """Makris & Roussos cycloidal pulse type A (= one-sine).

    Parameters
    ----------
    a_p : float
        [m/s^2] peak acceleration (negative: reversed).
    omega_p : float
        [rad/s] circular frequency of the pulse.
    duration : float
        [s] length of the motion (zero after the pulse: free vibration).
    component : Component
        horizontal (default) or vertical.

    Returns
    -------
    GroundMotion
        Analytic. The package's ``flexrock.cycloidal_pulse_a`` also takes the case file's keys
        (``amplitude=``, ``units=``, ``frequency_hz=`` or ``period=``).
    """

def cycloidal_pulse_b(a_p: float, omega_p: float, duration: float, component: Component = ...) -> GroundMotion:
    """Makris & Roussos cycloidal pulse type B: a_p cos(omega_p t) for one period.

    Parameters
    ----------
    a_p : float
        [m/s^2] peak acceleration (negative: reversed).
    omega_p : float
        [rad/s] circular frequency of the pulse.
    duration : float
        [s] length of the motion (zero after the pulse: free vibration).
    component : Component
        horizontal (default) or vertical.

    Returns
    -------
    GroundMotion
        Analytic. The package's ``flexrock.cycloidal_pulse_b`` also takes the case file's keys
        (``amplitude=``, ``units=``, ``frequency_hz=`` or ``period=``).
    """

def cycloidal_pulse_c(a_p: float, omega_p: float, duration: float, n: int = ..., component: Component = ...) -> GroundMotion:
    """Makris & Roussos cycloidal pulse type C_n: a_p cos(omega_p t + phi_n).

    Parameters
    ----------
    a_p : float
        [m/s^2] peak acceleration.
    omega_p : float
        [rad/s] circular frequency.
    duration : float
        [s] length of the motion.
    n : int
        [-] type index, >= 1.
    component : Component

    Returns
    -------
    GroundMotion
    """

def damage_state(text: str) -> DamageState:
    """A damage state as ``flexrock fragility --state`` reads it.

    Parameters
    ----------
    text : str
        overturned, uplift, theta:X, energy:X, offset:X or residual_offset:X (X > 0).

    Returns
    -------
    DamageState
    """

def event_columns() -> list[str]:
    """Column names of the event log.

    Returns
    -------
    list of str
        time_s, event, edge, theta_rad, theta_dot_before_rad_per_s, theta_dot_after_rad_per_s,
        energy_loss_J, impulse_x_N_s, impulse_y_N_s, friction_demand.
    """

def event_values(result: SimulationResult) -> list:
    """The event log as columns, in the order of event_columns().

    Parameters
    ----------
    result : SimulationResult

    Returns
    -------
    list
        One column per entry, one element per event: a float array, or a list of str for the
        ``event`` column (the kind's name). The values ``write_events`` prints.
    """

def events_csv(result: SimulationResult) -> str:
    """The event-log CSV text ``flexrock run`` writes.

    Parameters
    ----------
    result : SimulationResult

    Returns
    -------
    str
    """

def fit_capacity_intervals(lower: list[float], upper: list[float], confidence: float = ...) -> FragilityFit:
    """Lognormal fit of capacities known to lie in (lower, upper] (upper inf: truncated;
    lower == upper: exact), by maximum likelihood, as ``flexrock fragility --analysis ida`` fits it.

    Parameters
    ----------
    lower, upper : list of float
    confidence : float

    Returns
    -------
    FragilityFit
        samples: records, failures: records with a finite upper bound.
    """

def fit_lognormal(im: list[float], failed: list[int], confidence: float = ...) -> FragilityFit:
    """Maximum-likelihood lognormal fragility P(failure | IM = x) = Phi(ln(x/theta)/beta).

    Parameters
    ----------
    im : list of float
        Intensity measures, > 0 (theta comes out in their unit).
    failed : list of int
        0 or 1 per run.
    confidence : float
        Level of the bounds, in (0, 1).

    Returns
    -------
    FragilityFit
    """

def fit_stripes(im: list[float], runs: list[int], failures: list[int], confidence: float = ...) -> FragilityFit:
    """Multiple-stripe analysis: the binomial maximum-likelihood lognormal fragility (Baker
    2015), as ``flexrock fragility --analysis msa`` fits it.

    Parameters
    ----------
    im : list of float
        The stripes' intensity measures, > 0, distinct.
    runs, failures : list of int
        Runs at each stripe, and how many of them failed.
    confidence : float
        Level of the bounds, in (0, 1).

    Returns
    -------
    FragilityFit
        log_likelihood includes the binomial coefficients.
    """

def fragility_band(fit: FragilityFit, x: numpy.typing.NDArray[numpy.float64]) -> object:
    """The pointwise confidence band of the fitted curve (delta method).

    Parameters
    ----------
    fit : FragilityFit
        Its ``confidence`` is the level of the band.
    x : float or array_like
        Intensity measure in the fit's units; arrays of any shape broadcast elementwise.

    Returns
    -------
    (lower, upper) : tuple of float or of numpy.ndarray
        [-] probabilities, each of the shape of ``x``.
    """

def fragility_columns() -> list[str]:
    """Columns of the fit CSV of ``flexrock fragility``.

    Returns
    -------
    list of str
    """

def fragility_data(table: CsvTable, query: FragilityQuery) -> list[FragilityData]:
    """The (IM, failed) observations of each body of a sweep CSV.

    Parameters
    ----------
    table : CsvTable
    query : FragilityQuery
        im: pga [m/s^2], pga_g [g], pgv [m/s], scale [-] or requested_level; outcome:
        overturned, theta or energy, with its level.

    Returns
    -------
    list of FragilityData
        Rows whose outcome is stopped or contact_lost are left out and counted (``excluded``).
    """

def fragility_measure(name: str) -> FragilityMeasure:
    """The intensity measure of a fit so named (``flexrock fragility --im``).

    Parameters
    ----------
    name : str
        pga, pga_g, pgv, scale, requested_level or a measure of the sweep's [intensity] table.

    Returns
    -------
    FragilityMeasure
    """

def fragility_probability(fit: FragilityFit, x: numpy.typing.NDArray[numpy.float64]) -> object:
    """The fitted probability of failure P(failure | IM = x) = Phi(ln(x/theta)/beta).

    Parameters
    ----------
    fit : FragilityFit
    x : float or array_like
        Intensity measure, in the units of the IM the fit was made with (e.g. [g] for pga_g);
        arrays of any shape broadcast elementwise. x <= 0 gives 0.

    Returns
    -------
    float or numpy.ndarray
        [-] of the shape of ``x``.
    """

def fragility_row(data: FragilityData, fit: FragilityFit) -> str:
    """One line of the fit CSV.

    Parameters
    ----------
    data : FragilityData
    fit : FragilityFit

    Returns
    -------
    str
    """

def from_lumped_model(model: LumpedModel) -> BodyParameters:
    """The paper's parameters of a lumped-mass modal model (e.g. from an FE program).

    Parameters
    ----------
    model : LumpedModel
        Nodes [m, kg], pinned-base mode shapes [m] and frequencies [rad/s] or stiffness [N m].

    Returns
    -------
    BodyParameters
    """

def half_sine_pulse(a_p: float, omega_p: float, duration: float, component: Component = ...) -> GroundMotion:
    """Half a sine cycle a_p sin(omega_p t).

    Parameters
    ----------
    a_p : float
        [m/s^2] peak acceleration (negative: reversed).
    omega_p : float
        [rad/s] circular frequency of the pulse.
    duration : float
        [s] length of the motion (zero after the pulse: free vibration).
    component : Component
        horizontal (default) or vertical.

    Returns
    -------
    GroundMotion
        Analytic. The package's ``flexrock.half_sine_pulse`` also takes the case file's keys
        (``amplitude=``, ``units=``, ``frequency_hz=`` or ``period=``).
    """

def harmonic(amplitude: float, omega: float, duration: float, phase: float = ..., component: Component = ...) -> GroundMotion:
    """A steady harmonic base acceleration a sin(omega t + phase).

    Parameters
    ----------
    amplitude : float
        [m/s^2] peak acceleration.
    omega : float
        [rad/s] circular frequency.
    duration : float
        [s] length of the motion.
    phase : float
        [rad] phase at t = 0.
    component : Component
        horizontal (default) or vertical.

    Returns
    -------
    GroundMotion
    """

def harmonic_cycles(amplitude: float, omega: float, cycles: float, duration: float, phase: float = ..., component: Component = ...) -> GroundMotion:
    """A harmonic base acceleration over a whole number of cycles, then zero.

    Parameters
    ----------
    amplitude : float
        [m/s^2] peak acceleration.
    omega : float
        [rad/s] circular frequency.
    cycles : float
        [-] cycles before the motion stops.
    duration : float
        [s] length of the motion.
    phase : float
        [rad] phase at t = 0.
    component : Component

    Returns
    -------
    GroundMotion
    """

def intensity(motion: GroundMotion, measures: list[MeasureRequest] = ..., analytic_dt: float = ...) -> Intensity:
    """Peak ground acceleration and velocity of a motion's horizontal component.

    Parameters
    ----------
    motion : GroundMotion
    measures : list of MeasureRequest
        Further measures, written to ``Intensity.measures`` in this order.
    analytic_dt : float
        [s] sampling of an analytic motion (plus its breakpoints).

    Returns
    -------
    Intensity
        pga [m/s^2], pgv [m/s] (trapezoidal integral from 0), measures.
    """

def intensity_measure(name: str, t: list[float], a: list[float], period: float = ..., zeta: float = ...) -> float:
    """One intensity measure of a record, a piecewise linear between its samples.

    Parameters
    ----------
    name : str
        A name of ``intensity_measures()``.
    t : array of float
        [s] increasing sample times.
    a : array of float
        [m/s^2] horizontal acceleration at the samples.
    period, zeta : float
        [s] and [-]: only for ``sa``.

    Returns
    -------
    float
        In the measure's SI unit.
    """

def intensity_measures() -> list:
    """The table of intensity measures (the one the sweep columns, ``flexrock fragility --im``
    and the docs are written from).

    Returns
    -------
    list of dict
        name, column (empty for sa: ``sa_T<T>_z<zeta>_m_per_s2``), unit, doc, scale_power (the value
        of the record scaled by s is s**scale_power times the value), needs_period.
    """

def load_body(path: str) -> tuple:
    """The [body] table of a case or body file.

    Parameters
    ----------
    path : str

    Returns
    -------
    (BodyParameters, str)
        The parameters (SI) and the body's type name.
    """

def load_case(path: str) -> Case:
    """Reads and checks a case file (TOML, docs/case-file.md).

    Parameters
    ----------
    path : str

    Returns
    -------
    Case
        Body, motion (m/s^2), initial state, solver options and outputs; bad input raises
        InputError naming file, line and key.
    """

def load_spectrum_file(path: str) -> SpectrumFile:
    """Reads and checks a spectrum file (TOML, docs/studies.md).

    Parameters
    ----------
    path : str

    Returns
    -------
    SpectrumFile
        Grids as given: normalised, or in the units of ``pulse.units``.
    """

def load_sweep_manifest(path: str) -> SweepManifest:
    """Reads and checks a sweep manifest (TOML, docs/studies.md).

    Parameters
    ----------
    path : str

    Returns
    -------
    SweepManifest
        Its spec (target PGAs in m/s^2, the levels as written in ``spec.levels``) and hash.
    """

def lognormal_log_likelihood(im: list[float], failed: list[int], theta: float, beta: float) -> float:
    """The log-likelihood of lognormal fragility parameters.

    Parameters
    ----------
    im : list of float
        Intensity measures, > 0.
    failed : list of int
        0 or 1.
    theta : float
        Median, in the IM's unit.
    beta : float
        [-] lognormal standard deviation.

    Returns
    -------
    float
    """

def make_body(type: str, keys: dict[str, float]) -> BodyParameters:
    """A body of a type whose keys are all numbers, as a case file's [body] makes it.

    Parameters
    ----------
    type : str
        A body type (``body_kinds()``).
    keys : dict of str to float
        Its keys, in the units of the table; keys not given take their defaults.

    Returns
    -------
    BodyParameters
    """

def make_pulse(type: str, a_p: float, omega_p: float, duration: float, component: Component = ..., keys: dict[str, float] = ...) -> GroundMotion:
    """A motion of any pulse type, in SI units.

    Parameters
    ----------
    type : str
        A pulse type (``pulse_kinds()``).
    a_p : float
        [m/s^2] peak acceleration.
    omega_p : float
        [rad/s] circular frequency (ignored by a type without one).
    duration : float
        [s] length of the motion.
    component : Component
    keys : dict
        The type's other keys by their case-file names, in their units; absent keys take their
        defaults.

    Returns
    -------
    GroundMotion
    """

def measure_request(text: str) -> MeasureRequest:
    """A measure as the command line names it: a name of ``intensity_measures()`` or "sa:T",
    "sa:T:zeta".

    Parameters
    ----------
    text : str

    Returns
    -------
    MeasureRequest
    """

def newmark_sliding(time: list[float], acceleration: list[float], mu_s: float, mu_k: float, g: float = ...) -> dict:
    """Newmark's two-way rigid sliding block, exact for the piecewise-linear acceleration
    [m/s^2] at the times [s] (two equal times make a jump); returns the peak and final offset [m],
    the time sliding [s] and the slips.
    """

def one_sine_pulse(a_p: float, omega_p: float, duration: float, component: Component = ...) -> GroundMotion:
    """One full sine cycle a_p sin(omega_p t).

    Parameters
    ----------
    a_p : float
        [m/s^2] peak acceleration (negative: reversed).
    omega_p : float
        [rad/s] circular frequency of the pulse.
    duration : float
        [s] length of the motion (zero after the pulse: free vibration).
    component : Component
        horizontal (default) or vertical.

    Returns
    -------
    GroundMotion
        Analytic. The package's ``flexrock.one_sine_pulse`` also takes the case file's keys
        (``amplitude=``, ``units=``, ``frequency_hz=`` or ``period=``).
    """

def overturned(outcome: Outcome) -> bool:
    """Whether an outcome is one of the two overturning classes.

    Parameters
    ----------
    outcome : Outcome

    Returns
    -------
    bool
    """

def pulse_kinds() -> list[PulseKind]:
    """Every synthetic motion type, in the order of the docs.

    Returns
    -------
    list of PulseKind
    """

def pulse_length(type: str, omega_p: float) -> float:
    """The length of one pulse of a family.

    Parameters
    ----------
    type : str
        A pulse type of spectra (``spectrum_pulse_names()``).
    omega_p : float
        [rad/s]

    Returns
    -------
    float
        [s]
    """

def pulse_motion(type: str, a_p: float, omega_p: float, duration: float) -> GroundMotion:
    """A pulse of a family as a ground motion.

    Parameters
    ----------
    type : str
        A pulse type of spectra (``spectrum_pulse_names()``).
    a_p : float
        [m/s^2]
    omega_p : float
        [rad/s]
    duration : float
        [s]

    Returns
    -------
    GroundMotion
    """

def pushover_acceleration(body: Body, restraints: list[Restraint], edge: int, theta: float) -> float:
    """The base acceleration [m/s^2] that holds the body at theta (quasi-static pushover)."""

def qualify_key_reference() -> str:
    """The key reference of qualification files (docs/qualify.md), as Markdown."""

def read_at2(path: str) -> Record:
    """Reads a PEER NGA .AT2 record.

    Parameters
    ----------
    path : str

    Returns
    -------
    Record
        Values in g, as the file states, with its dt [s].
    """

def read_cosmos(path: str) -> Record:
    """Reads the first acceleration block of a COSMOS V1 or V2 file.

    Parameters
    ----------
    path : str

    Returns
    -------
    Record
        Values in the units its data line states, dt from real header value 62.
    """

def read_csv_table(path: str) -> CsvTable:
    """Reads a CSV file as text fields (a sweep CSV for a fragility fit).

    Parameters
    ----------
    path : str

    Returns
    -------
    CsvTable
    """

def read_esm(path: str) -> Record:
    """Reads an ESM ASCII acceleration file.

    Parameters
    ----------
    path : str

    Returns
    -------
    Record
        Values in the units the file states (UNITS), dt from SAMPLING_INTERVAL_S.
    """

def read_knet(path: str) -> Record:
    """Reads a NIED K-NET or KiK-net ASCII file.

    Parameters
    ----------
    path : str

    Returns
    -------
    Record
        Counts times the file's scale factor, in cm/s^2 (offset kept as published).
    """

def read_single_column(path: str, dt: float, units: AccelUnit) -> Record:
    """Reads a record of one value a line, sampled every dt.

    Parameters
    ----------
    path : str
    dt : float
        [s] sample spacing.
    units : AccelUnit
        Units of the file's values.

    Returns
    -------
    Record
    """

def read_smc(path: str) -> Record:
    """Reads a USGS SMC accelerogram.

    Parameters
    ----------
    path : str

    Returns
    -------
    Record
        Values in cm/s^2, dt from the file's sampling rate.
    """

def read_sweep_csv(spec: SweepSpec, path: str) -> list[SweepRow]:
    """A sweep CSV read back as the rows it was written from (every line checked against its
    run: it must be exactly what the row writes).

    Parameters
    ----------
    spec : SweepSpec
    path : str

    Returns
    -------
    list of SweepRow
        In index order.
    """

def read_time_series(path: str, units: Optional[AccelUnit] = ...) -> Record:
    """Reads time/acceleration pairs, one a line (blanks, commas or semicolons).

    Parameters
    ----------
    path : str
    units : AccelUnit, optional
        Units of the accelerations (times in s); required unless a row of the file states them
        ("s, g" or "time [s], acc [cm/s^2]"), and if both, they must agree.

    Returns
    -------
    Record
    """

def record_formats() -> list[RecordFormat]:
    """Every record format: the one table case files, study files and read_record use.

    Returns
    -------
    list of RecordFormat
    """

def rectangular_pulse(a_p: float, t_1: float, duration: float, component: Component = ...) -> GroundMotion:
    """A constant acceleration a_p for 0 <= t <= t_1, then zero.

    Parameters
    ----------
    a_p : float
        [m/s^2] acceleration.
    t_1 : float
        [s] length of the pulse (the case file's ``length``).
    duration : float
        [s] length of the motion.
    component : Component

    Returns
    -------
    GroundMotion
    """

def require_spectral_period(period: float, key: str) -> None:
    """Raises InputError naming ``key`` unless ``period`` [s] is finite and at least 1e-6 s
    (below it the oscillator follows the ground and Sa is the PGA).
    """

def restoring_moment(body: Body, restraints: list[Restraint], edge: int, theta: float) -> float:
    """The restoring moment [N m] about the pivot of `edge` at theta, gravity and ties."""

def ricker_wavelet(a_p: float, omega_p: float, t_c: float, duration: float, component: Component = ...) -> GroundMotion:
    """A Ricker wavelet peaking at t_c.

    Parameters
    ----------
    a_p : float
        [m/s^2] peak acceleration.
    omega_p : float
        [rad/s] circular peak frequency.
    t_c : float
        [s] time of the peak (the case file's ``center``).
    duration : float
        [s] length of the motion.
    component : Component

    Returns
    -------
    GroundMotion
    """

def rotd(t: list[float], a1: list[float], a2: list[float], period: float, zeta: float = ...) -> dict:
    """RotD50 and RotD100 of two orthogonal horizontal components (Boore 2010): for each
    rotation angle 0, 1, ..., 179 deg the pseudo-spectral acceleration of a1 cos + a2 sin (as
    ``intensity_measure("sa", ...)``); RotD50 the median over the angles, RotD100 the largest.

    Parameters
    ----------
    t : array of float
        [s] increasing sample times, shared by both components.
    a1, a2 : array of float
        [m/s^2] the two horizontal components at the samples.
    period, zeta : float
        [s] natural period of the oscillator, [-] its damping ratio.

    Returns
    -------
    dict
        ``rotd50``, ``rotd100`` [m/s^2] and ``by_angle`` (numpy array of 180 values, m/s^2).
    """

def run_azimuths(case: Case, step_deg: Optional[float] = ..., threads: int = ...) -> tuple:
    """Runs a case with a record pair at every azimuth of the grid over [0, 360) (as
    ``flexrock azimuths``), on threads with the GIL released.

    Parameters
    ----------
    case : Case
        From ``load_case`` of a file with ``[excitation.horizontal2]``.
    step_deg : float, optional
        [deg] the grid's step (default: the case's ``azimuth_step_deg``, 5).
    threads : int
        Worker threads (0: every core).

    Returns
    -------
    (dict, dict)
        The per-azimuth table (numpy arrays of float, ``outcome`` a list of str; the columns of the
        azimuth CSV) and the envelope (largest tilt, offset and impact force with their governing
        azimuths, the overturned azimuths).
    """

def run_pulse_cell(body: Body, spec: SpectrumSpec, a_p: float, omega_p: float) -> RunSummary:
    """One pulse-spectrum cell, as compute_spectrum runs it.

    Parameters
    ----------
    body : Body
    spec : SpectrumSpec
    a_p : float
        [m/s^2] amplitude.
    omega_p : float
        [rad/s] frequency.

    Returns
    -------
    RunSummary
    """

def run_record_cell(body: Body, spec: RecordSpectrumSpec, scale: float) -> RunSummary:
    """One record-spectrum cell.

    Parameters
    ----------
    body : Body
    spec : RecordSpectrumSpec
    scale : float
        [-] factor on the record.

    Returns
    -------
    RunSummary
    """

def run_sweep(spec: SweepSpec, indices: list[int] = ..., threads: int = ..., *, progress: object = ..., callback: Optional[object] = ...) -> list[SweepRow]:
    """Runs a sweep (bodies x records x scales), or the given run indices.

    Parameters
    ----------
    spec : SweepSpec
    indices : list of int
        Empty: every run.
    threads : int
        0: every core. The GIL is released.
    progress : bool
        A progress bar on stderr while it runs longer than a second (tqdm where it is installed,
        a plain line otherwise); False: none.
    callback : callable, optional
        Called as callback(done, total) on the calling thread while the runs go (every 20 ms at
        most, when the count moved) and once at the end: for a notebook's own display. An
        exception it raises stops the runs between two, as Ctrl-C does, and is raised here.

    Returns
    -------
    list of SweepRow
        In index order.
    """

def self_centring_stiffness(body: Body, restraints: list[Restraint], edge: int) -> float:
    """The post-uplift rotational stiffness [N m/rad] (negative: softening)."""

def sha256_hex(data: str) -> str:
    """SHA-256 of bytes as 64 hex digits."""

def simulate(body: Body, motion: GroundMotion, initial: InitialState = ..., options: SimulationOptions = ...) -> SimulationResult:
    """Simulates a body on a base moving with a ground motion.

    Parameters
    ----------
    body : Body
    motion : GroundMotion
        Base accelerations [m/s^2].
    initial : InitialState
        theta [rad], theta_dot [rad/s], q, q_dot; default at rest.
    options : SimulationOptions
        Solver options (SI).

    Returns
    -------
    SimulationResult
        Overturning, loss of contact and a stopped run are its ``status``, not exceptions. The
        GIL is released while it runs.
    """

def simulate_on_support(body: Body, support: SupportParameters, motion: GroundMotion, initial: InitialState = ..., options: SimulationOptions = ...) -> SupportRunResult:
    """Simulates a rigid block standing on a support that moves with it (docs/theory.md §24): full contact, rocking, impacts and overturning; sliding, flexible bodies and the compliant contact raise InputError, and a lift-off ends the run as stopped."""

def simulate_restrained(body: Body, restraints: list[Restraint], motion: GroundMotion, initial: InitialState = ..., options: SimulationOptions = ...) -> RestrainedResult:
    """Simulates a rigid body tied down by restraints (docs/theory.md §26)."""

def spectrum_arrays(result: SpectrumResult, g: float = ...) -> dict:
    """The cells of a spectrum as numpy arrays, one per column of its CSV, typed by the column
    table (the columns of ``spectrum_columns(result.sliding)``).

    Parameters
    ----------
    result : SpectrumResult
    g : float
        [m/s^2] the body's gravity, as for the CSV.

    Returns
    -------
    dict of str to numpy.ndarray
        int64 for indices and counts, float64 for reals (nan where the CSV leaves the field empty),
        object (str) for classes.
    """

def spectrum_columns(sliding: bool = ..., units: GridUnits = ...) -> list[str]:
    """Columns of the spectrum CSV (unit-suffixed).

    Parameters
    ----------
    sliding : bool
        With the sliding columns (regime, offsets, time sliding, slips) that a spectrum with a
        finite friction coefficient adds (``SpectrumResult.sliding``).
    units : GridUnits
        A physical grid's units (``SpectrumResult.units``): units other than SI add columns in them
        (``a_p_g``, ``f_p_hz``).

    Returns
    -------
    list of str
    """

def spectrum_csv(result: SpectrumResult, g: float) -> str:
    """The spectrum CSV text (one row per cell).

    Parameters
    ----------
    result : SpectrumResult
    g : float
        [m/s^2] gravity for the normalised columns.

    Returns
    -------
    str
    """

def spectrum_pulse_names() -> list[str]:
    """The pulse types that spectra sweep.

    Returns
    -------
    list of str
    """

def stack_uplift_bands(bottom_width: float, bottom_height: float, bottom_mass: float, top_width: float, top_height: float, top_mass: float) -> list[tuple[str, float, float]]:
    """How a uniform block standing centred on another starts to move from rest under a
    constant horizontal floor acceleration lambda g (docs/theory.md §25): the band [lo, hi) of
    lambda over which each pattern is the consistent one.

    Parameters
    ----------
    bottom_width, bottom_height : float
        [m] full width and height of the bottom block.
    bottom_mass : float
        [kg]
    top_width, top_height : float
        [m] of the top block, top_width <= bottom_width.
    top_mass : float
        [kg]

    Returns
    -------
    list of (str, float, float)
        (pattern, lo, hi) for "rest", "top_alone", "as_one", "separately" and
        "separately_opposite"; a pattern that never occurs has lo = hi = inf.
    """

def summarize(body: Body, result: SimulationResult) -> RunSummary:
    """The study outcome class and peaks of a finished simulation.

    Parameters
    ----------
    body : Body
    result : SimulationResult

    Returns
    -------
    RunSummary
    """

def summary_json(case: Case, body: Body, result: SimulationResult, paths: OutputPaths = ...) -> str:
    """The summary JSON text ``flexrock run`` writes (SI units, docs/case-file.md).

    Parameters
    ----------
    case : Case
    body : Body
    result : SimulationResult
    paths : OutputPaths
        Where the outputs went, for the summary's ``outputs``.

    Returns
    -------
    str
    """

def sweep_arrays(spec: SweepSpec, rows: list[SweepRow]) -> dict:
    """Rows of a sweep as numpy arrays, one per column of its CSV, typed by the column table.

    Parameters
    ----------
    spec : SweepSpec
    rows : list of SweepRow

    Returns
    -------
    dict of str to numpy.ndarray
        int64 for indices and counts, float64 for reals (nan where the CSV leaves the field empty),
        object (str) for names and classes.
    """

def sweep_column_info(spec: SweepSpec) -> list:
    """The columns of a spec's sweep CSV as the table declares them.

    Parameters
    ----------
    spec : SweepSpec

    Returns
    -------
    list of dict
        ``{"name", "unit", "type"}``, type "integer", "real" or "text" (the dtype of the column's
        array in :func:`sweep_arrays`: int64, float64, object).
    """

def sweep_columns(sliding: bool = ...) -> list[str]:
    """Columns of the sweep CSV.

    Parameters
    ----------
    sliding : bool
        With the sliding columns that a sweep with a finite friction coefficient adds
        (``sweep_has_friction(spec)``).

    Returns
    -------
    list of str
        index, body, record, requested_level, requested_units, scale, pga_m_per_s2, pga_g, ...
    """

def sweep_has_friction(spec: SweepSpec) -> bool:
    """Whether any run of a sweep has a finite friction coefficient (its rows then end
    with the sliding columns).

    Parameters
    ----------
    spec : SweepSpec

    Returns
    -------
    bool
    """

def sweep_row(spec: SweepSpec, row: SweepRow) -> str:
    """One line of the sweep CSV (no line end).

    Parameters
    ----------
    spec : SweepSpec
    row : SweepRow

    Returns
    -------
    str
    """

def sweep_spec_columns(spec: SweepSpec) -> list[str]:
    """Columns of a spec's sweep CSV: the requested intensity measures after pgv_m_per_s, the
    sliding columns if it has friction.

    Parameters
    ----------
    spec : SweepSpec

    Returns
    -------
    list of str
    """

def time_history_arrays(result: SimulationResult, body: Body) -> dict:
    """The time history as numpy arrays, by the CSV's column names.

    Parameters
    ----------
    result : SimulationResult
        A finished simulation.
    body : Body
        The body it simulated (for the uplift column).

    Returns
    -------
    dict of str to numpy.ndarray
        One float64 array per column of :func:`time_history_columns` (``time_s`` [s], ``phase``,
        ``theta_rad`` [rad], ..., ``impact_loss_J`` [J]), equal bit for bit to the values of
        :func:`time_history_csv`.
    """

def time_history_columns(modes: int) -> list[str]:
    """Column names of the time history, each with its unit suffix.

    Parameters
    ----------
    modes : int
        Deformation modes of the body.

    Returns
    -------
    list of str
        time_s, phase, theta_rad, theta_dot_rad_per_s, uplift_m, q1..., q1_dot_per_s...,
        base_acc_x_m_per_s2, ..., impact_loss_J.
    """

def time_history_csv(result: SimulationResult, body: Body) -> str:
    """The time-history CSV text ``flexrock run`` writes.

    Parameters
    ----------
    result : SimulationResult
    body : Body

    Returns
    -------
    str
    """

def uncertain_parameters() -> list:
    """The table of uncertain parameters (the one manifests, the sweep columns and the docs
    are written from).

    Returns
    -------
    list of dict
        name, column, unit, domain, doc.
    """

def uncertain_quantile(parameter: UncertainParameter, u: float) -> float:
    """The value of a parameter at probability u in (0, 1) (its truncated inverse CDF)."""

def uniform_cylinder(radius: float, height: float, mass: float, inner_radius: float = ...) -> AxisymmetricBody:
    """A uniform solid or hollow circular cylinder as a body of revolution in 3D.

    Parameters
    ----------
    radius : float
        [m] outer radius of the base.
    height : float
        [m] full height.
    mass : float
        [kg].
    inner_radius : float
        [m] bore of a hollow cylinder, < radius (0: solid).

    Returns
    -------
    AxisymmetricBody
        h = height / 2, A = M (3 (R^2 + Ri^2) + H^2) / 12, C = M (R^2 + Ri^2) / 2.
    """

def uplift_acceleration(body: Body, restraints: list[Restraint], edge: int) -> float:
    """The uplift threshold [m/s^2] onto `edge` with the restraints."""

def write_outputs(case: Case, body: Body, result: SimulationResult, output_dir: str = ...) -> OutputPaths:
    """Writes the outputs the case's [output] table asks for, atomically, summary last.

    Parameters
    ----------
    case : Case
    body : Body
    result : SimulationResult
    output_dir : str
        Relative names are relative to it.

    Returns
    -------
    OutputPaths
    """
