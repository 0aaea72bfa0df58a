# Set-up and the two everyday commands. Every target installs what it needs on a fresh Debian 12
# machine (run as root): Debian packages via apt, Python packages into ./.venv.
SHELL := /bin/bash
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
DEB_PACKAGES := texlive-latex-recommended texlive-lang-cyrillic texlive-xetex \
	texlive-fonts-recommended latexmk fonts-liberation fonts-texgyre-math poppler-utils librecad xvfb xauth \
	fonts-osifont
DEMO_OUT ?= demo

.PHONY: demo test check generated system venv compiled bench clean review

# Debian packages: TeX Live for the note, poppler for checking it, LibreCAD for checking the sheets,
# osifont (ISO 3098 lettering) for the sheets' previews.
system:
	@missing=""; for p in $(DEB_PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "Installing Debian packages:$$missing"; \
	  SUDO=""; [ "$$(id -u)" = 0 ] || SUDO=sudo; \
	  $$SUDO apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq --no-install-recommends $$missing; \
	fi

$(VENV)/.installed: pyproject.toml
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip
	$(PY) -m pip install -q -e '.[test]'
	touch $@

# What an installation compiles once (docs/build.md «Compiled at install time»): the Python modules'
# bytecode (read even where PYTHONDONTWRITEBYTECODE keeps Python from writing it) and the note's Jinja
# templates and catalogue snippets (latex_templates/precompiled.py). Run again after an edit: what
# changed is compiled by each build otherwise, never used stale.
compiled: $(VENV)/.installed
	$(PY) -m compileall -q reportgen latex_templates drawings
	$(PY) -m latex_templates.precompiled

venv: $(VENV)/.installed compiled

# The example note and sheets of the press mechanism.
demo: system venv
	$(VENV)/bin/reportgen build examples/press/task.toml -o $(DEMO_OUT)
	@echo "open $(DEMO_OUT)/report.pdf and $(DEMO_OUT)/sheets/*.dxf (previews: *.png)"

# The whole test suite (what CI runs): static checks, numerics, the note (LaTeX) and the sheets
# (LibreCAD).
test: system venv
	$(PY) -m pytest -n 2 -p no:cacheprovider tests

# The fast loop for developers, within a minute on two cores: ruff + mypy, then every test not
# marked slow (slow: TeX, LibreCAD, builds, or seconds of CPU — tests/conftest.py SLOW_TESTS; they
# are left to `make test`, see docs/testing.md).
check: venv
	$(VENV)/bin/ruff check .
	$(VENV)/bin/mypy
	$(PY) -m pytest -n 2 -p no:cacheprovider -m "not slow" --deselect tests/test_static.py tests

# Files written from reportgen/taskspec.py and examples/: docs/task-format.md, the JSON Schema
# examples/task.schema.json and the package's copy of the examples (reportgen/examples/).
generated: venv
	$(PY) -m reportgen.taskdoc

# Every example's note pages (60 dpi) and sheet previews as PNG in one folder, for a human to look
# through (not part of CI): $(REVIEW_OUT)/<example>-page-NN.png, <example>-sheetN-….png; the builds
# themselves go to a fresh temporary folder that is removed afterwards.
REVIEW_OUT ?= review
REVIEW_DPI ?= 60
review: system venv
	@mkdir -p $(REVIEW_OUT); tmp=$$(mktemp -d); trap 'rm -rf "$$tmp"' EXIT; \
	for task in examples/*/task.toml; do \
	  ex=$$(basename $$(dirname $$task)); \
	  echo "== $$ex"; \
	  $(VENV)/bin/reportgen build $$task -o "$$tmp/$$ex" > "$$tmp/$$ex.log" 2>&1 \
	    || { echo "build of $$ex failed:"; tail -20 "$$tmp/$$ex.log"; continue; }; \
	  pdftoppm -png -r $(REVIEW_DPI) "$$tmp/$$ex/report.pdf" "$(REVIEW_OUT)/$$ex-page"; \
	  for png in "$$tmp/$$ex"/sheets/*.png; do cp "$$png" "$(REVIEW_OUT)/$$ex-$$(basename $$png)"; done; \
	done; \
	echo "look through $(REVIEW_OUT)/ ($$(ls $(REVIEW_OUT) | wc -l) images)"

bench: venv
	$(VENV)/bin/reportgen bench

clean:
	rm -rf $(VENV) $(DEMO_OUT) .pytest_cache .hypothesis .mypy_cache .ruff_cache
