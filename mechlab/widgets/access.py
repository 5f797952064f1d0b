"""Explorers a keyboard and a screen reader can drive: named controls and an announced status line.

ipywidgets 8 draws a slider with noUiSlider, whose handle (``role="slider"``, the element that takes
the keyboard focus) gets no accessible name: the visible ``<label class="widget-label">`` beside it is
tied to nothing (ipywidgets does not pass noUiSlider's ``handleAttributes``; noUiSlider #1223), and a
:class:`ipywidgets.Play`'s buttons are bare icons. :data:`LABEL_CONTROLS_JS`, displayed once with an
explorer in a live kernel (:func:`announce_controls`), fixes that in the page: each slider handle is
``aria-labelledby`` its visible label, each readout is named after it, each toggle-button group is a
named ``group``, the play buttons are named "play", "stop" and "repeat", and every status line
(:func:`status_line`) is a polite live region (``role="status"``), so that a changed reading is
announced. It watches the page, so controls drawn later are named too.
"""

from __future__ import annotations

import os

import ipywidgets as W
from IPython.display import Javascript, display
from traitlets import Unicode

STATUS_CLASS = "mechlab-status"   # the class that makes an HTML widget a live region

LABEL_CONTROLS_JS = r"""
(() => {
  if (window.__mechlabLabelControls) { window.__mechlabLabelControls(); return; }
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
    root.querySelectorAll('img.widget-image[title]').forEach(i => i.setAttribute('alt', i.title));
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
  }).observe(document.body, {subtree: true, childList: true});
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
