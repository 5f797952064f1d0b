"""The course's one command, needing only Python 3.11+ (the Makefile calls it too).

    python course.py lab [--port 8888]   venv with the lab's part, sync my-notebooks/, JupyterLab on 127.0.0.1
    python course.py sync                refresh my-notebooks/ from notebooks/ (after a `git pull`)
    python course.py test                the library's tests, then every notebook and assignment (nbval)
    python course.py book                the static HTML book in book/_build/html
    python course.py pdf                 the whole book as one PDF (printed by Chromium)
    python course.py test-browser        tests_browser/: the built book, the PDF, every chapter in JupyterLab
    python course.py execute NB... --output-dir DIR   notebooks executed by nbconvert (as the book's kernels)
    python course.py venv PART           only install a part: lab, test, book, browser, hub, hubtest, all

Each part installs the extra of the same name from pyproject.toml with environment.txt as
constraints, so the one pinned set decides every version and a student gets only what
the lab needs.
"""

from __future__ import annotations

import argparse
import contextlib
import datetime
import hashlib
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent
# the oldest Python the pins install on (soupsieve stays at 2.10: its 3.x needs Python 3.11.5)
MIN_PYTHON = (3, 11)
# a part also counts as installed when a larger part that contains it is
PARTS = {"lab": {"lab"}, "test": {"lab", "test"}, "book": {"lab", "book"},
         "browser": {"lab", "test", "book", "browser"}, "hub": {"lab", "hub"},
         "hubtest": {"lab", "test", "hub", "hubtest"},
         "all": {"lab", "test", "book", "browser", "hub", "hubtest", "all"}}
# the course itself; everything else, pip included, must be at its pin
UNPINNED_OK = {"mechlab"}
WORKDIR = "my-notebooks"
MANIFEST = ".course-manifest.json"
PDF = "book/_build/pdf/mechlab.pdf"
# JupyterLab's defaults for students (the hub's image gets the same file, binder/postBuild): no
# "Would you like to get notified about official Jupyter news?" prompt, no update check
LAB_SETTINGS = ROOT / "binder" / "lab-settings"
# Every executed notebook's kernel over unique Unix sockets, its waits in slices (tools/ipc_kernels.py:
# no TCP port race, no missed reply), and a cell stopped with its source and the reason after
# MECHLAB_CELL_TIMEOUT seconds (60; book/conf.py reads the same variable)
CELL_TIMEOUT = int(os.environ.get("MECHLAB_CELL_TIMEOUT", "60"))
NBVAL_ARGS = ["-p", "ipc_kernels", "--nbval-lax", "--nbval-current-env", f"--nbval-cell-timeout={CELL_TIMEOUT}",
              "-p", "no:cacheprovider"]
NBCONVERT_ARGS = ["--NotebookClient.kernel_manager_class=ipc_kernels.IPCKernelManager",
                  f"--ExecutePreprocessor.timeout={CELL_TIMEOUT}"]


def say(message: str) -> None:
    print(f"course: {message}", flush=True)


# ---------------------------------------------------------------- venv and pinned installs

def venv_python(venv: Path) -> Path:
    return venv / ("Scripts/python.exe" if os.name == "nt" else "bin/python")


def install_hash() -> str:
    """Changes when the pinned set, the project's metadata or the interpreter's version changes."""
    h = hashlib.sha256()
    for name in ("environment.txt", "pyproject.toml"):
        h.update((ROOT / name).read_bytes())
    h.update(sys.version.encode())
    return h.hexdigest()[:16]


def pins() -> dict[str, str]:
    result = {}
    for line in (ROOT / "environment.txt").read_text().splitlines():
        line = line.split("#")[0].strip()
        if "==" in line:
            name, version = line.split("==")
            result[canonical(name)] = version.strip()
    return result


def canonical(name: str) -> str:
    return name.lower().replace("_", "-").replace(".", "-")


def venv_version(venv: Path) -> str | None:
    """The Python version `venv` was made with (pyvenv.cfg says `version` or `version_info`)."""
    cfg = venv / "pyvenv.cfg"
    if not cfg.exists():
        return None
    for line in cfg.read_text().splitlines():
        key, _, value = line.partition("=")
        if key.strip() in ("version", "version_info"):
            return value.strip()
    return None


def check_python() -> None:
    if sys.version_info < MIN_PYTHON:
        sys.exit(f"mechlab needs Python {'.'.join(map(str, MIN_PYTHON))} or newer (this is {sys.version.split()[0]})")


def ensure_venv(venv: Path, part: str) -> Path:
    """Create `venv` and install `part` into it unless its stamp says it is there already."""
    check_python()
    python = venv_python(venv)
    stamp = venv / f".installed-{part}-{install_hash()}"
    if stamp.exists() or any((venv / f".installed-{p}-{install_hash()}").exists()
                             for p, has in PARTS.items() if part in has):
        return python
    if venv_version(venv) not in (None, sys.version.split()[0]):
        say(f"{venv} was made with another Python; making it again with {sys.version.split()[0]}")
        shutil.rmtree(venv)
    if not python.exists():
        say(f"creating {venv} with Python {sys.version.split()[0]}")
        subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    for old in venv.glob(".installed-*"):
        if not old.name.endswith(install_hash()):
            old.unlink()
    pip = [str(python), "-m", "pip", "install", "--quiet", "--disable-pip-version-check"]
    # pip at its pin, without the bytecode that ensurepip compiles for it: 8 MB instead of 16 (the pin stays
    # below 26.3, which prints setuptools' notes on editable installs in spite of --quiet)
    subprocess.run(pip + ["--no-compile", "-c", "environment.txt", "pip"], cwd=ROOT, check=True)
    if "setuptools" in installed(python):
        # Python 3.11's venv adds it (3.12's no longer does), but the lab never runs it: pip builds mechlab in
        # an isolated environment (9 MB less); a part that needs it (the book's) brings it back at its pin
        subprocess.run([str(python), "-m", "pip", "uninstall", "--quiet", "--yes", "setuptools"], check=True)
    say(f"installing the {part!r} part of environment.txt")
    with tempfile.TemporaryDirectory(prefix="mechlab-wheels-") as wheels:
        pure = pure_wheels(python, Path(wheels))
        subprocess.run(install_command(pip, part, pure), cwd=ROOT, check=True)
    if part == "all":
        subprocess.run(pip + ["--no-deps", "-e", "."], cwd=ROOT, check=True)
    check_pinned(python)
    stamp.touch()
    return python


# pip prefers a platform wheel; these run as pure Python at their pin. ezdxf's compiled accelerators
# (ezdxf.acc) are 12 of its 18 MB, and the course only writes and reads back small DXF polylines
PURE = ("ezdxf",)


def pure_wheels(python: Path, into: Path) -> list[Path]:
    """Download the pure-Python wheel (py3-none-any) of each `PURE` distribution at its pin into `into`."""
    pinned = pins()
    version = f"{sys.version_info.major}.{sys.version_info.minor}"  # the venv is made with this Python
    files = []
    for dist in PURE:
        done = subprocess.run(
            [str(python), "-m", "pip", "download", "--quiet", "--disable-pip-version-check", "--no-deps",
             "--only-binary=:all:", "--platform", "any", "--implementation", "py", "--python-version", version,
             "-d", str(into), f"{dist}=={pinned[dist]}"], check=False)
        found = sorted(into.glob(f"{dist}-{pinned[dist]}-py3-none-any.whl"))
        if done.returncode or not found:
            sys.exit(f"course: could not download {dist}=={pinned[dist]} (its pure-Python wheel) from PyPI; "
                     "check the network connection (or pip's proxy settings) and run the command again")
        files.append(found[0])
    return files


def install_command(pip: list[str], part: str, pure: list[Path]) -> list[str]:
    """pip's command for `part`; the wheel files in `pure` stand for their distributions' requirements."""
    wheels = [str(path) for path in pure]
    # --no-compile: bytecode is written on first import instead, only for the modules used (compiling the whole
    # set took 33 of the 71 s `venv all` took on 2 cores, on the critical path of a fresh CI)
    if part == "all":
        return pip + ["--no-compile", "-r", "environment.txt", *wheels]
    return pip + ["--no-compile", "-c", "environment.txt", f"-e.[{part}]", *wheels]


def installed(python: Path) -> dict[str, str]:
    """The distributions in `python`'s environment, canonical name: version."""
    listing = subprocess.run(
        [str(python), "-c", "import importlib.metadata as m, json; "
         "print(json.dumps({d.metadata['Name']: d.version for d in m.distributions()}))"],
        check=True, capture_output=True, text=True).stdout
    return {canonical(name): version for name, version in json.loads(listing).items()}


def check_pinned(python: Path) -> None:
    """Fail when the venv holds a distribution that environment.txt does not pin at that version."""
    pinned = pins()
    wrong = [f"{name}=={version} (environment.txt: {pinned.get(canonical(name), 'not pinned')})"
             for name, version in installed(python).items()
             if canonical(name) not in UNPINNED_OK and pinned.get(canonical(name)) != version]
    if wrong:
        sys.exit("course: installed outside the pinned set: " + ", ".join(sorted(wrong)))


# ---------------------------------------------------------------- the student's working copy

def digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def course_files(source: Path) -> list[Path]:
    return sorted(p.relative_to(source) for p in source.rglob("*")
                  if p.is_file() and ".ipynb_checkpoints" not in p.parts and "__pycache__" not in p.parts)


def beside_name(rel: Path, today: str, taken) -> Path:
    """`05_x (course update 2026-12-01).ipynb`, then `(course update 2026-12-01, 2)` if taken by other content."""
    n = 1
    while True:
        candidate = rel.with_name(f"{rel.stem} (course update {today}{'' if n == 1 else f', {n}'}){rel.suffix}")
        if not taken(candidate):
            return candidate
        n += 1


def copy_file(src: Path, dst: Path) -> None:
    """Copy through a temporary file so an interrupted sync never leaves half a notebook."""
    dst.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=dst.parent, prefix=".sync-")
    os.close(fd)
    try:
        shutil.copyfile(src, tmp)
        os.replace(tmp, dst)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def topic(key: str) -> str:
    """A chapter's name without its number: `02_equivalence.ipynb` -> `equivalence.ipynb`."""
    parent, slash, name = key.rpartition("/")
    number, _, rest = name.partition("_")
    return f"{parent}{slash}{rest}" if number.isdigit() and rest else key


def renames(gone: set[str], arrived: set[str]) -> dict[str, str]:
    """{new key: old key} for files that left the course and came back under another number.

    Only a one-to-one match of topic words counts: a topic that two files share is no rename.
    """
    def by_topic(keys):
        found: dict[str, list[str]] = {}
        for key in keys:
            if topic(key) != key:
                found.setdefault(topic(key), []).append(key)
        return {t: k[0] for t, k in found.items() if len(k) == 1}
    old, new = by_topic(gone), by_topic(arrived)
    return {new[t]: old[t] for t in old.keys() & new.keys()}


def rename(work: Path, old: str, new: str, copied_hash: str) -> str:
    """Retire the working copy's `old` now that the course calls the chapter `new`; say what was done."""
    path = work / old
    if not path.exists():
        return f"added {new} (the chapter {old} under its new number)"
    if digest(path) == copied_hash:
        path.unlink()
        return f"renamed {old} to {new} (the chapter's new number; you had not changed it)"
    return (f"kept {old}: it has your changes; the course now calls this chapter {new}, "
            f"which holds the course's version (copy your work over, or keep working in {old})")


def sync(source: Path, work: Path, today: str | None = None) -> list[str]:
    """Bring the working copy `work` up to date with the course's `source`; return what happened.

    The rules are nbgitpuller's, with one change: where nbgitpuller merges a chapter both
    sides changed (keeping the student's side of conflicting lines), the student's file is
    left exactly as it is and the course's new version is placed beside it, because a
    line merge of notebook JSON can yield a notebook that does not open.
    - new in the course: added;
    - unchanged by the student since it was copied: refreshed to the course's version;
    - deleted by the student: restored;
    - changed by the student and by the course: kept, the update beside it;
    - a student's own file with a new chapter's name: kept, the chapter beside it;
    - removed from the course: deleted if unchanged, kept otherwise;
    - renamed (a chapter's number changes, its topic words stay: `01_equivalence` becomes
      `02_equivalence`): the new name is added; the old copy is deleted if unchanged, and kept
      otherwise, with a word on which chapter it now is.
    "Changed" means its bytes differ from those copied, whose hashes `MANIFEST` records.
    """
    today = today or datetime.date.today().isoformat()
    manifest_path = work / MANIFEST
    manifest = json.loads(manifest_path.read_text()) if manifest_path.exists() else {}
    copied: dict[str, str] = manifest.get("copied", {})
    offered: dict[str, str] = manifest.get("offered", {})  # updates placed beside a changed file
    report = []
    first = not work.exists()
    work.mkdir(parents=True, exist_ok=True)
    keys = {rel.as_posix() for rel in course_files(source)}
    renamed = renames(set(copied) - keys, keys - set(copied))
    for rel in course_files(source):
        key, src, dst = rel.as_posix(), source / rel, work / rel
        new = digest(src)
        if not dst.exists():
            copy_file(src, dst)  # first, so that a failure below leaves both names
            if key in renamed:
                report.append(rename(work, renamed[key], key, copied.pop(renamed[key])))
                offered.pop(renamed[key], None)
            elif key in copied and not first:
                report.append(f"restored {key} (it had been deleted)")
            elif not first:
                report.append(f"added {key} (new in the course)")
            copied[key] = new
            continue
        mine = digest(dst)
        if mine == new:
            copied[key] = new
        elif key in copied and mine == copied[key]:
            copy_file(src, dst)
            copied[key] = new
            report.append(f"refreshed {key} (you had not changed it)")
        elif key in copied and new == copied[key]:
            pass  # only the student changed it
        elif offered.get(key) == new:
            pass  # this update was placed beside it by an earlier sync
        else:
            side = beside_name(rel, today, lambda p, new=new: (work / p).exists() and digest(work / p) != new)
            if not (work / side).exists():
                copy_file(src, work / side)
            offered[key] = new
            why = "has your changes" if key in copied else "is a file of yours"
            report.append(f"kept {key}: it {why}; the course's new version is beside it: {side.as_posix()}")
    for key in sorted(set(copied) - {rel.as_posix() for rel in course_files(source)}):
        dst = work / key
        if dst.exists() and digest(dst) == copied[key]:
            dst.unlink()
            report.append(f"removed {key} (no longer in the course, you had not changed it)")
        elif dst.exists():
            report.append(f"kept {key}: no longer in the course, but it has your changes")
        del copied[key]
        offered.pop(key, None)
    fd, tmp = tempfile.mkstemp(dir=work, prefix=".sync-")
    with os.fdopen(fd, "w") as f:
        json.dump({"copied": copied, "offered": offered}, f, indent=1, sort_keys=True)
    os.replace(tmp, manifest_path)
    if first:
        report.append(f"created your working copy {work} with {len(copied)} files from the course")
    return report


def run_sync(args) -> None:
    work = Path(args.workdir)
    report = sync(ROOT / "notebooks", work)
    for line in report or [f"{work} is up to date with the course"]:
        say(line)
    say(f"you work in {work}/; the course's own notebooks/ stay untouched")


# ---------------------------------------------------------------- commands

def tools_env() -> dict:
    """The environment with tools/ (ipc_kernels, print_pdf) importable."""
    path = os.pathsep.join(filter(None, [str(ROOT / "tools"), os.environ.get("PYTHONPATH")]))
    return {**os.environ, "PYTHONPATH": path}


def run(python: Path, *args: str, env: dict | None = None) -> None:
    code = subprocess.run([str(python), *args], cwd=ROOT, env=env or tools_env()).returncode
    if code:
        sys.exit(code)


def cmd_venv(args) -> None:
    ensure_venv(Path(args.venv), args.part)


def lab_argv(python: Path, workdir: Path, port: int) -> list[str]:
    """JupyterLab on 127.0.0.1 with Jupyter's token, serving the working copy, never notebooks/."""
    flags = ["--allow-root"] if hasattr(os, "geteuid") and os.geteuid() == 0 else []  # a container's usual user
    return [str(python), "-m", "jupyter", "lab", "--ServerApp.ip=127.0.0.1", f"--ServerApp.port={port}",
            "--no-browser", *flags, f"--ServerApp.root_dir={workdir.resolve()}", "--LabApp.news_url=None",
            f"--LabApp.app_settings_dir={LAB_SETTINGS}",
            "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate", "--LabApp.extension_manager=readonly"]


def cmd_lab(args) -> None:
    python = ensure_venv(Path(args.venv), "lab")
    run_sync(args)
    server = subprocess.Popen(lab_argv(python, Path(args.workdir), args.port))
    while True:
        with contextlib.suppress(KeyboardInterrupt):  # Ctrl-C reaches JupyterLab too, which asks whether to stop
            sys.exit(server.wait())


def pytest_beside(python: Path, beside: list[str], chain: list[list[str]]) -> None:
    """pytest on `beside` in a second process while the commands of `chain` run one after another, its report
    printed after theirs; exits with the first failure's code. On one core: all in sequence."""
    if (os.cpu_count() or 1) < 2:
        for cmd in [*chain, ["-m", "pytest", "-q", "-p", "no:cacheprovider", *beside]]:
            run(python, *cmd)
        return
    with tempfile.TemporaryFile("w+", encoding="utf-8") as log:
        process = subprocess.Popen([str(python), "-m", "pytest", "-q", "-p", "no:cacheprovider", *beside], cwd=ROOT,
                                   env=tools_env(), stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
        try:
            codes = [subprocess.run([str(python), *cmd], cwd=ROOT, env=tools_env()).returncode for cmd in chain]
            codes.append(process.wait())
        finally:
            if process.poll() is None:  # interrupted: nothing is left running (its kernels, servers, browsers)
                os.killpg(process.pid, signal.SIGTERM) if hasattr(os, "killpg") else process.kill()
                process.wait()
        log.seek(0)
        say(f"{', '.join(beside)} (run beside the others):")
        print(log.read(), flush=True)
    if any(codes):
        sys.exit(next(c for c in codes if c))


# The grading tests (nbgrader executes every planted submission, one after another; a looping one is stopped),
# the one-call audit of the exercises, the many-kernels test and the lambda synthesis' sweeps over its existence
# region take about as long as all the other tests and the notebooks together, on about one core: with two cores
# they run beside them, their report after (measured side by side on 2 cores: the library 572 CPU-s, the grading,
# audit, kernels, looping submission and sweeps 884 s wall with 30 students graded, now 10).
BESIDE = ["tests/test_grading.py", "tests/test_exercises.py", "tests/test_kernels.py", "tests/test_report_stopped.py",
          "tests/test_chebyshev.py"]


def cmd_test(args) -> None:
    python = ensure_venv(Path(args.venv), "test")
    library = ["-m", "pytest", "tests", "-q", "--durations=15", *(f"--ignore={path}" for path in BESIDE)]
    pytest_beside(python, BESIDE, [library, ["-m", "pytest", *NBVAL_ARGS, "-q", "notebooks", "assignments/source"]])


# Every chapter in JupyterLab (a server, a kernel, the browser) and the book's pages and PDF (the browser on files)
# each keep about one core busy, with waits: with two cores they run beside each other. The chapters' accessibility
# audit and keyboard test run inside test_lab's visit of each chapter (one run of each chapter in the lab). The lab's
# tests need no book: `--only lab` runs them alone (CI starts them before the book is built), `--only pages` the rest.
LAB_TESTS = ["tests_browser/test_lab.py", "tests_browser/test_a11y_explorers.py", "tests_browser/test_drag_lab.py"]


def cmd_test_browser(args) -> None:
    python = ensure_venv(Path(args.venv), "browser")
    pytest = ["-m", "pytest", "-q", "-p", "no:cacheprovider"]
    pages = [*pytest, "tests_browser", *(f"--ignore={path}" for path in LAB_TESTS)]
    if args.only == "lab":
        run(python, *pytest, *LAB_TESTS)
    elif args.only == "pages":
        run(python, *pages)
    else:
        pytest_beside(python, LAB_TESTS, [pages])


def cmd_book(args) -> None:
    python = ensure_venv(Path(args.venv), "book")
    opts = os.environ.get("SPHINXOPTS", "-W --keep-going").split()
    run(python, "-m", "sphinx", *opts, "-b", "html", "-d", "book/_build/doctrees", "book", "book/_build/html")
    say("the book: book/_build/html/index.html")


def cmd_pdf(args) -> None:
    python = ensure_venv(Path(args.venv), "browser")
    opts = os.environ.get("SPHINXOPTS", "-W --keep-going").split()
    # the notebooks' outputs come from the HTML build's execution cache when it is current
    run(python, "-m", "sphinx", *opts, "-b", "singlehtml", "-d", "book/_build/doctrees-single", "book",
        "book/_build/singlehtml")
    # printed before from the same page and images (their names are not all content hashes) by the same print
    # tool (CI builds the book beside `make test`, then `make test-browser` asks again): not printed twice
    single, stamp = ROOT / "book/_build/singlehtml", ROOT / (PDF + ".from")
    sources = [single / "intro.html", *sorted((single / "_images").iterdir()), ROOT / "tools/print_pdf.py",
               ROOT / "tools/chromium.py"]
    printed_from = "\n".join(f"{digest(path)} {path.relative_to(ROOT)}" for path in sources)
    if (ROOT / PDF).is_file() and stamp.is_file() and stamp.read_text() == printed_from:
        say(f"the PDF is current (printed from this same page): {PDF}")
        return
    stamp.unlink(missing_ok=True)
    run(python, "tools/print_pdf.py", "book/_build/singlehtml/intro.html", PDF, "--quote-pages")
    stamp.write_text(printed_from)


def cmd_execute(args) -> None:
    python = ensure_venv(Path(args.venv), "lab")
    run(python, "-m", "jupyter", "nbconvert", "--execute", "--to", args.to, *NBCONVERT_ARGS,
        "--output-dir", str(Path(args.output_dir).resolve()), *(str(Path(nb).resolve()) for nb in args.notebooks))


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--venv", default=str(ROOT / ".venv"), help="the venv to use (default: .venv)")
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("venv", help="create the venv and install a part of environment.txt")
    p.add_argument("part", choices=list(PARTS))
    p.set_defaults(func=cmd_venv)
    for name, func in (("lab", cmd_lab), ("sync", None)):
        p = sub.add_parser(name, help="JupyterLab on your working copy" if func else "update your working copy")
        p.add_argument("--workdir", default=str(ROOT / WORKDIR), help=f"the working copy (default: {WORKDIR}/)")
        p.set_defaults(func=func or run_sync)
    sub.choices["lab"].add_argument("--port", type=int, default=8888)
    sub.add_parser("test", help="library tests, then every notebook").set_defaults(func=cmd_test)
    p = sub.add_parser("test-browser", help="tests_browser/: the built book, the PDF, every chapter in JupyterLab "
                       "(needs Chromium)")
    p.add_argument("--only", choices=["lab", "pages"], help="only the chapters in JupyterLab (no book needed), or "
                   "only the book's pages and the PDF")
    p.set_defaults(func=cmd_test_browser)
    sub.add_parser("book", help="the HTML book").set_defaults(func=cmd_book)
    sub.add_parser("pdf", help=f"the whole book as one PDF, {PDF} (needs Chromium)").set_defaults(func=cmd_pdf)
    p = sub.add_parser("execute", help="execute notebooks with nbconvert (IPC kernels, 60 s per cell)")
    p.add_argument("notebooks", nargs="+")
    p.add_argument("--output-dir", required=True)
    p.add_argument("--to", default="notebook", help="nbconvert's format (default: notebook)")
    p.set_defaults(func=cmd_execute)
    args = parser.parse_args(argv)
    args.func(args)


if __name__ == "__main__":
    main()
