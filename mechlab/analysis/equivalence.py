"""Kinematic equivalence of linkages with one second-order group and curved-slot slotted links; the
base mechanism; the symmetry of the two assemblies (Zinchenko et al. (2013), §1, Figs. 1-6).

A crank, the frame and one second-order group (a dyad, or the class-IV group of
:mod:`mechlab.mechanisms.sixbar_iv`) leave one degree of freedom relative to the output link, so the
pin A traces a fixed curve in the output's frame, the **relative path** (:func:`relative_path`):
a circle of radius l_AB for the four-bar (Fig. 2) and the slider-crank (Fig. 4), a coupler curve for
the class-IV six-bar. A slotted link with that slot, pivoted like the output, moves exactly like it
(:func:`equivalent_slot`, :class:`EquivalentSlot`). :func:`base_mechanism` and :func:`base_law` give
the straight-slot base mechanism (Figs. 5-6) in the mechanism's own frame;
:func:`assembly_symmetry` checks the relations between the k_c = +1 and -1 assemblies (after Fig. 6,
derived here). The book's first chapters derive all three.
"""

from __future__ import annotations

import numbers
from dataclasses import dataclass, fields, replace
from typing import Annotated

import numpy as np

from ..errors import DimensionError
from ..geometry import AnglePath, PointPath, as_angles, wrap
from ..mechanisms.base import FULL_TURN, AnyMechanism, Mechanism, Structure
from ..mechanisms.curved_slot import pin_relative_path, slot_sketch
from ..mechanisms.fourbar import FourBar
from ..mechanisms.slotted import SineMechanism, SlottedLink
from ..motion import AngularMotion, LinearMotion, Motion, scalar_law
from ..validate import Angles, Real, validated
from ..validate import mechanism as instance_of

AnyMotion = Annotated[Motion, instance_of(Motion)]


def _output_pivot(mechanism) -> str:
    """The fixed joint the output link turns about: the pivot other than the crank's O."""
    others = [p for p in mechanism.pivots if p != "O"]
    if mechanism.output != "angle" or len(others) != 1:
        raise DimensionError(f"{type(mechanism).__name__} has no output link turning about one fixed pivot "
                             f"(pivots {', '.join(mechanism.pivots)})")
    return others[0]


def _pivot_position(mechanism) -> np.ndarray:
    """Where the output link's fixed pivot is (it does not move: read at one crank angle)."""
    phi = mechanism.cycle(3)[1:2]
    return mechanism.motion(phi).points[_output_pivot(mechanism)].p[0]


def _rot(angle, v):
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]], axis=-1)


# ---------------------------------------------------------------------------------------------
# relative path
# ---------------------------------------------------------------------------------------------
@scalar_law
@validated
def relative_path(mechanism: AnyMechanism, phi: Angles) -> PointPath:
    """The crank pin seen from the output link, with its φ-analogs (Zinchenko et al. (2013) §1, Fig. 1-4).

    The pin, the output link and its pivot or guide are read from the mechanism's ``structure()``
    (:func:`mechlab.mechanisms.curved_slot.pin_relative_path`). Angular output about pivot P:
    w = Rot(-ψ)(A - P), w' = Rot(-ψ)(v' - ψ'·v⊥), w'' = Rot(-ψ)(v'' - 2ψ'·v'⊥ - ψ''·v⊥ - ψ'²·v) with v = A - P.
    Output sliding on a guide at γ: w = Rot(-γ)(A - O) - (s, 0), the analogs likewise.

    Parameters
    ----------
    mechanism : Mechanism
        A mechanism whose ``structure()`` has a crank pin jointed to a moving link.
    phi : float or array_like
        Crank angles (rad).

    Returns
    -------
    PointPath
        The pin's position in the output link's frame and its first and second φ-analogs.

    Raises
    ------
    TypeError
        ``mechanism`` is not a Mechanism.
    DimensionError
        ``phi`` is not finite, or the crank pin is not jointed to a moving link.
    AssemblyError
        The linkage cannot be assembled at a requested crank angle.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> from mechlab.analysis.equivalence import relative_path
    >>> w = relative_path(ml.FourBar(1, 3, 3, 4), np.linspace(0.0, 6.0, 7))
    >>> np.round(np.hypot(*(w.p - [3.0, 0.0]).T), 12)  # a circle of radius l_AB = 3 about B
    array([3., 3., 3., 3., 3., 3., 3.])
    """
    return pin_relative_path(mechanism, as_angles(phi))


# ---------------------------------------------------------------------------------------------
# the equivalent curved-slot mechanism
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class EquivalentSlot(Mechanism):
    """A linkage's curved-slot twin, expressed in the linkage's own frame.

    ``slot_mechanism`` is the curved-slot link in Zinchenko et al.'s (2013) frame; its crank angle is
    the linkage's minus ``phase`` (π for four-bars and six-bars, whose output pivot E
    lies on +x, 0 for the slider-crank), and its link angle is the linkage's minus ``phase``.
    Points: O, A and the pivot E (angular) or C = (s, 0) (translating).
    """

    @classmethod
    def example(cls) -> EquivalentSlot:
        """The curved-slot twin of ``FourBar.example()``.

        Returns
        -------
        EquivalentSlot
            A valid instance of the family, the one the services that find the families use.
        """
        return equivalent_slot(FourBar.example())

    linkage: AnyMechanism
    slot_mechanism: AnyMechanism
    phase: Real = 0.0

    @property
    def crank(self) -> float:
        return self.slot_mechanism.crank

    @property
    def pivots(self):
        return ("O", "E") if self.output == "angle" else ("O",)

    @property
    def output(self):
        return self.slot_mechanism.output

    def crank_ranges(self):
        ranges = self.slot_mechanism.crank_ranges()
        if ranges == FULL_TURN or self.phase == 0.0:
            return ranges
        return tuple((s + self.phase, e + self.phase) for s, e in ranges)

    def rotation_failure(self) -> str:
        return self.slot_mechanism.rotation_failure()

    def structure(self) -> Structure:
        """The curved-slot link's structure in the linkage's frame: its pivot B named E, the slot's normal at the
        pin turned by ``phase`` (a translating twin's is its curved-slot link's own)."""
        st = self.slot_mechanism.structure()
        if self.output == "position":
            return st

        def named(point):
            return "E" if point == "B" else point

        def turned(normal):
            return lambda mo: _rot(self.phase, normal(self.slot_mechanism.motion(mo.phi - self.phase)))

        links = tuple(replace(k, origin=named(k.origin), joints=tuple(map(named, k.joints))) for k in st.links)
        # a normal given in the fixed frame turns with the frame; one given as an angle to a link's axis does not
        pairs = tuple(replace(p, point=named(p.point), normal=turned(p.normal) if callable(p.normal) else p.normal)
                      for p in st.pairs)
        return replace(st, links=links, pairs=pairs)

    def slot_samples(self, n: int = 200) -> np.ndarray:
        """Points of the slot's working part in the output link's frame (the linkage's convention)."""
        return self.slot_mechanism.slot_samples(n)

    def sketch(self, motion):
        """The crank, the slot turning with the output link about E (or moving with it), and its arm."""
        return slot_sketch(self, motion, "E")

    def motion(self, phi):
        """The twin's motion at the linkage's crank angles φ, in the linkage's frame."""
        phi = as_angles(phi)
        mo = self.slot_mechanism.motion(phi - self.phase)
        if isinstance(mo, LinearMotion):
            return mo
        ph = self.phase
        pts = {"O": mo.points["O"], "A": self._turn(mo.points["A"]), "E": self._turn(mo.points["B"])}
        return AngularMotion(phi, pts, mo.transmission, mo.psi + ph, mo.dpsi, mo.ddpsi)

    def _turn(self, p: PointPath) -> PointPath:
        ph = self.phase
        if ph == np.pi:   # a half turn exactly (no rounding of sin π)
            return PointPath(-p.p, -p.d, -p.dd)
        return PointPath(_rot(ph, p.p), _rot(ph, p.d), _rot(ph, p.dd))


@validated
def equivalent_slot(mechanism: AnyMechanism) -> EquivalentSlot:
    """The curved-slot mechanism whose slot is the linkage's relative path (Zinchenko et al. (2013) §1), from the
    family's ``curved_slot_twin()``: FourBar → a circular slot of radius l_AB about B (Fig. 2),
    SliderCrank → a translating circular slot (Fig. 4); any other family with a structure → the pin's
    relative path read from it (:func:`mechlab.mechanisms.curved_slot.structural_twin`; for SixBarIV its inner
    four-bar's coupler curve).

    Parameters
    ----------
    mechanism : Mechanism
        A linkage with one second-order group.

    Returns
    -------
    EquivalentSlot
        The curved-slot twin, a Mechanism in the linkage's own frame.

    Raises
    ------
    TypeError
        ``mechanism`` is not a Mechanism.
    DimensionError
        The mechanism has no crank pin jointed to a moving link.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> from mechlab.analysis.equivalence import equivalent_slot, law_difference
    >>> fourbar = ml.FourBar(1, 3, 3, 4)
    >>> twin = equivalent_slot(fourbar)
    >>> phi = np.linspace(0.0, 6.0, 7)
    >>> max(law_difference(fourbar.motion(phi), twin.motion(phi))) < 1e-12
    True
    """
    twin, phase = mechanism.curved_slot_twin()
    return EquivalentSlot(mechanism, twin, phase)


@validated
def law_difference(m1: AnyMotion, m2: AnyMotion) -> tuple[float, float, float]:
    """Max |difference| of the law (angles compared mod 2π) and its two analogs, of two motions
    over the same crank angles.

    Parameters
    ----------
    m1, m2 : Motion
        Two motions of the same kind (angle or position) over the same crank angles.

    Returns
    -------
    tuple of float
        Largest |difference| of the law, of its first and of its second analog.

    Raises
    ------
    TypeError
        ``m1`` or ``m2`` is not a Motion.
    DimensionError
        The motions differ in kind or in their number of crank angles, or are empty.

    Examples
    --------
    >>> import mechlab as ml
    >>> from mechlab.analysis.equivalence import law_difference
    >>> a, b = ml.FourBar(1, 3, 3, 4), ml.FourBar(1, 3, 3, 4.1)
    >>> [round(v, 4) for v in law_difference(a.motion([0.0, 1.0]), b.motion([0.0, 1.0]))]
    [0.0268, 0.0108, 0.005]
    """
    a, b = m1.output, m2.output
    if a.kind != b.kind or np.shape(a.value) != np.shape(b.value) or np.size(a.value) == 0:
        raise DimensionError(f"m1 and m2 must be motions of the same kind over the same (one or more) crank angles, "
                             f"got a "
                             f"{a.kind} over {np.size(a.value)} and a {b.kind} over {np.size(b.value)}")
    d0 = wrap(a.value - b.value) if a.kind == "angle" else a.value - b.value
    return float(np.max(np.abs(d0))), float(np.max(np.abs(a.d - b.d))), float(np.max(np.abs(a.dd - b.dd)))


def equivalence_error(mechanism: Mechanism, phi=None) -> float:
    """Max over φ of |law − twin's law| for ψ (mod 2π), ψ', ψ'' (or s, s', s'')."""
    phi = mechanism.cycle(361) if phi is None else as_angles(phi)
    return max(law_difference(mechanism.motion(phi), equivalent_slot(mechanism).motion(phi)))


# ---------------------------------------------------------------------------------------------
# base mechanism
# ---------------------------------------------------------------------------------------------
@validated
def base_mechanism(mechanism: AnyMechanism):
    """The base mechanism (Zinchenko et al. (2013) Fig. 5, 6): same crank, straight slot through the output
    pivot (``SlottedLink(l_OA, l_OE)``), or the sine mechanism for a translating output.

    Parameters
    ----------
    mechanism : Mechanism
        A linkage with a crank whose output turns about one fixed pivot or translates.

    Returns
    -------
    SlottedLink or SineMechanism
        The straight-slot base mechanism.

    Raises
    ------
    TypeError
        ``mechanism`` is not a Mechanism.
    DimensionError
        The output does not turn about one fixed pivot.

    Examples
    --------
    >>> import mechlab as ml
    >>> from mechlab.analysis.equivalence import base_mechanism
    >>> base_mechanism(ml.FourBar(1, 3, 3, 4))
    SlottedLink(crank=1.0, pivot_distance=4.0)
    """
    if not isinstance(getattr(mechanism, "crank", None), numbers.Real):
        raise DimensionError(f"{type(mechanism).__name__} has no crank length l_OA: the base mechanism is that of "
                             f"a linkage driven by a crank (four-bar, slider-crank, slotted link, six-bar)")
    if mechanism.output == "position":
        return SineMechanism(mechanism.crank)
    return SlottedLink(mechanism.crank, float(np.hypot(*_pivot_position(mechanism))))


def frame_phase(mechanism: Mechanism) -> float:
    """Crank-angle shift from the mechanism's frame to Zinchenko et al.'s (2013), whose output pivot lies at angle π
    from O: the pivot's angle − π (π when the output pivot is on +x, as E of a four-bar)."""
    if mechanism.output == "position":
        return 0.0
    x, y = _pivot_position(mechanism)
    return float(np.mod(np.arctan2(y, x) - np.pi, 2 * np.pi))


@scalar_law
@validated
def base_law(mechanism: AnyMechanism, phi: Angles) -> AnglePath:
    """The base mechanism's law in the mechanism's own frame: ψ_K(φ) = angle of A - pivot
    (formulas (18)-(20) with λ = l_OA/l_OB), or x_K = l_OA cos φ (formulas (2), (5)).

    Parameters
    ----------
    mechanism : Mechanism
        A linkage with a crank whose output turns about one fixed pivot or translates.
    phi : float or array_like
        Crank angles (rad).

    Returns
    -------
    AnglePath
        ψ_K (rad) or x_K (length units) and its first and second φ-analogs.

    Raises
    ------
    TypeError
        ``mechanism`` is not a Mechanism.
    DimensionError
        ``phi`` is not finite, or the output does not turn about one fixed pivot.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> from mechlab.analysis.equivalence import base_law
    >>> law = base_law(ml.FourBar(1, 3, 3, 4), np.pi)
    >>> round(float(law.theta), 4), round(float(law.d), 4)
    (3.1416, 0.2)
    """
    phi = as_angles(phi)
    base = base_mechanism(mechanism)
    ph = frame_phase(mechanism)
    mo = base.motion(phi - ph)
    if isinstance(mo, LinearMotion):
        return AnglePath(mo.s, mo.ds, mo.dds)
    return AnglePath(mo.psi + ph, mo.dpsi, mo.ddpsi)


# ---------------------------------------------------------------------------------------------
# symmetry of the assemblies
# ---------------------------------------------------------------------------------------------
def other_assembly(mechanism: Mechanism) -> Mechanism:
    """The same linkage in the other assembly (kc → -kc)."""
    if "assembly" not in {f.name for f in fields(mechanism)}:
        raise DimensionError(f"assembly symmetry is stated for FourBar and SliderCrank (two assemblies ±1), "
                             f"not {type(mechanism).__name__}")
    return replace(mechanism, assembly=-mechanism.assembly)


@dataclass(frozen=True)
class AssemblySymmetry:
    """Max residuals of the exact relations between the two assemblies (listed in :func:`assembly_symmetry`)."""

    mirror: float        # ψ₋(φ) = -ψ₊(-φ) … / s₋(φ) = -s₊(π - φ) …, over the law and both analogs
    mean_is_base: float  # (ψ₊ + ψ₋)/2 = ψ_K … / (s₊ + s₋)/2 = x_K …
    branches: float      # the relative paths are mirror images (α1–α1 ↔ α2–α2)

    def holds(self, tol: float = 1e-9) -> bool:
        return max(self.mirror, self.mean_is_base, self.branches) <= tol


@validated
def assembly_symmetry(mechanism: AnyMechanism, phi: Angles) -> AssemblySymmetry:
    """Residuals of the assembly relations for a FourBar or SliderCrank at crank angles φ.

    Four-bar (ψ from the frame line): ψ₋(φ) = -ψ₊(-φ) (mod 2π), ψ'₋(φ) = ψ'₊(-φ),
    ψ''₋(φ) = -ψ''₊(-φ); (ψ₊ + ψ₋)/2 = ψ_K (mod π), likewise for the analogs (equal and opposite β,
    formula (12)); relative paths y₋ = -y₊, x₋ = x₊. Slider-crank (±1: slider ahead of / behind the
    pin): s₋(φ) = -s₊(π - φ), (s₊ + s₋)/2 = l_OA cos φ; relative paths x₋ = -x₊, y₋ = y₊.

    Parameters
    ----------
    mechanism : FourBar or SliderCrank
        Either assembly; the other one is built from it.
    phi : float or array_like
        Crank angles (rad).

    Returns
    -------
    AssemblySymmetry
        The largest residual of each relation; ``holds(tol)`` says whether all are within ``tol``.

    Raises
    ------
    TypeError
        ``mechanism`` is not a Mechanism.
    DimensionError
        ``phi`` is not finite.
    AssemblyError
        An assembly cannot be assembled at a requested crank angle.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> from mechlab.analysis.equivalence import assembly_symmetry
    >>> assembly_symmetry(ml.FourBar(1, 3, 3, 4), np.linspace(0.0, 6.0, 7)).holds()
    True
    """
    phi = as_angles(phi)
    plus = mechanism if getattr(mechanism, "assembly", None) == 1 else other_assembly(mechanism)
    minus = other_assembly(plus)
    m, base = minus.motion(phi), base_law(plus, phi)
    p = plus.motion(phi)
    rp, rm = relative_path(plus, phi), relative_path(minus, phi)
    if plus.output == "angle":
        q = plus.motion(-phi)
        mirror = max(np.max(np.abs(wrap(m.psi + q.psi))), np.max(np.abs(m.dpsi - q.dpsi)),
                     np.max(np.abs(m.ddpsi + q.ddpsi)))
        # the mean of two angles is defined mod π: compare 2·mean with 2·ψ_K mod 2π
        mean = max(np.max(np.abs(wrap(p.psi + m.psi - 2 * base.theta))),
                   np.max(np.abs(p.dpsi + m.dpsi - 2 * base.d)), np.max(np.abs(p.ddpsi + m.ddpsi - 2 * base.dd)))
        branches = np.max(np.abs(rm.p - rp.p * np.array([1.0, -1.0])))
    else:
        q = plus.motion(np.pi - phi)
        mirror = max(np.max(np.abs(m.s + q.s)), np.max(np.abs(m.ds - q.ds)), np.max(np.abs(m.dds + q.dds)))
        mean = max(np.max(np.abs(p.s + m.s - 2 * base.theta)), np.max(np.abs(p.ds + m.ds - 2 * base.d)),
                   np.max(np.abs(p.dds + m.dds - 2 * base.dd)))
        branches = np.max(np.abs(rm.p - rp.p * np.array([-1.0, 1.0])))
    return AssemblySymmetry(float(mirror), float(mean), float(branches))
