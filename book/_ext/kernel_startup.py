"""IPython start-up file for the kernels that execute the book's pages (never for JupyterLab).

book/conf.py copies it into a profile in the git-ignored build folder and points
IPYTHONDIR there. A static page has no kernel behind it, so:

* a mechlab explorer (``MechanismExplorer``) is shown as the figure for its default
  slider values plus a one-line note on running it live with ``make lab``;
* any other widget shows the same note instead of an empty widget view;
* ``%matplotlib widget`` / ``ipympl`` falls back to the inline backend (ipympl figures
  do not render in static HTML).
"""


def _mechbook_setup():
    import base64
    import html
    import io

    from IPython import get_ipython
    from IPython.display import display

    note = ('<p class="mechbook-live-note">Live widget: in the book you see the figure for the '
            'default values; run this notebook with <code>make lab</code> to move the sliders.</p>')

    def figure_bundle(fig, title):
        buf = io.BytesIO()
        fig.savefig(buf, format="png", dpi=fig.dpi)
        data = base64.b64encode(buf.getvalue()).decode("ascii")
        alt = html.escape(title or "widget figure for the default values", quote=True)
        return {"text/html": (f'<div class="mechbook-widget"><img src="data:image/png;base64,{data}" '
                              f'alt="{alt}"/>{note}</div>'),
                "text/plain": f"<widget: {title or 'explorer'} (run live with make lab)>"}

    try:
        from mechlab.widgets import MechanismExplorer
    except Exception:  # the book still builds the pages that do not need mechlab
        MechanismExplorer = None

    if MechanismExplorer is not None:
        def _static_display(self):
            title = self.fig.get_suptitle()
            parts = [f"{w.description} = {w.value}" for w in self.sliders.values()]
            caption = (f'<p class="mechbook-widget-values">{html.escape(", ".join(parts))}</p>'
                       if parts else "")
            bundle = figure_bundle(self.fig, title)
            bundle["text/html"] = bundle["text/html"].replace("</div>", caption + "</div>", 1)
            display(bundle, raw=True)

        MechanismExplorer._ipython_display_ = _static_display

    import ipywidgets

    original = ipywidgets.Widget._repr_mimebundle_

    def _with_note(self, **kwargs):
        data = original(self, **kwargs)
        if isinstance(data, dict):
            data = dict(data)
            data["text/html"] = f'<div class="mechbook-widget">{note}</div>'
        return data

    ipywidgets.Widget._repr_mimebundle_ = _with_note

    ip = get_ipython()
    if ip is not None:
        magics = ip.magics_manager.magics["line"]
        matplotlib_magic = magics.get("matplotlib")

        def _matplotlib(line=""):
            if line.strip() in ("widget", "ipympl", "notebook"):
                line = "inline"
            return matplotlib_magic(line)

        if matplotlib_magic is not None:
            ip.register_magic_function(_matplotlib, "line", "matplotlib")


_mechbook_setup()
del _mechbook_setup
