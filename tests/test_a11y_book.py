"""The book's images carry alternative text (issue 29): a small book built the way book/conf.py builds
the course (myst-nb executing the pages in kernels started with _ext/kernel_startup.py, _ext/alttext.py)
gives mechlab's figures and animations their descriptions as ``alt``, and a page with a figure that
names nothing is refused with a warning naming it."""

import os
import re
import subprocess
import sys
import textwrap
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EXT = ROOT / "book" / "_ext"
sys.path.insert(0, str(EXT))
from alttext import images_without_alt  # noqa: E402

HEADER = "---\nfile_format: mystnb\nkernelspec:\n  name: python3\n  display_name: Python 3\n---\n"
CONF = f"""
import os, sys
from pathlib import Path
sys.path.insert(0, {str(EXT)!r})
here = Path(__file__).parent
startup = here / "ipython" / "profile_default" / "startup"
startup.mkdir(parents=True, exist_ok=True)
(startup / "00-mechbook.py").write_text(Path({str(EXT / "kernel_startup.py")!r}).read_text())
os.environ["IPYTHONDIR"] = str(here / "ipython")
os.environ["MPLBACKEND"] = "module://matplotlib_inline.backend_inline"
extensions = ["myst_nb", "alttext"]
exclude_patterns = ["_build", "ipython"]
nb_execution_mode = "auto"
nb_execution_timeout = 120
nb_ipywidgets_js = {{}}
nb_mime_priority_overrides = [("html", "application/vnd.jupyter.widget-view+json", None),
                              ("html", "application/vnd.jupyter.widget-state+json", None)]
"""
INDEX = "# A small book\n\n```{toctree}\ndescribed\nplanted\n```\n"
DESCRIBED = HEADER + textwrap.dedent("""
    # Described figures

    ```{code-cell} python3
    import numpy as np
    import matplotlib.pyplot as plt
    from IPython.display import HTML
    from mechlab import ExternalGeneva, FourBar
    from mechlab.draw import animate, draw

    draw(FourBar(1, 3, 3, 4, 1), 0.3);
    ```

    ```{code-cell} python3
    HTML(animate(ExternalGeneva(4, 1.0), n=4).to_jshtml())
    ```

    ```{code-cell} python3
    fig, ax = plt.subplots()
    ax.plot(np.arange(3), np.arange(3) ** 2)
    ax.set(title="a parabola", xlabel="x", ylabel="y");
    ```
    """)
PLANTED = HEADER + textwrap.dedent("""
    # A figure that names nothing

    ```{code-cell} python3
    import matplotlib.pyplot as plt
    plt.plot([0, 1], [1, 0]);
    ```
    """)


def test_images_without_alt_are_found():
    html = ('<p><img src="a.png" alt="A cam."><img src="b.png"><img alt=" " src="c.png"><IMG SRC="d.png" ALT="">'
            '<img alt="_images/e.png" src="../_images/e.png"></p>')
    assert images_without_alt(html) == (5, ["b.png", "c.png", "d.png", "../_images/e.png"])


def test_a_small_book_gives_figures_alt_text_and_refuses_one_without(tmp_path):
    src = tmp_path / "src"
    src.mkdir()
    (src / "conf.py").write_text(CONF)
    (src / "index.md").write_text(INDEX)
    (src / "described.md").write_text(DESCRIBED)
    (src / "planted.md").write_text(PLANTED)
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])}
    run = subprocess.run([sys.executable, "-m", "sphinx", "-q", "-b", "html", str(src), str(tmp_path / "html")],
                         capture_output=True, text=True, timeout=280, env=env, cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    warnings = [line for line in run.stderr.splitlines() if "without alternative text" in line]
    # the planted figure is refused, by page; the described page passes
    assert len(warnings) == 1 and "planted.html" in warnings[0], run.stderr
    page = (tmp_path / "html" / "described.html").read_text()
    count, missing = images_without_alt(page)
    assert count == 3 and missing == []
    alts = re.findall(r'<img[^>]*\balt="([^"]+)"', page)
    assert any(a.startswith("Kinematic diagram of a four bar with joints O, A, B") and "φ = 17°" in a for a in alts)
    assert any("external geneva" in a and "Animation of 4 frames" in a for a in alts)
    assert "Figure: a parabola, y against x, y from 0 to 4." in alts   # its subject and its key reading
