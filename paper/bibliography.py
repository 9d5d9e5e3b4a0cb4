"""The appendix's own references, cited where they are used.

A physicist's host paper has its own bibliography (thebibliography, BibTeX,
biblatex, revtex's \\bibsection); a second `thebibliography` would number its
entries [1], [2] … again beside the host's and open a section at the host's
top level.  So the appendix carries a list of its own: entries [A1], [A2] …,
each with a label ``appell:bib:<key>`` that `cite` refers to
(`\\appellcite`, defined in appell-appendix.sty).
"""

from __future__ import annotations

from paper.latex_text import plain_text

# key -> the reference, in the order they are listed (LaTeX; accents written as LaTeX; an author's initials tied to
# the surname, so that a line never breaks between them).  mpmath's version is the pinned one (tested).
REFERENCES = {
    "appell1911": r"P.~Appell, \emph{Sur le mouvement d'une bille de billard avec frottement de roulement}, "
    r"J.~Math. Pures Appl. (6) \textbf{7} (1911) 85--96, \url{http://www.numdam.org/item?id=JMPA_1911_6_7__85_0}.",
    "appell1889": r"P.~Appell, \emph{Sur les invariants de quelques \'equations diff\'erentielles}, "
    r"J.~Math. Pures Appl. (4) \textbf{5} (1889) 361--423.",
    "liouville1902": r"R.~Liouville, \emph{Sur une \'equation diff\'erentielle du premier ordre}, "
    r"Acta Math. \textbf{26} (1902) 55--78.",
    "appell1880": r"P.~Appell, \emph{Sur les s\'eries hyperg\'eom\'etriques de deux variables et sur des \'equations "
    r"diff\'erentielles lin\'eaires aux d\'eriv\'ees partielles}, C.~R. Acad. Sci. Paris \textbf{90} (1880) 296--298.",
    "chebterrab2000": r"E.~S.~Cheb-Terrab and A.~D.~Roche, \emph{Abel ODEs: equivalence and integrable classes}, "
    r"Comput. Phys. Commun. \textbf{130} (2000) 204--231.",
    "kane1985": r"T.~R.~Kane and D.~A.~Levinson, \emph{Dynamics: Theory and Applications}, McGraw-Hill, New York, 1985.",
    "hairer1993": r"E.~Hairer, S.~P.~N{\o}rsett and G.~Wanner, \emph{Solving Ordinary Differential Equations~I: "
    r"Nonstiff Problems}, 2nd ed., Springer, Berlin, 1993.",
    "jorba2005": r"\`A.~Jorba and M.~Zou, \emph{A software package for the numerical integration of ODEs by means of "
    r"high-order Taylor methods}, Experiment. Math. \textbf{14} (2005) 99--117.",
    "sympy2017": r"A.~Meurer et al., \emph{SymPy: symbolic computing in Python}, PeerJ Comput. Sci. \textbf{3} (2017) e103.",
    "mpmath": r"The mpmath development team, \emph{mpmath: a Python library for arbitrary-precision floating-point "
    r"arithmetic} (version 1.3.0), 2023, \url{https://mpmath.org}.",
    "numpy2020": r"C.~R.~Harris et al., \emph{Array programming with NumPy}, Nature \textbf{585} (2020) 357--362.",
    "matplotlib2007": r"J.~D.~Hunter, \emph{Matplotlib: a 2D graphics environment}, Comput. Sci. Eng. \textbf{9} (2007) 90--95.",
    # The peers of the work-precision figure, and the compiler of the package's own engine.
    "scipy2020": r"P.~Virtanen et al., \emph{SciPy~1.0: fundamental algorithms for scientific computing in Python}, "
    r"Nat. Methods \textbf{17} (2020) 261--272.",
    "petzold1983": r"L.~Petzold, \emph{Automatic selection of methods for solving stiff and nonstiff systems of ordinary "
    r"differential equations}, SIAM J. Sci. Stat. Comput. \textbf{4} (1983) 136--148.",
    "biscani2021": r"F.~Biscani and D.~Izzo, \emph{Revisiting high-order Taylor methods for astrodynamics and celestial "
    r"mechanics}, Mon. Not. R. Astron. Soc. \textbf{504} (2021) 2614--2628.",
    "lam2015": r"S.~K.~Lam, A.~Pitrou and S.~Seibert, \emph{Numba: a LLVM-based Python JIT compiler}, in: Proc. Second "
    r"Workshop on the LLVM Compiler Infrastructure in HPC, ACM, New York, 2015, 1--6.",
}


def cite(*keys: str) -> str:
    """A citation of the appendix's references: [A1], or [A1], [A3]."""
    unknown = [key for key in keys if key not in REFERENCES]
    if unknown:
        raise KeyError(f"no reference {unknown[0]!r} in the appendix's bibliography")
    return ", ".join(rf"\appellcite{{{key}}}" for key in keys)


def references_tex(heading) -> str:
    """The reference list, under ``heading`` (a function of the title and the label's name)."""
    items = [rf"\item\label{{appell:bib:{key}}} {text}" for key, text in REFERENCES.items()]
    return heading(plain_text("References of this appendix"), "references") + (
        "\\begin{appellreferences}\n" + "\n".join(items) + "\n\\end{appellreferences}\n"
    )
