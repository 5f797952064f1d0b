"""Figures every student can read: alternative text and a colour-blind-safe palette.

* **Alternative text.** :func:`set_alt` attaches a description (subject and key reading) to a
  figure where it is made, from the very numbers drawn, so it stays true when they change;
  :func:`alt_text` returns it, or, for a figure nobody described, one composed from what the
  figure itself says (its titles, axis labels and legend entries): "" when it says nothing, a
  figure no reader can be told about. :func:`install_alt_text` makes an IPython kernel publish
  the text with every figure it displays (the output's ``image/png`` metadata ``alt``), which
  the book's ``_ext/alttext.py`` writes into the page as the image's ``alt``.
* **Palette.** :data:`OKABE_ITO` (Okabe & Ito, 2008), the categorical colours mechlab's figures
  use, ordered as :data:`CATEGORY_COLOURS`; a category is told apart by a second channel too
  (:data:`CATEGORY_MARKERS`, :data:`CATEGORY_DASHES`). :func:`simulate_cvd` (Machado, Oliveira and
  Fernandes, 2009) and :func:`delta_e` (CIE 1976, in CIELAB) let a test check that they stay
  distinguishable for protanopes and deuteranopes.
"""

from __future__ import annotations

import re

import numpy as np
from matplotlib.colors import to_rgb
from matplotlib.figure import Figure

from ..errors import MechanismError

ALT_ATTRIBUTE = "mechlab_alt"   # where set_alt keeps a figure's description
OKABE_ITO = {"blue": "#0072B2", "vermillion": "#D55E00", "bluish green": "#009E73", "reddish purple": "#CC79A7",
             "orange": "#E69F00", "sky blue": "#56B4E9", "black": "#000000", "yellow": "#F0E442"}
# a dark brown, a dark grey and Tol's indigo for a ninth, tenth and eleventh category (ΔE ≥ 18 from every
# Okabe-Ito colour, protan or deutan; the indigo ≥ 24 from all); yellow last: on white it has too little contrast
# for a thin line, no family of chapter 12 gets it
CATEGORY_COLOURS = (*(c for name, c in OKABE_ITO.items() if name != "yellow"), "#5A3C1E", "#5F5F5F", "#332288",
                    OKABE_ITO["yellow"])
CATEGORY_MARKERS = ("o", "s", "^", "D", "v", "P", "X", "*", "h", "p")
CATEGORY_DASHES = ("-", "--", "-.", ":", (0, (5, 1, 1, 1)), (0, (1, 1)), (0, (8, 2)), (0, (3, 1, 1, 1, 1, 1)),
                   (0, (6, 1, 2, 1)), (0, (2, 1, 2, 3)))

# Machado, Oliveira & Fernandes (2009), severity 1, applied to linear RGB
CVD_MATRICES = {
    "protanopia": np.array([[0.152286, 1.052583, -0.204868],
                            [0.114503, 0.786281, 0.099216],
                            [-0.003882, -0.048116, 1.051998]]),
    "deuteranopia": np.array([[0.367322, 0.860646, -0.227968],
                              [0.280085, 0.672501, 0.047413],
                              [-0.011820, 0.042940, 0.968881]]),
    "tritanopia": np.array([[1.255528, -0.076749, -0.178779],
                            [-0.078411, 0.930809, 0.147602],
                            [0.004733, 0.691367, 0.303900]]),
}


def category_style(i: int) -> dict:
    """The colour, marker and dash of category ``i`` (cycling): two channels, so that a reader who
    cannot tell the colours apart still tells the categories apart."""
    return {"color": CATEGORY_COLOURS[i % len(CATEGORY_COLOURS)], "marker": CATEGORY_MARKERS[i % len(CATEGORY_MARKERS)],
            "ls": CATEGORY_DASHES[i % len(CATEGORY_DASHES)]}


def set_alt(fig, text: str):
    """Attach the alternative text ``text`` (what the figure shows and its key reading) to ``fig``.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    text : str
        One or two sentences; not empty.

    Returns
    -------
    matplotlib.figure.Figure
        ``fig`` itself, so that a drawing function can ``return set_alt(fig, ...)``.

    Raises
    ------
    MechanismError
        ``fig`` is no Figure, or ``text`` is empty.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = set_alt(plt.figure(), "A blank figure.")
    >>> alt_text(fig)
    'A blank figure.'
    >>> plt.close(fig)
    """
    if not isinstance(fig, Figure):
        raise MechanismError(f"set_alt needs a matplotlib Figure, got {type(fig).__name__}")
    if not isinstance(text, str) or not text.strip():
        raise MechanismError("a figure's alternative text must be a non-empty string")
    setattr(fig, ALT_ATTRIBUTE, " ".join(text.split()))
    return fig


def plain(text: str) -> str:
    """A label's mathtext read as plain words: ``$l_{OB}$`` → ``l_OB``, ``$\\alpha$`` → ``alpha``."""
    return re.sub(r"\\([A-Za-z]+)", r"\1", text.replace("$", "")).replace("{", "").replace("}", "")


READINGS = 4   # the curves of a panel whose ranges a composed description gives


def _readings(ax) -> str:
    """The key reading of a panel, from the data it draws: each curve's range (its legend label, else the
    y-axis's), up to :data:`READINGS` of them; else the number of points scattered; "" if it draws neither.
    A flat line without a label (a zero line, a limit drawn across) is a reference, not a reading."""
    ranges = []
    for line in ax.get_lines():
        y = np.asarray(line.get_ydata(), float).ravel() if line.get_visible() else np.array([])
        y = y[np.isfinite(y)]
        label = line.get_label()
        named = bool(label) and not label.startswith("_")
        if len(y) < 2 or (np.ptp(y) == 0 and not named):
            continue
        name = plain(label) if named else (plain(ax.get_ylabel()) or "the curve")
        lo, hi = float(y.min()), float(y.max())
        ranges.append(f"{name} at {lo:.3g}" if lo == hi else f"{name} from {lo:.3g} to {hi:.3g}")
    if ranges:
        more = len(ranges) - READINGS
        return "; ".join(ranges[:READINGS]) + (f"; and {more} more curves" if more > 0 else "")
    points = sum(len(c.get_offsets()) for c in ax.collections if c.get_visible() and hasattr(c, "get_offsets"))
    return f"{points} points" if points > 1 else ""


def _axes_words(ax) -> str:
    words = []
    if ax.get_title():
        words.append(plain(ax.get_title()))
    labels = [plain(label) for label in (ax.get_xlabel(), ax.get_ylabel()) if label]
    if labels:
        words.append(" against ".join(reversed(labels)) if len(labels) == 2 else labels[0])
    legend = ax.get_legend()
    if legend is not None:
        entries = [plain(t.get_text()) for t in legend.get_texts() if t.get_text()]
        if entries:
            words.append("legend: " + "; ".join(entries))
    # a plot's reading (a drawing with its axes off, a kinematic diagram, is described by its own words)
    reading = _readings(ax) if labels and ax.axison else ""
    if reading:
        words.append(reading)
    return ", ".join(words)


def alt_text(fig) -> str:
    """The alternative text of ``fig``: what :func:`set_alt` attached, else a description composed
    from the figure's own words (its title, each panel's title, axis labels and legend entries) and
    each plot's key reading (a panel with labelled axes: its curves' ranges, or how many points it
    scatters), else "" (a
    figure that names nothing).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> alt_text(fig)
    ''
    >>> _ = ax.set(title="pressure angle", xlabel="φ (deg)", ylabel="μ (deg)")
    >>> alt_text(fig)
    'Figure: pressure angle, μ (deg) against φ (deg).'
    >>> _ = ax.plot([0, 180, 360], [40, 90, 40])
    >>> alt_text(fig)
    'Figure: pressure angle, μ (deg) against φ (deg), μ (deg) from 40 to 90.'
    >>> plt.close(fig)
    """
    own = getattr(fig, ALT_ATTRIBUTE, "")
    if own:
        return own
    parts = []
    suptitle = getattr(fig, "_suptitle", None)
    if suptitle is not None and suptitle.get_text():
        parts.append(plain(suptitle.get_text()))
    panels = [words for words in (_axes_words(ax) for ax in fig.axes if ax.get_visible()) if words]
    if len(panels) == 1:
        parts.append(panels[0])
    else:
        parts.extend(f"panel {k}: {words}" for k, words in enumerate(panels, 1))
    return f"Figure: {'; '.join(parts)}." if parts else ""


def install_alt_text(ip) -> None:
    """Make the IPython shell ``ip`` publish every displayed figure's :func:`alt_text` as the ``alt``
    of its image outputs' metadata (``{"image/png": {"alt": ...}}``); a figure without one gets none."""
    original = ip.display_formatter.format
    if getattr(original, "mechlab_alt", False):
        return

    def format_with_alt(obj, *args, **kwargs):
        data, metadata = original(obj, *args, **kwargs)
        if isinstance(obj, Figure):
            text = alt_text(obj)
            if text:
                for mime in data:
                    if mime.startswith("image/"):
                        metadata[mime] = {**metadata.get(mime, {}), "alt": text}
        return data, metadata

    format_with_alt.mechlab_alt = True
    ip.display_formatter.format = format_with_alt


def _linear(rgb: np.ndarray) -> np.ndarray:
    return np.where(rgb <= 0.04045, rgb / 12.92, ((rgb + 0.055) / 1.055) ** 2.4)


def _srgb(lin: np.ndarray) -> np.ndarray:
    lin = np.clip(lin, 0.0, 1.0)
    return np.where(lin <= 0.0031308, 12.92 * lin, 1.055 * lin ** (1 / 2.4) - 0.055)


def simulate_cvd(colour, kind: str) -> np.ndarray:
    """The sRGB colour (0…1) that a reader with colour-vision deficiency ``kind`` ("protanopia",
    "deuteranopia", "tritanopia") sees for ``colour`` (any matplotlib colour), by Machado et al.'s
    (2009) model at full severity.

    Examples
    --------
    >>> simulate_cvd("white", "deuteranopia").round(3).tolist()
    [1.0, 1.0, 1.0]
    """
    if kind not in CVD_MATRICES:
        raise MechanismError(f"kind must be one of {sorted(CVD_MATRICES)}, got {kind!r}")
    return _srgb(CVD_MATRICES[kind] @ _linear(np.asarray(to_rgb(colour))))


def lab(colour) -> np.ndarray:
    """CIELAB (D65) coordinates of an sRGB colour (a matplotlib colour or an RGB triple 0…1)."""
    rgb = np.asarray(colour, float) if not isinstance(colour, str) else np.asarray(to_rgb(colour))
    xyz = np.array([[0.4124564, 0.3575761, 0.1804375],
                    [0.2126729, 0.7151522, 0.0721750],
                    [0.0193339, 0.1191920, 0.9503041]]) @ _linear(rgb)
    t = xyz / np.array([0.95047, 1.0, 1.08883])
    f = np.where(t > (6 / 29) ** 3, np.cbrt(t), t / (3 * (6 / 29) ** 2) + 4 / 29)
    return np.array([116 * f[1] - 16, 500 * (f[0] - f[1]), 200 * (f[1] - f[2])])


def delta_e(a, b) -> float:
    """CIE 1976 colour difference ΔE*ab of two colours (about 2.3 is just noticeable).

    Examples
    --------
    >>> round(delta_e("black", "white"), 1)
    100.0
    """
    return float(np.linalg.norm(lab(a) - lab(b)))
