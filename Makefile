# Quick start: `make book` builds the book into _build/html, `make test` runs every test.
# Both create .venv from requirements.txt on first use (needs only python3.11 and the package index):
# pip installs uv (pinned), uv installs the exact pins of requirements.txt and constraints.txt (about
# 10 s instead of pip's 2.5 minutes).
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: book pdf test test-unit test-notebooks notebooks system clean

$(STAMP): requirements.txt constraints.txt pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet uv==0.9.5
	$(BIN)/uv pip install --quiet --python $(BIN)/python -r requirements.txt
	touch $(STAMP)

# jupyter-cache keys each chapter on its code cells only, Sphinx on the notebook file; the key of the package's code (and pins)
# is kept beside them, and a change clears both (cache and doctrees), so every chapter re-runs after a change
# under src/handbook and none re-runs when nothing changed.
book: $(STAMP)
	@key=$$(cat $$(find src/handbook -name '*.py' | sort) requirements.txt constraints.txt | sha256sum | cut -c1-16); \
	if [ "$$(cat _build/.src-key 2>/dev/null)" != "$$key" ]; then rm -rf _build/.jupyter_cache _build/.doctrees; fi; \
	$(BIN)/jupyter-book build . -W -n --keep-going && echo "$$key" > _build/.src-key

# The book as one PDF (_build/pdf/handbook.pdf): the single-page HTML build of the committed outputs, printed by
# Debian's Chromium with the math typeset, a document outline and page numbers (tools/build_pdf.py).
pdf: $(STAMP) system
	$(BIN)/python tools/build_pdf.py

# Unit tests and notebooks in one pytest on both cores (pytest-xdist): every test is scheduled on its own,
# a notebook's cells (nbval, one kernel per notebook) stay together on one worker (conftest.py).
# The Python packages and Debian's packages install side by side. Python may write its bytecode caches
# during the run even where the environment sets PYTHONDONTWRITEBYTECODE (as CI's machines do): every
# kernel, worker and command the tests start would otherwise compile sympy, matplotlib and the rest
# from source again, about a minute of the run.
test:
	@$(MAKE) --no-print-directory -j2 $(STAMP) system
	env -u PYTHONDONTWRITEBYTECODE $(BIN)/python -m pytest -n 2 --dist loadscope tests book

test-unit: $(STAMP)
	$(BIN)/python -m pytest tests

test-notebooks: $(STAMP)
	$(BIN)/python -m pytest book

# The browser check (tests/test_browser.py) needs Debian's chromium and the SPICE checks Debian's ngspice;
# install them where the machine allows (root with apt-get), otherwise those checks report themselves
# skipped and say why. No browser or simulator is downloaded from anywhere else.
system:
	@missing=""; for p in chromium ngspice; do command -v $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then \
	    echo "installing Debian's$$missing"; \
	    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing) >/dev/null 2>&1 \
	      || echo "could not install$$missing: the checks that need it will be skipped"; \
	  else echo "missing$$missing, and apt-get is not available as root: the checks that need it will be skipped"; fi; \
	fi

# Re-execute every chapter in place after a change to src/handbook (nbval compares these outputs).
notebooks: $(STAMP)
	$(BIN)/python tools/run_notebooks.py
	$(BIN)/python tools/make_examples.py

clean:
	rm -rf _build $(VENV)
