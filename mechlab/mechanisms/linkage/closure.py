"""Groups without a closed form in the builder: their two unknowns x solve the group's closure F(x) = 0, by
Newton's method continued over the crank angle from an assembly chosen at the start.

:class:`Tetrad` is the class-IV group of the second order (two ternary links joined by two binary links, a
four-sided contour; Artobolevsky, 1965); :class:`CurvedSlot` is a pin in a curved slot of a link that turns
about a pivot or slides on a guide, :class:`CamFollower` a follower's point riding on a curve fixed on a moving
link (a cam), both higher pairs. All are solved the same way (:class:`_Closure`): once per
linkage, the closure is followed over a grid of 720 crank angles per turn from ``start`` at the crank angle
``at`` (a predictor from the analogs, then Newton); at any crank angles the grid's interpolated solution starts a
vectorised Newton iteration to rounding; the analogs come from the closure differentiated once and twice, two
2×2 linear solves (J·x′ = b′, J·x″ = b″), singular only at a dead position of the group.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated, Any, ClassVar

import numpy as np

from ...errors import DimensionError, StructureError
from ...geometry import AnglePath, _abs2, _im_conj, _re_conj, as_complex, relative, vector_angle
from ...validate import Angle, Checked, Name, Spec, angle, check_value, length, mechanism
from ..base import Link, Pair, Part
from ..curved_slot import CircleSlot, ParametricSlot, SampledSlot
from .groups import Group, Guide, _broadcast, _guide_axis

# Crank angles per turn of the continuation grid; Newton iterations at most; the relative steps that end them on
# the grid and at the crank angles asked (each leaves an error of the order of its square), and the largest step
# a converged row may end with.
GRID = 720
_ITERATIONS = 40
_FOLLOWED, _POLISHED, _CONVERGED = 1e-9, 1e-13, 1e-11
_POINT, _LENGTH, _ANGLE = Spec("point"), length(), angle()


def _solve2(J, b):
    """x with J·x = b for stacks of 2×2 systems (Cramer's rule; NaN where J is singular)."""
    det = J[..., 0, 0] * J[..., 1, 1] - J[..., 0, 1] * J[..., 1, 0]
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.stack([(b[..., 0] * J[..., 1, 1] - J[..., 0, 1] * b[..., 1]) / det,
                         (J[..., 0, 0] * b[..., 1] - J[..., 1, 0] * b[..., 0]) / det], axis=-1), det


def _rows(*rows):
    """A stack of 2×2 matrices from its rows, each a pair of arrays."""
    return np.stack([np.stack(r, axis=-1) for r in rows], axis=-2)


def _complex_system(j1, j2):
    """The real 2×2 matrix of the complex equation j1·x1 + j2·x2 = b (its real and imaginary parts)."""
    return _rows((j1.real, j2.real), (j1.imag, j2.imag))


def _take(known, rows):
    """The known joints' paths at some rows (a slice)."""
    return tuple(tuple(v[rows] for v in path) for path in known)


class _Closure(Group):
    """A group whose two unknowns solve its closure, followed over the crank angle from ``start`` at ``at``.

    A subclass gives ``_known(state)`` (the known joints' complex paths, one value per crank angle),
    ``_system(x, known)`` → (F, J), ``_first(x, known)`` → b′ and ``_second(x, dx, known)`` → b″ with
    J·x′ = b′, J·x″ = b″, ``periods`` (each unknown's period: 2π for an angle, None for a length) and
    ``_write(state, x, dx, ddx, known)``, which places its joints and links.
    """

    periods: tuple = (2 * np.pi, 2 * np.pi)

    def _initial(self, known):
        """The unknowns near which the group is assembled at φ = ``at`` (``known``: one row there)."""
        return np.array([self.start], dtype=float)

    def _valid(self, x):
        """Where the unknowns describe an assembly (finite; a subclass may add limits)."""
        return np.all(np.isfinite(x), axis=-1)

    def _newton(self, x, known, stop=_POLISHED):
        """Newton's iteration from ``x`` until every step is below ``stop`` (relative; the error left is of the
        order of the last step squared); the rows whose last step is not below ``max(stop, 1e-11)`` are NaN."""
        step = np.full_like(x, np.nan)
        for _ in range(_ITERATIONS):
            F, J = self._system(x, known)
            step, _ = _solve2(J, -F)
            x = x + step
            if not np.any(np.abs(step) > stop * (1 + np.abs(x))):
                break
        bad = ~np.all(np.abs(step) <= max(stop, _CONVERGED) * (1 + np.abs(x)), axis=-1)
        x[bad] = np.nan
        return x

    def _follow(self, known, ok, x0, h):
        """The solutions along a grid of crank angles (step h) from x0, up to the first one it cannot reach."""
        xs = [x0]
        for k in range(len(ok) - 1):
            here = _take(known, slice(k, k + 1))
            _, J = self._system(xs[-1], here)
            dx, det = _solve2(J, self._first(xs[-1], here))
            if not ok[k + 1] or not np.all(np.isfinite(dx)) or not self._valid(xs[-1]).all() or \
                    abs(det[0]) <= 1e-9 * (np.abs(J[0, 0, 0] * J[0, 1, 1]) + np.abs(J[0, 0, 1] * J[0, 1, 0])):
                break
            y = self._newton(xs[-1] + h * dx, _take(known, slice(k + 1, k + 2)), stop=_FOLLOWED)
            if not np.all(np.isfinite(y)) or np.any(np.abs(y - xs[-1]) > 0.5) or not self._valid(y).all():
                break
            xs.append(y)
        return np.concatenate(xs)

    def _grid(self, state):
        """(φ's, x's, turns, periodic) of the solution followed over the crank angle; cached per linkage."""
        key = state.element   # this group's place in its linkage (an id could be reused once the linkage is copied)
        if key in state.grids:
            return state.grids[key]
        self._following(True)
        try:
            grid = self._continue(state)
        finally:
            self._following(False)
        state.grids[key] = grid
        return grid

    def _following(self, on: bool) -> None:
        """Called with True before the grid is followed and False after (a subclass may solve a cheaper
        closure there: the grid only starts the Newton iteration at the crank angles asked)."""

    def _continue(self, state):
        h = 2 * np.pi / GRID
        k = np.arange(GRID + 1)
        ahead = state.before(self, self.at + h * k)
        known = self._known(ahead)
        x0 = self._newton(self._initial(_take(known, slice(0, 1))), _take(known, slice(0, 1)))
        grid = None
        if ahead.ok[0] and np.all(np.isfinite(x0)):
            xs = self._follow(known, ahead.ok, x0, h)
            if len(xs) == GRID + 1:
                turns = [0.0 if p is None else np.round((xs[-1, j] - xs[0, j]) / p)
                         for j, p in enumerate(self.periods)]
                closing = xs[-1] - xs[0] - np.array([t * (p or 0.0) for t, p in zip(turns, self.periods, strict=True)])
                if np.all(np.abs(closing) <= 1e-8 * (1 + np.abs(xs[0]))):
                    grid = (self.at + h * k, xs, np.array(turns), True)
            if grid is None:   # not round a whole turn: follow it backwards too
                back = state.before(self, self.at - h * k)
                xb = self._follow(self._known(back), back.ok, x0, -h)[::-1]
                xs = xs[:min(len(xs), GRID + 2 - len(xb))]
                phis = self.at + h * np.arange(1 - len(xb), len(xs))
                grid = (phis, np.concatenate([xb, xs[1:]]), np.zeros(2), False)
        return grid

    def _guess(self, state):
        """The grid's solution interpolated at the state's crank angles, and where the grid reaches them."""
        grid = self._grid(state)
        if grid is None:
            return np.full((state.n, 2), np.nan), np.zeros(state.n, dtype=bool)
        phis, xs, turns, periodic = grid
        lo = phis[0]
        local = lo + np.mod(state.phi - lo, 2 * np.pi)
        x = np.stack([np.interp(local, phis, xs[:, j]) for j in range(2)], axis=-1)
        if periodic:
            laps = np.floor((state.phi - lo) / (2 * np.pi))
            x += laps[:, None] * turns * np.array([p or 0.0 for p in self.periods])
            return x, np.ones(state.n, dtype=bool)
        # a crank angle up to one step beyond either end of the grid starts from the end's solution
        h = 2 * np.pi / GRID
        below = local > lo + 2 * np.pi - h
        x[below] = xs[0]
        return x, below | (local <= phis[-1] + h)

    def place(self, state, carrier):
        guess, reached = self._guess(state)
        known = self._known(state)
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            x = self._newton(guess.copy(), known)
            good = reached & np.all(np.abs(x - guess) < 0.5, axis=-1) & self._valid(x)
            state.closes(good, self, lambda i: self._failure(state))
            _, J = self._system(x, known)
            dx, det = _solve2(J, self._first(x, known))
            state.dead(det, self)
            ddx, _ = _solve2(J, self._second(x, dx, known))
        state.solved[id(self)] = x
        self._write(state, x, dx, ddx, known)

    def _failure(self, state) -> str:
        grid = self._grid(state)
        if grid is None:
            return f"it cannot be assembled near start = {self.start} at φ = {np.degrees(self.at):.2f}°"
        if grid[3]:
            return "it cannot follow the crank there"
        return (f"followed from its assembly at φ = {np.degrees(self.at):.2f}°, it reaches only φ ∈ "
                f"[{np.degrees(grid[0][0]):.2f}°, {np.degrees(grid[0][-1]):.2f}°] (a dead position or the end "
                f"of a slot beyond)")


def _check_point(name, value):
    return complex(*check_value(name, value, _POINT))


@dataclass(frozen=True)
class Tetrad(_Closure, Checked):
    """The class-IV group of the second order: two ternary links on the known joints ``first`` and ``second``,
    joined by two binary links; its closed contour Q-R-T-P has four sides.

    The first link turns about ``first`` and carries Q and P; the second turns about ``second`` and carries R and T
    (``joints`` = (Q, P, R, T)); the binary links are Q-R and P-T. Each ternary link's joints are given in its own
    frame (origin at its outer joint, x axis at the link's angle θ); the unknowns are the two angles, solved from
    |Q - R| = l₁, |P - T| = l₂ (Newton with continuation over φ from ``start`` at the crank angle ``at``).

    Parameters
    ----------
    first, second : str
        The known joints the two ternary links turn about.
    joints : sequence of str
        The new joints Q, P (on the first link) and R, T (on the second).
    on_first, on_second : sequence of (float, float)
        Q and P in the first link's frame, R and T in the second's (lengths).
    lengths : (float, float)
        |QR| and |PT|, the binary links (positive lengths).
    start : (float, float)
        The two ternary links' angles (radians) near which the group is assembled at φ = ``at``.
    at : float, optional
        The crank angle of ``start`` (radians).
    links : sequence of str, optional
        The first ternary link's, the binary links Q-R and P-T, and the second ternary link's names (default
        "AQP", "QR", "PT", "ERT" for first A, second E).

    Raises
    ------
    DimensionError
        For a point that is not two finite numbers, a length that is not positive, or a ternary link whose two
        joints coincide.
    StructureError
        For ``joints`` that are not four names or ``links`` that are not four.

    Examples
    --------
    >>> g = Tetrad("A", "E", ("Q", "P", "R", "T"), ((-0.2, 0.55), (0.7, 0.55)), ((0.55, 0.45), (1.35, 0.15)),
    ...            (0.25, 0.85), (0.0, 0.0))
    >>> g.link_names(), g.assur_class
    (('AQP', 'QR', 'PT', 'ERT'), 4)
    """

    first: Name
    second: Name
    joints: Annotated[Any, Spec("items", expected=str)]
    on_first: Any
    on_second: Any
    lengths: Any
    start: Any
    at: Angle = 0.0
    links: Annotated[Any, Spec("items", expected=str, optional=True)] = None

    kind: ClassVar[str] = "tetrad"
    assur_class: ClassVar[int] = 4

    def __post_init__(self):
        super().__post_init__()
        if len(self.joints) != 4:
            raise StructureError(f"joints of a tetrad: four names (Q, P, R, T), got {self.joints!r}")
        if self.links is not None and len(self.links) != 4:
            raise StructureError(f"links of a tetrad: four names, got {self.links!r}")
        pts = []
        for what, pair in (("on_first", self.on_first), ("on_second", self.on_second)):
            if not isinstance(pair, tuple | list) or len(pair) != 2:
                raise DimensionError(f"{what} must be two points ((x, y), (x, y)), got {pair!r:.60}")
            one, two = (_check_point(what, p) for p in pair)
            if one == two:
                raise DimensionError(f"{what}: the link's two joints coincide at {pair[0]!r}")
            pts += [one, two]
        if not isinstance(self.lengths, tuple | list) or len(self.lengths) != 2:
            raise DimensionError(f"lengths must be |QR| and |PT|, got {self.lengths!r:.60}")
        lengths = tuple(check_value("lengths", v, _LENGTH) for v in self.lengths)
        if not isinstance(self.start, tuple | list) or len(self.start) != 2:
            raise DimensionError(f"start must be the two ternary links' angles, got {self.start!r:.60}")
        start = tuple(check_value("start", v, _ANGLE) for v in self.start)
        object.__setattr__(self, "_consts", (*pts, *lengths))
        object.__setattr__(self, "start", start)

    def needs(self):
        return (self.first, self.second)

    def makes(self):
        return tuple(self.joints)

    def carriers(self, names):
        """The link each new joint is fixed on: Q and P on the first ternary link, R and T on the second.

        Parameters
        ----------
        names : tuple of str
            This group's link names.

        Returns
        -------
        dict
            Joint → link.
        """
        Q, P, R, T = self.joints
        return {Q: names[0], P: names[0], R: names[3], T: names[3]}

    def link_names(self):
        Q, P, R, T = self.joints
        if self.links is not None:
            return tuple(self.links)
        return (self.first + Q + P, Q + R, P + T, self.second + R + T)

    def _axis(self, origin, joint, offset):
        def axis(motion):
            th = vector_angle(relative(motion.points[joint], motion.points[origin]))
            return th.theta - offset, th.d, th.dd
        return axis

    def structure(self, carrier, links):
        Q, P, R, T = self.joints
        q, p, r, t, l1, l2 = self._consts
        one, qr, pt, two = self.link_names()
        # each ternary link's axis: the direction to its farther joint, turned back by that joint's polar angle
        a1 = max((q, Q), (p, P), key=lambda v: abs(v[0]))
        a2 = max((r, R), (t, T), key=lambda v: abs(v[0]))
        return ((Link(one, self.first, self._axis(self.first, a1[1], float(np.angle(a1[0]))), abs(a1[0]),
                      joints=(self.first, Q, P, self.first)),
                 Link(qr, Q, (Q, R), l1, joints=(Q, R)), Link(pt, P, (P, T), l2, joints=(P, T)),
                 Link(two, self.second, self._axis(self.second, a2[1], float(np.angle(a2[0]))), abs(a2[0]),
                      joints=(self.second, R, T, self.second))),
                (Pair("revolute", self.first, carrier(self.first), one, self.first),
                 Pair("revolute", Q, one, qr, Q), Pair("revolute", P, one, pt, P),
                 Pair("revolute", R, qr, two, R), Pair("revolute", T, pt, two, T),
                 Pair("revolute", self.second, carrier(self.second), two, self.second)))

    # -- the closure |Q - R|² = l₁², |P - T|² = l₂², halved -----------------------------------------------
    def _known(self, state):
        return tuple(tuple(_broadcast(v, state.n) for v in state.z(j)) for j in (self.first, self.second))

    def _joints(self, x, known):
        (A, _, _), (E, _, _) = known
        q, p, r, t = self._consts[:4]
        e1, e2 = np.exp(1j * x[..., 0]), np.exp(1j * x[..., 1])
        return A + e1 * q, A + e1 * p, E + e2 * r, E + e2 * t

    def _system(self, x, known):
        (A, _, _), (E, _, _) = known
        Q, P, R, T = self._joints(x, known)
        l1, l2 = self._consts[4:]
        w1, w2 = Q - R, P - T
        F = 0.5 * np.stack([_abs2(w1) - l1 * l1, _abs2(w2) - l2 * l2], axis=-1)
        J = _rows((_re_conj(w1, 1j * (Q - A)), -_re_conj(w1, 1j * (R - E))),
                  (_re_conj(w2, 1j * (P - A)), -_re_conj(w2, 1j * (T - E))))
        return F, J

    def _first(self, x, known):
        (_, dA, _), (_, dE, _) = known
        Q, P, R, T = self._joints(x, known)
        return -np.stack([_re_conj(Q - R, dA - dE), _re_conj(P - T, dA - dE)], axis=-1)

    def _rates(self, x, dx, known):
        """Q, P, R, T and their first analogs."""
        (A, dA, _), (E, dE, _) = known
        Q, P, R, T = self._joints(x, known)
        w1, w2 = 1j * dx[..., 0], 1j * dx[..., 1]
        return (Q, P, R, T), (dA + w1 * (Q - A), dA + w1 * (P - A), dE + w2 * (R - E), dE + w2 * (T - E))

    def _second(self, x, dx, known):
        (A, _, ddA), (E, _, ddE) = known
        (Q, P, R, T), (dQ, dP, dR, dT) = self._rates(x, dx, known)
        s1, s2 = dx[..., 0] ** 2, dx[..., 1] ** 2
        return -np.stack([_abs2(dQ - dR) + _re_conj(Q - R, ddA - s1 * (Q - A) - ddE + s2 * (R - E)),
                          _abs2(dP - dT) + _re_conj(P - T, ddA - s1 * (P - A) - ddE + s2 * (T - E))], axis=-1)

    def _write(self, state, x, dx, ddx, known):
        (A, _, ddA), (E, _, ddE) = known
        joints, rates = self._rates(x, dx, known)
        for name, z, dz, origin, ddo, j in zip(self.joints, joints, rates, (A, A, E, E), (ddA, ddA, ddE, ddE),
                                               (0, 0, 1, 1), strict=True):
            r = z - origin
            state.points[name] = state.path(z, dz, ddo + (1j * ddx[:, j] - dx[:, j] ** 2) * r)
        one, _, _, two = self.link_names()
        state.link(one, self.first, AnglePath(x[:, 0], dx[:, 0], ddx[:, 0]))
        state.link(two, self.second, AnglePath(x[:, 1], dx[:, 1], ddx[:, 1]))
        Q, P, R, T = self.joints
        for (start, end), name in zip(((Q, R), (P, T)), self.link_names()[1:3], strict=True):
            state.link(name, start, vector_angle(relative(state.points[end], state.points[start])))

    def transmission(self, state):
        """μ of the inner four-bar at P: the angle between P→Q (on the first link) and P→T (the binary link).

        Parameters
        ----------
        state : State
            The placed linkage.

        Returns
        -------
        numpy.ndarray
            μ (radians) at every crank angle.
        """
        Q, P, _, T = (as_complex(state.points[j].p) for j in self.joints)
        return np.arccos(np.clip(_re_conj(Q - P, T - P) / (np.abs(Q - P) * np.abs(T - P)), -1.0, 1.0))


# a slot curve of mechlab.mechanisms.curved_slot
SlotSpec = Annotated[Any, mechanism((CircleSlot, ParametricSlot, SampledSlot), error=DimensionError)]
# samples of a slot searched for the parameter of a point on it, and interpolated while the grid is followed
_SAMPLES, _TABLE = 2049, 4097


class _OnCurve(_Closure):
    """A group whose closure holds a joint on a curve (``curve``: c(t) in its link's frame); the unknowns are a
    coordinate of a link and the curve parameter t."""

    def _curve_link(self) -> str:
        """The name of the link the curve is fixed on."""
        raise NotImplementedError

    def _one_support(self, what: str) -> None:
        """StructureError unless exactly one of ``pivot`` and ``guide`` is given; the unknowns' periods."""
        if (self.pivot is None) == (self.guide is None):
            raise StructureError(f"{what} turns about a pivot or slides on a guide: give one of pivot= and guide=, "
                                 f"got pivot={self.pivot!r}, guide={self.guide!r}")
        object.__setattr__(self, "_table", [])
        object.__setattr__(self, "periods", (2 * np.pi if self.guide is None else None,
                                             self.curve.t1 - self.curve.t0 if self.curve.periodic else None))

    def guides(self):
        """The guides this element slides on: the sliding link's guide (none for a turning one).

        Returns
        -------
        tuple of Guide
            The guides.
        """
        return () if self.guide is None else (self.guide,)

    def makes(self):
        return (self.joint,)

    def sliding(self):
        return {} if self.guide is None else {self.link_names()[0]: self.guide}

    def _supported(self, carrier, links, length: float):
        """This group's link, turning about ``pivot`` (its axis to ``joint``, of ``length``) or sliding on
        ``guide`` (its origin ``joint``), and the pair that holds it there."""
        (name,) = self.link_names()
        if self.guide is None:
            return (Link(name, self.pivot, (self.pivot, self.joint), length, joints=(self.pivot, self.joint)),
                    Pair("revolute", self.pivot, carrier(self.pivot), name, self.pivot))
        on = self.guide.link(carrier)
        return (Link(name, self.joint, _guide_axis(self.guide, on, links)),
                Pair("prismatic", f"{name} on {on}", on, name, self.joint, self.guide.angle))

    def drawing(self, motion, structure):
        """The curve carried by its link over the motion.

        Parameters
        ----------
        motion : Motion
            The motion drawn.
        structure : Structure
            The linkage's structure.

        Returns
        -------
        tuple of Part
            One "slot" part, the curve in the fixed frame at each frame.
        """
        link = structure.link(self._curve_link())
        turn = np.atleast_1d(np.exp(1j * link.angle(motion).theta))
        origin = np.broadcast_to(as_complex(motion.points[link.origin].p), turn.shape)   # a pivot is one number
        curve = as_complex(self.curve.points(np.linspace(self.curve.t0, self.curve.t1, 200)))

        def at(i):
            z = origin[i] + turn[i] * curve
            return np.stack([z.real, z.imag], axis=-1)

        return (Part("slot", at),)

    def _following(self, on):
        """While the grid is followed, the curve is its cubic Hermite interpolant on 4097 points (c within about
        1e-11 of the slot's scale; one call of the slot's functions instead of thousands, each of which may solve
        a mechanism's motion for a slot read from one); the crank angles asked are solved on the slot itself."""
        if not on:
            self._table[:] = []
            return
        t = np.linspace(self.curve.t0, self.curve.t1, _TABLE)
        c = self.curve.evaluate(t)
        self._table[:] = [t, as_complex(c.p), as_complex(c.d)]

    @staticmethod
    def _hermite(table, t, periodic):
        """c, c_t (and NaN for c_tt, which the grid does not use) of the interpolant ``table`` at t."""
        grid, c, ct = table
        span = grid[-1] - grid[0]
        if periodic:
            t = grid[0] + np.mod(t - grid[0], span)
        step = span / (len(grid) - 1)
        k = np.clip(np.floor((t - grid[0]) / step).astype(int), 0, len(grid) - 2)
        s = (t - grid[k]) / step
        a, b, da, db = c[k], c[k + 1], step * ct[k], step * ct[k + 1]
        value = (2 * s**3 - 3 * s**2 + 1) * a + (s**3 - 2 * s**2 + s) * da + (3 * s**2 - 2 * s**3) * b + \
            (s**3 - s**2) * db
        slope = ((6 * s**2 - 6 * s) * a + (3 * s**2 - 4 * s + 1) * da + (6 * s - 6 * s**2) * b
                 + (3 * s**2 - 2 * s) * db) / step
        return [value, slope, np.full(t.shape, np.nan + 0j)]

    def _curve(self, t):
        """c, c_t, c_tt (complex) at the finite rows of t (NaN elsewhere)."""
        out = [np.full(t.shape, np.nan + 0j) for _ in range(3)]
        finite = np.isfinite(t)
        if finite.any():
            table = list(self._table)   # read once: another thread may end its own following meanwhile
            values = self._hermite(table, t[finite], self.curve.periodic) if table else \
                (as_complex(v) for v in self.curve.evaluate(t[finite]))
            for k, v in enumerate(values):
                out[k][finite] = v
        return out

    def parameter(self, local) -> np.ndarray:
        """The curve parameter t of points on the curve given in its link's frame.

        Parameters
        ----------
        local : array of complex
            Points on the curve, x + iy in its link's frame.

        Returns
        -------
        numpy.ndarray
            t of each (the nearest of 2049 samples, refined by Newton's method on (c(t) - point)·c_t(t) = 0).

        Examples
        --------
        >>> import mechlab as ml
        >>> g = CurvedSlot("A", ml.CircleSlot((3.0, 0.0), 3.0), "K", pivot="B", start=1.0)
        >>> round(float(g.parameter(np.array([3.0 + 3.0j]))[0]), 12)
        1.570796326795
        """
        c0, c1 = self.curve.t0, self.curve.t1
        grid = np.linspace(c0, c1, _SAMPLES)
        pts = as_complex(self.curve.points(grid))
        t = grid[np.argmin(np.abs(pts[None, :] - local[:, None]), axis=1)]
        for _ in range(8):
            c, ct, ctt = self._curve(t)
            g, dg = _re_conj(c - local, ct), _abs2(ct) + _re_conj(c - local, ctt)
            t = t - g / dg
            if not self.curve.periodic:
                t = np.clip(t, c0, c1)
        return t

    def tangent(self, motion, link: Link, point: str) -> np.ndarray:
        """The curve's tangent c_t at ``point``, in the fixed frame, over a motion.

        Parameters
        ----------
        motion : Motion
            A motion of the linkage.
        link : Link
            The link carrying the curve (its origin and axis).
        point : str
            The joint on the curve.

        Returns
        -------
        numpy.ndarray
            Complex tangents, one per crank angle.
        """
        turn = np.exp(1j * link.angle(motion).theta)
        local = (as_complex(motion.points[point].p) - as_complex(motion.points[link.origin].p)) / turn
        return self._curve(self.parameter(local))[1] * turn

    def _valid(self, x):
        ok = np.all(np.isfinite(x), axis=-1)
        if not self.curve.periodic:
            ok &= (x[..., 1] >= self.curve.t0) & (x[..., 1] <= self.curve.t1)
        return ok



@dataclass(frozen=True)
class CurvedSlot(_OnCurve, Checked):
    """The known joint ``pin`` runs in a curved slot of a link that turns about the known joint ``pivot`` or
    slides on ``guide`` (give one): a higher pair, one link, W = 3 - 2 - 1 = 0.

    The slot is ``curve`` (a :class:`~mechlab.CircleSlot`, :class:`~mechlab.ParametricSlot` or
    :class:`~mechlab.SampledSlot`: c(t) in the link's frame, whose origin is the pivot, or the new joint ``joint`` on
    the guide for a sliding link). The unknowns, the link's angle θ (or its displacement s along the guide) and the
    slot parameter t of the pin, solve origin + Rot(θ)·c(t) = pin, by Newton's method continued over φ from
    the pin at ``start`` on the slot at the crank angle ``at``.

    Parameters
    ----------
    pin : str
        The known joint running in the slot.
    curve : SlotCurve
        The slot in the link's frame.
    joint : str
        The new joint: for a turning link the point (ℓ, 0) of its frame, ℓ = |c(start)| (its arm is drawn to it);
        for a sliding link its origin, on the guide.
    pivot : str, optional
        The known joint the link turns about.
    guide : Guide, optional
        The straight guide the link slides on.
    start : float, optional
        The slot parameter t near which the pin lies at φ = ``at``.
    at : float, optional
        The crank angle of ``start`` (radians).
    link : str, optional
        The slotted link's name (default "slotted K" for joint K).

    Raises
    ------
    StructureError
        With neither or both of ``pivot`` and ``guide``.
    DimensionError
        For a curve that is not a slot curve, or a turning link whose slot passes through the pivot at ``start``.

    Examples
    --------
    >>> import mechlab as ml
    >>> CurvedSlot("A", ml.CircleSlot((3.0, 0.0), 3.0), "K", pivot="B", start=1.0).link_names()
    ('slotted K',)
    """

    pin: Name
    curve: SlotSpec
    joint: Name
    pivot: Annotated[str | None, Spec("text", optional=True)] = None
    guide: Annotated[Any, mechanism(Guide, optional=True)] = None
    start: Angle = 0.0
    at: Angle = 0.0
    link: Annotated[str | None, Spec("text", optional=True)] = None

    kind: ClassVar[str] = "slot"

    def __post_init__(self):
        super().__post_init__()
        self._one_support("a curved slot's link")
        reach = float(np.abs(as_complex(self.curve.points(np.array([self.start])))[0]))
        if self.pivot is not None and reach == 0.0:
            raise DimensionError(f"the slot passes through the pivot at start = {self.start:g}: give a start "
                                 "where the pin is off the pivot")
        object.__setattr__(self, "_reach", reach)

    def needs(self):
        return (self.pin, self.pivot) if self.guide is None else (self.pin, self.guide.through)

    def link_names(self):
        return (self.link or f"slotted {self.joint}",)

    def _curve_link(self):
        return self.link_names()[0]

    def structure(self, carrier, links):
        (name,) = self.link_names()
        link, support = self._supported(carrier, links, self._reach)

        def normal(motion):
            tangent = self.tangent(motion, link, self.pin)
            return np.stack([-tangent.imag, tangent.real], axis=-1) / np.abs(tangent)[:, None]

        return ((link,), (Pair("higher", f"{self.pin} in {name}", name, carrier(self.pin), self.pin, normal=normal),
                          support))

    # -- the closure origin + Rot(θ)·c(t) = pin ---------------------------------------------------------------
    def _known(self, state):
        pin = tuple(_broadcast(v, state.n) for v in state.z(self.pin))
        if self.guide is None:
            zero = np.zeros(state.n)
            return pin, tuple(_broadcast(v, state.n) for v in state.z(self.pivot)), (zero, zero, zero)
        Q, th = self.guide.line(state, state.carrier)
        return pin, tuple(_broadcast(v, state.n) for v in Q), tuple(_broadcast(v, state.n) for v in th)

    def _initial(self, known):
        (A, _, _), (O, _, _), (th, _, _) = known
        c = as_complex(self.curve.points(np.array([self.start])))
        if self.guide is None:
            return np.stack([np.angle(A - O) - np.angle(c), np.full(1, self.start)], axis=-1)
        u = np.exp(1j * th)
        return np.stack([_re_conj(u, A - O) - _re_conj(u, u * c), np.full(1, self.start)], axis=-1)

    def _frame(self, x, known):
        """The link's origin and orientation e = exp(iθ), with the slot's c, c_t, c_tt at t."""
        (_, _, _), (O, _, _), (th, _, _) = known
        c = self._curve(x[..., 1])
        if self.guide is None:
            return O, np.exp(1j * x[..., 0]), c
        u = np.exp(1j * th)
        return O + x[..., 0] * u, u, c

    def _system(self, x, known):
        A = known[0][0]
        O, e, (c, ct, _) = self._frame(x, known)
        J = _complex_system(1j * e * c if self.guide is None else e, e * ct)
        F = O + e * c - A
        return np.stack([F.real, F.imag], axis=-1), J

    def _first(self, x, known):
        (_, dA, _), (_, dO, _), (_, w, _) = known
        O, e, (c, _, _) = self._frame(x, known)
        b = dA - dO - (0 if self.guide is None else 1j * w * (O - known[1][0] + e * c))
        return np.stack([b.real, b.imag], axis=-1)

    def _second(self, x, dx, known):
        (_, _, ddA), (Q, _, ddO), (_, w, dw) = known
        O, e, (c, ct, ctt) = self._frame(x, known)
        d1, dt = dx[..., 0], dx[..., 1]
        if self.guide is None:
            b = ddA - ddO + e * c * d1**2 - 2j * e * ct * d1 * dt - e * ctt * dt**2
        else:
            b = (ddA - ddO - (1j * dw - w**2) * (O - Q + e * c) - 2j * w * e * (d1 + ct * dt)
                 - e * ctt * dt**2)
        return np.stack([b.real, b.imag], axis=-1)

    def _write(self, state, x, dx, ddx, known):
        (_, _, _), (Q, dQ, ddQ), (th, w, dw) = known
        (name,) = self.link_names()
        if self.guide is None:
            e = np.exp(1j * x[:, 0])
            r = self._reach * e
            state.points[self.joint] = state.path(Q + r, dQ + 1j * dx[:, 0] * r,
                                                  ddQ + (1j * ddx[:, 0] - dx[:, 0] ** 2) * r)
            state.link(name, self.pivot, AnglePath(x[:, 0], dx[:, 0], ddx[:, 0]))
            return
        u = np.exp(1j * th)
        s, ds, dds = x[:, 0], dx[:, 0], ddx[:, 0]
        state.points[self.joint] = state.path(Q + s * u, dQ + (ds + 1j * w * s) * u,
                                              ddQ + (dds + 2j * w * ds + (1j * dw - w**2) * s) * u)
        state.link(name, self.joint, AnglePath(th, w, dw))

    def transmission(self, state):
        """μ between the slot's tangent at the pin and the direction the link's point under the pin can move:
        the radius from the pivot (μ = 90° - the pressure angle), or the guide's normal for a sliding link.

        Parameters
        ----------
        state : State
            The placed linkage.

        Returns
        -------
        numpy.ndarray
            μ (radians) at every crank angle.
        """
        x = state.solved[id(self)]
        known = self._known(state)
        _, e, (_, ct, _) = self._frame(x, known)
        tangent = e * ct
        if self.guide is None:
            radius = known[0][0] - known[1][0]
            cos = np.abs(_re_conj(tangent, radius)) / (np.abs(tangent) * np.abs(radius))
        else:
            cos = np.abs(_im_conj(tangent, np.exp(1j * known[2][0]))) / np.abs(tangent)
        return np.arcsin(np.clip(cos, 0.0, 1.0))


@dataclass(frozen=True)
class CamFollower(_OnCurve, Checked):
    """A follower whose point ``joint`` (a roller's centre) rides on the curve ``curve`` fixed on the known link
    ``on`` (a cam's pitch curve): the follower turns about the known joint ``pivot`` on an arm of length ``arm``, or
    slides on ``guide`` with ``joint`` on the guide's line. A higher pair, one link, W = 3 - 2 - 1 = 0.

    The unknowns, the arm's angle ψ (or the displacement s along the guide) and the curve parameter u of the contact,
    solve origin_on + Rot(θ_on)·c(u) = joint, by Newton's method continued over φ from the contact at ``start`` on the
    curve at the crank angle ``at``.

    Parameters
    ----------
    curve : SlotCurve
        The curve in the frame of the link ``on`` (origin at its origin joint, x along its axis).
    on : str
        The known link carrying the curve (the cam).
    joint : str
        The new joint on the curve: the follower's roller centre.
    pivot : str, optional
        The known joint the follower's arm turns about.
    arm : float, optional
        |pivot joint|, with ``pivot`` (positive length).
    guide : Guide, optional
        The straight guide the follower slides on; ``joint`` moves on its line.
    start : float, optional
        The curve parameter near which the contact lies at φ = ``at``.
    at : float, optional
        The crank angle of ``start`` (radians).
    link : str, optional
        The follower's name (default "follower").

    Raises
    ------
    StructureError
        With neither or both of ``pivot`` and ``guide``.
    DimensionError
        For a curve that is not a slot curve, or an arm that is not a positive length with a pivot.

    Examples
    --------
    >>> import mechlab as ml
    >>> CamFollower(ml.CircleSlot((0.5, 0.0), 2.0), "cam", "C", guide=ml.Guide("F", np.pi / 2)).link_names()
    ('follower',)
    """

    curve: SlotSpec
    on: Name
    joint: Name
    pivot: Annotated[str | None, Spec("text", optional=True)] = None
    arm: Annotated[float, length(zero=True)] = 0.0
    guide: Annotated[Any, mechanism(Guide, optional=True)] = None
    start: Angle = 0.0
    at: Angle = 0.0
    link: Annotated[str | None, Spec("text", optional=True)] = None

    kind: ClassVar[str] = "cam"

    def __post_init__(self):
        super().__post_init__()
        self._one_support("a cam follower")
        if self.pivot is not None and not self.arm > 0:
            raise DimensionError(f"arm must be a positive length with a pivot, got {self.arm!r}")

    def needs(self):
        return (self.pivot,) if self.guide is None else (self.guide.through,)

    def uses(self):
        """The links this element needs defined before it: the one carrying the curve.

        Returns
        -------
        tuple of str
            ``(on,)``.
        """
        return (self.on,)

    def link_names(self):
        return (self.link or "follower",)

    def _curve_link(self):
        return self.on

    def structure(self, carrier, links):
        (name,) = self.link_names()
        link, support = self._supported(carrier, links, self.arm)
        cam = links[self.on]

        def normal(motion):
            tangent = self.tangent(motion, cam, self.joint)
            return np.stack([-tangent.imag, tangent.real], axis=-1) / np.abs(tangent)[:, None]

        return ((link,), (Pair("higher", f"{self.joint} on {self.on}", self.on, name, self.joint, normal=normal),
                          support))

    # -- the closure origin_on + Rot(θ_on)·c(u) = joint -------------------------------------------------------
    def _known(self, state):
        cam = tuple(_broadcast(v, state.n) for v in state.z(state.origins[self.on]))
        turn = tuple(_broadcast(v, state.n) for v in state.angles[self.on])
        if self.guide is None:
            zero = np.zeros(state.n)
            return cam, turn, tuple(_broadcast(v, state.n) for v in state.z(self.pivot)), (zero, zero, zero)
        Q, th = self.guide.line(state, state.carrier)
        return cam, turn, tuple(_broadcast(v, state.n) for v in Q), tuple(_broadcast(v, state.n) for v in th)

    def _contact(self, x, known):
        """The contact on the curve (its point, e·c_u, e·c_uu with e = exp(iθ_on)) and the follower's point C with
        dC/dx₁ (i(C - pivot) or the guide's direction)."""
        (O, _, _), (th, _, _), (B, _, _), (tg, _, _) = known
        e = np.exp(1j * th)
        c, cu, cuu = self._curve(x[..., 1])
        if self.guide is None:
            C = B + self.arm * np.exp(1j * x[..., 0])
            return O + e * c, e * cu, e * cuu, C, 1j * (C - B)
        u = np.exp(1j * tg)
        return O + e * c, e * cu, e * cuu, B + x[..., 0] * u, u

    def _initial(self, known):
        (O, _, _), (th, _, _), (B, _, _), (tg, _, _) = known
        K = O + np.exp(1j * th) * as_complex(self.curve.points(np.array([self.start])))
        first = np.angle(K - B) if self.guide is None else _re_conj(np.exp(1j * tg), K - B)
        return np.stack([first, np.full(1, self.start)], axis=-1)

    def _system(self, x, known):
        K, Ku, _, C, Cx = self._contact(x, known)
        F = K - C
        return np.stack([F.real, F.imag], axis=-1), _complex_system(-Cx, Ku)

    def _first(self, x, known):
        (O, dO, _), (_, w, _), (B, dB, _), (_, wg, _) = known
        K, _, _, C, _ = self._contact(x, known)
        b = dB - dO - 1j * w * (K - O) + (0 if self.guide is None else 1j * wg * (C - B))
        return np.stack([b.real, b.imag], axis=-1)

    def _second(self, x, dx, known):
        (O, _, ddO), (_, w, dw), (B, _, ddB), (_, wg, dwg) = known
        K, Ku, Kuu, C, Cx = self._contact(x, known)
        d1, du = dx[..., 0], dx[..., 1]
        # the follower's point: -ψ′²(C - B) on an arm; along a guide turning at wg, Coriolis and the guide's turn
        own = -(d1**2) * (C - B) if self.guide is None else 2j * wg * Cx * d1 + (1j * dwg - wg**2) * (C - B)
        b = ddB - ddO - (1j * dw - w**2) * (K - O) - 2j * w * Ku * du - Kuu * du**2 + own
        return np.stack([b.real, b.imag], axis=-1)

    def _write(self, state, x, dx, ddx, known):
        (_, _, _), (_, _, _), (B, dB, ddB), (tg, wg, dwg) = known
        (name,) = self.link_names()
        _, _, _, C, Cx = self._contact(x, known)
        if self.guide is None:
            r = C - B
            state.points[self.joint] = state.path(C, dB + 1j * dx[:, 0] * r, ddB + (1j * ddx[:, 0] - dx[:, 0] ** 2) * r)
            state.link(name, self.pivot, AnglePath(x[:, 0], dx[:, 0], ddx[:, 0]))
            return
        s, ds, dds = x[:, 0], dx[:, 0], ddx[:, 0]
        state.points[self.joint] = state.path(C, dB + (ds + 1j * wg * s) * Cx,
                                              ddB + (dds + 2j * wg * ds + (1j * dwg - wg**2) * s) * Cx)
        state.link(name, self.joint, AnglePath(tg, wg, dwg))

    def transmission(self, state):
        """μ = 90° - |α|, α the pressure angle between the contact's normal and the direction the follower's
        point moves (the arm's normal, or the guide).

        Parameters
        ----------
        state : State
            The placed linkage.

        Returns
        -------
        numpy.ndarray
            μ (radians) at every crank angle.
        """
        _, Ku, _, _, Cx = self._contact(state.solved[id(self)], self._known(state))
        return np.arccos(np.clip(np.abs(_re_conj(Ku, Cx)) / (np.abs(Ku) * np.abs(Cx)), 0.0, 1.0))
