"""Schematics of the machines in which the course's mechanisms work.

Each schematic is a labelled matplotlib drawing built around a mechlab mechanism object
drawn in one position (the Geneva drive of an indexing table, the Chebyshev six-bar of a
screen-printing machine, ...); the machine around it is sketched with plain lines. The
machines are those the sources name where they name one: multi-station machines for the
offset Geneva (Vainer & Shatokhina), screen-printing machines and the nail-making
automata of forging-press works for the Chebyshev six-bars (Kinitsky, 1994); otherwise
well-known ones (a film projector's Geneva, a loom's sley, a cartoning line's pusher on a
curved-slot link or on a disc cam).

``schematic(name)`` returns the Figure; :data:`MACHINES` lists the names. ``label_joints``
writes the joint letters into any mechlab drawing.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import Circle, FancyBboxPatch, Polygon, Rectangle

from ..errors import MechanismError
from ..mechanisms.cam import TranslatingRollerCam
from ..mechanisms.fourbar import FourBar
from ..mechanisms.geneva import ExternalGeneva
from ..mechanisms.slider_crank import SliderCrank
from ..synthesis.cam_design import CamProgramme
from . import LINK_STYLE, MIN_WIDTH_PX, draw
from .access import set_alt

MACHINE_STYLE = dict(color="#555555", lw=1.5, zorder=1)
PART_FILL = dict(facecolor="#e8e8e8", edgecolor="#555555", lw=1.2, zorder=1)
WORK_FILL = dict(facecolor="#f2c14e", edgecolor="#8a6d1c", lw=1.2, zorder=2)
LABEL_STYLE = dict(fontsize=10, color="#222222", zorder=6,
                   arrowprops=dict(arrowstyle="-|>", color="#444444", lw=0.9, shrinkA=2, shrinkB=3))
LETTER_BOX = {"boxstyle": "round,pad=0.1", "facecolor": "white", "edgecolor": "none", "alpha": 0.85}  # over a line
DEG = np.pi / 180


def _axes(ax, figsize):
    if ax is None:
        _, ax = plt.subplots(figsize=figsize)
    ax.set_aspect("equal")
    ax.set_axis_off()
    return ax


def _label(ax, text, at, to):
    """A label at ``to`` with an arrow to the point ``at``."""
    ax.annotate(text, xy=at, xytext=to, ha="center", va="center", **LABEL_STYLE)
    ax.update_datalim([to])


def _fit(ax, margin: float = 0.06):
    """Limits that hold every line, patch and label (``draw`` fixed them to the mechanism)."""
    for line in ax.lines:
        xy = np.asarray(line.get_xydata(), float)
        ax.update_datalim(xy[np.isfinite(xy).all(axis=1)])
    for patch in ax.patches:
        ax.update_datalim(patch.get_patch_transform().transform(patch.get_path().vertices))
    (x0, y0), (x1, y1) = ax.dataLim.get_points()
    pad = margin * max(x1 - x0, y1 - y0)
    ax.set_xlim(x0 - pad, x1 + pad)
    ax.set_ylim(y0 - pad, y1 + pad)


def _letters(ax, points: dict, names: str, offset=(0.0, 0.0)):
    """Joint letters next to the joints (the letters the chapters use)."""
    for name in names:
        x, y = points[name]
        ax.text(x + offset[0], y + offset[1], name, fontsize=11, fontweight="bold", color="#1f4e79",
                ha="left", va="bottom", zorder=7, bbox=LETTER_BOX)


def label_joints(drawing, i: int = 0):
    """Write each joint's letter next to it in a mechlab drawing, at frame i (the letters the
    chapters use: O, A, B, E, ...)."""
    if getattr(drawing, "letters", None):   # mechlab.draw already lettered its joints
        return
    points = {k: v.p[i] for k, v in drawing.motion.points.items()}
    x0, x1 = drawing.ax.get_xlim()
    _letters(drawing.ax, points, list(points), (0.015 * (x1 - x0), 0.015 * (x1 - x0)))


def _ground(ax, xy, size):
    """Hatching under a fixed pivot."""
    x, y = xy
    ax.plot([x - size, x + size], [y - 0.45 * size, y - 0.45 * size], **MACHINE_STYLE)
    for k in np.linspace(-size, size, 6):
        ax.plot([k + x, k + x - 0.4 * size], [y - 0.45 * size, y - 0.85 * size], **MACHINE_STYLE)


def _frame_points(mechanism, phi):
    mo = mechanism.motion(np.atleast_1d(phi))
    return {k: v.p[0] for k, v in mo.points.items()}, mo


def _geneva(ax, z: int, phi: float, disc_distance: float, disc_radius: float):
    """An external Geneva drive (C = 1) drawn at φ with its letters and hatched pivots, and the
    disc its wheel's shaft carries (a sprocket, a table) drawn beside it, joined by the shaft's
    centre line. Returns the joints, the motion and the disc's centre."""
    g = ExternalGeneva(z, 1.0)
    draw(g, phi, ax=ax, labels=False, ground=False)
    pts, mo = _frame_points(g, phi)
    _letters(ax, pts, "OW", (-0.12, 0.06))
    _letters(ax, pts, "A", (0.0, -0.22))                 # below the pin, clear of the crank's leader line
    for p in "OW":
        _ground(ax, pts[p] + (0, -0.08), 0.1)
    W = pts["W"]
    centre = W + np.array([disc_distance, 0.0])
    ax.plot([W[0], centre[0]], [W[1], centre[1]], color="#555555", lw=1, ls="-.", zorder=0)
    ax.add_patch(Circle(centre, disc_radius, **PART_FILL))
    return pts, mo, centre


def film_projector(ax=None):
    """A film projector's intermittent film advance: a four-slot Geneva drive turns the
    sprocket a quarter turn per frame; the film stands still in the gate during the dwell."""
    ax = _axes(ax, (10, 5.2))
    rs = 0.45
    pts, _, S = _geneva(ax, 4, np.pi - 0.25, 1.9, rs)                 # S: the sprocket on the wheel's shaft
    O, W, A = pts["O"], pts["W"], pts["A"]
    for t in np.arange(16) * 2 * np.pi / 16:
        tooth = S + (rs + 0.05) * np.array([np.cos(t), np.sin(t)])
        ax.add_patch(Circle(tooth, 0.035, facecolor="#555555", zorder=2))
    # the film: down the gate, round the sprocket
    fx = S[0] + rs + 0.09
    ax.add_patch(Rectangle((fx - 0.07, S[1] - 0.1), 0.14, 2.3, facecolor="#d9d0c1", edgecolor="#6b5f4b", zorder=1))
    for y in np.arange(S[1], S[1] + 2.2, 0.18):
        ax.add_patch(Rectangle((fx - 0.02, y), 0.04, 0.07, facecolor="white", edgecolor="none", zorder=2))
    gate_y = S[1] + 1.45
    ax.add_patch(Rectangle((fx - 0.16, gate_y - 0.3), 0.32, 0.6, fill=False, edgecolor="#333333", lw=2, zorder=3))
    ax.add_patch(Polygon([[fx - 0.9, gate_y - 0.18], [fx - 0.9, gate_y + 0.18], [fx - 0.25, gate_y]],
                         facecolor="#fff3b0", edgecolor="#b8860b", zorder=1))
    ax.add_patch(Rectangle((fx + 0.3, gate_y - 0.22), 0.35, 0.44, **PART_FILL))
    _label(ax, "crank O-A with its pin\n(turns uniformly, one turn per frame)", (O + A) / 2, O + (-0.6, 1.5))
    _label(ax, "Geneva wheel (4 slots):\na quarter turn, then locked", W + (0.35, 0.45), W + (0.0, 1.9))
    _label(ax, "sprocket on the\nwheel's shaft", S + (0.0, -rs), S + (-0.2, -1.2))
    _label(ax, "film gate: the frame stands\nstill while it is projected", (fx, gate_y + 0.3),
           (fx - 0.2, gate_y + 1.25))
    _label(ax, "lamp", (fx - 0.7, gate_y), (fx - 1.2, gate_y + 0.7))
    _label(ax, "lens", (fx + 0.47, gate_y + 0.22), (fx + 0.9, gate_y + 0.75))
    _fit(ax)
    ax.set_title("Film projector: a four-slot Geneva drive advances the film one frame per crank turn")
    return ax.figure


def indexing_table(ax=None):
    """A multi-station indexing table: a six-slot Geneva wheel turns the table by 60°, the
    table dwells while every station works on its part."""
    ax = _axes(ax, (10, 5.2))
    rt = 1.15
    pts, mo, T = _geneva(ax, 6, np.pi - 0.2, 2.4, rt)                 # T: the table (top view) on the wheel's shaft
    O, W, A = pts["O"], pts["W"], pts["A"]
    stations = ("load", "drill", "ream", "tap", "inspect", "unload")
    psi = mo.psi[0]
    for k, name in enumerate(stations):
        t = psi + np.pi / 2 + k * 2 * np.pi / 6
        u = np.array([np.cos(t), np.sin(t)])
        ax.add_patch(Rectangle(T + 0.78 * rt * u - 0.09, 0.18, 0.18, **WORK_FILL))
        ax.text(*(T + 1.32 * rt * u), name, ha="center", va="center", fontsize=9)
    ax.plot(*T, "^", color="#555555", ms=9)
    _label(ax, "drive crank O-A\n(turns uniformly)", (O + A) / 2, O + (-0.6, 1.4))
    _label(ax, "Geneva wheel, 6 slots:\nindexes 60°, then locked", W + (0.1, 0.75), W + (0.5, 1.6))
    _label(ax, "index table on the wheel's shaft:\nparts move from station to station",
           T + (0.0, -rt), T + (0.0, -1.75))
    _fit(ax)
    ax.set_title("Multi-station indexing table: the table stands still while the stations work")
    return ax.figure


def screen_printing(ax=None):
    """A screen-printing machine: the output rocker of a Chebyshev dwell six-bar (МЧВ1)
    holds the screen on the print while the squeegee sweeps, then lifts it."""
    from ..synthesis.lambda_guiding import circle_guiding
    from ..synthesis.lambda_sixbars import mchv1

    ax = _axes(ax, (9, 6))
    guide = circle_guiding(150 * DEG, 0.9, 120 * DEG)
    six = mchv1(guide, 1.0, 20 * DEG)
    phi = np.pi
    draw(six, phi, ax=ax, trace="D", labels=False, ground=False)
    pts, _ = _frame_points(six, phi)
    _letters(ax, pts, "OBCDEF", (0.04, 0.03))
    _letters(ax, pts, "A", (-0.2, 0.03))                 # the crank points left: A left of its pin
    for p in ("O", "C", "F"):
        _ground(ax, pts[p] + (0, -0.05), 0.09)
    F, E = pts["F"], pts["E"]
    # the screen frame carried by the rocker F-E, beyond E
    u = (E - F) / np.hypot(*(E - F))
    tip = E + 0.9 * u
    ax.plot(*np.array([E, tip]).T, **LINK_STYLE)
    n = np.array([-u[1], u[0]])
    frame = np.array([tip - 0.8 * n, tip + 0.8 * n])
    ax.plot(*frame.T, color="#1f4e79", lw=6, solid_capstyle="butt", zorder=3)
    ax.add_patch(Polygon([tip + 0.1 * n + 0.12 * u, tip + 0.3 * n + 0.12 * u, tip + 0.2 * n + 0.35 * u],
                         facecolor="#c0392b", edgecolor="#7b241c", zorder=4))
    below = tip + 0.08 * u
    substrate = np.array([below - 0.9 * n, below + 0.9 * n])
    ax.plot(*substrate.T, color="#f2c14e", lw=5, zorder=2)
    _label(ax, "crank O-A", (pts["O"] + pts["A"]) / 2, pts["O"] + (-0.6, -0.7))
    _label(ax, "Chebyshev's lambda linkage:\nD runs almost on a circular arc", pts["D"], pts["D"] + (-1.5, 0.7))
    _label(ax, "rocker F-E stands still\nwhile D is on the arc", (F + E) / 2, F + (-1.4, 0.4))
    _label(ax, "screen frame, squeegee\nand substrate", tip + 0.7 * n, tip + 1.2 * n + 0.9 * u)
    _fit(ax)
    ax.set_title("Screen-printing machine: a Chebyshev dwell six-bar holds the screen while it prints")
    return ax.figure


def forging_press(ax=None):
    """A crank (forging) press: the slider-crank drives the ram; in a nail-making automaton
    a Chebyshev dwell six-bar feeds the wire while the ram is up (Kinitsky, 1994)."""
    ax = _axes(ax, (8, 7))
    press = SliderCrank(crank=1.0, rod=3.2)
    phi = 2.3
    pts, _ = _frame_points(press, phi)
    turn = np.array([[0.0, -1.0], [1.0, 0.0]])          # the guide vertical: (x, y) ↦ (y, −x), ram below
    O, A, B = (pts[k] @ turn for k in "OAB")
    ax.plot(*np.array([O, A]).T, **LINK_STYLE)
    ax.plot(*np.array([A, B]).T, **LINK_STYLE)
    ax.plot(*np.array([A, B]).T, "o", ms=6, mfc="white", mec="#1f4e79", mew=1.5, zorder=4)
    ax.plot(*O, "^", ms=11, color="#555555", zorder=2)
    for name, p, dx in zip("OAB", (O, A, B), (-0.4, 0.12, 0.12), strict=False):   # O left of its crank
        ax.text(p[0] + dx, p[1] + 0.05, name, fontsize=11, fontweight="bold", color="#1f4e79", zorder=7,
                bbox=LETTER_BOX)
    ax.add_patch(Circle(O, 1.45, fill=False, edgecolor="#555555", lw=1.2, ls="--", zorder=0))
    ram_w, ram_h = 1.0, 0.9
    ax.add_patch(Rectangle((B[0] - ram_w / 2, B[1] - ram_h), ram_w, ram_h, **PART_FILL))
    ax.add_patch(Rectangle((B[0] - 0.15, B[1] - ram_h - 0.35), 0.3, 0.35, facecolor="#777777", zorder=1))
    bottom = -(press.crank + press.rod) - ram_h - 0.35          # the punch's lowest point
    ax.add_patch(Rectangle((-0.25, bottom - 0.3), 0.5, 0.3, **WORK_FILL))
    ax.add_patch(Rectangle((-1.2, bottom - 0.9), 2.4, 0.6, **PART_FILL))
    for x in (-1.6, 1.6):
        ax.plot([x, x], [bottom - 0.9, 1.7], **MACHINE_STYLE)
    for x in (-ram_w / 2 - 0.06, ram_w / 2 + 0.06):                     # the ram's guides
        ax.plot([x, x], [bottom + 0.2, -(press.rod - press.crank) + 0.2], color="#555555", lw=3, zorder=1)
    ax.plot([-1.6, 1.6], [1.7, 1.7], **MACHINE_STYLE)
    feed = np.array([2.6, bottom - 0.15])
    ax.add_patch(FancyBboxPatch(feed - (0.45, 0.3), 0.9, 0.6, boxstyle="round,pad=0.05", **PART_FILL))
    ax.plot([0.25, feed[0] - 0.5], [bottom - 0.15, bottom - 0.15], color="#8a6d1c", lw=2, zorder=2)
    _label(ax, "flywheel and crank O-A", O + (-1.0, 1.05), O + (-3.1, 1.3))
    _label(ax, "connecting rod A-B", (A + B) / 2, (A + B) / 2 + (2.3, 0.3))
    _label(ax, "ram (slider B) in its guides", B + (ram_w / 2, -ram_h / 2), B + (3.1, -0.5))
    _label(ax, "die and workpiece", (0.0, bottom - 0.3), (-2.6, bottom - 1.2))
    _label(ax, "wire feed: a Chebyshev dwell\nsix-bar (chapter 8)", feed + (0, 0.3), feed + (0.8, 1.5))
    _fit(ax)
    ax.set_title("Crank press (nail-making automaton): the slider-crank drives the ram")
    return ax.figure


def packaging_line(ax=None):
    """A cartoning line: an arm on a curved-slot link pushes the cartons along the line
    and stands still while each carton is filled."""
    from ..synthesis.dwell_slot import curved_slot_dwell

    ax = _axes(ax, (10, 6))
    link = curved_slot_dwell(0.5, 60 * DEG, 150 * DEG, transition="quintic")
    phi = 100 * DEG                                        # inside the dwell
    draw(link, phi, ax=ax, labels=False, ground=False)
    pts, mo = _frame_points(link, phi)
    _letters(ax, pts, "OAB", (0.03, 0.03))
    _ground(ax, pts["O"] + (0, -0.05), 0.08)
    _ground(ax, pts["B"] + (0, -0.05), 0.08)
    B, psi = pts["B"], mo.psi[0]
    arm = psi - np.pi / 2                                  # the arm is fixed to the link, across its slot
    u = np.array([np.cos(arm), np.sin(arm)])
    tip = B + 1.6 * u
    ax.plot(*np.array([B, tip]).T, color="#1f4e79", lw=3, zorder=3)
    ax.plot(*np.array([tip - 0.05 * u, tip + 0.3 * u]).T, color="#1f4e79", lw=7, zorder=3)
    belt_y = tip[1] + 0.3 * u[1] - 0.12
    x0, x1 = B[0] - 1.6, B[0] + 2.4
    ax.add_patch(FancyBboxPatch((x0, belt_y - 0.2), x1 - x0, 0.12, boxstyle="round,pad=0.02", **PART_FILL))
    for x in (x0, x1):
        ax.add_patch(Circle((x, belt_y - 0.14), 0.1, facecolor="#999999", zorder=2))
    for x in np.arange(tip[0] + 0.06, x1 - 0.2, 0.55):
        ax.add_patch(Rectangle((x, belt_y - 0.08), 0.3, 0.3, **WORK_FILL))
    filler = np.array([tip[0] + 0.8, belt_y + 0.75])
    ax.add_patch(Polygon([filler + (-0.2, 0.2), filler + (0.2, 0.2), filler + (0.05, -0.2), filler + (-0.05, -0.2)],
                         **PART_FILL))
    _label(ax, "crank O-A with the pin A", (pts["O"] + pts["A"]) / 2, pts["A"] + (0.9, 0.5))
    _label(ax, "slotted link about B: its slot\nhas an arc of radius OA (the dwell)", B + (0.3, 0.03),
           B + (0.6, 1.3))
    _label(ax, "arm and pusher on the link:\nstill while a carton is filled", tip - 0.3 * u, tip + (-1.5, 0.7))
    _label(ax, "filling head", filler + (0.2, 0.0), filler + (1.0, 0.3))
    _label(ax, "cartons on the line", (x1 - 0.4, belt_y - 0.2), (x1 - 0.4, belt_y - 0.8))
    _fit(ax)
    ax.set_title("Cartoning line: a curved-slot dwell link drives the pusher")
    return ax.figure


def cartoning_cam(ax=None):
    """The cartoning line's pusher on a disc cam: the cam of chapter 7's pusher (3-4-5 polynomial
    rise of 20 mm over 120°, outer dwell 40°, return 100°; base radius 40 mm, roller 10 mm, offset
    8 mm) lifts a carton from the incoming belt to the take-over level and holds it there."""

    ax = _axes(ax, (9, 7))
    programme = CamProgramme(stroke=20.0, rise=120 * DEG, ret=100 * DEG, outer_dwell=40 * DEG,
                             law="3-4-5 polynomial")
    cam = TranslatingRollerCam(programme, base_radius=40.0, roller_radius=10.0, offset=8.0)
    phi = 140 * DEG                                        # in the outer dwell: the carton is held up
    draw(cam, phi, ax=ax, labels=False, ground=False)
    pts, _ = _frame_points(cam, phi)
    _letters(ax, pts, "OC", (12.0, -3.0))          # right of the stem and the pivot
    _ground(ax, pts["O"] + (0, -6.0), 9.0)
    O, C = pts["O"], pts["C"]
    reach = 55.0                                           # from the roller's centre to the pusher's plate
    plate = C + (0.0, reach)
    ax.plot(*np.array([C, plate]).T, **LINK_STYLE)
    ax.plot([plate[0] - 20, plate[0] + 20], [plate[1], plate[1]], color="#1f4e79", lw=6, solid_capstyle="butt",
            zorder=3)
    low, high = cam.s0 + reach, cam.s0 + programme.stroke + reach      # the plate down and up
    ax.add_patch(Rectangle((plate[0] - 15, plate[1]), 30, 30, **WORK_FILL))
    ax.add_patch(FancyBboxPatch((plate[0] - 150, low - 8), 125, 6, boxstyle="round,pad=1", **PART_FILL))
    for x in (plate[0] - 135, plate[0] - 95, plate[0] - 55):
        ax.add_patch(Rectangle((x, low - 2), 30, 30, **WORK_FILL))
    ax.add_patch(FancyBboxPatch((plate[0] + 25, high - 8), 125, 6, boxstyle="round,pad=1", **PART_FILL))
    head = np.array([plate[0] + 75, high + 62])
    ax.add_patch(Polygon([head + (-14, 14), head + (14, 14), head + (4, -14), head + (-4, -14)], **PART_FILL))
    ax.add_patch(Rectangle((plate[0] + 60, high - 2), 30, 30, **WORK_FILL))
    _label(ax, "disc cam on the line's shaft O:\none turn per carton", O + (-30.0, -30.0), O + (-95.0, -45.0))
    _label(ax, "roller, centre C", C + (7.0, -7.5), C + (75.0, -30.0))   # below the letter C
    _label(ax, "pusher stem in its guide", (C + plate) / 2 + (-3.0, -5.0), (C + plate) / 2 + (-110.0, -5.0))
    _label(ax, f"pusher: lifts the carton {programme.stroke:g} mm,\nholds it while it is taken over",
           plate + (20.0, 0.0), plate + (95.0, -45.0))
    _label(ax, "cartons arrive", (plate[0] - 110, low + 28), (plate[0] - 110, low + 55))
    _label(ax, "filling head", head + (14, 0), head + (70, 10))
    _fit(ax)
    ax.set_title("Cartoning line: a disc cam lifts the pusher, holds it, and brings it back")
    return ax.figure


def loom(ax=None):
    """A loom's sley drive: a crank-rocker four-bar swings the sley, whose reed beats each
    weft thread into the cloth."""
    ax = _axes(ax, (9, 6.5))
    fb = FourBar(crank=1.0, coupler=3.5, rocker=3.0, ground=3.8)
    phi = 0.6
    draw(fb, phi, ax=ax, labels=False, ground=False)
    pts, _ = _frame_points(fb, phi)
    _letters(ax, pts, "OA", (-0.32, 0.05))   # left of the crank, which points up and to the right
    _letters(ax, pts, "BE", (0.08, 0.05))
    for p in ("O", "E"):
        _ground(ax, pts[p] + (0, -0.08), 0.15)
    E, B = pts["E"], pts["B"]
    u = (B - E) / fb.rocker
    top = B + 1.2 * u
    ax.plot(*np.array([B, top]).T, **LINK_STYLE)
    ax.plot(*np.array([top - 0.8 * u, top + 0.5 * u]).T, color="#8a6d1c", lw=7, zorder=2)
    for y in np.linspace(top[1] - 0.5, top[1] + 0.3, 5):
        ax.plot([top[0] - 2.6, top[0] + 2.2], [y, y], color="#999999", lw=0.8, zorder=0)
    ax.add_patch(Rectangle((top[0] - 3.4, top[1] - 0.6), 2.5, 1.0, facecolor="#d9d0c1", edgecolor="#6b5f4b"))
    _label(ax, "crank shaft O-A", (pts["O"] + pts["A"]) / 2, pts["O"] + (1.2, -1.2))
    _label(ax, "crank arm (coupler) A-B", (pts["A"] + B) / 2, (pts["A"] + B) / 2 + (-2.0, 0.4))
    _label(ax, "sley sword: rocker E-B", (E + B) / 2, (E + B) / 2 + (1.8, -0.4))
    _label(ax, "reed beats the weft\ninto the cloth", top + 0.5 * u, top + (1.5, 1.1))
    _label(ax, "cloth", (top[0] - 2.2, top[1] + 0.4), (top[0] - 2.2, top[1] + 1.2))
    _label(ax, "warp threads", (top[0] + 1.5, top[1] + 0.3), (top[0] + 3.0, top[1] + 0.3))
    _fit(ax)
    ax.set_title("Loom: a crank-rocker four-bar swings the sley")
    return ax.figure


MACHINES = {"film_projector": film_projector, "indexing_table": indexing_table, "screen_printing": screen_printing,
            "forging_press": forging_press, "packaging_line": packaging_line, "cartoning_cam": cartoning_cam,
            "loom": loom}


def schematic(name: str, ax=None):
    """Draw the labelled schematic of a machine; returns the Figure.

    Parameters
    ----------
    name : one of :data:`MACHINES`: ``"indexing_table"``, ``"film_projector"`` (Geneva drives),
        ``"screen_printing"`` (Chebyshev six-bar), ``"forging_press"`` (slider-crank),
        ``"packaging_line"`` (curved-slot dwell), ``"cartoning_cam"`` (disc cam), ``"loom"`` (four-bar).
    ax : matplotlib axes to draw on; a new figure when None.
    """
    if name not in MACHINES:
        raise MechanismError(f"machine name = {name!r} is not one of {', '.join(sorted(MACHINES))}")
    fig = MACHINES[name](ax)
    if ax is None:
        _widen(fig, SCHEMATIC_WIDTH_PX)
    set_alt(fig, schematic_alt(fig))
    return fig


def schematic_alt(fig) -> str:
    """A schematic's alternative text: its title (the machine and the mechanism that drives it) and what
    each labelled part does, in the drawing's own words (its arrowed labels, top to bottom)."""
    ax = fig.axes[0]
    labels = [t for t in ax.texts if hasattr(t, "xy") and len(t.get_text()) > 2]
    labels.sort(key=lambda t: -t.get_position()[1])
    parts = "; ".join(" ".join(t.get_text().split()) for t in labels)
    return f"Schematic. {ax.get_title()}. Labelled parts: {parts}."


SCHEMATIC_WIDTH_PX = MIN_WIDTH_PX + 20   # shown width (tight crop, figure dpi): animations' width and a margin


def _widen(fig, px: float) -> None:
    """Scale ``fig`` so that its tight crop, the image the notebook shows (bbox_inches="tight"),
    is at least ``px`` wide at the figure's dpi; an equal-aspect drawing leaves margins uncropped."""
    for _ in range(3):   # labels keep their point size, so the crop grows a little less than the figure
        width = fig.get_tightbbox(fig.canvas.get_renderer()).width * fig.dpi
        if width >= px:
            return
        fig.set_size_inches(fig.get_size_inches() * (px / width))
