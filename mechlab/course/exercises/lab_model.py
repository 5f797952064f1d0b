"""A lab's model of one assembly only: the kc = +1 rocker's ψ′, handed to a student's function as ``plus``.

Why a class of its own (and not a FourBar): the symmetry assignment's debug exercise gives the student
``plus(phi)``, ψ′ of the kc = +1 assembly, and asks for the kc = −1 assembly's ψ′ from it. The object must be
importable so that the in-notebook self-check can rebuild the hidden test's cases from its token (an object is
carried as its class and attributes), and it must hold nothing that turns it into the other assembly: it has no
assembly switch, only the +1 closure below.
"""

from __future__ import annotations

import numpy as np

from ...errors import AssemblyError


class PlusAssemblyRate:
    """ψ′(φ) = dψ/dφ of a four-bar's kc = +1 assembly (B on the left of the directed line A→E).

    From the loop closure a·e^{iφ} + b·e^{iθ} = d + c·e^{iψ} (θ the coupler's angle), differentiated in φ
    and projected across the coupler: ψ′ = a·sin(φ − θ) / (c·sin(ψ − θ)).

    Parameters
    ----------
    crank, coupler, rocker, ground : float
        Link lengths l_OA, l_AB, l_EB, l_OE (dimensionless or mm).

    Examples
    --------
    >>> plus = PlusAssemblyRate(1.0, 3.0, 3.0, 4.0)
    >>> round(float(plus(np.radians(90.0))[0]), 4)
    0.2814
    """

    def __init__(self, crank: float, coupler: float = 3.0, rocker: float = 3.0, ground: float = 4.0):
        self.crank, self.coupler, self.rocker, self.ground = (float(x) for x in (crank, coupler, rocker, ground))

    def __call__(self, phi) -> np.ndarray:
        """ψ′ of the kc = +1 assembly at crank angles ``phi`` (radians; a number or an array).

        Returns
        -------
        numpy.ndarray
            ψ′ at each angle (1-D, one value per angle).

        Raises
        ------
        AssemblyError
            Where the coupler and rocker cannot reach each other (|AE| outside [|b − c|, b + c]).
        """
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        a, b, c, d = self.crank, self.coupler, self.rocker, self.ground
        A = a * np.exp(1j * phi)
        AE = d - A
        f = np.abs(AE)
        cos_alpha = (b * b + f * f - c * c) / (2 * b * f)
        if np.any(np.abs(cos_alpha) > 1):
            raise AssemblyError(f"the loop does not close at φ = {np.degrees(phi[np.abs(cos_alpha) > 1][0]):.4g}°: "
                                f"|AE| is out of reach of the coupler {b:g} and the rocker {c:g}")
        # B left of A→E: the coupler turned from A→E by +α
        B = A + b * AE / f * (cos_alpha + 1j * np.sqrt(1 - cos_alpha ** 2))
        theta, psi = np.angle(B - A), np.angle(B - d)
        return a * np.sin(phi - theta) / (c * np.sin(psi - theta))

    def __repr__(self) -> str:
        return f"plus(crank={self.crank:.4g})"
