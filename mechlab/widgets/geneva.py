"""Explorers for the Geneva drives: planar (external/internal toggle, z, C) and the
spherical offset Geneva of Vainer & Shatokhina (R, e, z) drawn in 3-D (turn it with the
mouse in JupyterLab, where the canvas is live). Both reuse
:class:`mechlab.widgets.MechanismExplorer`; the status line shows the dwell fraction,
the peak analogs and the kind of impact instead of the (constant) transmission angle."""

from __future__ import annotations

from ..mechanisms.geneva import ExternalGeneva, InternalGeneva
from ..mechanisms.spherical_geneva import SphericalGeneva
from . import Choice, Control, MechanismExplorer


def _planar(z, centre_distance, kind="external"):
    return (ExternalGeneva if kind == "external" else InternalGeneva)(z, centre_distance)


class GenevaExplorer(MechanismExplorer):
    """MechanismExplorer with a Geneva status line (and, for the planar drive, a toggle
    between the external and the internal wheel)."""

    def __init__(self, factory, controls, **kw):
        super().__init__(factory, controls, **kw)
        if self.drawing is not None and hasattr(self.drawing, "ax"):
            self.ax_mech = self.drawing.ax  # the spherical drawing puts a 3-D axes in its place
        self.kind = self.sliders.get("kind")

    def rebuild(self):
        super().rebuild()
        g = self.mechanism
        if g is None:
            return
        if hasattr(self.drawing, "ax"):
            self.ax_mech = self.drawing.ax
        imp = g.impacts()
        acc = g.max_acceleration()
        acc = acc[0] if isinstance(acc, tuple) else acc
        self.status.value = (f"dwell fraction {g.dwell_fraction:.3f} · max |ψ′| = {g.max_velocity():.3f} · "
                             f"max |ψ″| = {acc:.3f} · {imp.kind} impact "
                             f"(ψ′ jumps by {abs(imp.entry_velocity_jump):.3f}, "
                             f"ψ″ by {abs(imp.entry_acceleration_jump):.3f})")


def planar_geneva_explorer(z: int = 4, centre_distance: float = 100.0, *, live: bool | None = None,
                           question: str | None = None) -> GenevaExplorer:
    """Sliders for z and the centre distance C (mm), a toggle external/internal."""
    controls = {"z": Control("slots z", 3, 12, 1, z),
                "centre_distance": Control("centre dist. C", 20, 200, 1, centre_distance, "mm"),
                "kind": Choice("wheel", ("external", "internal"), "external")}
    return GenevaExplorer(_planar, controls, title="Planar Geneva drive", live=live, question=question,
                          length_unit="mm")


def spherical_geneva_explorer(R: float = 40.0, e: float = 15.0, z: int = 4, *, live: bool | None = None,
                              question: str | None = None) -> GenevaExplorer:
    """Sliders for the sphere radius R, the offset e (mm) and z; the wheel in 3-D, large
    (the mechanism takes the left half of the figure) and turnable with the mouse when live."""
    controls = {"R": Control("sphere radius R", 10, 100, 1, R, "mm"), "e": Control("offset e", 0, 100, 0.5, e, "mm"),
                "z": Control("slots z", 3, 12, 1, z)}
    return GenevaExplorer(SphericalGeneva, controls, trace="P", live=live, question=question, length_unit="mm",
                          title="Spherical offset Geneva (Vainer & Shatokhina)")
