# One-command set-up for students, lecturers and CI.
# `make lab`  : the course in JupyterLab (127.0.0.1, token authentication on)
# `make test` : library tests, then every notebook executed by nbval
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
# The venv is rebuilt only when the pinned set or the project's metadata changes.
HASH   := $(shell cat environment.txt pyproject.toml | $(PYTHON) -c "import hashlib,sys; print(hashlib.sha256(sys.stdin.buffer.read()).hexdigest()[:16])")
STAMP  := $(VENV)/.installed-$(HASH)
PORT   ?= 8888
# JupyterLab refuses to run as root unless told; a container's root user is the usual case
ROOT_FLAG := $(if $(filter 0,$(shell id -u)),--allow-root,)

.PHONY: venv lab test test-lib test-notebooks book bench clean

venv: $(STAMP)

$(STAMP):
	@$(PYTHON) -c "import sys; sys.exit(sys.version_info < (3, 11))" || { echo "mechlab needs Python 3.11 or newer (found $$($(PYTHON) --version))"; exit 1; }
	rm -f $(VENV)/.installed-*
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -r environment.txt
	$(BIN)/python -m pip install --quiet --disable-pip-version-check --no-deps -e .
	touch $@

lab: venv
	$(BIN)/jupyter lab --ServerApp.ip=127.0.0.1 --ServerApp.port=$(PORT) --no-browser $(ROOT_FLAG) \
	    --ServerApp.root_dir=notebooks --LabApp.news_url=None \
	    --LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate --LabApp.extension_manager=readonly

test: venv nbgrader
	$(BIN)/python -m pytest tests -q
	$(BIN)/python -m pytest --nbval-lax --nbval-current-env -q -p no:cacheprovider notebooks assignments/source

# `make book`: the course as static HTML in book/_build/html, every notebook executed at build
# time (the execution cache is book/_build/.jupyter_cache); warnings fail the build.
BOOK_OUT   := book/_build/html
SPHINXOPTS ?= -W --keep-going
book: venv
	$(BIN)/sphinx-build $(SPHINXOPTS) -b html -d book/_build/doctrees book $(BOOK_OUT)
	@echo "the book: $(BOOK_OUT)/index.html"

# `make test-browser`: the built book and every chapter in JupyterLab, in Debian's Chromium
# driven by Playwright (the browser comes from apt, never from `playwright install`).
CHROMIUM ?= /usr/bin/chromium
SUDO     := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
.PHONY: test-browser chromium
chromium:
	@test -x $(CHROMIUM) || { $(SUDO) apt-get update && $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y chromium; }

test-browser: book chromium
	CHROMIUM=$(CHROMIUM) $(BIN)/python -m pytest -q -p no:cacheprovider tests_browser

# pylinkage and numba are only for the comparison: they go to a folder of their own, not into the course's venv
BENCH_DEPS := .bench-deps
bench: venv
	test -d $(BENCH_DEPS) || $(BIN)/python -m pip install --quiet --disable-pip-version-check --no-deps \
	    --target $(BENCH_DEPS) pylinkage==1.3.0 numba==0.68.1 llvmlite==0.50.0 tqdm==4.70.1
	PYTHONPATH=$(BENCH_DEPS) $(BIN)/python benchmarks/bench_fourbar.py
	$(BIN)/python benchmarks/bench_design.py

clean:
	rm -rf $(VENV) book/_build

# -- assignments (nbgrader) -------------------------------------------------------------------
# nbgrader lives in a folder of its own, not in the course's venv, so its JupyterLab extensions stay
# out of the students' lab; `make student` writes the student edition to assignments/release,
# `make grade SUBMISSIONS=<folder>` grades <folder>/<student>/<id>.ipynb into assignments/graded
# (grades.csv, feedback/<student>/<id>.html), `make book-instructor` executes the worked solutions
# to HTML in assignments/instructor (all three folders git-ignored).
NBGRADER_DEPS := assignments/.nbgrader-deps
NBGRADER_PINS := nbgrader==0.9.6 alembic==1.20.1 Mako==1.4.3 RapidFuzz==3.14.6
NBGRADER_ENV  := PATH="$(CURDIR)/$(NBGRADER_DEPS)/bin:$$PATH" PYTHONPATH="$(CURDIR)/$(NBGRADER_DEPS):$(CURDIR)"
.PHONY: nbgrader student grade book-instructor
nbgrader: venv
	test -d $(NBGRADER_DEPS)/nbgrader || $(BIN)/python -m pip install --quiet --disable-pip-version-check --no-deps \
	    --target $(NBGRADER_DEPS) $(NBGRADER_PINS)

student: nbgrader
	$(NBGRADER_ENV) $(BIN)/python assignments/course.py student

grade: nbgrader
	@test -n "$(SUBMISSIONS)" || { echo "usage: make grade SUBMISSIONS=<folder of <student>/<id>.ipynb>"; exit 1; }
	$(NBGRADER_ENV) $(BIN)/python assignments/course.py grade "$(SUBMISSIONS)"

book-instructor: venv
	rm -rf assignments/instructor
	PYTHONPATH="$(CURDIR)" $(BIN)/jupyter nbconvert --to html --execute --output-dir assignments/instructor \
	    --ExecutePreprocessor.timeout=120 assignments/source/*/*.ipynb
	@echo "worked solutions: assignments/instructor/<id>.html"
