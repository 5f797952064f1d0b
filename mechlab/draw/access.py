"""Figures every student can read: alternative text and a colour-blind-safe palette.

* **Alternative text.** :func:`set_alt` attaches a description (subject and key reading) to a
  figure where it is made, from the very numbers drawn, so it stays true when they change;
  :func:`alt_text` returns it, or, for a figure nobody described, one composed from what the
  figure itself says (its titles, axis labels and legend entries): "" when it says nothing, a
  figure no reader can be told about. :func:`install_alt_text` makes an IPython kernel publish
  the text with every figure it displays (the output's ``image/png`` metadata ``alt``), which
  the book's ``_ext/alttext.py`` writes into the page as the image's ``alt``, and, for JupyterLab,
  which reads no such metadata, a ``text/html`` copy of the figure that carries it
  (:func:`figure_html`); a kernel that imports this module installs it by itself.
* **Palette.** :data:`OKABE_ITO` (Okabe & Ito, 2008), the categorical colours mechlab's figures
  use, ordered as :data:`CATEGORY_COLOURS`; a category is told apart by a second channel too
  (:data:`CATEGORY_MARKERS`, :data:`CATEGORY_DASHES`). :func:`simulate_cvd` (Machado, Oliveira and
  Fernandes, 2009) and :func:`delta_e` (CIE 1976, in CIELAB) let a test check that they stay
  distinguishable for protanopes and deuteranopes.
"""

from __future__ import annotations

import base64
import html
import os
import re
import sys

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


def figure_html(png, alt: str, width=None, height=None) -> str:
    """An ``<img>`` that carries the PNG ``png`` (bytes, or their base64 text) inline with ``alt`` as its
    alternative text, and the displayed ``width`` and ``height`` (pixels) if given.

    Parameters
    ----------
    png : bytes or str
        The image, as a PNG file's bytes or their base64 encoding (how a kernel sends it).
    alt : str
        The alternative text; not empty.
    width, height : int, optional
        The size to show it at (the inline backend's metadata for a high-resolution figure).

    Returns
    -------
    str
        One ``<img>`` element whose ``src`` is a ``data:image/png;base64`` address.

    Raises
    ------
    MechanismError
        ``alt`` is empty.

    Examples
    --------
    >>> figure_html(b"PNG", "A <small> square.", width=40)
    '<img src="data:image/png;base64,UE5H" alt="A &lt;small&gt; square." width="40">'
    """
    if not isinstance(alt, str) or not alt.strip():
        raise MechanismError("an image's alternative text must be a non-empty string")
    text = base64.b64encode(png).decode("ascii") if isinstance(png, bytes) else str(png)
    size = "".join(f' {name}="{int(value)}"' for name, value in (("width", width), ("height", height))
                   if value is not None)
    return f'<img src="data:image/png;base64,{text}" alt="{html.escape(alt, quote=True)}"{size}>'


def install_alt_text(ip, html_copy: bool | None = None) -> None:
    """Make the IPython shell ``ip`` publish every displayed figure with its :func:`alt_text`.

    The text goes into the image outputs' metadata (``{"image/png": {"alt": ...}}``), which the book's
    renderer reads (``book/_ext/alttext.py``). JupyterLab reads no ``alt`` metadata (it draws an
    ``image/png`` output as an ``<img>`` without one: jupyter/enhancement-proposals#120), so for a live
    front end the figure is published a second time as ``text/html``, an :func:`figure_html` ``<img>``
    with the ``alt``: a front end shows the richest type it renders, JupyterLab (and Notebook 7, VS Code)
    that one, whose sanitizer keeps ``alt`` and the ``data:`` image even in an untrusted notebook.
    A figure without a description gets neither.

    Parameters
    ----------
    ip : IPython.core.interactiveshell.InteractiveShell
        The shell whose display formatter is wrapped (once: a second call changes nothing).
    html_copy : bool, optional
        Publish the ``text/html`` copy; by default yes, except where the book's kernels render static
        pages (``MECHLAB_WIDGETS=static``): the book shows the ``image/png`` with its metadata's ``alt``,
        so that its pages do not carry the picture twice.

    Returns
    -------
    None

    Raises
    ------
    MechanismError
        ``ip`` has no display formatter (no IPython shell).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> from IPython.core.interactiveshell import InteractiveShell
    >>> from IPython.core.pylabtools import select_figure_formats
    >>> ip = InteractiveShell.instance()
    >>> select_figure_formats(ip, {"png"})
    >>> install_alt_text(ip)
    >>> data, metadata = ip.display_formatter.format(set_alt(plt.subplots(figsize=(1, 1))[0], "A blank square."))
    >>> metadata["image/png"]["alt"], 'alt="A blank square."' in data["text/html"]
    ('A blank square.', True)
    >>> plt.close("all")
    """
    formatter = getattr(ip, "display_formatter", None)
    if formatter is None:
        raise MechanismError(f"install_alt_text needs an IPython shell, got {type(ip).__name__}")
    original = formatter.format
    if getattr(original, "mechlab_alt", False):
        return
    if html_copy is None:
        html_copy = os.environ.get("MECHLAB_WIDGETS") != "static"

    def format_with_alt(obj, include=None, exclude=None):
        data, metadata = original(obj, include=include, exclude=exclude)
        if isinstance(obj, Figure):
            text = alt_text(obj)
            if text:
                for mime in data:
                    if mime.startswith("image/"):
                        metadata[mime] = {**metadata.get(mime, {}), "alt": text}
                wanted = (include is None or "text/html" in include) and not (exclude and "text/html" in exclude)
                if html_copy and wanted and "image/png" in data and "text/html" not in data:
                    size = metadata.get("image/png", {})
                    data["text/html"] = figure_html(data["image/png"], text, size.get("width"), size.get("height"))
        return data, metadata

    format_with_alt.mechlab_alt = True
    formatter.format = format_with_alt


def _install_in_running_shell() -> None:
    """Publish alt texts in the IPython kernel that imports mechlab.draw (a chapter in JupyterLab): no
    start-up file of the student's is needed. Outside IPython, nothing (IPython is not even imported)."""
    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None else None
    if shell is not None and hasattr(shell, "display_formatter"):
        install_alt_text(shell)


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


_install_in_running_shell()
