"""The result of ``mechanism.motion(phi)``: joint paths, the output law and every link's angle;
and the one convention for results: frozen dataclasses, a table a :class:`Table` of them.

Analogs are derivatives with respect to the crank angle φ; physical values at a
crank speed ω1 and crank acceleration ε1 follow from the chain rule:
ω2 = ψ'·ω1 and ε2 = ψ''·ω1² + ψ'·ε1 (likewise v = s'·ω1, a = s''·ω1² + s'·ε1).
A scalar φ gives a motion of scalars (positions of shape ``(2,)``), an array of n
angles a motion of arrays (positions ``(n, 2)``).
"""

from __future__ import annotations

import functools
import html
import inspect
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, fields, is_dataclass, replace
from numbers import Real

import numpy as np

from .errors import DimensionError, SingularityError
from .geometry import AnglePath, PointPath, as_angles, relative, vector_angle
from .validate import Reals, validated

# |x′| ≤ STILL·max|x′| over a turn: the output stands exactly still, up to rounding; small enough that a dwell
# which ends smoothly (|x′| ~ Δφ²) ends within ~1e-6 rad. The one threshold of "still": the dwell fraction,
# the dwell's ends and the still output of the inverse problem.
STILL = 1e-12


@dataclass(frozen=True, eq=False)
class Law:
    """A quantity of the mechanism with its first and second analogs (d/dφ, d²/dφ²).

    Parameters
    ----------
    name : str
        What it is: ``"ψ"``, ``"s"`` or ``"θ(A→B)"``.
    value : numpy.ndarray or float
        The quantity over the crank angles (a float at a scalar crank angle): radians for an angle,
        a length (dimensionless or mm) for a position.
    d : numpy.ndarray or float
        The first analog d(value)/dφ (dimensionless, or length/rad).
    dd : numpy.ndarray or float
        The second analog d²(value)/dφ² (1/rad, or length/rad²).
    kind : {"angle", "position"}, optional
        Whether ``value`` is an angle or a position.

    Examples
    --------
    >>> from mechlab import FourBar
    >>> law = FourBar(1, 3, 3.5, 4).motion(0.3).output
    >>> law
    Law(ψ = 2.10358 rad = 120.526°, ψ′ = -0.256937, ψ″ = 0.348417)
    >>> round(float(law.velocity(10.0)), 4)  # rad/s at ω1 = 10 rad/s
    -2.5694
    """

    name: str
    value: np.ndarray | float
    d: np.ndarray | float
    dd: np.ndarray | float
    kind: str = "angle"

    @validated
    def velocity(self, omega1: Reals) -> np.ndarray | float:
        """The physical rate value'·ω1 at crank speed ω1.

        Parameters
        ----------
        omega1 : float or numpy.ndarray
            Crank speed ω1 (rad/s): a number or one value per crank angle.

        Returns
        -------
        numpy.ndarray or float
            The output's angular velocity (rad/s) or linear velocity (length/s).

        Raises
        ------
        DimensionError
            If ``omega1`` is not finite, or is an array whose shape differs from ``value``'s.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import Law
        >>> Law("ψ", np.array([0.1, 0.2]), np.array([0.5, 0.4]), np.array([0.0, -0.1])).velocity(10.0)
        array([5., 4.])
        """
        return self.d * self._per_angle("omega1", omega1)

    @validated
    def acceleration(self, omega1: Reals, eps1: Reals = 0.0) -> np.ndarray | float:
        """The physical acceleration value''·ω1² + value'·ε1.

        Parameters
        ----------
        omega1 : float or numpy.ndarray
            Crank speed ω1 (rad/s): a number or one value per crank angle.
        eps1 : float or numpy.ndarray, optional
            Crank acceleration ε1 (rad/s²): a number or one value per crank angle.

        Returns
        -------
        numpy.ndarray or float
            The output's angular acceleration (rad/s²) or linear acceleration (length/s²).

        Raises
        ------
        DimensionError
            If ``omega1`` or ``eps1`` is not finite, or is an array whose shape differs from ``value``'s.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import Law
        >>> Law("ψ", np.array([0.1, 0.2]), np.array([0.5, 0.4]), np.array([0.0, -0.1])).acceleration(10.0, 1.0)
        array([ 0.5, -9.6])
        """
        return self.dd * self._per_angle("omega1", omega1)**2 + self.d * self._per_angle("eps1", eps1)

    def _per_angle(self, name: str, value):
        if np.ndim(value) and np.shape(value) != np.shape(self.value):
            raise DimensionError(f"{name} must be a number or one value per crank angle (shape "
                                 f"{np.shape(self.value)}), got shape {np.shape(value)}")
        return value

    @property
    def degrees(self) -> np.ndarray | float:
        """The value in degrees (angles only).

        Returns
        -------
        numpy.ndarray or float
            ``value`` converted to degrees.

        Raises
        ------
        DimensionError
            If the law is a position, not an angle.
        """
        if self.kind != "angle":
            raise DimensionError(f"{self.name} is a {self.kind}, not an angle: it has no value in degrees")
        return np.degrees(self.value)

    def __repr__(self) -> str:
        if np.ndim(self.value):
            return f"Law({self.name}, {self.kind}, n={np.size(self.value)})"
        value = (f"{self.name} = {float(self.value):.6g} rad = {float(np.degrees(self.value)):.6g}°"
                 if self.kind == "angle" else f"{self.name} = {float(self.value):.6g}")
        return f"Law({value}, {self.name}′ = {float(self.d):.6g}, {self.name}″ = {float(self.dd):.6g})"


@dataclass(frozen=True, eq=False)
class Motion:
    """Joint paths over the crank angles ``phi`` (radians).

    A mechanism's ``motion(phi)`` returns one; a scalar φ gives a motion of scalars (positions of shape
    ``(2,)``), an array of n angles a motion of arrays (positions ``(n, 2)``). ``output`` is the output law
    whatever its kind; :meth:`link_angle` gives any link's angle.

    The transmission angle (:attr:`transmission`) is given as an array or, by a mechanism, as a function
    of the motion (the private ``_transmission`` field), evaluated on first use.

    Parameters
    ----------
    phi : numpy.ndarray or float
        Crank angles φ (radians).
    points : Mapping[str, PointPath]
        Joint names to their :class:`~mechlab.geometry.PointPath` (positions and first and second analogs).

    Examples
    --------
    >>> from mechlab import FourBar
    >>> mo = FourBar(1, 3, 3.5, 4).motion(0.3)
    >>> sorted(mo.points)
    ['A', 'B', 'E', 'O']
    >>> round(float(mo.transmission), 4)
    0.9688
    """

    phi: np.ndarray
    points: Mapping[str, PointPath]
    _transmission: np.ndarray | Callable[[Motion], np.ndarray] = field(repr=False)

    @property
    def transmission(self) -> np.ndarray:
        """The transmission angle μ at every crank angle.

        Returns
        -------
        numpy.ndarray or float
            μ in [0, π] (radians; π/2 is ideal).
        """
        if callable(self._transmission):
            object.__setattr__(self, "_transmission", self._transmission(self))
        return self._transmission

    @property
    def pressure_angle(self) -> np.ndarray:
        """The pressure angle |π/2 - μ| at every crank angle.

        Returns
        -------
        numpy.ndarray or float
            The pressure angle in [0, π/2] (radians; 0 is ideal).
        """
        return np.abs(np.pi / 2 - self.transmission)

    @property
    def output(self) -> Law:  # pragma: no cover - every motion is angular or linear
        """The output law, whatever its kind (an angle ψ or a displacement s).

        Returns
        -------
        Law
            The output with its first and second analogs.
        """
        raise NotImplementedError

    def velocity(self, omega1: float) -> np.ndarray:
        """The output velocity at crank speed ω1.

        Parameters
        ----------
        omega1 : float or numpy.ndarray
            Crank speed ω1 (rad/s): a number or one value per crank angle.

        Returns
        -------
        numpy.ndarray or float
            ψ'·ω1 (rad/s) or s'·ω1 (length/s).

        Raises
        ------
        DimensionError
            If ``omega1`` is not finite or does not match the crank angles (checked by :class:`Law`).

        Examples
        --------
        >>> from mechlab import FourBar
        >>> round(float(FourBar(1, 3, 3.5, 4).motion(0.3).velocity(10.0)), 4)
        -2.5694
        """
        return self.output.velocity(omega1)

    def acceleration(self, omega1: float, eps1: float = 0.0) -> np.ndarray:
        """The output acceleration at crank speed ω1 and crank acceleration ε1.

        Parameters
        ----------
        omega1 : float or numpy.ndarray
            Crank speed ω1 (rad/s).
        eps1 : float or numpy.ndarray, optional
            Crank acceleration ε1 (rad/s²).

        Returns
        -------
        numpy.ndarray or float
            ψ''·ω1² + ψ'·ε1 (rad/s²) or s''·ω1² + s'·ε1 (length/s²).

        Raises
        ------
        DimensionError
            If ``omega1`` or ``eps1`` is not finite or does not match the crank angles.

        Examples
        --------
        >>> from mechlab import FourBar
        >>> round(float(FourBar(1, 3, 3.5, 4).motion(0.3).acceleration(10.0, 2.0)), 4)
        34.3278
        """
        return self.output.acceleration(omega1, eps1)

    def link_angle(self, start: str, end: str) -> Law:
        """Angle θ of the line from joint ``start`` to joint ``end``, counter-clockwise from +x.

        θ' = (v × v')/|v|² and θ'' = (v × v'')/|v|² - 2θ'(v·v')/|v|², v = end - start
        (differentiating θ = atan2(v_y, v_x)). Over an array of crank angles θ is continuous along the
        samples (unwrapped) and starts in (-π, π].

        Parameters
        ----------
        start, end : str
            Joint names of this motion, e.g. ``"A", "B"`` for a four-bar's coupler, ``"E", "B"`` for its rocker.

        Returns
        -------
        Law
            θ (radians) with θ' and θ'', named ``"θ(start→end)"``.

        Raises
        ------
        DimensionError
            If a joint is not in this motion, or the motion is spatial.
        SingularityError
            If the two joints coincide at some crank angle.

        Examples
        --------
        >>> from mechlab import FourBar
        >>> round(float(FourBar(1, 3, 3.5, 4).motion(0.3).link_angle("A", "B").value), 4)
        1.1348
        """
        for name, joint in (("start", start), ("end", end)):
            if joint not in self.points:
                raise DimensionError(f"link_angle: {name} = {joint!r} is not a joint of this motion; "
                                     f"its joints are {sorted(self.points)}")
        if np.shape(self.points[start].p)[-1] != 2:
            raise DimensionError(f"link_angle is planar: the joints of this motion are points in space "
                                 f"(shape {np.shape(self.points[start].p)})")
        if np.ndim(self.phi) == 0:
            law = self.as_arrays().link_angle(start, end)
            return Law(law.name, law.value[0], law.d[0], law.dd[0], law.kind)
        v = relative(self.points[end], self.points[start])
        length = np.hypot(v.p[:, 0], v.p[:, 1])
        if np.any(length == 0.0):
            i = int(np.argmin(length))
            raise SingularityError(f"link_angle: joints {start} and {end} coincide at "
                                   f"φ = {np.degrees(self.phi[i]):.2f}°, so the line between them has no angle")
        ang = vector_angle(v)
        return Law(f"θ({start}→{end})", np.unwrap(ang.theta), ang.d, ang.dd, "angle")

    def placed(self, origin=(0.0, 0.0), angle: float = 0.0) -> Motion:
        """The motion seen in a frame where the mechanism's own frame sits at ``origin``, turned by ``angle``.

        Positions rotate by ``angle`` and translate by ``origin``; their analogs rotate; φ, an output angle ψ
        and every link angle grow by ``angle`` (they are measured from the new x axis); a slider's displacement
        s and the transmission angle are intrinsic and stay. A Watt linkage with pivots O and E anywhere::

            alpha = np.arctan2(E[1] - O[1], E[0] - O[0])
            mech = FourBar(crank, coupler, rocker, ground=np.hypot(E[0] - O[0], E[1] - O[1]))
            mo = mech.motion(theta2 - alpha).placed(O, alpha)   # θ2: the crank from the x axis

        Parameters
        ----------
        origin : sequence of float, optional
            Where the mechanism's origin lies in the new frame (length).
        angle : float, optional
            The mechanism's x axis from the new x axis (radians).

        Returns
        -------
        Motion
            A motion of the same type, in the new frame.

        Raises
        ------
        DimensionError
            If the motion is spatial.

        Examples
        --------
        >>> from mechlab import FourBar
        >>> mo = FourBar(1, 3, 3.5, 4).motion(0.3).placed((1.0, 2.0), 0.5)
        >>> mo.points["O"].p, round(float(mo.phi), 4)
        (array([1., 2.]), 0.8)
        """
        if any(np.shape(p.p)[-1] != 2 for p in self.points.values()):
            raise DimensionError("placed is planar: the joints of this motion are points in space")
        c, s = np.cos(angle), np.sin(angle)
        rot = np.array([[c, s], [-s, c]])  # row vectors times rot = rotation by +angle
        o = np.asarray(origin, dtype=float)
        points = {k: PointPath(p.p @ rot + o, p.d @ rot, p.dd @ rot) for k, p in self.points.items()}
        return self._with(points=points, phi=self.phi + angle, **self._placed_output(angle))

    def _placed_output(self, angle: float) -> dict:
        return {}

    def _with(self, **changes) -> Motion:
        values = {f.name: getattr(self, f.name) for f in fields(self)}
        values["_transmission"] = self.transmission
        values.update(changes)
        return type(self)(**values)

    def _map(self, take) -> Motion:
        """The same motion with ``take`` applied to every array (positions and analogs row-wise)."""
        points = {k: PointPath(take(p.p), take(p.d), take(p.dd)) for k, p in self.points.items()}
        values = {f.name: take(getattr(self, f.name)) for f in fields(self)
                  if f.name not in ("points", "_transmission")}
        return self._with(points=points, _transmission=take(self.transmission), **values)

    def _first(self):
        return self._map(lambda a: a[0])

    def as_arrays(self) -> Motion:
        """The motion over an array of crank angles: a motion at a scalar φ becomes one at [φ].

        Returns
        -------
        Motion
            This motion if it is over an array already, else the same motion over ``[φ]``.

        Examples
        --------
        >>> from mechlab import FourBar
        >>> FourBar(1, 3, 3.5, 4).motion(0.3).as_arrays().phi
        array([0.3])
        """
        return self._map(lambda a: np.asarray(a)[None]) if np.ndim(self.phi) == 0 else self

    def __len__(self) -> int:
        return len(self.phi)


@dataclass(frozen=True, eq=False)
class AngularMotion(Motion):
    """Motion whose output is an angle ψ (radians) with analogs ψ' and ψ''.

    Parameters
    ----------
    phi : numpy.ndarray or float
        Crank angles φ (radians).
    points : Mapping[str, PointPath]
        Joint names to their paths.
    psi : numpy.ndarray or float
        Output angle ψ (radians).
    dpsi : numpy.ndarray or float
        ψ' = dψ/dφ (dimensionless).
    ddpsi : numpy.ndarray or float
        ψ'' = d²ψ/dφ² (1/rad).

    Examples
    --------
    >>> from mechlab import FourBar
    >>> round(float(FourBar(1, 3, 3.5, 4).motion(0.3).psi), 4)
    2.1036
    """

    psi: np.ndarray
    dpsi: np.ndarray
    ddpsi: np.ndarray

    @property
    def output(self) -> Law:
        """The output law ψ, ψ', ψ''.

        Returns
        -------
        Law
            The output angle (kind ``"angle"``).
        """
        return Law("ψ", self.psi, self.dpsi, self.ddpsi, "angle")

    def _placed_output(self, angle: float) -> dict:
        return {"psi": self.psi + angle}


@dataclass(frozen=True, eq=False)
class LinearMotion(Motion):
    """Motion whose output is a displacement s (length) with analogs s' and s''.

    Parameters
    ----------
    phi : numpy.ndarray or float
        Crank angles φ (radians).
    points : Mapping[str, PointPath]
        Joint names to their paths.
    s : numpy.ndarray or float
        Output displacement (length).
    ds : numpy.ndarray or float
        s' = ds/dφ (length/rad).
    dds : numpy.ndarray or float
        s'' = d²s/dφ² (length/rad²).

    Examples
    --------
    >>> from mechlab import SliderCrank
    >>> SliderCrank(1, 3).motion(0.3).output
    Law(s = 3.94075, s′ = -0.390087, s″ = -1.23479)
    """

    s: np.ndarray
    ds: np.ndarray
    dds: np.ndarray

    @property
    def output(self) -> Law:
        """The output law s, s', s''.

        Returns
        -------
        Law
            The output displacement (kind ``"position"``).
        """
        return Law("s", self.s, self.ds, self.dds, "position")


def _real_scalar(phi) -> bool:
    return isinstance(phi, Real) or (isinstance(phi, np.ndarray) and phi.ndim == 0)


def scalar_in_scalar_out(motion):
    """Wrap a mechanism's ``motion(phi)`` so that a real scalar φ gives a motion of scalars.

    The wrapped method always receives an array; anything that is not a real scalar
    passes through unchanged (and is checked there).
    """
    @functools.wraps(motion)
    def wrapped(self, phi, *args, **kwargs):
        if _real_scalar(phi):
            return motion(self, as_angles(phi), *args, **kwargs)._first()  # checked: 10**400, NaN named
        return motion(self, phi, *args, **kwargs)
    return wrapped


def first_of(result):
    """A result over crank angles [φ] (arrays of one) as the result at φ: every array, path and motion
    taken at its first row, in the result itself or in a field of a frozen dataclass result
    (one level down, so that a mechanism held by the result is left alone). A result with its own
    ``_first()`` (a motion, the instantaneous centres) gives that."""
    if hasattr(result, "_first"):
        return result._first()
    if is_dataclass(result) and not isinstance(result, (type, AnglePath)):
        return replace(result, **{f.name: _first(getattr(result, f.name)) for f in fields(result) if f.init})
    return _first(result)


def _first(value):
    if hasattr(value, "_first"):
        return value._first()
    if isinstance(value, (PointPath, AnglePath)):
        return type(value)(*(v[0] for v in value))
    if isinstance(value, np.ndarray):
        return value[0] if value.ndim else value
    if isinstance(value, tuple):
        return tuple(_first(v) for v in value)
    if isinstance(value, dict):
        return {k: first_of(v) for k, v in value.items()}
    return value


def scalar_law(law_of):
    """Wrap ``law_of(x, ..., phi, ...)`` (a function of an object and crank angles ``phi``, or a
    method), which returns results over φ, so that a real scalar φ gives the results at that φ as scalars
    (:func:`first_of`)."""
    at = list(inspect.signature(law_of).parameters).index("phi") - 1   # in args after x

    @functools.wraps(law_of)
    def wrapped(x, *args, **kwargs):
        phi = args[at] if len(args) > at else kwargs.get("phi")
        if not _real_scalar(phi):
            return law_of(x, *args, **kwargs)
        if len(args) > at:
            args = (*args[:at], as_angles(phi), *args[at + 1:])
        else:
            kwargs["phi"] = as_angles(phi)
        return first_of(law_of(x, *args, **kwargs))
    return wrapped


@dataclass(frozen=True)
class Extremes:
    """The two limit (dead-centre) positions of a rocking output driven by a turning crank.

    At ``phi_extended`` the crank and the coupler (rod) lie in line, stretched; at ``phi_folded`` in line,
    folded over each other. Turning counter-clockwise the crank needs ``forward`` for one stroke and
    ``back`` for the other; the time ratio is the slower over the faster stroke.

    Parameters
    ----------
    phi_extended, phi_folded : float
        Crank angles of the stretched and folded positions (radians, in [0, 2π)).
    extended, folded : float
        The output there (ψ in radians or s in length).
    kind : {"angle", "position"}, optional
        The output's kind.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab import FourBar
    >>> ex = FourBar(1, 3, 3.5, 4).extremes()
    >>> round(ex.time_ratio, 4), round(float(np.degrees(ex.stroke)), 4)
    (1.107, 34.0608)
    """

    phi_extended: float
    phi_folded: float
    extended: float
    folded: float
    kind: str = "angle"

    @property
    def stroke(self) -> float:
        """|folded - extended|: the rocker's swing or the slider's stroke.

        Returns
        -------
        float
            Radians for a rocker, a length for a slider.
        """
        return abs(self.folded - self.extended)

    @property
    def forward(self) -> float:
        """The crank's turn from the stretched to the folded position, (φ_folded - φ_extended) mod 2π.

        Returns
        -------
        float
            Radians, in [0, 2π).
        """
        return float(np.mod(self.phi_folded - self.phi_extended, 2 * np.pi))

    @property
    def back(self) -> float:
        """The crank's turn from the folded back to the stretched position, 2π - forward.

        Returns
        -------
        float
            Radians.
        """
        return 2 * np.pi - self.forward

    @property
    def time_ratio(self) -> float:
        """The time ratio Q = (π + θ)/(π - θ) ≥ 1 with θ = |forward - π|: the slower stroke over the faster.

        Returns
        -------
        float
            Q, dimensionless.
        """
        return max(self.forward, self.back) / min(self.forward, self.back)

    def __repr__(self) -> str:
        deg = np.degrees
        sym, fmt = ("ψ", lambda v: f"{deg(v):.4f}°") if self.kind == "angle" else ("s", lambda v: f"{v:.6g}")
        return (f"Extremes(extended at φ = {deg(self.phi_extended):.4f}° ({sym} = {fmt(self.extended)}), "
                f"folded at φ = {deg(self.phi_folded):.4f}° ({sym} = {fmt(self.folded)}); stroke {fmt(self.stroke)}; "
                f"the crank turns {deg(self.forward):.4f}° then {deg(self.back):.4f}°: "
                f"time ratio {self.time_ratio:.6f})")


def limit_positions(mechanism, joint: str, extended, folded) -> Extremes:
    """The :class:`Extremes` of a mechanism whose crank turns about the origin.

    ``extended`` and ``folded`` each hold the two mirror candidates for the position of
    the output ``joint`` when crank and coupler lie in line (|O joint| = coupler ± crank);
    the crank then points at the joint (stretched) or away from it (folded). Of each
    pair the one on the mechanism's own assembly branch is kept.
    """
    def on_branch(candidates, turn):
        best = None
        for xy in candidates:
            phi = float(np.mod(np.arctan2(xy[1], xy[0]) + turn, 2 * np.pi))
            mo = mechanism.motion(phi)
            gap = float(np.hypot(*(mo.points[joint].p - np.asarray(xy))))
            if best is None or gap < best[0]:
                best = (gap, phi, float(mo.output.value))
        return best[1:]

    phi_e, out_e = on_branch(extended, 0.0)
    phi_f, out_f = on_branch(folded, np.pi)
    return Extremes(phi_e, phi_f, out_e, out_f, mechanism.output)


@dataclass(frozen=True)
class Quantity:
    """A named value of a design sheet (the unit in the name where it has one).

    Parameters
    ----------
    name : str
        What it is, with its unit: ``"crank, mm"``.
    value : float
        Its value.

    Examples
    --------
    >>> from mechlab import Quantity
    >>> Quantity("crank, mm", 40.0).value
    40.0
    """

    name: str
    value: float


def _cell(value, fmt: str = ".6g") -> str:
    if isinstance(value, bool) or not isinstance(value, Real):
        return str(value)
    return format(float(value), fmt)


@dataclass(frozen=True)
class Table:
    """Rows, each a frozen dataclass of one type; the columns are the rows' shown fields.

    Iterates over its rows, indexes like a tuple, looks rows up by a column (``table.by("z")[4]``), gives
    a column as an array (``table.column("eps_max")``) and shows as an HTML table in a notebook. A field's
    ``metadata={"label": ...}`` names its column for the reader, with its unit (``"α0, °"``), and
    ``metadata={"format": ".3f"}`` its numbers' format (default ``.6g``); ``columns`` keeps the field names.

    Parameters
    ----------
    rows : iterable of dataclass instances
        The rows, all of one frozen dataclass type (kept as a tuple).

    Examples
    --------
    >>> from mechlab import Quantity, Table
    >>> table = Table([Quantity("crank, mm", 40.0), Quantity("rod, mm", 120.0)])
    >>> table
    name       value
    crank, mm     40
    rod, mm      120
    >>> table.column("value")
    array([ 40., 120.])
    """

    rows: tuple

    def __post_init__(self):
        object.__setattr__(self, "rows", tuple(self.rows))

    def __iter__(self):
        return iter(self.rows)

    def __len__(self) -> int:
        return len(self.rows)

    def __getitem__(self, i):
        return self.rows[i]

    @property
    def columns(self) -> tuple[str, ...]:
        """The names of the rows' shown fields.

        Returns
        -------
        tuple of str
            Field names (empty for a table without rows).
        """
        return tuple(f.name for f in fields(self.rows[0]) if f.repr) if self.rows else ()

    @property
    def headers(self) -> tuple[str, ...]:
        """The columns as shown: each field's ``label`` metadata, else its name.

        Returns
        -------
        tuple of str
            One header per column (empty for a table without rows).
        """
        if not self.rows:
            return ()
        return tuple(f.metadata.get("label", f.name) for f in fields(self.rows[0]) if f.repr)

    def column(self, name: str) -> np.ndarray:
        """One column over the rows, as an array.

        Parameters
        ----------
        name : str
            A field name of the rows.

        Returns
        -------
        numpy.ndarray
            The field's value in every row.

        Examples
        --------
        >>> from mechlab import Quantity, Table
        >>> Table([Quantity("a", 1.0), Quantity("b", 2.5)]).column("value")
        array([1. , 2.5])
        """
        return np.array([getattr(r, name) for r in self.rows])

    def by(self, name: str) -> dict:
        """The rows keyed by the values of one column.

        Parameters
        ----------
        name : str
            A field name of the rows.

        Returns
        -------
        dict
            Each row under its value of ``name`` (a later row wins on equal values).

        Examples
        --------
        >>> from mechlab import Quantity, Table
        >>> Table([Quantity("a", 1.0), Quantity("b", 2.5)]).by("name")["b"]
        Quantity(name='b', value=2.5)
        """
        return {getattr(r, name): r for r in self.rows}

    def _text_rows(self) -> list[list[str]]:
        shown = [f for f in fields(self.rows[0]) if f.repr] if self.rows else []
        return [[_cell(getattr(r, f.name), f.metadata.get("format", ".6g")) for f in shown] for r in self.rows]

    def __repr__(self) -> str:
        body = [list(self.headers), *self._text_rows()]
        widths = [max(len(line[i]) for line in body) for i in range(len(self.columns))]
        # numbers right-aligned, words left-aligned
        numeric = [all(isinstance(getattr(r, c), Real) for r in self.rows) for c in self.columns]
        return "\n".join("  ".join(s.rjust(w) if num else s.ljust(w)
                                   for s, w, num in zip(line, widths, numeric, strict=False)).rstrip() for line in body)

    def _repr_html_(self) -> str:
        head = "".join(f"<th>{html.escape(c)}</th>" for c in self.headers)
        body = "".join("<tr>" + "".join(f"<td>{html.escape(s)}</td>" for s in line) + "</tr>"
                       for line in self._text_rows())
        return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"
