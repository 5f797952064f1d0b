"""Controls for a disc cam with a translating roller follower: base and roller radii, offset (mm), the
programme (stroke in mm, rise, outer dwell and return in degrees, the law), driving the drawing and the
lift s, s′, s″; the status line gives the largest pressure angles and the smallest radius of curvature
of the profile. An undercut profile or an impossible programme shows its message instead."""

from __future__ import annotations

import html

import ipywidgets as W
import numpy as np

from ..analysis.motion_laws import LAWS
from ..mechanisms.cam import TranslatingRollerCam
from ..synthesis.cam_design import CamProgramme
from . import Choice, Control, MechanismExplorer


class CamExplorer(MechanismExplorer):
    """Sliders → :class:`~mechlab.mechanisms.cam.TranslatingRollerCam` → drawing and lift; ``question``
    is shown above the controls as "Investigate: …"."""

    def __init__(self, base_radius=40.0, roller_radius=10.0, offset=8.0, stroke=20.0, rise_deg=120.0,
                 outer_dwell_deg=40.0, return_deg=100.0, law="3-4-5 polynomial", *, n: int = 121,
                 question: str | None = None):
        controls = {
            "base_radius": Control("base radius r_b", 10.0, 80.0, 1.0, base_radius, "mm"),
            "roller_radius": Control("roller r_r", 0.0, 25.0, 0.5, roller_radius, "mm"),
            "offset": Control("offset e", -30.0, 30.0, 0.5, offset, "mm"),
            "stroke": Control("stroke h", 2.0, 60.0, 1.0, stroke, "mm"),
            "rise": Control("rise", 20.0, 240.0, 5.0, rise_deg, "deg"),
            "outer_dwell": Control("outer dwell", 0.0, 180.0, 5.0, outer_dwell_deg, "deg"),
            "ret": Control("return", 20.0, 240.0, 5.0, return_deg, "deg"),
            "law": Choice("law", tuple(LAWS), law),
        }
        super().__init__(self._build, controls, n=n, title="Disc cam with a translating roller follower (mm)",
                         length_unit="mm")
        if question:
            self.widget.children = (W.HTML(f"<b>Investigate:</b> {html.escape(question)}"), *self.widget.children)

    @staticmethod
    def _build(base_radius, roller_radius, offset, stroke, rise, outer_dwell, ret, law):
        programme = CamProgramme(stroke, rise, ret, outer_dwell, law=law)
        return TranslatingRollerCam(programme, base_radius, roller_radius, offset=offset)

    def _status(self) -> str:
        """The pressure angles and the profile's sharpest curvature only: a cam has no transmission angle."""
        cam, phi = self.mechanism, self.motion.phi
        alpha = np.degrees(cam.pressure_angle(phi))
        k = cam.curvature(phi)
        rho = 1 / k.max() - cam.roller_radius
        return (f"pressure angle: largest {alpha.max():.1f}° (rise), {alpha.min():.1f}° (return)"
                f"<br>smallest radius of curvature of the profile: {rho:.1f} mm at φ = "
                f"{np.degrees(phi[np.argmax(k)]):.0f}°")


def cam_explorer(**kwargs) -> CamExplorer:
    """The cam explorer with the packaging-line pusher's defaults (see :class:`CamExplorer`)."""
    return CamExplorer(**kwargs)
