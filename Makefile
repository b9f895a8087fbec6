# pgsym: set-up, book, tests, benchmarks. `make book` and `make test` are the two commands a new machine needs.
SHELL := /bin/bash
.DEFAULT_GOAL := help
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
INSTALLED := $(VENV)/.installed
MATHJAX := _mathjax/_static/mathjax/tex-chtml.js
NODE_MODULES := node_modules/.installed
LIVE := _live/_static/live
LIVE_BUILT := $(LIVE)/.built
BOOK_INDEX := _build/html/index.html
BOOK_PDF := _build/latex/book.pdf

.PHONY: help venv mathjax live system-deps book pdf test lint lab bench clean

help:  ## list the targets
	@grep -E '^[a-z-]+:.*## ' $(MAKEFILE_LIST) | sed -E 's/:.*## /\t/' | expand -t 14

$(INSTALLED): requirements.txt pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet -r requirements.txt
	$(BIN)/python -m pip install --quiet --no-deps --editable .
	touch $@

venv: $(INSTALLED)  ## create .venv with pinned dependencies and pgsym installed (editable)

$(NODE_MODULES): package.json package-lock.json
	@command -v npm >/dev/null || { echo "npm is missing: install Node.js and npm (Debian: apt-get install nodejs npm)"; exit 1; }
	npm ci --no-audit --no-fund --loglevel=error
	touch $@

# MathJax comes from npm so math renders with no network; Sphinx serves it from _static/mathjax.
$(MATHJAX): $(NODE_MODULES)
	rm -rf _mathjax && mkdir -p _mathjax/_static
	cp -r node_modules/mathjax/es5 _mathjax/_static/mathjax
	touch $@

mathjax: $(MATHJAX)  ## fetch MathJax 3 from npm

# Live cells (book/_ext/live_cells.py): Pyodide's files from npm, the CodeMirror editor bundled by
# esbuild, the pure-Python wheels the page installs (pgsym from this checkout, SymPy and mpmath at
# the versions of .venv), and a memory snapshot of Pyodide with SymPy and pgsym imported, made by Node
# (book/_ext/live/snapshot.mjs), from which the page starts Python in about a second instead of many;
# the extension copies them to _static/live of the book. No CDN is involved.
PYODIDE_FILES := pyodide.mjs pyodide.asm.mjs pyodide.asm.wasm python_stdlib.zip pyodide-lock.json
LIVE_SOURCES := $(wildcard book/_ext/live/*)
PGSYM_SOURCES := $(shell find pgsym -name '*.py' -not -path '*/__pycache__/*')
$(LIVE_BUILT): $(NODE_MODULES) $(INSTALLED) $(LIVE_SOURCES) $(PGSYM_SOURCES) pyproject.toml
	rm -rf _live && mkdir -p $(LIVE)/pyodide $(LIVE)/wheels
	cp $(addprefix node_modules/pyodide/,$(PYODIDE_FILES)) $(LIVE)/pyodide/
	cp book/_ext/live/live-cells.js book/_ext/live/live-cells.css book/_ext/live/worker.js \
	   book/_ext/live/live_kernel.py $(LIVE)/
	node_modules/.bin/esbuild book/_ext/live/editor.mjs --bundle --format=esm --minify --legal-comments=none \
	   --log-level=warning --outfile=$(LIVE)/editor.js
	$(BIN)/python -m pip wheel --quiet --no-deps --wheel-dir $(LIVE)/wheels .
	$(BIN)/python -m pip download --quiet --no-deps --only-binary=:all: --dest $(LIVE)/wheels \
	   $$($(BIN)/python -c "from importlib.metadata import version as v; print(f'sympy=={v(\"sympy\")} mpmath=={v(\"mpmath\")}')")
	cd $(LIVE)/wheels && ls *.whl | $(CURDIR)/$(BIN)/python -c "import json, sys; print(json.dumps({'wheels': sys.stdin.read().split()}))" > manifest.json
	node book/_ext/live/snapshot.mjs $(LIVE)
	touch $@
	@echo "Live cells add $$(du -sb _live | cut -f1 | awk '{printf "%.1f MB", $$1 / 1e6}') to the book (Pyodide, its snapshot, wheels, editor)"

live: $(LIVE_BUILT)  ## build the live cells' assets (Pyodide, wheels, editor bundle)

# Debian packages: chromium for the browser test, TeX for the PDF exercise sheets, pdftotext to read them back.
# The sheets are typeset by LuaLaTeX with the Noto fonts, so every script prints (Latin, Greek, Cyrillic,
# CJK, Arabic, Hebrew, Devanagari, Thai, Bengali, Tamil, Ethiopic, Khmer, ...: fonts-noto-core and
# fonts-noto-cjk) and emoji print in colour (fonts-noto-color-emoji, through luaotfload's HarfBuzz mode);
# poppler-utils cuts the class PDF into one PDF per student.
# Maxima runs the potential response trees of the STACK export in the tests (the CAS behind Moodle's STACK).
APT_PACKAGES := chromium texlive-latex-extra texlive-fonts-recommended tex-gyre latexmk lmodern poppler-utils \
                texlive-luatex fonts-noto-core fonts-noto-cjk fonts-noto-color-emoji maxima
system-deps:  ## install Debian's chromium, TeX, fonts and Maxima (when root), or say how
	@missing=""; \
	command -v chromium >/dev/null || missing="$$missing chromium"; \
	command -v pdflatex >/dev/null && command -v latexmk >/dev/null || missing="$$missing tex"; \
	kpsewhich unicode-math.sty latinmodern-math.otf >/dev/null || missing="$$missing unicode-math"; \
	fc-list | grep -q 'DejaVu Sans Mono' || missing="$$missing fonts-dejavu-core"; \
	command -v lualatex >/dev/null && kpsewhich luaotfload.sty >/dev/null || missing="$$missing texlive-luatex"; \
	fc-list | grep -q 'Noto Serif CJK SC' || missing="$$missing fonts-noto-cjk"; \
	fc-list | grep -q 'Noto Naskh Arabic' || missing="$$missing fonts-noto-core"; \
	fc-list | grep -q 'Noto Sans Khmer' || missing="$$missing fonts-noto-core"; \
	fc-list | grep -q 'Noto Color Emoji' || missing="$$missing fonts-noto-color-emoji"; \
	command -v pdftotext >/dev/null && command -v pdfseparate >/dev/null && command -v pdfunite >/dev/null \
	  || missing="$$missing poppler-utils"; \
	command -v maxima >/dev/null || missing="$$missing maxima"; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
	    echo "installing Debian packages for:$$missing"; \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $(APT_PACKAGES) >/dev/null; \
	  else \
	    echo "missing:$$missing. Run: sudo apt-get install $(APT_PACKAGES)"; exit 1; \
	  fi; \
	fi

book: $(INSTALLED) $(MATHJAX) $(LIVE_BUILT)  ## build the book with -W (warnings are errors) and print the path of index.html
	$(BIN)/jupyter-book build . -W -n --keep-going
	@echo "Book: $(CURDIR)/$(BOOK_INDEX)"

# The PDF of the book is typeset by LuaLaTeX as well: its code in DejaVu Sans Mono (fonts-dejavu-core), its
# formulas with unicode-math in Latin Modern Math (lmodern, texlive-latex-extra); system-deps checks them.
APT_PACKAGES += fonts-dejavu-core

# The PDF of the whole book: Sphinx's LaTeX builder, then LuaLaTeX through latexmk (the latex: section of
# _config.yml). An existing venv is used as it is (never reinstalled); `make venv` runs only when there is none.
pdf: system-deps  ## build the PDF of the whole book with LuaLaTeX and print its path
	@test -x $(BIN)/jupyter-book || $(MAKE) venv
	$(BIN)/jupyter-book build . --builder pdflatex -W -n --keep-going
	@test -s $(BOOK_PDF) && echo "PDF: $(CURDIR)/$(BOOK_PDF)"

lint: $(INSTALLED)  ## ruff
	$(BIN)/ruff check .

# The tests run on every core (PYTEST_WORKERS=1 runs them in one process); the files stay whole on one
# worker, so a module's fixtures (a built PDF, a browser) are made once. tests/test_book_pdf.py runs
# `make pdf` itself, on one worker, while the other workers go on with the rest.
PYTEST_WORKERS ?= auto
test: book system-deps lint  ## everything: lint, unit/property/doctests, strict nbval, CLI, the built book in a real browser and as PDF
	$(BIN)/python -m pytest -n $(PYTEST_WORKERS) --dist loadfile

lab: $(INSTALLED)  ## open the chapters in JupyterLab from the same venv (one chapter: make lab NB=harris)
	$(BIN)/jupyter lab $(if $(NB),book/$(NB).ipynb,book/)

bench: book  ## run every benchmark in bench/ (one JSON line per case; bench_live.py needs the built book)
	@for b in bench/bench_*.py; do [ -e "$$b" ] || continue; $(BIN)/python "$$b" || exit 1; done

clean:  ## remove the build, MathJax and live-cell copies and caches (keeps .venv)
	rm -rf _build _mathjax _live node_modules .pytest_cache .hypothesis
