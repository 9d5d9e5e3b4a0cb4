"""A block of lanes in one buffer (`numerics.lanes`): every quantity of every lane is a row of LANES floats.

Row r, lane l is element r·LANES + l of one flat array.  A loop over lanes then
reads and writes the array's start plus a constant plus the lane, and the
compiler can prove that the rows it writes do not overlap the rows it reads:
it vectorises the loop for any number of lanes from 8 (one AVX-512
instruction).  With one array per quantity it could not prove it and checked
the overlaps at run time instead, checks that it only found worth making from
24 lanes on (seen in the LLVM code: 165 checks in the rates loop): a block of
fewer busy lanes ran lane by lane.

The generated lane stages (`numerics.dop853_steps`) and `numerics.lanes`
address the buffer by these rows: what the vectorised loops read and write.
The rest of the step control (scalar code: accepting a step, its next size)
reads it through (component, lane) views.  Every float of a lane is a row
here, so that a lane moves whole (`lanes._move`).
"""

from numerics.dop853_tables import N_STAGES

N_Y = 7  # the numerical slide's state: t, cos α, sin α, p, q, ξ, η (`numerics.engine`)
# The components the rates read: cos α, sin α, p, q (`engine.rates_in_sigma`; t, ξ and η are quadratures, their
# rates independent of them: tested).  A stage's input is computed for these only (`numerics.codegen`).
RATES_READ = range(1, 5)
LANES = 32  # lanes in a block (measured fastest from 32 to 64: `numerics.lanes`)

# The rates of stage s, component i: row ROW_K + s·N_Y + i, s = 0 … N_STAGES.  Block N_STAGES receives every
# evaluation of the rates (the next stage copies it into its own block); at a step's end it holds the rates at
# the new point, the next step's first stage.
ROW_K = 0
STAGE = N_Y * LANES  # from one stage's rates to the next's, in elements
NEWEST = N_STAGES  # the block the rates are written to
ROW_Y = ROW_K + (N_STAGES + 1) * N_Y  # the state at the step's start
ROW_Y_NEW = ROW_Y + N_Y  # the 8th-order solution at its end
ROW_Y_STAGE = ROW_Y_NEW + N_Y  # a stage's input
ROW_PAR = ROW_Y_STAGE + N_Y  # f, R, k, δ, ε, g
ROW_SIGMA = ROW_PAR + 6  # σ at the step's start
ROW_H = ROW_SIGMA + 1  # the step in σ
ROW_BASE = ROW_H + 1  # each component's error scale (`engine.slide_start`)
ROW_SPIN_SCALE, ROW_TOL = ROW_BASE + N_Y, ROW_BASE + N_Y + 1  # Ω's scale, the tolerance
ROW_NORM, ROW_SPIN = ROW_TOL + 1, ROW_TOL + 2  # the step's error over the tolerance, Ω's size for it
ROW_ERR = ROW_SPIN + 1  # the accepted steps' errors, summed (`engine.accept`)
ROW_SIGMA_END = ROW_ERR + N_Y  # σ at the slide's end
N_ROWS = ROW_SIGMA_END + 1
