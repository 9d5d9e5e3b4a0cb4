"""Our English translation of each French sentence of the paper that a claim quotes (n°2–n°11).

The appendix sets each translation, in italics, under the verbatim quotation (`paper.claim_blocks.quotation`).
Keys are the quotes exactly as the claims give them (`Claim.printed_tex`, from the transcription); the formulas
in $…$ are copied from the quote, the transcription's glyphs included (ĉ and U printed for δ and V stay as
printed: the translation sits beside the quote, and the claim's erratum says what is meant).

Conventions: glissement = sliding, roulement = rolling, pivotement = pivoting, frottement = friction,
force vive = vis viva, bille = ball, second membre = right-hand side, "on" = one, "nous" = we; n° as printed.
A word not in the French, added so that a quote standing alone reads, is in [brackets].
"""

TRANSLATIONS = {
    # n°2.  "nul" of a rotation rendered "zero" throughout (not "null").
    r"le pivotement est nul : il reste ensuite nul":
        r"the pivoting is zero: it remains zero thereafter",

    r"Il suffit donc d'étudier les quatre équations (4)":
        r"It therefore suffices to study the four equations (4)",

    # "digne d'attention": literally "worthy of attention"; kept literal rather than "remarkable".
    # "le glissement" here is the slip V of the contact point, paired with the rotation Ω: "sliding".
    r"Ces quatre équations (7) et (8) présentent une symétrie digne d'attention entre le glissement et la rotation":
        r"These four equations (7) and (8) exhibit a symmetry worthy of attention between the sliding and the rotation",

    # n°3.  "elle" is the magnitude V of the sliding velocity.
    r"elle s'annule au bout d'un temps fini, puis reste nulle":
        r"it vanishes after a finite time, and then remains zero",

    # The tail of the previous quote: translated identically ("puis" = "and then") so the two agree.
    r"puis reste nulle":
        r"and then remains zero",

    r"le mouvement parabolique du centre":
        r"the parabolic motion of the centre",

    # n°4.
    r"$\Omega$ a donc une direction fixe et s'annule au bout d'un temps fini":
        r"$\Omega$ therefore has a fixed direction and vanishes after a finite time",

    # n°5.  "admettrons" = "shall assume" (not "admit"); "assez petit pour que" = "small enough that".
    r"Nous admettrons que le coefficient $\delta$ est assez petit pour que $$(9) \quad \delta < fR.$$":
        r"We shall assume that the coefficient $\delta$ is small enough that $$(9) \quad \delta < fR.$$",

    # "le cas réel": real as opposed to the "Mathématiques pures" of the preceding sentence, so "real"
    # (not "actual"/"physical").  "billard ordinaire": "billard" is both the game and the table; chose
    # "ordinary billiards" (the game as commonly played).  "a une importance beaucoup plus petite que"
    # kept close to the French: "is of much smaller importance than".
    r"Nous n'envisagerons que le cas réel du billard ordinaire, dans lequel le frottement de roulement a une importance beaucoup plus petite que le frottement de glissement":
        r"We shall consider only the real case of ordinary billiards, in which rolling friction is of much smaller importance than sliding friction",

    # Conditional kept: "from the point of view of pure mathematics, there would be ..." (n°5 opening).
    r"il y aurait différents cas à distinguer suivant les grandeurs relatives des coefficients":
        r"there would be various cases to distinguish according to the relative magnitudes of the coefficients",

    # "hypothèse" = the assumption (9); rendered "hypothesis" as the project calls (9) a hypothesis.
    r"Dans cette hypothèse la discussion se simplifie comme il suit":
        r"Under this hypothesis the discussion simplifies as follows",

    # Truncated form of the eq9 quote; translated identically up to the cut.
    r"Nous admettrons que le coefficient $\delta$ est assez petit pour que":
        r"We shall assume that the coefficient $\delta$ is small enough that",

    # n°6.  "La première" = the first of the two equations just written; "[equation]" supplied in
    # brackets (scholarly convention for a word not in the original) since the quote stands alone.
    r"La première donne $\beta - \alpha = \frac{\pi}{2}$ ou $\frac{3\pi}{2}$":
        r"The first [equation] gives $\beta - \alpha = \frac{\pi}{2}$ or $\frac{3\pi}{2}$",

    # "supposé" = the motion supposed (hypothesised) at the start of n°6.
    r"Donc le mouvement supposé, glissement sans roulement, est impossible":
        r"Hence the supposed motion, sliding without rolling, is impossible",

    # n°7.  "encore" read as "again" (the same choice β − α = π/2 was made in n°6), not "still".
    # "pour que ... puisse être satisfaite" = "so that ... can be satisfied".
    r"Il faut prendre encore $(\beta - \alpha) = \frac{\pi}{2}$ pour que la seconde équation puisse être satisfaite":
        r"Again one must take $(\beta - \alpha) = \frac{\pi}{2}$ so that the second equation can be satisfied",

    # "bien inférieure" can mean "much lower" or "indeed lower".  Chose "indeed less than": Appell's
    # reason ("car δ/R est supposé inférieur à f (n° 5)") yields only f₁ < f, the condition the law of
    # static friction requires (f₁ ≤ f); "bien" confirms that the condition is met.
    r"valeur de $f_1$ qui est bien inférieure à $f$":
        r"a value of $f_1$ which is indeed less than $f$",

    r"Les équations (8) montrent alors que $\beta' = 0$":
        r"Equations (8) then show that $\beta' = 0$",

    # "est animé d'un mouvement" = "has a motion" / "moves with a motion".  "uniformément retardé" kept
    # as the classical term "uniformly retarded" (= uniformly decelerated).
    r"le centre est animé d'un mouvement rectiligne perpendiculaire à la direction de la rotation instantanée, uniformément retardé":
        r"the centre moves with a rectilinear motion perpendicular to the direction of the instantaneous rotation, uniformly retarded",

    r"uniformément retardé":
        r"uniformly retarded",

    # n°8.  OCR glyph: $\hat{c}$ is printed for δ (the hypothesis is (9), δ < fR).  Math kept verbatim;
    # "l'hypothèse" = "the hypothesis" (i.e. (9)).
    r"où le second membre est négatif à cause de l'hypothèse $\hat{c} < fR$":
        r"where the right-hand side is negative because of the hypothesis $\hat{c} < fR$",

    # "se détruisent" (literally "destroy each other") = "cancel each other".
    r"Dans cette relation les termes en $r$ se détruisent":
        r"In this relation the terms in $r$ cancel each other",

    # "essentiellement négatif" is the 19th-century idiom for "negative by its very form, whatever the
    # values"; "essentially" in English would suggest "roughly",
    # so chose "necessarily negative".
    r"Le second membre est essentiellement négatif":
        r"The right-hand side is necessarily negative",

    # Sentence fragment ("la force vive va constamment en diminuant, et cela dans toutes ...").
    r"et cela dans toutes les phases du mouvement":
        r"and this in every phase of the motion",

    # "essentiellement négatif": as above, "necessarily negative".
    r"Le coefficient du second membre est essentiellement négatif":
        r"The coefficient on the right-hand side is necessarily negative",

    r"en remarquant que $\beta'$ et $\alpha'$ sont de signes contraires":
        r"by noting that $\beta'$ and $\alpha'$ are of opposite signs",

    r"où le coefficient de $\cos(\beta - \alpha)$ est positif":
        r"where the coefficient of $\cos(\beta - \alpha)$ is positive",

    # "d'abord" = "initially" (at the start); "constamment" = "continually" (it never stops
    # increasing), not "at a constant rate".
    r"si l'angle $\beta - \alpha$ est d'abord positif et aigu, il augmente constamment":
        r"if the angle $\beta - \alpha$ is initially positive and acute, it increases continually",

    # "devient droit": the subject is the angle β − α, so "becomes a right angle".
    r"devient droit en un temps fini":
        r"becomes a right angle in a finite time",

    # Parse: "immédiatement après" is the adverb "immediately afterwards" and "Ω cesse d'être nul" the
    # main clause (the preceding words are "Si Ω s'annule avant V, à un instant t₀,"), not "immediately
    # after Ω ceases to be zero".  "cas particulier" = "particular case"; "n° 6" kept as printed.
    r"immédiatement après $\Omega$ cesse d'être nul, d'après le cas particulier du n° 6":
        r"immediately afterwards, $\Omega$ ceases to be zero, by the particular case of n° 6",

    # "s'arrête" = "stops" (comes to rest).
    r"jusqu'au moment où la bille s'arrête":
        r"until the moment when the ball stops",

    # OCR glyph: $U$ is printed for V (the bound V < V₀ − fgt derived just above).  Math kept verbatim.
    r"parce que $U < V_0 - fgt$":
        r"because $U < V_0 - fgt$",

    # n°10.  "en fonction de" = "as functions of".
    r"et l'on peut calculer $x$ et $y$ en fonction de $\theta$":
        r"and one can calculate $x$ and $y$ as functions of $\theta$",

    # "On a ainsi" = "one thus has", i.e. y − x and yx are now known (from y − x = A and x(x + A) = ...).
    r"On a ainsi $y - x$ et $yx$":
        r"One thus has $y - x$ and $yx$",

    r"si $a = c$":
        r"if $a = c$",

    # "En se plaçant au point de vue" (literally "placing oneself at the point of view") rendered
    # "From the ... point of view"; "une intégration immédiate" = an integration at once (by
    # quadratures), kept literal.  The comma before "si" is dropped as unidiomatic in English.
    r"En se plaçant au point de vue purement analytique, on a une intégration immédiate, si $a = c$":
        r"From the purely analytical point of view, one has an immediate integration if $a = c$",

    # n°11.
    r"où $\lambda$ peut être considéré comme une fonction connue de $\varphi$":
        r"where $\lambda$ may be regarded as a known function of $\varphi$",
}


def english(quote: str) -> str | None:
    """The translation of a quoted sentence, or None (a formula, or a quote not in `TRANSLATIONS`)."""
    return TRANSLATIONS.get(quote)
