"""The appendix in other people's documents: its style file, the hosts, and what fails a compilation."""

import re
import shutil
import subprocess

import pytest

from paper import latex_hosts

needs_pdflatex = pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex: make tex installs it (make test does)")


def _pdflatex(tmp_path, documentclass: str, body: str, preamble: str = "") -> str:
    """What pdflatex prints for ``body`` in a document of ``documentclass`` with the style file, then ``preamble``
    (it must compile)."""
    (tmp_path / latex_hosts.STY).write_text(latex_hosts.sty())
    (tmp_path / "t.tex").write_text(rf"{documentclass}\usepackage{{appell-appendix}}{preamble}\begin{{document}}{body}\end{{document}}")
    run = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "t.tex"], cwd=tmp_path,
                         capture_output=True, text=True, check=False)
    assert run.returncode == 0, run.stdout[-500:]
    return run.stdout


def test_the_style_file_loads_what_the_appendix_needs_and_lets_the_host_set_the_levels():
    sty = latex_hosts.sty()
    for package in ("amsmath", "amssymb", "graphicx", "url"):
        assert f"\\RequirePackage{{{package}}}" in sty
    assert "longtable" not in sty
    assert r"\providecommand{\appellsection}{\section}" in sty and r"\providecommand{\appellsubsection}{\subsection}" in sty
    assert r"\providecommand{\appellroot}{.}" in sty


def test_each_host_loads_the_style_file_and_inputs_the_appendix_as_a_paper_would():
    files = latex_hosts.files()
    assert set(files) == {latex_hosts.STY} | {f"hosts/{name}.tex" for name in latex_hosts.HOSTS}
    for name in latex_hosts.HOSTS:
        tex = files[f"hosts/{name}.tex"]
        assert r"\usepackage{appell-appendix}" in tex and r"\input{\appellroot/appendix}" in tex
        opens = r"\appendices" if name == "ieeetran" else r"\appendix"
        assert tex.index(opens + "\n") < tex.index(r"\input{\appellroot/appendix}")
        # the host's own citation, bibliography, numbered equation and figure beside the appendix's (a clash of
        # counters or labels would show in the compiled host)
        assert r"\cite{host}" in tex and r"\begin{thebibliography}" in tex and r"\label{eq:host}" in tex
        assert r"\label{fig:host}" in tex and tex.index(r"\input{\appellroot/appendix}") < tex.index(r"\begin{thebibliography}")
    assert "twocolumn" in files["hosts/article-twocolumn.tex"] and "babel" in files["hosts/article-twocolumn.tex"]
    assert r"\documentclass{mnras}" in files["hosts/mnras.tex"].splitlines()  # its figures read no placement option
    assert "reprint" in files["hosts/revtex-reprint.tex"]
    # the class's defaults, nothing loaded (10 pt on letter paper overfilled a line 11 pt on a4 did not); IEEEtran
    # drops the appendix's title under \appendix: \appendices
    assert r"\documentclass{article}" in files["hosts/article-default.tex"].splitlines()
    assert r"\appendices" in files["hosts/ieeetran.tex"].splitlines()
    book = files["hosts/book-chapter.tex"].splitlines()  # a thesis: the headings set before the style file
    assert book.index(r"\newcommand{\appellsection}{\chapter}") < book.index(r"\usepackage{appell-appendix}")
    sty = files[latex_hosts.STY]
    assert r"\DeclareRobustCommand{\appellno}" in sty and r"\providecommand{\appellsectionmark}[1]{}" in sty
    assert r"\providecommand{\appelltag}[1]{\tag{#1}}" in sty  # Appell's (1)-(14), a host may make them (A1)...
    assert r"\def\@currentlabel{\texttt{#1}}" in sty and r"\hskip .5em plus 1em\relax" in sty  # \ref gives eq10; a line can stretch


@pytest.mark.slow  # pdflatex, five small documents
@needs_pdflatex
def test_the_line_a_display_stands_on_picks_its_wide_or_its_narrow_layout(tmp_path):
    """\\appellwideornarrow{wide}{narrow} (`paper.claim_blocks.fitted`): the wide one on a one-column page at 10, 11
    and 12 pt, the narrow one in a column of two, or indented (a quotation); only one of them is typeset (an
    unprotected dimension once let TeX expand past it and both were, their labels defined twice)."""
    for options, inside, expected in (("", "", "WIDE"), ("11pt", "", "WIDE"), ("12pt", "", "WIDE"), ("twocolumn", "", "NARROW"),
                                      ("", "quotation", "NARROW")):
        fit = r"\appellwideornarrow{\typeout{picked WIDE}}{\typeout{picked NARROW}}"
        body = rf"\begin{{{inside}}}{fit}\end{{{inside}}}" if inside else fit
        printed = _pdflatex(tmp_path, rf"\documentclass[{options}]{{article}}", "x" + body)
        assert re.findall(r"picked (\w+)", printed) == [expected], (options, inside)


@pytest.mark.slow  # pdflatex, two small documents
@needs_pdflatex
def test_an_identifiers_underscore_is_a_glyph_that_copies_as_one(tmp_path):
    """A referee copied "n8.V decreases" out of the PDF: LaTeX's \\_ is a rule in OT1 (a space to a PDF reader).
    \\appellus is the typewriter font's glyph 95, the underscore, in OT1 and in T1, in a bold heading too."""
    (tmp_path / latex_hosts.STY).write_text(latex_hosts.sty())
    for preamble, font in (("", "OT1/cmtt"), (r"\usepackage[T1]{fontenc}", "T1/cmtt")):
        (tmp_path / "t.tex").write_text(
            rf"\documentclass{{article}}{preamble}\usepackage{{appell-appendix}}\begin{{document}}"
            r"\showboxdepth=9 \showboxbreadth=99 \setbox0\hbox{\textbf{x\appellus}\texttt{y\appellus}}\showbox0 \end{document}")
        subprocess.run(["pdflatex", "-interaction=nonstopmode", "t.tex"], cwd=tmp_path, capture_output=True, check=False)
        box = (tmp_path / "t.log").read_text().split("> \\box0=")[1].split("! OK")[0]
        assert box.count(f"\\{font}/m/n/10 _") == 2 and "rule" not in box, box


@pytest.mark.slow  # pdflatex, two small documents
@needs_pdflatex
def test_a_term_of_a_list_starts_at_the_margin_not_in_it(tmp_path):
    """The table of symbols and the hard cases (appellnotation): a label stood \\labelsep (5 pt) left of the text's
    margin, into the gutter of a two-column page.  Positions as pdfTeX saves them, at shipout."""
    where = lambda name: rf"\pdfsavepos\write16{{{name}=\the\pdflastxpos}}"  # noqa: E731
    # The references too (appellreferences), in revtex4-2, whose lists indent by \\leftskip, which \\raggedright reset:
    # [A1] stood a label's width out, over the left column's text (a referee).  Two columns of filler after the list
    # keep it in the first column with the margin measured (revtex balances a short last page).
    for cls, options, env, item in (("article", "", "appellnotation", r"\item[LABEL$R$]"),
                                    ("article", "twocolumn", "appellnotation", r"\item[LABEL$R$]"),
                                    ("revtex4-2", "reprint", "appellreferences", r"\item[{LABEL[A1]}]")):
        body = (rf"\noindent{where('MARGIN')}x\par\begin{{{env}}}{item.replace('LABEL', where('LABEL'))} radius of the ball"
                rf"\end{{{env}}}" + r"filler text\par " * 200)
        x = dict(re.findall(r"(MARGIN|LABEL)=(\d+)", _pdflatex(tmp_path, rf"\documentclass[{options}]{{{cls}}}", body)))
        # At the margin; a reference's [A1] set flush right in the width of [A10], a digit's width in.
        assert 0 <= int(x["LABEL"]) - int(x["MARGIN"]) < 8 * 65536, (cls, options, x)


@needs_pdflatex
def test_a_long_term_of_a_list_breaks_in_a_narrow_column(tmp_path):
    """The hard case "draw near the straight line, delta tiny" was set in a label's box, which cannot break, and
    overfilled an 11 pt column (an audit of hosts): the term is set in the line."""
    term = r"\item[\texttt{draw near the straight line, delta tiny}] a draw whose spin passes near zero."
    out = _pdflatex(tmp_path, r"\documentclass[11pt,a4paper,twocolumn]{article}", rf"\begin{{appellnotation}}{term}\end{{appellnotation}}")
    assert "Overfull" not in out


@needs_pdflatex
def test_a_figure_is_no_taller_than_half_the_page_and_the_root_may_follow_the_style_file(tmp_path):
    """A figure with its caption was taller than a 12 pt page (an audit of hosts): \appellfigure keeps the width it
    is given and at most half the text's height.  \appellroot named after the style file (which provides a default)
    is no "already defined" error."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    for name, size in (("tall", (2, 8)), ("square", (3, 3))):
        fig = plt.figure(figsize=size)
        fig.savefig(tmp_path / f"{name}.pdf")
        plt.close(fig)
    measure = "".join(rf"\sbox0{{\appellfigure{{\appellroot/{name}.pdf}}{{3.6in}}}}\immediate\write16{{{name}=\the\ht0,\the\wd0}}"
                      for name in ("tall", "square"))
    out = _pdflatex(tmp_path, r"\documentclass[12pt]{article}", measure + r"\immediate\write16{TEXT=\the\textheight}",
                    preamble=r"\newcommand{\appellroot}{.}")
    sizes = {k: [float(x) for x in v.split("pt,")] for k, v in re.findall(r"(tall|square)=([0-9.]+pt,[0-9.]+)pt", out)}
    text_height = float(re.search(r"TEXT=([0-9.]+)pt", out).group(1))
    assert sizes["tall"][0] <= text_height / 2 + 0.01 and sizes["tall"][1] < 3.6 * 72.27 / 2  # its aspect kept
    assert abs(sizes["square"][1] - 3.6 * 72.27) < 0.1  # within both bounds: as wide as asked (to keepaspectratio's rounding)


def _pages_of(tmp_path, body: str) -> dict[str, int]:
    """The page each \\write16{NAME=\\thepage} of ``body`` was shipped out on (article, one column)."""
    return {name: int(page) for name, page in re.findall(r"(\w+)=(\d+)", _pdflatex(tmp_path, r"\documentclass{article}", body))}


@needs_pdflatex
def test_a_claim_does_not_start_in_the_last_lines_of_a_page(tmp_path):
    """A referee found claims' identifiers and statements alone at the foot of a page, their forms on the next."""
    fill = r"\noindent\rule{1pt}{\dimexpr\textheight-4\baselineskip}\par"
    claim = r"\appellclaim{eq3}\write16{CLAIM=\thepage}Statement.\par" + r"\appelllabel{Printed:}\[x\]" * 3  # longer than 4 lines
    assert _pages_of(tmp_path, fill + claim)["CLAIM"] == 2
    roomy = r"\noindent\rule{1pt}{\dimexpr\textheight-12\baselineskip}\par"  # room enough: it stays
    assert _pages_of(tmp_path, roomy + r"\appellclaim{eq3}\write16{CLAIM=\thepage}Statement.")["CLAIM"] == 1


@needs_pdflatex
def test_waiting_figures_are_set_before_what_follows_the_flush(tmp_path):
    """The simulated shots' figures floated in between two errata: \\appellflushfloats sets them first."""
    figure = r"\begin{figure}\rule{1pt}{0.8\textheight}\write16{FIGURE=\thepage}\caption{x}\end{figure}"
    body = r"\noindent\rule{1pt}{0.5\textheight}\par" + figure * 2 + r"\appellflushfloats After.\write16{AFTER=\thepage}"
    pages = _pages_of(tmp_path, body)
    assert pages["AFTER"] > pages["FIGURE"]


LOG = r"""
Overfull \hbox (2.59395pt too wide) detected at line 118
Overfull \vbox (12.0pt too high) has occurred while \output is active
LaTeX Warning: Reference `appell:eq:7' on page 3 undefined on input line 12.
LaTeX Warning: Label `appell:sec:n2' multiply defined.
Package hyperref Warning: Token not allowed in a PDF string (Unicode):
! Undefined control sequence.
Underfull \hbox (badness 10000) in paragraph at lines 3--4
Output written on main.pdf (37 pages, 12345 bytes).
"""


def test_every_kind_of_problem_is_read_from_the_log():
    problems = latex_hosts.problems_in(LOG)
    assert len(problems) == 6  # all but the underfull box (a matter of taste, not a defect)
    assert any("vbox" in p for p in problems) and any("multiply defined" in p for p in problems)
    assert latex_hosts.pages(LOG) == 37


def test_a_figure_that_never_reached_a_page_is_a_problem():
    log = "<../figures/shots.pdf, id=429, 505.89pt x 202.356pt>\n[21 <../figures/phases.pdf>]"
    assert latex_hosts.unplaced_figures(log, ("shots", "phases")) == ["figure shots never placed on a page"]


# One line of each kind pdflatex writes, each of which must fail a compilation (a mutation audit: the LOG above has no
# citation warning, no "There were ..." summary, no float too large and no error but an undefined control sequence,
# and dropping each from `PROBLEMS`, or reading only "! Undefined ..." errors, passed).
EACH_KIND = [
    "! LaTeX Error: File `natbib.sty' not found.",
    "! Missing $ inserted.",
    "LaTeX Warning: Citation `host' on page 1 undefined on input line 12.",
    "LaTeX Warning: There were undefined references.",
    "LaTeX Warning: There were multiply-defined labels.",
    "LaTeX Warning: Float too large for page by 12.0pt on input line 30.",
    # revtex4-2 loads natbib, whose warnings are its own (a revtex host citing nothing known compiled "clean").
    "Package natbib Warning: Citation `nosuch' on page 1 undefined on input line 5.",
    "Package natbib Warning: There were undefined citations.",
]


@pytest.mark.parametrize("line", EACH_KIND)
def test_each_kind_of_problem_is_read_alone(line):
    assert latex_hosts.problems_in(f"This is pdfTeX\n{line}\nOutput written on x.pdf (1 page).\n") == [line]
