"""The follower's programme of a disc cam over one turn: rise, outer dwell, return, inner dwell.

Each transition is one of the laws of :mod:`mechlab.analysis.motion_laws` on the normalised
time x = (φ − start)/duration (Kinitsky, 1994, chapter 2, compares them with linkages); the
lift is y = h·Y(x) on the rise and h·(1 − Y(x)) on the return. The cams of
:mod:`mechlab.mechanisms.cam` turn it into a profile.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..analysis.motion_laws import RiseLaw, named_law
from ..errors import DimensionError
from ..geometry import AnglePath, check_length
from ..mechanisms.base import TWO_PI

__all__ = ["CamProgramme"]


@dataclass(frozen=True)
class CamProgramme:
    """Rise – outer dwell – return – inner dwell over one cam turn (angles in radians).

    The inner dwell is what is left of the turn. Calling the programme at cam angles φ gives
    the lift y(φ) (stroke units) and its analogs y′, y″ as an ``AnglePath``.

    Parameters
    ----------
    stroke : float
        h: a length (mm, translating follower) or an angle (rad, oscillating follower), > 0.
    rise, ret : float
        Cam angles of the rise and of the return (rad), > 0.
    outer_dwell : float
        Cam angle of the dwell at full lift (rad), ≥ 0 (default 0).
    law : str or RiseLaw
        The rise's law, a name of :mod:`mechlab.analysis.motion_laws` (default "cycloidal (sine)").
    return_law : str or RiseLaw, optional
        The return's law, y = h·(1 − Y(x)); by default the rise's.

    Raises
    ------
    DimensionError
        A stroke or angle that is not a positive finite number (the outer dwell may be 0), an
        unknown law, or rise + outer dwell + return exceeding one turn.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> prog = ml.CamProgramme(10.0, np.pi / 2, np.pi / 2, outer_dwell=np.pi / 4)
    >>> lift = prog(np.pi / 4)  # half-way up a cycloidal rise
    >>> round(float(lift.theta), 4), round(float(lift.d), 4)
    (5.0, 12.7324)
    """

    stroke: float
    rise: float
    ret: float
    outer_dwell: float = 0.0
    law: str | RiseLaw = "cycloidal (sine)"
    return_law: str | RiseLaw | None = None

    def __post_init__(self):
        object.__setattr__(self, "stroke", check_length("stroke", self.stroke))
        for name in ("rise", "ret"):
            object.__setattr__(self, name, check_length(f"{name} angle", getattr(self, name)))
        object.__setattr__(self, "outer_dwell", check_length("outer dwell", self.outer_dwell, allow_zero=True))
        object.__setattr__(self, "law", named_law(self.law, "law"))
        object.__setattr__(self, "return_law", self.law if self.return_law is None else
                           named_law(self.return_law, "return_law"))
        total = self.rise + self.outer_dwell + self.ret
        if total > TWO_PI * (1 + 1e-12):
            raise DimensionError(
                f"rise + outer dwell + return = {np.degrees(self.rise):.4g}° + {np.degrees(self.outer_dwell):.4g}° "
                f"+ {np.degrees(self.ret):.4g}° = {np.degrees(total):.4g}° exceeds one turn (360°)")

    @property
    def breaks(self) -> tuple[float, float, float, float, float]:
        """Cam angles where the phases start: rise, outer dwell, return, inner dwell, and 2π.

        Returns
        -------
        tuple of float
            Five cam angles (rad), ascending from 0 to 2π.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> [round(b, 4) for b in ml.CamProgramme(10.0, np.pi / 2, np.pi / 2, outer_dwell=np.pi / 4).breaks]
        [0.0, 1.5708, 2.3562, 3.927, 6.2832]
        """
        a = self.rise
        b = a + self.outer_dwell
        c = b + self.ret
        return 0.0, a, b, min(c, TWO_PI), TWO_PI

    def __call__(self, phi) -> AnglePath:
        """The follower's lift y(φ) (stroke units) with its analogs y′, y″ at cam angles φ."""
        t = np.mod(np.asarray(phi, dtype=float), TWO_PI)
        _, a, b, c, _ = self.breaks
        h = self.stroke
        y, d, dd = np.zeros_like(t), np.zeros_like(t), np.zeros_like(t)
        y[(t >= a) & (t < b)] = h
        up = t < a
        Y, dY, ddY = self.law(t[up] / self.rise)
        y[up], d[up], dd[up] = h * Y, h * dY / self.rise, h * ddY / self.rise**2
        down = (t >= b) & (t < c)
        Y, dY, ddY = self.return_law((t[down] - b) / self.ret)
        y[down], d[down], dd[down] = h * (1 - Y), -h * dY / self.ret, -h * ddY / self.ret**2
        return AnglePath(y, d, dd)

    def jerk(self, phi) -> np.ndarray:
        """The lift's third analog y‴(φ) (stroke units per rad³; the jerk is y‴·ω³ at constant cam speed ω):
        h·Y‴/Φ³ on the rise, −h·Y‴/Φ³ on the return, 0 in the dwells; between the points where y″ jumps,
        where the jerk is an impulse (:func:`~mechlab.analysis.motion_laws.law_jerk` gives inf there).

        Parameters
        ----------
        phi : array_like
            Cam angles (rad), taken modulo 2π.

        Returns
        -------
        numpy.ndarray
            y‴ at each angle.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import CamProgramme
        >>> prog = CamProgramme(10.0, np.pi / 2, np.pi / 2, law="3-4-5 polynomial")
        >>> float(prog.jerk(np.array([0.0]))[0]) == 10.0 * 60 / (np.pi / 2) ** 3
        True
        """
        t = np.mod(np.asarray(phi, dtype=float), TWO_PI)
        _, a, b, c, _ = self.breaks
        out = np.zeros_like(t)
        up, down = t < a, (t >= b) & (t < c)
        out[up] = self.stroke * self.law.jerk(t[up] / self.rise) / self.rise**3
        out[down] = -self.stroke * self.return_law.jerk((t[down] - b) / self.ret) / self.ret**3
        return out

    def in_dwell(self, phi) -> np.ndarray:
        """True where the follower stands still (either dwell).

        Parameters
        ----------
        phi : array_like
            Cam angles (rad), taken modulo 2π.

        Returns
        -------
        numpy.ndarray of bool
            True in the outer and the inner dwell.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> prog = ml.CamProgramme(10.0, np.pi / 2, np.pi / 2, outer_dwell=np.pi / 4)
        >>> prog.in_dwell(np.array([0.1, 2.0, 5.0])).tolist()
        [False, True, True]
        """
        t = np.mod(np.asarray(phi, dtype=float), TWO_PI)
        _, a, b, c, _ = self.breaks
        return ((t >= a) & (t < b)) | (t >= c)
