"""Every family synthesised to one specification, simulated, and compared on the same criteria."""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass
from typing import Annotated

import numpy as np

from ..errors import MechanismError, renamed
from ..validate import Length, Spec, choice, validated
from .criteria import AnyMovable, Counts, Criteria, Phase, counted, evaluate
from .families import FAMILIES, Design, Unsuitable
from .spec import IMPACTS, AnySpecification, Specification


@dataclass(frozen=True)
class Refusal:
    """A family that cannot meet the specification, and why (with the numbers).

    Parameters
    ----------
    family : str
        The family's name, a key of :data:`~mechlab.design.FAMILIES`.
    reason : str
        Why it was refused: the synthesis's refusal, or each missed limit with its numbers.

    Examples
    --------
    >>> from mechlab.design import Refusal
    >>> str(Refusal("disc cam", "a swing was asked"))
    'disc cam: a swing was asked'
    """

    family: str
    reason: str

    def __str__(self) -> str:
        return f"{self.family}: {self.reason}"


@dataclass(frozen=True)
class Candidate:
    """A family's design and its criteria, read off its simulated motion.

    Parameters
    ----------
    design : Design
        The family's synthesised design (:class:`~mechlab.design.Design`).
    criteria : Criteria
        Its judged figures (:class:`~mechlab.design.Criteria`).

    Examples
    --------
    >>> from mechlab.design import Specification, candidates
    >>> comparison = candidates(Specification("index", 0.75, stations=4), families=("external Geneva",))
    >>> best = comparison.candidates[0]
    >>> round(best.criteria.dwell_fraction, 3)
    0.75
    """

    design: Design
    criteria: Criteria

    @property
    def family(self) -> str:
        """The design's family name.

        Returns
        -------
        str
            ``design.family``, a key of :data:`~mechlab.design.FAMILIES`.

        Examples
        --------
        >>> from mechlab.design import Specification, candidates
        >>> comparison = candidates(Specification("index", 0.75, stations=4), families=("external Geneva",))
        >>> comparison.candidates[0].family
        'external Geneva'
        """
        return self.design.family


# (column, heading, unit, formatter); the order of the table
COLUMNS = (
    ("dwell_fraction", "dwell", "of turn", "{:.3f}"),
    ("standstill_fraction", "near-standstill", "of turn", "{:.3f}"),
    ("dwell_residual", "dwell residual", "of amplitude", "{:.2e}"),
    ("B", "C_v", "", "{:.3f}"),   # Kinitsky's invariants B, C, D in the glossary's symbols
    ("C", "C_a", "", "{:.3f}"),
    ("D", "C_p", "", "{:.3f}"),
    ("J", "jerk J", "", "{:.3g}"),
    ("impact", "impact", "", "{}"),
    ("pressure_angle", "pressure angle", "deg", "{:.1f}"),
    ("size", "size", "mm", "{:.0f}"),
    ("peak_torque", "peak torque", "N·m", "{:.3g}"),
    ("rms_torque", "rms torque", "N·m", "{:.3g}"),
    ("motor_power", "motor", "W", "{:.3g}"),
    ("structure", "parts and pairs", "", "{}"),
)


RANKABLE = tuple(k for k, *_ in COLUMNS if k not in ("impact", "structure"))  # the numeric columns


def _value(c: Criteria, key: str):
    v = getattr(c, key)
    return np.degrees(v) if key == "pressure_angle" else v


@dataclass(frozen=True)
class LimitVerdict:
    """One limit of a specification: met or missed, in words with the numbers.

    Parameters
    ----------
    criterion : str
        The limit judged: "amplitude", "dwell", "pressure angle", "size" or "impacts".
    met : bool
        Whether the design meets it.
    text : str
        The numbers: what the design reached against what was asked.

    Examples
    --------
    >>> import mechlab as ml
    >>> from mechlab.design import Specification, check_design
    >>> report = check_design(Specification("index", 0.75, stations=4), ml.ExternalGeneva(4, 1.0), scale=50)
    >>> str(report.verdicts[3])
    '✓ size: 85 mm ≤ 1000 mm'
    """

    criterion: str
    met: bool
    text: str

    @property
    def reason(self) -> str:
        """The criterion and its numbers, as a refusal states it.

        Returns
        -------
        str
            ``"criterion: text"``.

        Examples
        --------
        >>> import mechlab as ml
        >>> from mechlab.design import Specification, check_design
        >>> report = check_design(Specification("index", 0.75, stations=4), ml.ExternalGeneva(4, 1.0), scale=50)
        >>> report.verdicts[3].reason
        'size: 85 mm ≤ 1000 mm'
        """
        return f"{self.criterion}: {self.text}"

    def __str__(self) -> str:
        return f"{'✓' if self.met else '✗'} {self.reason}"


def limits(spec: Specification, c: Criteria) -> list[LimitVerdict]:
    """The specification's limits on a simulated design (dwell, pressure angle, size, impacts), each
    met or missed with its numbers: :func:`check_design` reports them, :func:`candidates` refuses on them."""
    # the specification's dwell is a near-standstill (within its dwell_precision): a longer one than asked
    # still serves the machine, a shorter one does not
    dwell_ok = c.standstill_fraction >= spec.dwell_fraction - spec.dwell_tolerance
    pa_ok = c.pressure_angle <= spec.max_pressure_angle + 1e-9
    size_ok = c.size <= spec.max_size
    impact_ok = IMPACTS.index(c.impact) <= IMPACTS.index(spec.impacts)
    return [
        LimitVerdict("dwell", dwell_ok, f"near-standstill {c.standstill_fraction:.3f} of the turn (output within "
                                   f"± {spec.dwell_precision:g} of its amplitude; exact dwell {c.dwell_fraction:.3f}) "
                                   f"{'≥' if dwell_ok else '<'} {spec.dwell_fraction:.3f} − {spec.dwell_tolerance:.3f} "
                                   f"asked"),
        LimitVerdict("pressure angle", pa_ok, f"worst {np.degrees(c.pressure_angle):.1f}° {'≤' if pa_ok else '>'} "
                                         f"{np.degrees(spec.max_pressure_angle):.1f}°"),
        LimitVerdict("size", size_ok, f"{c.size:.0f} mm {'≤' if size_ok else '>'} {spec.max_size:.0f} mm"),
        LimitVerdict("impacts", impact_ok, f"{c.impact}, {spec.impacts} at worst admitted" if impact_ok
                else f"{c.impact} where {spec.impacts} at worst are admitted"),
    ]


@dataclass(frozen=True)
class Comparison:
    """The candidates that meet a specification and the families refused, with a table view.

    Shows as an HTML table in a notebook; :meth:`to_csv` writes the same table; :meth:`ranked`
    orders the candidates by a criterion.

    Parameters
    ----------
    spec : Specification
        The specification the families were synthesised for.
    candidates : tuple of Candidate
        The designs that meet it.
    refusals : tuple of Refusal
        The families that do not, with the reason.

    Examples
    --------
    >>> from mechlab.design import Specification, candidates
    >>> comparison = candidates(Specification("index", 0.75, stations=4), families=("external Geneva",))
    >>> len(comparison.candidates), len(comparison.refusals)
    (1, 0)
    """

    spec: Specification
    candidates: tuple[Candidate, ...]
    refusals: tuple[Refusal, ...]

    @validated
    def ranked(self, by: Annotated[str, choice(*RANKABLE)] = "motor_power") -> Comparison:
        """The same comparison with the candidates ordered by ``by``, smallest first (a missing J last).

        Parameters
        ----------
        by : str
            One of :data:`RANKABLE`, the numeric columns of the table (default ``"motor_power"``).

        Returns
        -------
        Comparison
            The same specification and refusals, the candidates reordered.

        Raises
        ------
        DimensionError
            ``by`` is not a numeric column.

        Examples
        --------
        >>> from mechlab.design import Specification, candidates
        >>> comparison = candidates(Specification("index", 0.75, stations=4), families=("external Geneva",))
        >>> comparison.ranked("size").candidates[0].family
        'external Geneva'
        """

        def key(c):
            v = _value(c.criteria, by)
            return (v is None, v if v is not None else 0.0)

        return Comparison(self.spec, tuple(sorted(self.candidates, key=key)), self.refusals)

    def rows(self) -> list[tuple[str, ...]]:
        """The table as text: a header row, then one row a candidate.

        Returns
        -------
        list of tuple of str
            The header (column with its unit), then each candidate's formatted values.

        Examples
        --------
        >>> from mechlab.design import Specification, candidates
        >>> comparison = candidates(Specification("index", 0.75, stations=4), families=("external Geneva",))
        >>> comparison.rows()[0][:2]
        ('family', 'dwell (of turn)')
        """
        head = ("family",) + tuple(f"{h} ({u})" if u else h for _, h, u, _ in COLUMNS)
        body = [(c.family,) + tuple("—" if _value(c.criteria, k) is None else f.format(_value(c.criteria, k))
                                    for k, _, _, f in COLUMNS) for c in self.candidates]
        return [head] + body

    @validated
    def to_csv(self, path: Annotated[object, Spec("path", optional=True)] = None) -> str:
        """The table as CSV (full precision); written to ``path`` when given.

        Parameters
        ----------
        path : str or path-like, optional
            File to write (UTF-8); nothing is written when None.

        Returns
        -------
        str
            The CSV text: a header of column keys, then one row a candidate.

        Raises
        ------
        DimensionError
            ``path`` is not a path.

        Examples
        --------
        >>> from mechlab.design import Specification, candidates
        >>> comparison = candidates(Specification("index", 0.75, stations=4), families=("external Geneva",))
        >>> comparison.to_csv().splitlines()[0][:35]
        'family,dwell_fraction,standstill_fr'
        """
        buf = io.StringIO()
        w = csv.writer(buf, lineterminator="\n")
        w.writerow(["family"] + [k for k, *_ in COLUMNS])
        for c in self.candidates:
            w.writerow([c.family] + ["" if _value(c.criteria, k) is None else _value(c.criteria, k)
                                     for k, *_ in COLUMNS])
        text = buf.getvalue()
        if path is not None:
            with open(path, "w", encoding="utf-8", newline="") as f:
                f.write(text)
        return text

    def __str__(self) -> str:
        rows = self.rows()
        widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
        lines = ["  ".join(v.ljust(w) for v, w in zip(r, widths, strict=False)) for r in rows]
        lines += [f"refused — {r}" for r in self.refusals]
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        rows = self.rows()
        head = "".join(f"<th>{h}</th>" for h in rows[0])
        body = "".join("<tr>" + "".join(f"<td>{v}</td>" for v in r) + "</tr>" for r in rows[1:])
        refused = "".join(f"<li><b>{r.family}</b>: {r.reason}</li>" for r in self.refusals)
        return (f"<p>{self.spec.describe()}</p><div style='overflow-x:auto'><table><thead><tr>{head}</tr></thead>"
                f"<tbody>{body}</tbody></table></div>" + (f"<p>Refused:</p><ul>{refused}</ul>" if refused else ""))


@validated
def candidates(spec: AnySpecification,
               families: Annotated[tuple | None, Spec("items", expected=str, optional=True)] = None) -> Comparison:
    """Synthesise a design of every family (or of ``families``, names of :data:`FAMILIES`) for ``spec``.

    Each design is simulated and judged by :func:`~mechlab.design.criteria.evaluate`; a family
    whose synthesis refuses, or whose simulated design misses a limit of the specification
    (:func:`limits`), is listed among the refusals with the reason.

    Parameters
    ----------
    spec : Specification
        The machine's requirement.
    families : tuple of str, optional
        Names of :data:`~mechlab.design.FAMILIES` to try; all of them when None.

    Returns
    -------
    Comparison
        The designs that meet ``spec`` and the families refused, with the reasons.

    Raises
    ------
    MechanismError
        A name in ``families`` is not a known family.
    TypeError
        ``spec`` is not a :class:`Specification`.

    Examples
    --------
    >>> from mechlab.design import Specification, candidates
    >>> comparison = candidates(Specification("index", 0.75, stations=4),
    ...                         families=("external Geneva", "curved slot"))
    >>> [c.family for c in comparison.candidates], [r.family for r in comparison.refusals]
    (['external Geneva'], ['curved slot'])
    """
    names = list(FAMILIES) if families is None else list(families)
    unknown = [n for n in names if n not in FAMILIES]
    if unknown:
        raise MechanismError(f"unknown families {unknown}; known: {list(FAMILIES)}")
    found, refused = [], []
    for name in names:
        try:
            design = FAMILIES[name](spec)
            crit = evaluate(design.mechanism, spec, scale=design.scale, structure=design.structure,
                            circles=design.circles, pressure_angle=design.pressure_angle, phase=design.phase)
        except Unsuitable as why:
            refused.append(Refusal(name, str(why)))
            continue
        except MechanismError as err:
            refused.append(Refusal(name, f"{type(err).__name__}: {err}"))
            continue
        missed = [v.reason for v in limits(spec, crit) if not v.met]
        if missed:
            refused.append(Refusal(name, "; ".join(missed)))
        else:
            found.append(Candidate(design, crit))
    return Comparison(spec, tuple(found), tuple(refused))


@dataclass(frozen=True)
class SpecificationReport:
    """A student's (or anyone's) design run against a specification: each limit met or missed.

    Parameters
    ----------
    spec : Specification
        The specification run against.
    criteria : Criteria
        The design's figures, read off its simulated motion.
    verdicts : tuple
        One verdict a limit: amplitude, dwell, pressure angle, size and impacts, each met or missed.

    Examples
    --------
    >>> import mechlab as ml
    >>> from mechlab.design import Specification, check_design
    >>> report = check_design(Specification("index", 0.75, stations=4), ml.ExternalGeneva(4, 1.0), scale=50)
    >>> [v.criterion for v in report.verdicts]
    ['amplitude', 'dwell', 'pressure angle', 'size', 'impacts']
    """

    spec: Specification
    criteria: Criteria
    verdicts: tuple[LimitVerdict, ...]

    @property
    def met(self) -> bool:
        """Whether every limit is met.

        Returns
        -------
        bool
            True when all the verdicts are met.

        Examples
        --------
        >>> import mechlab as ml
        >>> from mechlab.design import Specification, check_design
        >>> check_design(Specification("index", 0.75, stations=4), ml.ExternalGeneva(4, 1.0), scale=50).met
        True
        """
        return all(v.met for v in self.verdicts)

    def __str__(self) -> str:
        head = "meets the specification" if self.met else "misses the specification"
        return "\n".join([f"The design {head}:"] + [f"  {v}" for v in self.verdicts])

    def _repr_html_(self) -> str:
        rows = "".join(f"<li style='color:{'#2a7f62' if v.met else '#b00020'}'>{v}</li>" for v in self.verdicts)
        head = "meets the specification" if self.met else "misses the specification"
        return f"<p><b>The design {head}</b></p><ul>{rows}</ul>"


def _counts(mechanism) -> Counts:
    """The parts and pairs of a mechanism that describes its structure; none known for one with motion() alone."""
    try:
        return counted(mechanism)
    except (AttributeError, MechanismError):
        return Counts(0, 0, 0)


@validated
def check_design(spec: AnySpecification, mechanism: AnyMovable, *, scale: Length = 1.0,
                 phase: Phase = 0.0) -> SpecificationReport:
    """Run ``mechanism`` against ``spec``: each limit met or missed, from its simulated motion.

    The limits are the amplitude (± 1 %), dwell, pressure angle, size and impacts, each
    with the numbers.

    Parameters
    ----------
    spec : Specification
        The machine's requirement.
    mechanism : Mechanism
        Any object with ``motion(phi)``, e.g. a mechlab mechanism or one built with ``ml.Linkage``.
    scale : float
        Its lengths × ``scale`` are mm (default 1).
    phase : float
        Shift of the sampled crank angles (rad), off a point where its motion cannot be evaluated.

    Returns
    -------
    SpecificationReport
        The criteria and one verdict a limit.

    Raises
    ------
    TypeError
        ``spec`` is not a Specification, or ``mechanism`` has no ``motion``.
    DimensionError
        ``scale`` is not a positive length, or ``phase`` lies outside [−2π, 2π].
    MechanismError
        The mechanism's own motion refuses a crank angle of the turn.

    Examples
    --------
    >>> import mechlab as ml
    >>> from mechlab.design import Specification, check_design
    >>> report = check_design(Specification("index", 0.75, stations=4), ml.ExternalGeneva(4, 1.0), scale=50)
    >>> report.met, round(report.criteria.dwell_fraction, 3)
    (True, 0.75)
    """
    c = evaluate(mechanism, spec, scale=scale, structure=_counts(mechanism), phase=phase)
    phi = phase + np.linspace(0.0, 2 * np.pi, 2881)
    x = np.asarray(mechanism.motion(phi).output.value, float) * (1.0 if spec.rotary else scale)
    reached = abs(x[-1] - x[0]) if spec.motion == "index" else float(np.ptp(x))
    unit, shown = ("deg", np.degrees) if spec.rotary else ("mm", lambda v: v)
    amp_ok = abs(reached - spec.amplitude) <= 0.01 * spec.amplitude
    v = [LimitVerdict("amplitude", amp_ok, f"{shown(reached):.4g} {unit} reached, {shown(spec.amplitude):.4g} {unit} "
                                      f"asked (± 1 %)")]
    return SpecificationReport(spec, c, tuple(v + limits(spec, c)))


# the old names (the exercises' Verdict and DesignReport are the course's)
__getattr__ = renamed(__name__, Verdict=(LimitVerdict, "mechlab.design.LimitVerdict"),
                      DesignReport=(SpecificationReport, "mechlab.design.SpecificationReport"))
