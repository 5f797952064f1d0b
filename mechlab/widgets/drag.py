"""Drag a linkage by its joints (:class:`DragEditor`): its dimensions, coupler curve, instantaneous centres and
transmission angle follow; undo, snapping to a grid, "copy as code" and a keyboard route (issue 27).

It edits any :class:`mechlab.Linkage` the structure builder makes and the families with a builder twin
(:func:`as_linkage`); :func:`moved` says what a handle's new position changes, :func:`linkage_code` writes the
cell that rebuilds a linkage exactly. Where the linkage cannot assemble, the named MechanismError replaces the
drawing and the last linkage that assembles is kept.

Why ipympl's mouse events and not an anywidget: the explorers already draw on an ipympl canvas with blitting,
a PNG diff per frame (:func:`mechlab.widgets.diff_image`), the course's error display, alt text and static-book
path, and ipympl forwards ``button_press``, ``motion_notify``, ``button_release`` and ``key_press`` events; so a
drag is a few lines of picking in Python on the figure every chapter shows. An anywidget would need its own
JavaScript drawing of every mechanism (or a second channel beside the canvas), duplicating the sketch, labels
and centres of :class:`mechlab.draw.LinkageDrawing`, for the same kernel round trip (the kinematics run in
Python either way).

Live in JupyterLab (blitting over a saved background, as every explorer); in the book
(``MECHLAB_WIDGETS=static``) the same figure, the mechanism with its coupler curve, is shown as an image.
"""

from __future__ import annotations

import html
import math
import time
from collections.abc import Callable
from dataclasses import replace

import ipywidgets as W
import numpy as np
from matplotlib.ticker import MultipleLocator, NullLocator

from ..analysis.centres import instant_centres
from ..draw import LinkageDrawing
from ..draw.access import set_alt
from ..errors import MechanismError, StructureError
from ..mechanisms.base import FULL_TURN, TWO_PI
from ..mechanisms.fourbar import FourBar
from ..mechanisms.lambda_mechanism import LambdaMechanism
from ..mechanisms.lambda_sixbars import LambdaRockerSixBar
from ..mechanisms.lambda_sliders import LambdaSliderSixBar
from ..mechanisms.linkage.built import Linkage, LinkageFamily
from ..mechanisms.linkage.groups import PRP, RPR, RRP, RRR, Crank, Guide, Point
from ..mechanisms.slider_crank import SliderCrank
from ..mechanisms.slotted import SlottedLink
from . import SIDE_COLUMN, SLIDER_COLUMN, Explorer, _fit

PICK_PX = 12.0            # a press this close to a handle (figure pixels) grabs it
STATUS_EVERY = 0.15       # s: while a handle is held the status line is rewritten at most this often
CURVE_STYLE = dict(color="#9467bd", lw=1.6, zorder=1.5)
HANDLE_STYLE = dict(ls="none", marker="o", ms=13, mfc="none", mec="#1f77b4", mew=1.6, zorder=7)
CHOSEN_STYLE = dict(ls="none", marker="o", ms=19, mfc="none", mec="#e08214", mew=2.5, zorder=7)
CENTRE_STYLE = dict(ls="none", marker="x", ms=7, mew=1.8, color="#d62728", zorder=6)
CENTRE_LABEL = dict(color="#d62728", fontsize=8, ha="left", va="bottom", zorder=6)
MOVES = {"left": (-1, 0), "right": (1, 0), "up": (0, 1), "down": (0, -1)}


# -- mechanisms as builder linkages --------------------------------------------------------------------------
def _fourbar(m) -> Linkage:
    return Linkage({"O": (0.0, 0.0), "E": (float(m.ground), 0.0)}, Crank("O", "A", m.crank)).rrr(
        "A", "E", "B", m.coupler, m.rocker, m.assembly, links=("coupler", "rocker"))


def _slider_crank(m) -> Linkage:
    return Linkage({"O": (0.0, 0.0), "G": (0.0, float(m.offset))}, Crank("O", "A", m.crank)).rrp(
        "A", "B", m.rod, "G", m.assembly, links=("rod", "slider"))


def _slotted_link(m) -> Linkage:
    d = float(m.pivot_distance)
    return Linkage({"O": (0.0, 0.0), "B": (-d, 0.0)}, Crank("O", "A", m.crank)).rpr("A", "B", d + m.crank)


def _lambda(m, **frame) -> Linkage:
    """Chebyshev's lambda: crank r, coupler A-B of length 1 carrying D at (1 - cos kc·δ, -sin kc·δ) in its frame
    (D = B + Rot(kc·δ)(A - B)), rocker C-B of length 1."""
    th = m.assembly * m.delta
    return (Linkage({"O": (0.0, 0.0), "C": (float(m.a), 0.0), **frame}, Crank("O", "A", m.r))
            .rrr("A", "C", "B", 1.0, 1.0, m.assembly, links=("coupler", "rocker"))
            .point("D", "coupler", (float(1 - np.cos(th)), float(-np.sin(th)))))


# the families with a builder twin that moves as they do (tests/test_overrides.py holds each to 1e-12)
TWINS = {
    FourBar: _fourbar,
    SliderCrank: _slider_crank,
    SlottedLink: _slotted_link,
    LambdaMechanism: lambda m: _lambda(m).with_output("rocker"),
    LambdaRockerSixBar: lambda m: _lambda(m.base, F=(float(m.fx), float(m.fy))).rrr(
        "D", "F", "E", m.rod, m.rocker, m.assembly),
    LambdaSliderSixBar: lambda m: _lambda(m.base, Q=(float(m.qx), float(m.qy))).rrp(
        "D", "E", m.rod, Guide("Q", float(m.theta)), m.assembly),
}


def as_linkage(mechanism) -> Linkage:
    """The structure builder's :class:`~mechlab.Linkage` of a mechanism, for the drag editor.

    A Linkage is returned as it is; a ``LinkageFamily`` gives the linkage it builds; a
    :class:`~mechlab.FourBar` becomes O(0, 0)-A-B-E(ground, 0) with links "coupler" and "rocker"; a
    :class:`~mechlab.SliderCrank` O(0, 0)-A-B with its guide through G(0, offset) (links "rod", "slider");
    a :class:`~mechlab.SlottedLink` the crank O-A and the lever pivoted at B(-pivot distance, 0); Chebyshev's
    :class:`~mechlab.LambdaMechanism` O-A-B-C with its point D on the coupler, and its rocker and slider six-bars
    that dyad more (F or the guide through Q). Each moves exactly as the family does.

    Parameters
    ----------
    mechanism : Linkage, LinkageFamily, FourBar, SliderCrank, SlottedLink, LambdaMechanism, \
LambdaRockerSixBar or LambdaSliderSixBar
        The mechanism to edit.

    Returns
    -------
    Linkage
        The same mechanism, built from its crank and groups.

    Raises
    ------
    StructureError
        A mechanism of another kind (a cam, a Geneva wheel: not built from a crank and dyads).

    Examples
    --------
    >>> import mechlab as ml
    >>> as_linkage(ml.FourBar(1, 3, 3, 4)).formula()
    'I(crank) → II₂(coupler, rocker)'
    """
    if isinstance(mechanism, Linkage):
        return mechanism
    if isinstance(mechanism, LinkageFamily):
        return mechanism.linkage()
    twin = next((make for kind, make in TWINS.items() if isinstance(mechanism, kind)), None)
    if twin is None:
        raise StructureError(f"the drag editor edits linkages built from a crank and Assur groups (ml.Linkage, a "
                             f"LinkageFamily, or one of {', '.join(k.__name__ for k in TWINS)}), not a "
                             f"{type(mechanism).__name__}")
    return twin(mechanism)


def _num(v) -> str:
    """A float as Python reads it back exactly (repr), whole numbers with their ".0"."""
    return repr(float(v))


def _pair(xy) -> str:
    return f"({_num(xy[0])}, {_num(xy[1])})"


def _guide_code(g: Guide) -> str:
    extra = f", {g.on!r}" if g.on is not None else ""
    return f"ml.Guide({g.through!r}, {_num(g.angle)}{extra})"


def _links_code(g) -> str:
    return "" if g.links is None else f", links=({', '.join(repr(k) for k in g.links)})"


def _group_code(g) -> str:
    """The builder call that attaches ``g``."""
    if isinstance(g, RRR):
        return (f".rrr({g.first!r}, {g.second!r}, {g.joint!r}, {_num(g.first_length)}, {_num(g.second_length)}, "
                f"{int(g.assembly)}{_links_code(g)})")
    if isinstance(g, RRP):
        return (f".rrp({g.pin!r}, {g.joint!r}, {_num(g.length)}, {_guide_code(g.guide)}, {int(g.assembly)}"
                f"{_links_code(g)})")
    if isinstance(g, RPR):
        return f".rpr({g.pin!r}, {g.pivot!r}, {_num(g.length)}{_links_code(g)})"
    if isinstance(g, PRP):
        return f".prp({_guide_code(g.first)}, {_guide_code(g.second)}, {g.joint!r}{_links_code(g)})"
    if isinstance(g, Point):
        return f".point({g.name!r}, {g.on!r}, {_pair(g.at)})"
    raise StructureError(f"no builder call for {type(g).__name__}")   # pragma: no cover - every group above


def linkage_code(linkage: Linkage, name: str = "linkage") -> str:
    """The notebook cell that rebuilds ``linkage`` with the structure builder (every number exactly).

    Parameters
    ----------
    linkage : Linkage
        The linkage.
    name : str, optional
        The variable the cell assigns.

    Returns
    -------
    str
        Python source: ``import mechlab as ml`` and ``name = (ml.Linkage(...) .rrr(...) ...)``.

    Examples
    --------
    >>> import mechlab as ml
    >>> print(linkage_code(ml.Linkage({"O": (0, 0), "E": (4, 0)}, ml.Crank("O", "A", 1.0)).rrr("A", "E", "B", 3, 3)))
    import mechlab as ml
    <BLANKLINE>
    linkage = (
        ml.Linkage({'O': (0.0, 0.0), 'E': (4.0, 0.0)}, ml.Crank('O', 'A', 1.0))
        .rrr('A', 'E', 'B', 3.0, 3.0, 1)
    )
    """
    d = linkage.driver
    crank = f"ml.Crank({d.pivot!r}, {d.joint!r}, {_num(d.radius)}" + (f", {d.name!r})" if d.name != "crank" else ")")
    frame = ", ".join(f"{k!r}: {_pair(xy)}" for k, xy in linkage.frame)
    lines = [f"    ml.Linkage({{{frame}}}, {crank})", *(f"    {_group_code(g)}" for g in linkage.groups)]
    if linkage.output_link is not None:
        lines.append(f"    .with_output({linkage.output_link!r})")
    return "import mechlab as ml\n\n" + f"{name} = (\n" + "\n".join(lines) + "\n)"


# -- what a handle's new position means ----------------------------------------------------------------------
def _snap(v: float, step: float | None, positive: bool = False) -> float:
    """``v`` to the nearest multiple of ``step`` (unchanged without a step); a length stays ≥ one step."""
    if not step:
        return float(v)
    k = round(v / step)
    if positive:
        k = max(k, 1)
    return round(k * step, 12)


def _angle_of(linkage: Linkage, motion, link: str) -> float:
    """The angle of ``link``'s axis in the one-row ``motion``."""
    return float(np.atleast_1d(linkage.structure().link(link).angle(motion).theta)[-1])


def handles(linkage: Linkage) -> dict[str, str]:
    """The joints the drag editor offers, each with what dragging it changes (in words).

    Parameters
    ----------
    linkage : Linkage
        The linkage.

    Returns
    -------
    dict
        Joint name → "frame point (x, y)", "crank pin: crank length", … in the order joints are defined.

    Examples
    --------
    >>> import mechlab as ml
    >>> list(handles(as_linkage(ml.FourBar(1, 3, 3, 4))).values())[2:]
    ['crank pin: crank length and φ', 'joint of coupler and rocker: their lengths']
    """
    out = {name: "frame point: its position" for name, _ in linkage.frame}
    d = linkage.driver
    out[d.joint] = "crank pin: crank length and φ"
    for g in linkage.groups:
        if isinstance(g, RRR):
            one, two = g.link_names()
            out[g.joint] = f"joint of {one} and {two}: their lengths"
        elif isinstance(g, RRP):
            out[g.joint] = f"slider pin on its guide: the length of {g.link_names()[0]}"
        elif isinstance(g, Point):
            out[g.name] = f"point on {g.on}: its (ξ, η)"
    return out


def moved(linkage: Linkage, joint: str, xy, phi: float, step: float | None = None) -> tuple[Linkage, float]:
    """The linkage whose ``joint`` is at ``xy`` at crank angle φ: the dimensions the joint implies changed.

    A frame point takes the position; the crank's pin gives the crank's length and φ; an RRR dyad's joint the
    two lengths meeting there and the branch (the side of the line first → second it lies on); an RRP dyad's
    pin, projected on its guide, the rod's length and the branch; a point on a link its (ξ, η). With
    ``step``, coordinates, lengths and (ξ, η) are rounded to multiples of it (a length to one step at least).

    Parameters
    ----------
    linkage : Linkage
        The linkage before the move.
    joint : str
        A joint of :func:`handles`.
    xy : (float, float)
        Where the joint goes.
    phi : float
        The crank angle (radians) of the pose the joint is dragged in.
    step : float, optional
        The grid's step (None: no snapping).

    Returns
    -------
    (Linkage, float)
        The new linkage and the crank angle to show it at (φ, or the crank pin's new angle).

    Raises
    ------
    StructureError
        A joint that no dimension places (a PRP joint, an unknown name).
    MechanismError
        The new linkage cannot be built (AssemblyError, DimensionError …, each named) or cannot assemble at φ.

    Examples
    --------
    >>> import mechlab as ml
    >>> lk, phi = moved(as_linkage(ml.FourBar(1, 3, 3, 4)), "A", (0.0, 1.5), 0.0)
    >>> round(lk.driver.radius, 12), round(float(np.degrees(phi)), 9)
    (1.5, 90.0)
    """
    x, y = (float(v) for v in xy)
    if not (math.isfinite(x) and math.isfinite(y)):
        raise StructureError(f"the joint {joint} cannot go to ({x}, {y})")
    motion = linkage.motion(np.array([float(phi)]))
    pts = {k: v.p[-1] for k, v in motion.points.items()}
    frame = dict(linkage.frame)
    d = linkage.driver
    if joint in frame:
        frame[joint] = (_snap(x, step), _snap(y, step))
        new = replace(linkage, frame=frame)
    elif joint == d.joint:
        O = np.asarray(frame[d.pivot], float)
        r = _snap(math.hypot(x - O[0], y - O[1]), step, positive=True)
        phi = math.atan2(y - O[1], x - O[0]) % TWO_PI
        new = replace(linkage, driver=replace(d, radius=r))
    else:
        groups = list(linkage.groups)
        k = next((i for i, g in enumerate(groups) if joint in g.makes()), None)
        g = groups[k] if k is not None else None
        B = np.array([x, y])
        if isinstance(g, RRR):
            P1, P2 = pts[g.first], pts[g.second]
            side = float((P2 - P1)[0] * (B - P1)[1] - (P2 - P1)[1] * (B - P1)[0])
            groups[k] = replace(g, first_length=_snap(np.hypot(*(B - P1)), step, positive=True),
                                second_length=_snap(np.hypot(*(B - P2)), step, positive=True),
                                assembly=g.assembly if side == 0.0 else (1 if side > 0 else -1))
        elif isinstance(g, RRP):
            Q = pts[g.guide.through]
            on = g.guide.link(linkage._carriers.__getitem__)
            th = g.guide.angle + (0.0 if on == "frame" else _angle_of(linkage, motion, on))
            u = np.array([np.cos(th), np.sin(th)])
            P = pts[g.pin]
            t, foot = float((B - Q) @ u), float((P - Q) @ u)
            on_guide = Q + t * u
            ahead = t - foot
            groups[k] = replace(g, length=_snap(np.hypot(*(on_guide - P)), step, positive=True),
                                assembly=g.assembly if ahead == 0.0 else (1 if ahead > 0 else -1))
        elif isinstance(g, Point):
            origin = linkage.structure().link(g.on).origin
            th = _angle_of(linkage, motion, g.on)
            r = (B - pts[origin]) @ np.array([[np.cos(th), -np.sin(th)], [np.sin(th), np.cos(th)]])
            groups[k] = replace(g, at=(_snap(r[0], step), _snap(r[1], step)))
        else:
            raise StructureError(f"no dimension places the joint {joint!r}; drag one of "
                                 f"{', '.join(handles(linkage))}")
        new = replace(linkage, groups=tuple(groups))
    new.motion(np.array([phi]))   # it must assemble where it is dragged (the named error otherwise)
    return new, float(phi)


def _curve_angles(linkage: Linkage, phi: float, n: int) -> tuple[np.ndarray, float]:
    """``n`` crank angles over the turn, or over the reachable range that holds φ (stopping 1e-4 of it short of
    its dead points, as Mechanism.cycle does), and φ moved into that range."""
    ranges = linkage.crank_ranges()
    if ranges == FULL_TURN:
        return np.linspace(0.0, TWO_PI, n), phi
    for s, e in ranges:
        for shifted in (phi, phi - TWO_PI, phi + TWO_PI):
            if s < shifted < e:
                m = 1e-4 * (e - s)
                return np.linspace(s + m, e - m, n), shifted
    return np.array([]), phi   # φ unreachable: motion(φ) names why


class DragEditor(Explorer):
    """Drag a linkage's joints: its dimensions, coupler curve, instantaneous centres and transmission angle
    follow (see :mod:`mechlab.widgets.drag`).

    Handles (circles) sit on the frame points and on the joints a dimension places, at the crank angle of the
    slider: a frame point takes its new position, the crank's pin sets the crank's length (φ follows the
    pointer), an RRR dyad's joint the two lengths meeting there, an RRP dyad's slider pin the rod's length, a
    point on a link its (ξ, η) (:func:`moved`). A PRP joint and an RPR block are placed by other joints: no
    handle. Keyboard: every control is reached by Tab (the joint to move, ← ↑ ↓ → buttons, the step, snapping,
    undo, copy as code); with the canvas focused the arrow keys move the chosen joint by the step (shift: ten
    steps), ``j`` chooses the next joint, ``u`` undoes.

    Parameters
    ----------
    linkage : Linkage, LinkageFamily, FourBar, SliderCrank or SlottedLink
        The mechanism to edit (:func:`as_linkage`).
    point : str, optional
        The joint whose path (the coupler curve) is drawn; default: the last point fixed on a link, else the
        last joint defined.
    phi : float, optional
        The crank angle shown (radians).
    grid : float, optional
        Snap to a grid of this step (length units); None: snapping off (the step for the arrows is then a
        round twentieth of the linkage's size).
    n : int, optional
        Crank angles sampled for the coupler curve.
    live : bool, optional
        A live canvas (default: in a kernel, :func:`mechlab.widgets.live_by_default`).
    question : str, optional
        A question shown above the controls.

    Attributes
    ----------
    linkage : Linkage
        The current (last assembling) linkage.
    phi : float
        The crank angle shown (radians).

    Raises
    ------
    StructureError
        A mechanism the builder does not make, or a ``point`` that is not one of its joints.
    MechanismError
        A linkage that does not assemble at φ.

    Examples
    --------
    >>> import mechlab as ml
    >>> ed = DragEditor(ml.FourBar(1, 3, 3, 4), live=True)
    >>> ed.move("B", (2.0, 3.0))
    True
    >>> [round(v, 6) for v in (ed.linkage.groups[0].first_length, ed.linkage.groups[0].second_length)]
    [3.162278, 3.605551]
    >>> ed.undo()
    True
    >>> ed.linkage.groups[0].first_length
    3.0
    """

    def __init__(self, linkage, *, point: str | None = None, phi: float = 0.0, grid: float | None = None,
                 n: int = 361, live: bool | None = None, question: str | None = None, figsize=(8.0, 5.6)):
        lk = as_linkage(linkage)
        phis, phi_in = _curve_angles(lk, float(phi) % TWO_PI, n)
        lk.motion(np.append(phis, phi_in))   # the named error here if it does not assemble at φ
        super().__init__(as_linkage, {}, n=n, title="", live=live, figsize=figsize, angle=0.0, question=question)
        self.angle.step, self.angle.readout_format = 1.0, ".0f"
        self.linkage, self.phi = lk, float(phi) % TWO_PI
        self.angle.value = round(math.degrees(self.phi)) % 360
        joints = [*(name for name, _ in lk.frame), lk.driver.joint, *(j for g in lk.groups for j in g.makes())]
        points = [g.name for g in lk.groups if isinstance(g, Point)]
        self.point = point if point is not None else (points or joints)[-1]
        if self.point not in joints:
            raise StructureError(f"point = {self.point!r} is not a joint of the linkage; joints: {', '.join(joints)}")
        self._undo: list[tuple[Linkage, float]] = []
        self._callbacks: list[tuple[Callable, bool]] = []
        self._overlays: list = []
        self._drag = None          # (joint, linkage, φ) at the press while a handle is held
        self._quiet = False        # an angle set by a drag: no second redraw
        self._far: list[str] = []
        self._why = ""
        self._read_at = -math.inf   # when the status line was last written
        scale = lk.structure().scale
        default = float(10.0 ** math.floor(math.log10(scale / 20.0)))
        self.ax = self.fig.add_axes((0.06, 0.07, 0.92, 0.9))
        self.ax.set_aspect("equal")
        self.ax.grid(True, alpha=0.3)
        self.ax.set_xlabel("x")
        self.ax.set_ylabel("y")
        self.drawing = LinkageDrawing(self.ax, lk, n=n)
        (self.curve_line,) = self.ax.plot([], [], label=f"path of {self.point}", **CURVE_STYLE)
        (self.handle_marks,) = self.ax.plot([], [], **HANDLE_STYLE)
        (self.chosen_mark,) = self.ax.plot([], [], **CHOSEN_STYLE)
        (self.centre_marks,) = self.ax.plot([], [], **CENTRE_STYLE)
        self.centre_labels: list = []
        self.ax.legend(handles=[self.curve_line], loc="upper left", fontsize=9, frameon=False)
        # controls: every action reachable by Tab, each with a name a screen reader reads
        self.joint = W.Dropdown(options=[(f"{j} — {what}", j) for j, what in handles(lk).items()],
                                value=lk.driver.joint, description="joint to move",
                                style={"description_width": "95px"}, layout=W.Layout(width="445px"))
        self.arrows = {key: W.Button(description=f"{sym} {key}", tooltip=f"move the joint {key} by one step",
                                     layout=W.Layout(width="80px"))
                       for key, sym in (("left", "←"), ("up", "↑"), ("down", "↓"), ("right", "→"))}
        self.step = W.BoundedFloatText(value=grid or default, min=1e-6, max=1e6, description="step",
                                       style={"description_width": "95px"}, layout=W.Layout(width="200px"))
        self.snap = W.Checkbox(value=grid is not None, description="snap to the grid of this step", indent=False)
        self.undo_button = W.Button(description="undo", icon="undo", tooltip="undo the last change", disabled=True)
        self.copy_button = W.Button(description="copy as code", icon="clipboard",
                                    tooltip="the cell that rebuilds this mechanism")
        self.code_box = W.Textarea(value="", description="code", placeholder="press “copy as code”",
                                   layout=W.Layout(width="98%", height="9em", display="none"))
        for key, button in self.arrows.items():
            button.on_click(lambda _b, key=key: self.nudge(key))
        self.undo_button.on_click(lambda _b: self.undo())
        self.copy_button.on_click(lambda _b: self._show_code())
        self.joint.observe(lambda _c: self._update_handles(redraw=True), names="value")
        self.snap.observe(lambda _c: self._show_grid(redraw=True), names="value")
        self.step.observe(lambda _c: self._show_grid(redraw=True), names="value")
        self.angle.observe(self._on_angle, names="value")
        canvas = self.fig.canvas
        manager = getattr(canvas, "manager", None)
        if manager is not None and getattr(manager, "key_press_handler_id", None) is not None:
            # matplotlib's own keys (s saves, q closes, g grids, arrows pan back and forth) are not the editor's
            canvas.mpl_disconnect(manager.key_press_handler_id)
        toolbar = getattr(canvas, "toolbar", None)
        for cid in ("_id_press", "_id_release", "_id_drag"):
            # the hidden toolbar's pan and zoom, and its pointer readout (a widget message per mouse move)
            if hasattr(toolbar, cid):
                canvas.mpl_disconnect(getattr(toolbar, cid))
        for event, handler in (("button_press_event", self._on_press), ("motion_notify_event", self._on_motion),
                               ("button_release_event", self._on_release), ("key_press_event", self._on_key)):
            canvas.mpl_connect(event, handler)
        # a status line of fixed height: a longer one (an error) must not move the canvas under the pointer
        self.status.layout = W.Layout(height="5.5em", overflow_y="auto")
        pad = W.HBox([self.arrows["left"], self.arrows["up"], self.arrows["down"], self.arrows["right"]])
        self.widget = W.VBox([self.question,
                              W.HBox([W.VBox([self.joint, pad, W.HBox([self.step, self.snap])], **SLIDER_COLUMN),
                                      W.VBox([self.angle, W.HBox([self.undo_button, self.copy_button]),
                                              self.status], **SIDE_COLUMN)]),
                              self._canvas_widget, self.code_box])
        self._show_grid(redraw=False)
        self._show(lk, self.phi, fit=True)

    # -- public ------------------------------------------------------------------------------------------------
    def code(self, name: str = "linkage") -> str:
        """The cell that rebuilds the current linkage with ``ml.Linkage`` (:func:`linkage_code`).

        Parameters
        ----------
        name : str, optional
            The variable the cell assigns.

        Returns
        -------
        str
            Python source.
        """
        return linkage_code(self.linkage, name)

    def move(self, joint: str, xy, *, push: bool = True) -> bool:
        """Put ``joint`` at ``xy`` (at the current crank angle), as a drag dropping it there does.

        Parameters
        ----------
        joint : str
            A joint with a handle.
        xy : (float, float)
            Its new position.
        push : bool, optional
            Record the linkage before the move for :meth:`undo`.

        Returns
        -------
        bool
            True if the linkage assembles there (it is then the current one); False: the named error is shown
            and the last linkage kept.
        """
        return self._propose(self.linkage, joint, xy, self.phi, push=push, notify=True)

    def nudge(self, direction: str, steps: int = 1) -> bool:
        """Move the chosen joint (the "joint to move" drop-down) by ``steps`` steps.

        Parameters
        ----------
        direction : {"left", "right", "up", "down"}
            Where to.
        steps : int, optional
            How many steps.

        Returns
        -------
        bool
            True if the linkage assembles there.
        """
        dx, dy = MOVES[direction]
        x, y = self._positions()[self.joint.value]
        h = steps * float(self.step.value)
        return self.move(self.joint.value, (x + dx * h, y + dy * h))

    def undo(self) -> bool:
        """Go back to the linkage (and crank angle) before the last change.

        Returns
        -------
        bool
            False if there is nothing to undo.
        """
        if not self._undo:
            return False
        lk, phi = self._undo.pop()
        self._show(lk, phi, fit=True)
        self.undo_button.disabled = not self._undo
        self._notify(dragging=False)
        return True

    def on_change(self, callback: Callable, *, while_dragging: bool = False) -> Callable:
        """Call ``callback(linkage)`` after every change of the dimensions (a drop, an arrow move, an undo).

        Parameters
        ----------
        callback : callable
            Called with the new :class:`~mechlab.Linkage`.
        while_dragging : bool, optional
            Also at every step of a drag (keep it fast: it adds to the drag's latency).

        Returns
        -------
        callable
            ``callback`` (so this works as a decorator).
        """
        self._callbacks.append((callback, while_dragging))
        return callback

    def add_overlay(self, *artists) -> None:
        """Artists of the caller's on :attr:`ax` (an arc fit, …) that an :meth:`on_change` callback moves: drawn with
        the linkage, and again once the callbacks have run.

        Parameters
        ----------
        *artists : matplotlib.artist.Artist
            Artists already added to ``self.ax``.
        """
        self._overlays.extend(artists)
        self._animate_moving()
        self._redraw()

    def refresh(self) -> None:
        """Redraw the moving artists (after a callback changed an overlay outside a change)."""
        self._blit_or_redraw()

    # -- state → figure -----------------------------------------------------------------------------------
    def _positions(self) -> dict[str, np.ndarray]:
        return {k: v.p[-1] for k, v in self.motion.points.items()}

    def _show(self, linkage: Linkage, phi: float, fit: bool = False) -> bool:
        """Compute and draw ``linkage`` at φ; on a MechanismError show it and keep the last good state."""
        try:
            phis, phi_in = _curve_angles(linkage, phi, self.n)
            motion = linkage.motion(np.append(phis, phi_in))
        except MechanismError as err:
            self._show_error(str(err))
            return False
        try:
            centres, why = instant_centres(linkage, phi_in), ""
        except MechanismError as err:
            centres, why = None, str(err)
        was_hidden = bool(self.message)
        self.message = ""
        self.linkage, self.phi, self.motion = linkage, float(phi) % TWO_PI, motion
        self.drawing.set_motion(linkage, motion)
        self.drawing.set_frame(len(motion) - 1)
        path = motion.points[self.point].p[:-1]
        self.curve_line.set_data(path[:, 0], path[:, 1])
        self._why = why
        self._place_centres(centres)
        if self._drag is not None:   # while a handle is held, of the texts only its letter (each costs ~1.5 ms a frame)
            held = self.drawing.letters.get(self._drag[0])
            for text in (*self.drawing.label_artists, *self.centre_labels):
                text.set_visible(text is held)
        self._update_handles(redraw=False)
        self._animate_moving()
        now = time.monotonic()
        if self._drag is None or was_hidden or now - self._read_at >= STATUS_EVERY:   # a message fewer per step
            self.status.value, self._read_at = self._reading(), now
        mu = np.degrees(motion.transmission[:-1])
        set_alt(self.fig, f"Kinematic diagram of the linkage {linkage.formula()} with joints "
                          f"{', '.join(motion.points)}, drawn at crank angle φ = {math.degrees(self.phi):.0f}°, "
                          f"handles (circles) on the joints that can be dragged, the path of {self.point} over the "
                          f"crank's motion (purple) and the instantaneous centres (red crosses); transmission angle "
                          f"from {mu.min():.0f}° to {mu.max():.0f}°.")
        self._set_visible(True)
        # while a handle is held the view stays (each step a blit, nothing jumps under the pointer)
        rescaled = self._fit_view(path) if fit else False
        if rescaled or was_hidden or not (self.live and self.blit):
            self._redraw()
        else:
            self._blit_or_redraw()
        return True

    def _fit_view(self, path) -> bool:
        x0, x1, y0, y1 = self.drawing.bounds(margin=0.08)
        if len(path):
            x0, x1 = min(x0, np.nanmin(path[:, 0])), max(x1, np.nanmax(path[:, 0]))
            y0, y1 = min(y0, np.nanmin(path[:, 1])), max(y1, np.nanmax(path[:, 1]))
        if not _fit(self.ax, (x0, x1, y0, y1), fill=True):
            return False
        self.ax.apply_aspect()   # the view final now, not at the next draw: the pointer's next event maps onto it
        self._show_grid(redraw=False)   # as many grid lines as the new view holds
        return True

    def _show_grid(self, redraw: bool) -> None:
        """With snapping on, the grid's lines at every step (as minor gridlines, up to 100 across the view)."""
        step = float(self.step.value)
        span = max(np.ptp(self.ax.get_xlim()), np.ptp(self.ax.get_ylim()))
        shown = bool(self.snap.value) and span / step <= 100
        for axis in (self.ax.xaxis, self.ax.yaxis):
            axis.set_minor_locator(MultipleLocator(step) if shown else NullLocator())
        if shown:
            self.ax.grid(True, which="minor", alpha=0.12)
        else:
            self.ax.grid(False, which="minor")
        if redraw:
            self._redraw()

    def _place_centres(self, centres) -> None:
        rows = [] if centres is None else sorted(centres.centres.items())
        finite = [(centres.label(i + 1, j + 1), c.h[:2]) for (i, j), c in rows if c.h[2] == 1.0]
        xy = np.array([p for _, p in finite]).reshape(-1, 2)
        self.centre_marks.set_data(xy[:, 0], xy[:, 1])
        # a centre at a joint is that joint (its letter is there): named only the centres found by Kennedy's lines
        joints = np.array(list(self._positions().values()))
        size = self.linkage.structure().scale
        finite = [(name, p) for name, p in finite if np.min(np.hypot(*(joints - p).T)) > 1e-9 * size]
        while len(self.centre_labels) < len(finite):
            self.centre_labels.append(self.ax.annotate("", (0, 0), xytext=(3, 3), textcoords="offset points",
                                                       annotation_clip=True, **CENTRE_LABEL))
        for k, text in enumerate(self.centre_labels):
            text.set_visible(k < len(finite))
            if k < len(finite):
                text.set_text(finite[k][0])
                text.xy = tuple(finite[k][1])
        self._far = [centres.label(i + 1, j + 1) for (i, j), c in rows if c.h[2] != 1.0]

    def _reading(self) -> str:
        """The status line: the chosen joint's dimensions, μ here and over the turn, the centres."""
        mu = np.degrees(self.motion.transmission)
        here = f"transmission angle μ = {mu[-1]:.1f}° at φ = {math.degrees(self.phi):.0f}°"
        where = "over the turn" if self.linkage.crank_ranges() == FULL_TURN else "where the crank rocks"
        turn = f"{mu[:-1].min():.1f}° … {mu[:-1].max():.1f}° {where}"
        if self._why:
            poles = f"centres undefined here ({self._why})"
        else:
            poles = f"{len(self._far) + len(self.centre_marks.get_xdata())} instantaneous centres (×)" + (
                f", at infinity: {', '.join(self._far)}" if self._far else "")
        return html.escape(f"{self._dimension_text()} · {here}, {turn} · {poles}")

    def _dimension_text(self) -> str:
        """What the chosen joint's dimensions are now."""
        lk, j = self.linkage, self.joint.value
        if j in dict(lk.frame):
            x, y = dict(lk.frame)[j]
            return f"{j} = ({x:.4g}, {y:.4g})"
        if j == lk.driver.joint:
            return f"crank {lk.driver.pivot}{j} = {lk.driver.radius:.4g}"
        g = next(g for g in lk.groups if j in g.makes())
        if isinstance(g, RRR):
            one, two = g.link_names()
            return f"{one} = {g.first_length:.4g}, {two} = {g.second_length:.4g}"
        if isinstance(g, RRP):
            return f"{g.link_names()[0]} = {g.length:.4g}"
        return f"{j} on {g.on}: (ξ, η) = ({g.at[0]:.4g}, {g.at[1]:.4g})"

    def _update_handles(self, redraw: bool) -> None:
        pts = self._positions()
        xy = np.array([pts[k] for k in handles(self.linkage)])
        self.handle_marks.set_data(xy[:, 0], xy[:, 1])
        chosen = pts[self.joint.value]
        self.chosen_mark.set_data([chosen[0]], [chosen[1]])
        if redraw and not self.message:   # another joint chosen: its dimensions in the status line
            self.status.value = self._reading()
            self._blit_or_redraw()

    def _moving_artists(self):
        return [*self.drawing.artists, self.curve_line, self.centre_marks, *self.centre_labels, self.handle_marks,
                self.chosen_mark, *self._overlays]

    def _axes(self):
        return (self.ax,)

    def _ready(self) -> bool:
        return not self.message

    # -- changes ---------------------------------------------------------------------------------------------
    def _propose(self, base: Linkage, joint: str, xy, phi: float, *, push: bool, notify: bool,
                 dragging: bool = False) -> bool:
        step = float(self.step.value) if self.snap.value else None
        try:
            new, new_phi = moved(base, joint, xy, phi, step)
        except MechanismError as err:
            self._show_error(str(err))
            return False
        before = (self.linkage, self.phi)
        if not self._show(new, new_phi, fit=not dragging):
            return False
        if new_phi != before[1]:
            self._quiet = True
            self.angle.value = round(math.degrees(new_phi)) % 360
            self._quiet = False
        if push:
            self._undo.append(before)
            self.undo_button.disabled = False
        if notify:
            self._notify(dragging=dragging)
        return True

    def _notify(self, dragging: bool) -> None:
        called = [callback(self.linkage) for callback, always in self._callbacks if always or not dragging]
        if called and self._overlays and not self.message:   # the overlays the callbacks moved, drawn
            self._blit_or_redraw()

    def _show_code(self) -> None:
        self.code_box.value = self.code()
        self.code_box.layout.display = None

    def _on_angle(self, change=None):
        if self._quiet:
            return
        self._show(self.linkage, math.radians(self.angle.value))

    # -- mouse and keys (ipympl forwards them) ---------------------------------------------------------------
    def _pick(self, event) -> str | None:
        """The handle within PICK_PX of the press, the nearest one."""
        if event.inaxes is not self.ax or self.message:
            return None
        pts = self._positions()
        names = list(handles(self.linkage))
        px = self.ax.transData.transform(np.array([pts[k] for k in names]))
        dist = np.hypot(px[:, 0] - event.x, px[:, 1] - event.y)
        k = int(np.argmin(dist))
        return names[k] if dist[k] <= PICK_PX else None

    def _on_press(self, event):
        joint = self._pick(event)
        if joint is None:
            return
        self._drag = (joint, self.linkage, self.phi)
        if self.joint.value != joint:
            self.joint.value = joint

    def _data_xy(self, event):
        """The pointer in data coordinates, also where the axes are hidden (the error shown in their place)."""
        return self.ax.transData.inverted().transform((event.x, event.y))

    def _on_motion(self, event):
        if self._drag is None or event.x is None:
            return
        joint, base, phi = self._drag
        self._propose(base, joint, self._data_xy(event), phi, push=False, notify=True, dragging=True)

    def _on_release(self, event):
        if self._drag is None:
            return
        joint, base, phi = self._drag
        self._drag = None
        if event.x is not None:
            self._propose(base, joint, self._data_xy(event), phi, push=False, notify=False, dragging=True)
        failed = self.message
        if self.linkage is not base:
            self._undo.append((base, phi))
            self.undo_button.disabled = False
        self._show(self.linkage, self.phi, fit=True)   # the last good linkage, fitted to the view
        if failed:
            self.status.value = (f"<span style='color:#b00020'>not applied: {html.escape(failed)}</span> · "
                                 f"kept the last linkage that assembles")
        if self.linkage is not base:
            self._notify(dragging=False)

    def _on_key(self, event):
        key = event.key or ""
        steps = 10 if key.startswith("shift+") else 1
        key = key.removeprefix("shift+")
        if key in MOVES:
            self.nudge(key, steps)
        elif key in ("u", "ctrl+z"):
            self.undo()
        elif key == "j":
            options = [v for _, v in self.joint.options]
            self.joint.value = options[(options.index(self.joint.value) + 1) % len(options)]


__all__ = ["DragEditor", "as_linkage", "handles", "linkage_code", "moved"]
