"""Sliders for chapter 01: a linkage with the fixed and moving centrodes of one of its
links, the pole moving along them as the crank turns (Kozhevnikov, §7.2)."""

from __future__ import annotations

from ..analysis.centres import centrodes
from ..draw.centres import CentrodeOverlay
from ..errors import MechanismError
from ..mechanisms.antiparallelogram import Antiparallelogram
from ..mechanisms.fourbar import FourBar
from ..mechanisms.trammel import EllipticTrammel
from . import Control, MechanismExplorer


class CentrodeExplorer(MechanismExplorer):
    """:class:`MechanismExplorer` plus the centrodes of ``link`` relative to ``reference``.

    The centrodes are recomputed (Kennedy's construction over the whole cycle) when a
    dimension changes; the crank slider moves the pole and carries the moving centrode.
    A geometry whose centres cannot be constructed shows the error's message.
    """

    def __init__(self, factory, controls, *, link: str, reference: str = "frame", **kwargs):
        self.link, self.reference = link, reference
        self.overlay = None
        self.centrodes = None
        super().__init__(factory, controls, **kwargs)

    def rebuild(self):
        self.centrodes = None
        super().rebuild()
        if self.mechanism is None:
            return
        try:
            cd = centrodes(self.mechanism, self.link, self.reference, self.motion.phi)
        except MechanismError as err:
            self._show_error(str(err))
            return
        self.centrodes = cd
        if self.overlay is None or self.overlay.fixed_line.axes is not self.ax_mech:
            self.overlay = CentrodeOverlay(self.ax_mech, cd)
            self._animate_moving()
            # below the drawing, outside it: the centrodes run anywhere in the axes
            self.ax_mech.legend(loc="upper left", bbox_to_anchor=(0.0, 0.0), ncols=3, fontsize=8, frameon=False,
                                borderaxespad=0.2)
        else:
            self.overlay.cd = cd
        self._select_frame()
        self._redraw()

    def _select_frame(self):
        super()._select_frame()
        if self.overlay is not None and self.centrodes is not None:
            self.overlay.set_frame(self.frame)
            P = self.centrodes.centre[self.frame]
            where = (f"({P.h[0, 0]:.3f}, {P.h[0, 1]:.3f})" if P.finite[0]
                     else f"at infinity along ({P.h[0, 0]:.2f}, {P.h[0, 1]:.2f})")
            label = self.centrodes.centres.label(self.link, self.reference)
            # and the mechanism's own reading, so that a change of a dimension is told too
            self.status.value = (f"pole {label} of the {self.link} relative to the {self.reference}: {where} · "
                                 f"{self._status()}")

    def _moving_artists(self):
        extra = self.overlay.artists if self.overlay is not None else []
        return [*super()._moving_artists(), *extra]


def fourbar_centrode_explorer(crank=1.0, coupler=3.0, rocker=3.0, ground=4.0, *, link="coupler",
                              reference="frame", max_length=10.0, live=None, question=None) -> CentrodeExplorer:
    """A four-bar with the centrodes of its ``link`` (default: the coupler's about the frame);
    lengths dimensionless."""
    def ctl(label, v):
        return Control(label, 0.1, max_length, 0.05, v)
    controls = {"crank": ctl("crank OA", crank), "coupler": ctl("coupler AB", coupler),
                "rocker": ctl("rocker BE", rocker), "ground": ctl("ground OE", ground)}
    return CentrodeExplorer(FourBar, controls, link=link, reference=reference, assembly=True,
                            title=f"Four-bar: centrodes of the {link}", live=live, question=question)


def trammel_explorer(rod=1.0, beta_deg=90.0, *, live=None, question=None) -> CentrodeExplorer:
    """The elliptic trammel with its Cardan circles; sliders: rod length (dimensionless) and guide angle β."""
    controls = {"rod": Control("rod AB", 0.2, 5.0, 0.05, rod),
                "beta": Control("guide angle β", 10.0, 170.0, 1.0, beta_deg, "deg")}
    return CentrodeExplorer(EllipticTrammel, controls, link="rod", title="Elliptic trammel: Cardan circles",
                            live=live, question=question)


def antiparallelogram_explorer(crank=1.0, ground=2.0, *, link="rocker", reference="crank",
                               live=None, question=None) -> CentrodeExplorer:
    """The crossed antiparallelogram; default centrodes: rocker relative to crank (elliptic gears
    when the frame is the long link)."""
    controls = {"crank": Control("crank = rocker", 0.2, 5.0, 0.05, crank),
                "ground": Control("frame = coupler", 0.2, 5.0, 0.05, ground)}
    return CentrodeExplorer(Antiparallelogram, controls, link=link, reference=reference,
                            title=f"Antiparallelogram: centrodes of the {link} about the {reference}", live=live,
                            question=question)


__all__ = ["CentrodeExplorer", "antiparallelogram_explorer", "fourbar_centrode_explorer", "trammel_explorer"]
