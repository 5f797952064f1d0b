"""The check of a dwell six-bar designed from a coupler curve (chapter 8a's assignment): the student's linkage is
simulated over a crank turn and measured here, from its joints' paths, without the synthesis that built it.

A design passes on what it does, not on how it was made: the crank turns fully; the output rocker stays within
``max_residual`` degrees over a crank interval of at least ``min_dwell`` degrees (the longest such interval, found
on the sampled turn); it swings at least ``min_swing`` degrees; and every RRR dyad's angle between its two links
(the transmission angle of that loop) stays within [``min_transmission``, 180° − ``min_transmission``].
"""

from __future__ import annotations

import numpy as np
from scipy.ndimage import maximum_filter1d, minimum_filter1d

from ...errors import MechanismError
from .design import DesignReport, Requirement

SAMPLES = 3600   # crank angles over the turn: 0.1° apart


def longest_still_interval(psi: np.ndarray, band: float) -> tuple[int, int]:
    """The longest run of consecutive samples of the periodic ``psi`` (one crank turn) whose spread max − min
    stays within ``band``: (length in samples, the index of its first sample).

    Parameters
    ----------
    psi : array
        The output over one turn at equally spaced crank angles (periodic: the last sample precedes the first).
    band : float
        The largest spread allowed, in ``psi``'s unit.

    Returns
    -------
    (int, int)
        The run's length in samples (the whole turn: ``len(psi)``) and its first sample.

    Examples
    --------
    >>> longest_still_interval(np.array([0.0, 0.0, 0.1, 1.0, 0.05, 0.0]), 0.1)
    (5, 4)
    """
    psi = np.asarray(psi, dtype=float)
    n = len(psi)
    if np.ptp(psi) <= band:
        return n, 0

    def spreads(size: int) -> np.ndarray:   # the spread of the window of `size` samples starting at each sample
        hi = maximum_filter1d(psi, size, mode="wrap", origin=-(size // 2))   # scipy centres a window: start it at i
        lo = minimum_filter1d(psi, size, mode="wrap", origin=-(size // 2))
        return hi - lo

    lo, hi = 1, n - 1   # a single sample is still; the whole turn is not
    while lo < hi:       # the longest window length whose best start stays within the band
        mid = (lo + hi + 1) // 2
        if spreads(mid).min() <= band:
            lo = mid
        else:
            hi = mid - 1
    return lo, int(np.argmin(spreads(lo)))


def dwell_sixbar_design(mech, *, min_dwell: float, max_residual: float, min_swing: float,
                        min_transmission: float = 40.0) -> DesignReport:
    """A dwell six-bar built with the structure builder (a ``mechlab.Linkage`` whose output is a rocker),
    simulated over one crank turn and measured from its joints.

    Parameters
    ----------
    mech : mechlab.Linkage
        The student's design.
    min_dwell : float
        The crank angle (degrees) over which the output must stand nearly still.
    max_residual : float
        "Nearly still": the output's largest spread (degrees) over that interval.
    min_swing : float
        The least swing of the output over the turn (degrees).
    min_transmission : float, optional
        Every RRR dyad's angle between its links stays within [this, 180° − this] (degrees).

    Returns
    -------
    DesignReport
        Each specification met or missed, with the measured number and where; ``problem`` when the design
        cannot be simulated (no linkage, a crank that does not turn fully, an output that slides).

    Raises
    ------
    NotYet
        Only from the report's ``require()``, when a specification is missed.

    Examples
    --------
    >>> import mechlab as ml
    >>> fb = ml.Linkage({"O": (0, 0), "E": (4, 0)}, ml.Crank("O", "A", 1.0)).rrr("A", "E", "B", 3.0, 3.0)
    >>> dwell_sixbar_design(fb, min_dwell=60, max_residual=0.5, min_swing=10).ok
    False
    """
    from ...mechanisms.linkage import RRR, Linkage

    title = "dwell six-bar design"
    if mech is None or mech is Ellipsis:
        return DesignReport(title, problem="no design yet: build the six-bar (a mechlab Linkage)")
    if not isinstance(mech, Linkage):
        return DesignReport(title, problem=f"expected a mechlab Linkage (the structure builder's), "
                                           f"got {type(mech).__name__}")
    if mech.output != "angle":
        return DesignReport(title, problem="the output slides: this machine needs a rocker (an angle) at the output")
    phi = np.arange(SAMPLES) * (2 * np.pi / SAMPLES)
    try:
        mo = mech.motion(phi)
    except MechanismError as err:
        return DesignReport(title, problem=f"the crank does not turn fully: {err}")
    psi = np.degrees(mo.psi)
    length, start = longest_still_interval(psi, max_residual)
    step = 360.0 / SAMPLES
    dwell = (length - 1) * step   # from the first to the last sample of the run
    at = f"φ = {start * step:.0f}°…{(start + length - 1) * step % 360:.0f}°"
    specs = [Requirement(f"crank angle with the output within {max_residual:g}°", dwell, "≥", min_dwell, "°", at),
             Requirement("output swing", float(np.ptp(psi)), "≥", min_swing, "°")]
    for group in (g for g in mech.groups if isinstance(g, RRR)):
        p = {name: mo.points[name].p for name in (group.first, group.second, group.joint)}
        u, v = p[group.first] - p[group.joint], p[group.second] - p[group.joint]
        mu = np.degrees(np.arctan2(np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]), np.einsum("ij,ij->i", u, v)))
        dev = np.minimum(mu, 180.0 - mu)
        k = int(np.argmin(dev))
        specs.append(Requirement(f"transmission angle at {group.joint}, min(μ, 180° − μ)", float(dev[k]), "≥",
                                 min_transmission, "°", f"φ = {k * step:.0f}°"))
    return DesignReport(title, tuple(specs))
