# pgsym: set-up, book, tests, benchmarks. `make book` and `make test` are the two commands a new machine needs.
SHELL := /bin/bash
.DEFAULT_GOAL := help
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
INSTALLED := $(VENV)/.installed
MATHJAX := _mathjax/_static/mathjax/tex-chtml.js
BOOK_INDEX := _build/html/index.html

.PHONY: help venv mathjax system-deps book test lint lab bench clean

help:  ## list the targets
	@grep -E '^[a-z-]+:.*## ' $(MAKEFILE_LIST) | sed -E 's/:.*## /\t/' | expand -t 14

$(INSTALLED): requirements.txt pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet -r requirements.txt
	$(BIN)/python -m pip install --quiet --no-deps --editable .
	touch $@

venv: $(INSTALLED)  ## create .venv with pinned dependencies and pgsym installed (editable)

# MathJax comes from npm so math renders with no network; Sphinx serves it from _static/mathjax.
$(MATHJAX): package.json package-lock.json
	@command -v npm >/dev/null || { echo "npm is missing: install Node.js and npm (Debian: apt-get install nodejs npm)"; exit 1; }
	npm ci --no-audit --no-fund --loglevel=error
	rm -rf _mathjax && mkdir -p _mathjax/_static
	cp -r node_modules/mathjax/es5 _mathjax/_static/mathjax
	touch $@

mathjax: $(MATHJAX)  ## fetch MathJax 3 from npm

# Debian packages: chromium for the browser test, TeX for the PDF exercise sheets, pdftotext to read them back.
APT_PACKAGES := chromium texlive-latex-extra texlive-fonts-recommended tex-gyre latexmk lmodern poppler-utils
system-deps:  ## install Debian's chromium and TeX (when root), or say how
	@missing=""; \
	command -v chromium >/dev/null || missing="$$missing chromium"; \
	command -v pdflatex >/dev/null && command -v latexmk >/dev/null || missing="$$missing tex"; \
	command -v pdftotext >/dev/null || missing="$$missing poppler-utils"; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
	    echo "installing Debian packages for:$$missing"; \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $(APT_PACKAGES) >/dev/null; \
	  else \
	    echo "missing:$$missing. Run: sudo apt-get install $(APT_PACKAGES)"; exit 1; \
	  fi; \
	fi

book: $(INSTALLED) $(MATHJAX)  ## build the book with -W (warnings are errors) and print the path of index.html
	$(BIN)/jupyter-book build . -W -n --keep-going
	@echo "Book: $(CURDIR)/$(BOOK_INDEX)"

lint: $(INSTALLED)  ## ruff
	$(BIN)/ruff check .

test: book system-deps lint  ## everything: lint, unit/property/doctests, strict nbval, CLI, the built book in a real browser
	$(BIN)/python -m pytest

lab: $(INSTALLED)  ## open the chapters in JupyterLab from the same venv
	$(BIN)/jupyter lab book/

bench: $(INSTALLED)  ## run every benchmark in bench/ (one JSON line per case)
	@for b in bench/bench_*.py; do [ -e "$$b" ] || continue; $(BIN)/python "$$b" || exit 1; done

clean:  ## remove the build, MathJax copy and caches (keeps .venv)
	rm -rf _build _mathjax node_modules .pytest_cache .hypothesis
