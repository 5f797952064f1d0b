"""Explorers a keyboard and a screen reader can drive: named controls and an announced status line.

ipywidgets 8 draws a slider with noUiSlider, whose handle (``role="slider"``, the element that takes
the keyboard focus) gets no accessible name: the visible ``<label class="widget-label">`` beside it is
tied to nothing (ipywidgets does not pass noUiSlider's ``handleAttributes``; noUiSlider #1223), and a
:class:`ipywidgets.Play`'s buttons are bare icons. :data:`LABEL_CONTROLS_JS`, displayed once with an
explorer in a live kernel (:func:`announce_controls`), fixes that in the page: each slider handle is
``aria-labelledby`` its visible label, each readout is named after it, each toggle-button group is a
named ``group``, every control shows a focus outline (ipywidgets draws none on a slider's handle and
removes the browser's on a drop-down), a drop-down keeps its arrow keys from JupyterLab's shortcuts, the
play buttons are named "play", "stop" and "repeat", and every status line (:func:`status_line`) is a
polite live region (``role="status"``), so that a changed reading is announced. It watches the page, so
controls drawn later are named too. A live plot (an ipympl canvas, :func:`describe_live_figure`) is an
image (``role="img"``) named by the figure's alternative text.
"""

from __future__ import annotations

import os

import ipywidgets as W
from IPython.display import Javascript, display
from traitlets import Unicode

from ..draw.access import alt_text

STATUS_CLASS = "mechlab-status"   # the class that makes an HTML widget a live region
FOCUS_COLOUR = "#0072B2"   # Okabe-Ito blue: 5.1:1 on white, above the 3:1 a focus indicator needs

LABEL_CONTROLS_JS = r"""
(() => {
  if (window.__mechlabLabelControls) { window.__mechlabLabelControls(); return; }
  // a visible focus on every control (ipywidgets draws none on a slider's handle): WCAG 2.4.7
  const style = document.createElement('style');
  style.id = 'mechlab-focus-style';
  style.textContent = `:is(.noUi-handle, .widget-readout, .jupyter-matplotlib-canvas-div, .jupyter-widgets button,
    .jupyter-widgets select, .jupyter-widgets input):focus-visible
    { outline: 2px solid """ + FOCUS_COLOUR + r""" !important; outline-offset: 2px !important; }`;
  document.head.appendChild(style);
  let serial = 0;
  const idOf = el => el.id || (el.id = 'mechlab-label-' + (++serial));
  const name = root => {
    root.querySelectorAll('.widget-slider, .widget-hslider').forEach(s => {
      const label = s.querySelector(':scope > .widget-label');
      if (!label || !label.textContent.trim()) return;
      s.querySelectorAll('.noUi-handle').forEach(h => h.setAttribute('aria-labelledby', idOf(label)));
      s.querySelectorAll('.widget-readout').forEach(r => {   // an editable box: a named textbox
        r.setAttribute('role', 'textbox');
        r.setAttribute('aria-label', label.textContent.trim() + ', value');
      });
    });
    root.querySelectorAll('.widget-toggle-buttons').forEach(g => {
      const label = g.querySelector(':scope > .widget-label');
      g.setAttribute('role', 'group');
      if (label && label.textContent.trim()) g.setAttribute('aria-labelledby', idOf(label));
    });
    root.querySelectorAll('.widget-play button').forEach(b => {
      const icon = b.querySelector('i');
      const kind = icon && ['pause', 'play', 'stop', 'retweet'].find(k => icon.classList.contains('fa-' + k));
      if (kind) b.setAttribute('aria-label', kind === 'retweet' ? 'repeat' : kind);
    });
    // a drop-down keeps its arrow keys: JupyterLab's notebook shortcuts (arrows move between cells) skip it
    root.querySelectorAll('.jupyter-widgets select').forEach(s => s.setAttribute('data-lm-suppress-shortcuts', 'true'));
    root.querySelectorAll('img.widget-image[title]').forEach(i => i.setAttribute('alt', i.title));
    // a live plot (ipympl): its canvas, which takes the focus, is an image named by the figure's alt text
    root.querySelectorAll('.jupyter-matplotlib-canvas-div').forEach(c => {
      const described = c.closest('.jupyter-matplotlib[title], .jupyter-matplotlib-figure[title]');
      if (!described) return;
      c.setAttribute('role', 'img');
      c.setAttribute('aria-label', described.title);
    });
    root.querySelectorAll('.""" + STATUS_CLASS + r"""').forEach(s => {
      s.setAttribute('role', 'status');
      s.setAttribute('aria-live', 'polite');
    });
  };
  let queued = false;
  window.__mechlabLabelControls = () => name(document);
  new MutationObserver(() => {
    if (queued) return;
    queued = true;
    requestAnimationFrame(() => { queued = false; name(document); });
  }).observe(document.body, {subtree: true, childList: true, attributes: true, attributeFilter: ['title']});
  name(document);
})();
"""


class AltImage(W.Image):
    """An image widget with an alternative text: ``alt`` is shown as the image's tooltip (its ``title``,
    which :data:`LABEL_CONTROLS_JS` copies into its ``alt``) and read by the book's static pages.

    Examples
    --------
    >>> AltImage(format="png", alt="A blank picture.").tooltip
    'A blank picture.'
    """

    # the front end names a widget by its tooltip only when its description is empty: an Image has
    # none, so it gets an empty one
    description = Unicode("").tag(sync=True)

    def __init__(self, alt: str = "", **kwargs):
        super().__init__(**kwargs)
        self.alt = alt

    @property
    def alt(self) -> str:
        return self.tooltip or ""

    @alt.setter
    def alt(self, text: str):
        self.tooltip = text or None


def describe_live_figure(fig) -> None:
    """Keep the figure's :func:`~mechlab.draw.access.alt_text` on its live canvas (an ipympl widget) as its
    tooltip, which :data:`LABEL_CONTROLS_JS` makes the canvas's accessible name; renewed at every full draw
    (a change of the mechanism; a blitted frame keeps it: the status line states the moving reading).
    A figure on another canvas is left alone.

    Parameters
    ----------
    fig : matplotlib.figure.Figure

    Returns
    -------
    None

    Raises
    ------
    None

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> describe_live_figure(Figure())   # no widget canvas: nothing to do
    """
    canvas = fig.canvas
    if not isinstance(canvas, W.DOMWidget):
        return
    if not canvas.has_trait("description"):
        # the front end shows a widget's tooltip only when its description is empty: an ipympl canvas has none
        canvas.add_traits(description=Unicode("").tag(sync=True))

    def describe(_event=None):
        canvas.tooltip = alt_text(fig) or None

    canvas.mpl_connect("draw_event", describe)
    describe()


def status_line(value: str = "") -> W.HTML:
    """An HTML widget that the page announces when its text changes (``role="status"``, polite).

    Examples
    --------
    >>> status_line("ready")._dom_classes
    ('mechlab-status',)
    """
    line = W.HTML(value)
    line.add_class(STATUS_CLASS)
    return line


def announce_controls() -> None:
    """Display :data:`LABEL_CONTROLS_JS` (in a live kernel only: a static page has no widget to name).

    JupyterLab runs a trusted output's JavaScript, and a cell's output is trusted in the session that
    made it; the script installs itself once per page and names the controls of every widget shown.
    """
    if os.environ.get("MECHLAB_WIDGETS") != "static":
        display(Javascript(LABEL_CONTROLS_JS))
