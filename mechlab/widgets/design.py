"""The choosing explorer: change the specification, and every family is synthesised, compared and ranked anew."""

from __future__ import annotations

import html
import io
from dataclasses import replace

import ipywidgets as W
import matplotlib.pyplot as plt
import numpy as np
from IPython.display import display
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from PIL import Image

from ..design import Specification, candidates
from ..design.candidates import COLUMNS
from ..draw.access import alt_text
from ..draw.design import FIGSIZE, ComparisonFigure
from ..errors import MechanismError
from . import SLIDER_STYLE, _uses_ipympl, bare_canvas
from .access import AltImage, announce_controls, status_line

# the library's label width: in 150 px, "pressure angle ≤ (deg)" (150.2 px) was cut
_STYLE = SLIDER_STYLE["style"]
_LAYOUT = W.Layout(width="435px")


class ChoosingExplorer:
    """Sliders for the specification's dwell, speed, pressure-angle limit and stations (or amplitude);
    a table of the candidates ranked by a chosen criterion, the refusals with their reasons, and the
    trade-off figure moved in place. An impossible specification shows why, and the explorer stays
    usable.

    It opens on exactly ``spec``: a slider still at its opening reading (the value rounded to its step)
    stands for the specification's own value (2/3, not 0.67). A release of a slider re-runs the
    comparison once; the figure's axes, ticks and titles are drawn once, and a change draws only the data
    lines and the legend over them and sends the picture as one PNG."""

    def __init__(self, spec: Specification, *, question: str | None = None, live: bool | None = None):
        self.base = spec
        self.live = _uses_ipympl() if live is None else live
        s = {}
        s["dwell_fraction"] = W.FloatSlider(value=round(spec.dwell_fraction, 2), min=0.05, max=0.9, step=0.01,
                                            description="dwell (of the turn)", style=_STYLE, layout=_LAYOUT,
                                            continuous_update=False)
        s["rpm"] = W.FloatSlider(value=round(spec.rpm / 5.0) * 5.0, min=5.0, max=200.0, step=5.0,
                                 description="crank speed (rpm)", style=_STYLE, layout=_LAYOUT, continuous_update=False)
        s["max_pressure_angle"] = W.FloatSlider(value=round(np.degrees(spec.max_pressure_angle)), min=20.0,
                                                max=85.0, step=1.0, description="pressure angle ≤ (deg)",
                                                style=_STYLE, layout=_LAYOUT, continuous_update=False)
        if spec.motion == "index":
            s["stations"] = W.IntSlider(value=spec.stations, min=2, max=12, description="stations", style=_STYLE,
                                        layout=_LAYOUT, continuous_update=False)
        elif spec.motion == "swing":
            s["amplitude"] = W.FloatSlider(value=round(np.degrees(spec.amplitude)), min=5.0, max=120.0, step=1.0,
                                           description="swing (deg)", style=_STYLE, layout=_LAYOUT,
                                           continuous_update=False)
        else:
            s["amplitude"] = W.FloatSlider(value=round(spec.amplitude / 5.0) * 5.0, min=5.0, max=300.0, step=5.0,
                                           description="stroke (mm)", style=_STYLE, layout=_LAYOUT,
                                           continuous_update=False)
        self.sliders = s
        self._opening = {k: w.value for k, w in s.items()}
        # the criteria by the table's headings (C_v, not the library's B), each handing its key to ranked()
        keys = [(head, k) for k, head, *_ in COLUMNS if k not in ("impact", "structure", "J")]
        self.rank = W.Dropdown(options=keys, value="motor_power", description="rank by", style=_STYLE,
                               layout=_LAYOUT)
        self.table = W.HTML()
        self.status = status_line()   # the outcome in one line, announced when it changes
        if self.live:
            with plt.ioff():
                fig = plt.figure(figsize=FIGSIZE, dpi=100, layout="constrained")
            bare_canvas(fig.canvas)
        else:
            fig = Figure(figsize=FIGSIZE, dpi=100, layout="constrained")
            FigureCanvasAgg(fig)
        self.comparison = None
        self._background = None   # (the laws' y-limits, the pixels of everything but the data) once drawn
        self.message = ""
        self.figure = ComparisonFigure(candidates(spec), fig)
        self.output = None if self.live else AltImage(format="png", layout=W.Layout(width="880px"))
        canvas = fig.canvas if self.live else self.output
        ask = [W.HTML(f"<b>Investigate:</b> {question}")] if question else []
        self.widget = W.VBox(ask + [W.HBox([W.VBox(list(s.values())), W.VBox([self.rank, self.status])]), canvas,
                                     self.table])
        for w in [*s.values(), self.rank]:
            w.observe(lambda change: self.rebuild(), names="value")
        self.rebuild()

    def spec(self) -> Specification:
        """The specification the sliders describe (radians inside); a slider not moved from its opening
        reading keeps the starting specification's exact value."""
        v = {k: w.value for k, w in self.sliders.items() if w.value != self._opening[k]}
        if "max_pressure_angle" in v:
            v["max_pressure_angle"] = np.radians(v["max_pressure_angle"])
        if "amplitude" in v and self.base.motion == "swing":
            v["amplitude"] = np.radians(v["amplitude"])
        return replace(self.base, **v)

    def rebuild(self) -> None:
        try:
            comp = candidates(self.spec()).ranked(self.rank.value)
        except MechanismError as err:
            self.message = str(err)
            self.table.value = f"<p style='color:#b00020'>{err}</p>"
            self.status.value = f"<span style='color:#b00020'>{html.escape(str(err))}</span>"
            return
        self.comparison = comp
        self.figure.update(comp)
        if comp.candidates:
            self.message = ""
            self.table.value = comp._repr_html_()
        else:
            self.message = "No family meets this specification."
            why = "".join(f"<li><b>{r.family}</b>: {r.reason}</li>" for r in comp.refusals)
            self.table.value = f"<p style='color:#b00020'><b>{self.message}</b> Why:</p><ul>{why}</ul>"
        self.status.value = html.escape(self._summary(comp))
        self._redraw()

    def _summary(self, comp) -> str:
        """How many families meet the specification, and which comes first by the ranking criterion."""
        kept, refused = len(comp.candidates), len(comp.refusals)
        head = f"{kept} of {kept + refused} families meet the specification"
        if not comp.candidates:
            return head + "."
        key, heading, unit, fmt = next(col for col in COLUMNS if col[0] == self.rank.value)
        first = comp.candidates[0]
        value = fmt.format(getattr(first.criteria, key))
        # a no-break space keeps the value and its unit on one line of the status
        return f"{head}; first by {heading}: {first.family} ({value}{chr(0xA0) + unit if unit else ''})."

    def _redraw(self) -> None:
        if self.live:
            self.figure.fig.canvas.draw_idle()
        else:
            self.output.value = self._png()
            self.output.alt = alt_text(self.figure.fig)

    def _png(self) -> bytes:
        """The figure as PNG: the axes, ticks and titles drawn once (their layout frozen), then only the data
        lines and the legend drawn over them, so that a slider release costs no text layout."""
        fig, laws = self.figure.fig, self.figure.laws
        canvas = fig.canvas
        data = [*self.figure.spokes.values(), *self.figure.curves.values()]
        if self._background is None or self._background[0] != laws.get_ylim():
            legend = laws.get_legend()
            shown = [a for a in data + [legend] if a is not None and a.get_visible()]
            for a in shown:
                a.set_visible(False)
            canvas.draw()
            fig.set_layout_engine("none")   # the first drawing's layout holds: the axes and their labels stay
            self._background = (laws.get_ylim(), canvas.copy_from_bbox(fig.bbox))
            for a in shown:
                a.set_visible(True)
        canvas.restore_region(self._background[1])
        for a in data:
            if a.get_visible():
                a.axes.draw_artist(a)
        if laws.get_legend() is not None:
            laws.draw_artist(laws.get_legend())
        png = io.BytesIO()
        Image.frombuffer("RGBA", canvas.get_width_height(), canvas.buffer_rgba()).save(png, format="png",
                                                                                        compress_level=1)
        return png.getvalue()

    def _ipython_display_(self):
        announce_controls()
        display(self.widget)


def choosing_explorer(spec: Specification, *, question: str | None = None) -> ChoosingExplorer:
    """The choosing explorer for a starting specification (see :class:`ChoosingExplorer`)."""
    return ChoosingExplorer(spec, question=question)
