# Two commands do all the set-up on a fresh machine with Python 3.11 and pip:
#   make run   — virtual environment, install, verify every claim, regenerate the appendix (and its PDF)
#   make test  — the same with the test extras, the whole test suite, the staleness check of paper/
#                and the PDF compiled with pdflatex, alone and in the host documents (Debian's TeX Live
#                and texlive-publishers, installed when missing)
#   make check — the fast subset of the tests, for the edit-test loop
PYTHON ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
# texlive-publishers: revtex4-2, the class of one of the host documents the appendix is compiled in.
TEX_PACKAGES := texlive-latex-base texlive-latex-recommended texlive-fonts-recommended texlive-publishers latexmk
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
HAVE_TEX := $(shell command -v pdflatex >/dev/null && kpsewhich revtex4-2.cls)
# The simulator's compiled code (numerics.compiled), shared by every test run and worker of this checkout.
export APPELL_NUMBA_CACHE := $(CURDIR)/build/numba

.PHONY: run test check tex clean

run: $(VENV)/.installed
	$(BIN)/appell verify
	$(BIN)/appell paper $(if $(HAVE_TEX),--pdf,)
	@echo "appendix: paper/main.tex (standalone), paper/appendix.tex with paper/appell-appendix.sty (for your paper)$(if $(HAVE_TEX), and paper/main.pdf,; no TeX Live (or no revtex4-2): make tex installs it)"

# The generated kernels first (numerics/kernels.py, dop853_steps.py: stale means the derivation
# changed and they were not regenerated), then the whole suite on every core; its `appell verify`
# run keeps the verification record in build/record, which paper --check then reuses (same
# source, same verdicts) instead of checking every claim a third time.  paper --check --pdf:
# regenerate into build/paper, fail if paper/ differs, then compile that copy (identical to
# paper/) with pdflatex, alone (main.tex) and in each host document (hosts/: article in one and
# two columns and with its defaults, amsart, revtex4-2, IEEEtran, mnras, book): any LaTeX error, undefined or multiply-defined label, overfull
# box or hyperref warning fails.  Last, every `$ appell` example of README.md is run and its shown
# output compared with what it prints, the numbers of tests it gives with what pytest collects, and
# its page counts with what pdflatex wrote in build/paper (paper/readme.py): the README cannot drift from the code.
test: $(VENV)/.installed-test tex
	$(BIN)/python -m numerics.codegen --check
	APPELL_TEST_RECORD=$(CURDIR)/build/record $(BIN)/python -m pytest -n $(JOBS)
	APPELL_CACHE=$(CURDIR)/build/record $(BIN)/appell paper --check --pdf --out build/paper
	APPELL_CACHE=$(CURDIR)/build/record $(BIN)/python -m paper.readme --check

# The fast subset for the edit-test loop: everything but the tests marked slow (about a minute on two cores).
check: $(VENV)/.installed-test
	$(BIN)/python -m pytest -n $(JOBS) -m "not slow"

tex:
	@{ command -v pdflatex >/dev/null && kpsewhich revtex4-2.cls >/dev/null; } || { echo "installing TeX Live from Debian: $(TEX_PACKAGES)"; \
	  $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $(TEX_PACKAGES); }

$(VENV)/.installed: pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --editable .
	touch $@

$(VENV)/.installed-test: pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --editable '.[test]'
	touch $@ $(VENV)/.installed

clean:
	rm -rf $(VENV) build *.egg-info
