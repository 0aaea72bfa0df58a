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

.PHONY: demo test system venv bench clean

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

venv: $(VENV)/.installed

# The example note and sheets of the press mechanism.
demo: system venv
	$(VENV)/bin/reportgen build examples/press/task.toml -o $(DEMO_OUT)
	@echo "open $(DEMO_OUT)/report.pdf and $(DEMO_OUT)/sheets/*.dxf (previews: *.png)"

# The whole test suite (what CI runs).
test: system venv
	$(PY) -m pytest -n 2 -p no:cacheprovider tests

bench: venv
	$(VENV)/bin/reportgen bench

clean:
	rm -rf $(VENV) $(DEMO_OUT) .pytest_cache .hypothesis
