"""IPython start-up file for the kernels that execute the book's pages (never for JupyterLab).

book/conf.py copies it into a profile in the git-ignored build folder and points
IPYTHONDIR there. A static page has no kernel behind it, so a widget is shown as what
it displays for its default values plus a one-line note on running it live:

* mechlab's explorers are told to draw statically (``MECHLAB_WIDGETS=static``: an image in
  an Output widget, not a live ipympl canvas);
* every image (a figure with the inline backend) displayed into an ``ipywidgets.Output``
  is remembered, and a widget's HTML representation shows the last image of each
  Output widget it contains — so a mechlab explorer, an ``interact`` or any box of
  controls with a plot appears as its plot, with the text of the HTML widgets it holds
  (an explorer's question and status line) above it and its controls' values as a
  caption (a play button is no value: it is left out);
* every figure is published with its alternative text (``mechlab.draw.access.install_alt_text``),
  which ``_ext/alttext.py`` writes into the page as the image's ``alt``; a widget's image keeps it
  (an ``ipywidgets.Image`` its ``alt``, :class:`mechlab.widgets.access.AltImage`, or tooltip); an image
  without one gets an empty ``alt``, which ``_ext/alttext.py`` refuses;
* ``%matplotlib widget`` / ``ipympl`` falls back to the inline backend (ipympl figures
  do not render in static HTML).

conf.py removes the widget view from myst-nb's MIME priority, so this HTML is chosen.
"""


def _mechbook_setup():
    import base64
    import html
    import os

    import ipywidgets
    from IPython import get_ipython

    ip = get_ipython()
    if ip is None:
        return
    os.environ["MECHLAB_WIDGETS"] = "static"
    from mechlab.draw.access import install_alt_text

    install_alt_text(ip)

    note = ('<p class="mechbook-live-note">Live widget: the book shows it for the default values; '
            'run this notebook with <code>make lab</code> to move the sliders.</p>')
    last_image: dict[str, tuple[str, str]] = {}  # Output widget model id -> last image/png (base64), its alt
    capturing: list = []  # the Output widgets being written into (nested `with out:`)

    publish = ip.display_pub.publish

    def recording_publish(data, metadata=None, *args, **kwargs):
        if capturing and isinstance(data, dict) and "image/png" in data:
            alt = ((metadata or {}).get("image/png") or {}).get("alt") or ""
            last_image[capturing[-1].model_id] = (data["image/png"], alt)
        return publish(data, metadata, *args, **kwargs)

    ip.display_pub.publish = recording_publish

    enter, exit_ = ipywidgets.Output.__enter__, ipywidgets.Output.__exit__

    def output_enter(self):
        capturing.append(self)
        return enter(self)

    def output_exit(self, *exc):
        if capturing and capturing[-1] is self:
            capturing.pop()
        return exit_(self, *exc)

    ipywidgets.Output.__enter__, ipywidgets.Output.__exit__ = output_enter, output_exit

    def walk(widget, seen):
        if id(widget) in seen:
            return
        seen.add(id(widget))
        yield widget
        for child in getattr(widget, "children", ()) or ():
            if isinstance(child, ipywidgets.Widget):
                yield from walk(child, seen)

    def static_html(widget) -> str:
        parts, values, texts = [], [], []
        for w in walk(widget, set()):
            if isinstance(w, ipywidgets.Output) and w.model_id in last_image:
                png, alt = last_image[w.model_id]
                parts.append(f'<img src="data:image/png;base64,{png}" alt="{html.escape(alt, quote=True)}"/>')
            elif isinstance(w, ipywidgets.Image) and w.value:   # an explorer that sends its figure as one picture
                alt = getattr(w, "alt", "") or w.tooltip or ""   # mechlab.widgets.access.AltImage's
                parts.append(f'<img src="data:image/{w.format};base64,{base64.b64encode(w.value).decode()}" '
                             f'alt="{html.escape(alt, quote=True)}"/>')
            elif isinstance(w, ipywidgets.HTML) and w.value.strip():
                texts.append(f'<div class="mechbook-widget-text">{w.value}</div>')  # the widget's own HTML
            elif isinstance(w, ipywidgets.Play):
                continue
            elif isinstance(w, ipywidgets.ValueWidget) and getattr(w, "description", ""):
                values.append(f"{w.description} = {_shown(w)}")
        caption = (f'<p class="mechbook-widget-values">{html.escape(", ".join(values))}</p>'
                   if values and parts else "")
        return f'<div class="mechbook-widget">{"".join(texts + parts)}{caption}{note}</div>'

    def _shown(w) -> str:
        """A slider's value as its readout shows it ("4", "0.30", not "4.0" or "0.30000000000000004")."""
        fmt = getattr(w, "readout_format", None)
        if isinstance(w.value, float) and fmt:
            try:
                return format(w.value, fmt)
            except ValueError:
                pass
        return str(w.value)

    original = ipywidgets.Widget._repr_mimebundle_

    def with_static_html(self, **kwargs):
        data = original(self, **kwargs)
        if isinstance(data, dict):
            data = dict(data)
            data["text/html"] = static_html(self)
        return data

    ipywidgets.Widget._repr_mimebundle_ = with_static_html

    enable_matplotlib = ip.enable_matplotlib  # what %matplotlib calls

    def inline_matplotlib(gui=None):
        return enable_matplotlib("inline" if gui in ("widget", "ipympl", "notebook", "nbagg") else gui)

    ip.enable_matplotlib = inline_matplotlib


_mechbook_setup()
del _mechbook_setup
