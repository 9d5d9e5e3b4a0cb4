"""Dormand–Prince 8(5,3)'s linear combinations, unrolled from `numerics.dop853_tables` by `numerics.codegen`:
do not edit.

Every stage's input y + h Σ_j a_sj k_j (of the components the rates read:
`numerics.lane_rows.RATES_READ`), the 8th-order solution, the two
embedded error estimates and the dense output's rows, written out with only
the nonzero coefficients (exact: each float is the table's own), for state
vectors of length n: straight-line arithmetic that numba compiles to a few
instructions per component, where a loop over the table's zeros cost ten
times more.  The lanes' versions address a block of lanes by its rows
(`numerics.lane_rows`).
"""

from numerics.lane_rows import LANES, NEWEST, ROW_H, ROW_K, ROW_Y, ROW_Y_NEW, ROW_Y_STAGE, STAGE



def stage_1(y, K, h, out):
    """out = y + h Σ_j A[1, j] K[j], the input of stage 1: the components its rates read."""
    for i in range(1, 5):
        out[i] = y[i] + h * (0.05260015195876773 * K[0, i])


def stage_2(y, K, h, out):
    """out = y + h Σ_j A[2, j] K[j], the input of stage 2: the components its rates read."""
    for i in range(1, 5):
        out[i] = y[i] + h * (0.0197250569845379 * K[0, i] + 0.0591751709536137 * K[1, i])


def stage_3(y, K, h, out):
    """out = y + h Σ_j A[3, j] K[j], the input of stage 3: the components its rates read."""
    for i in range(1, 5):
        out[i] = y[i] + h * (0.02958758547680685 * K[0, i] + 0.08876275643042054 * K[2, i])


def stage_4(y, K, h, out):
    """out = y + h Σ_j A[4, j] K[j], the input of stage 4: the components its rates read."""
    for i in range(1, 5):
        out[i] = y[i] + h * (0.2413651341592667 * K[0, i] + -0.8845494793282861 * K[2, i] + 0.924834003261792 * K[3, i])


def stage_5(y, K, h, out):
    """out = y + h Σ_j A[5, j] K[j], the input of stage 5: the components its rates read."""
    for i in range(1, 5):
        out[i] = y[i] + h * (0.037037037037037035 * K[0, i] + 0.17082860872947386 * K[3, i] + 0.12546768756682242 * K[4, i])


def stage_6(y, K, h, out):
    """out = y + h Σ_j A[6, j] K[j], the input of stage 6: the components its rates read."""
    for i in range(1, 5):
        out[i] = y[i] + h * (0.037109375 * K[0, i] + 0.17025221101954405 * K[3, i] + 0.06021653898045596 * K[4, i] + -0.017578125 * K[5, i])


def stage_7(y, K, h, out):
    """out = y + h Σ_j A[7, j] K[j], the input of stage 7: the components its rates read."""
    for i in range(1, 5):
        out[i] = y[i] + h * (0.03709200011850479 * K[0, i] + 0.17038392571223998 * K[3, i] + 0.10726203044637328 * K[4, i] + -0.015319437748624402 * K[5, i] + 0.008273789163814023 * K[6, i])


def stage_8(y, K, h, out):
    """out = y + h Σ_j A[8, j] K[j], the input of stage 8: the components its rates read."""
    for i in range(1, 5):
        out[i] = y[i] + h * (0.6241109587160757 * K[0, i] + -3.3608926294469414 * K[3, i] + -0.868219346841726 * K[4, i] + 27.59209969944671 * K[5, i] + 20.154067550477894 * K[6, i] + -43.48988418106996 * K[7, i])


def stage_9(y, K, h, out):
    """out = y + h Σ_j A[9, j] K[j], the input of stage 9: the components its rates read."""
    for i in range(1, 5):
        out[i] = y[i] + h * (0.47766253643826434 * K[0, i] + -2.4881146199716677 * K[3, i] + -0.590290826836843 * K[4, i] + 21.230051448181193 * K[5, i] + 15.279233632882423 * K[6, i] + -33.28821096898486 * K[7, i] + -0.020331201708508627 * K[8, i])


def stage_10(y, K, h, out):
    """out = y + h Σ_j A[10, j] K[j], the input of stage 10: the components its rates read."""
    for i in range(1, 5):
        out[i] = y[i] + h * (-0.9371424300859873 * K[0, i] + 5.186372428844064 * K[3, i] + 1.0914373489967295 * K[4, i] + -8.149787010746927 * K[5, i] + -18.52006565999696 * K[6, i] + 22.739487099350505 * K[7, i] + 2.4936055526796523 * K[8, i] + -3.0467644718982196 * K[9, i])


def stage_11(y, K, h, out):
    """out = y + h Σ_j A[11, j] K[j], the input of stage 11: the components its rates read."""
    for i in range(1, 5):
        out[i] = y[i] + h * (2.273310147516538 * K[0, i] + -10.53449546673725 * K[3, i] + -2.0008720582248625 * K[4, i] + -17.9589318631188 * K[5, i] + 27.94888452941996 * K[6, i] + -2.8589982771350235 * K[7, i] + -8.87285693353063 * K[8, i] + 12.360567175794303 * K[9, i] + 0.6433927460157636 * K[10, i])


def stage_13(y, K, h, out):
    """out = y + h Σ_j A[13, j] K[j], the input of stage 13: the components its rates read."""
    for i in range(1, 5):
        out[i] = y[i] + h * (0.056167502283047954 * K[0, i] + 0.25350021021662483 * K[6, i] + -0.2462390374708025 * K[7, i] + -0.12419142326381637 * K[8, i] + 0.15329179827876568 * K[9, i] + 0.00820105229563469 * K[10, i] + 0.007567897660545699 * K[11, i] + -0.008298 * K[12, i])


def stage_14(y, K, h, out):
    """out = y + h Σ_j A[14, j] K[j], the input of stage 14: the components its rates read."""
    for i in range(1, 5):
        out[i] = y[i] + h * (0.03183464816350214 * K[0, i] + 0.028300909672366776 * K[5, i] + 0.053541988307438566 * K[6, i] + -0.05492374857139099 * K[7, i] + -0.00010834732869724932 * K[10, i] + 0.0003825710908356584 * K[11, i] + -0.00034046500868740456 * K[12, i] + 0.1413124436746325 * K[13, i])


def stage_15(y, K, h, out):
    """out = y + h Σ_j A[15, j] K[j], the input of stage 15: the components its rates read."""
    for i in range(1, 5):
        out[i] = y[i] + h * (-0.42889630158379194 * K[0, i] + -4.697621415361164 * K[5, i] + 7.683421196062599 * K[6, i] + 4.06898981839711 * K[7, i] + 0.3567271874552811 * K[8, i] + -0.0013990241651590145 * K[12, i] + 2.9475147891527724 * K[13, i] + -9.15095847217987 * K[14, i])


def lanes_stage_1(L, width):
    """Y_STAGE = Y + h Σ_j A[1, j] K[j], the input of stage 1 (the components its rates read), in lanes [0, width) of the block L (`numerics.lanes`)."""
    k, y, out = ROW_K * LANES, ROW_Y * LANES, ROW_Y_STAGE * LANES
    for l in range(width):
        h = L[ROW_H * LANES + l]
        L[out + 1 * LANES + l] = L[y + 1 * LANES + l] + h * (0.05260015195876773 * L[k + 1 * LANES + l])
        L[out + 2 * LANES + l] = L[y + 2 * LANES + l] + h * (0.05260015195876773 * L[k + 2 * LANES + l])
        L[out + 3 * LANES + l] = L[y + 3 * LANES + l] + h * (0.05260015195876773 * L[k + 3 * LANES + l])
        L[out + 4 * LANES + l] = L[y + 4 * LANES + l] + h * (0.05260015195876773 * L[k + 4 * LANES + l])


def lanes_stage_2(L, width):
    """Y_STAGE = Y + h Σ_j A[2, j] K[j], the input of stage 2 (the components its rates read), in lanes [0, width) of the block L (`numerics.lanes`)."""
    k, y, out = ROW_K * LANES, ROW_Y * LANES, ROW_Y_STAGE * LANES
    for l in range(width):
        h = L[ROW_H * LANES + l]
        newest_0 = L[k + NEWEST * STAGE + l]
        L[k + 1 * STAGE + l] = newest_0
        newest_1 = L[k + NEWEST * STAGE + 1 * LANES + l]
        L[k + 1 * STAGE + 1 * LANES + l] = newest_1
        L[out + 1 * LANES + l] = L[y + 1 * LANES + l] + h * (0.0197250569845379 * L[k + 1 * LANES + l] + 0.0591751709536137 * newest_1)
        newest_2 = L[k + NEWEST * STAGE + 2 * LANES + l]
        L[k + 1 * STAGE + 2 * LANES + l] = newest_2
        L[out + 2 * LANES + l] = L[y + 2 * LANES + l] + h * (0.0197250569845379 * L[k + 2 * LANES + l] + 0.0591751709536137 * newest_2)
        newest_3 = L[k + NEWEST * STAGE + 3 * LANES + l]
        L[k + 1 * STAGE + 3 * LANES + l] = newest_3
        L[out + 3 * LANES + l] = L[y + 3 * LANES + l] + h * (0.0197250569845379 * L[k + 3 * LANES + l] + 0.0591751709536137 * newest_3)
        newest_4 = L[k + NEWEST * STAGE + 4 * LANES + l]
        L[k + 1 * STAGE + 4 * LANES + l] = newest_4
        L[out + 4 * LANES + l] = L[y + 4 * LANES + l] + h * (0.0197250569845379 * L[k + 4 * LANES + l] + 0.0591751709536137 * newest_4)
        newest_5 = L[k + NEWEST * STAGE + 5 * LANES + l]
        L[k + 1 * STAGE + 5 * LANES + l] = newest_5
        newest_6 = L[k + NEWEST * STAGE + 6 * LANES + l]
        L[k + 1 * STAGE + 6 * LANES + l] = newest_6


def lanes_stage_3(L, width):
    """Y_STAGE = Y + h Σ_j A[3, j] K[j], the input of stage 3 (the components its rates read), in lanes [0, width) of the block L (`numerics.lanes`)."""
    k, y, out = ROW_K * LANES, ROW_Y * LANES, ROW_Y_STAGE * LANES
    for l in range(width):
        h = L[ROW_H * LANES + l]
        newest_0 = L[k + NEWEST * STAGE + l]
        L[k + 2 * STAGE + l] = newest_0
        newest_1 = L[k + NEWEST * STAGE + 1 * LANES + l]
        L[k + 2 * STAGE + 1 * LANES + l] = newest_1
        L[out + 1 * LANES + l] = L[y + 1 * LANES + l] + h * (0.02958758547680685 * L[k + 1 * LANES + l] + 0.08876275643042054 * newest_1)
        newest_2 = L[k + NEWEST * STAGE + 2 * LANES + l]
        L[k + 2 * STAGE + 2 * LANES + l] = newest_2
        L[out + 2 * LANES + l] = L[y + 2 * LANES + l] + h * (0.02958758547680685 * L[k + 2 * LANES + l] + 0.08876275643042054 * newest_2)
        newest_3 = L[k + NEWEST * STAGE + 3 * LANES + l]
        L[k + 2 * STAGE + 3 * LANES + l] = newest_3
        L[out + 3 * LANES + l] = L[y + 3 * LANES + l] + h * (0.02958758547680685 * L[k + 3 * LANES + l] + 0.08876275643042054 * newest_3)
        newest_4 = L[k + NEWEST * STAGE + 4 * LANES + l]
        L[k + 2 * STAGE + 4 * LANES + l] = newest_4
        L[out + 4 * LANES + l] = L[y + 4 * LANES + l] + h * (0.02958758547680685 * L[k + 4 * LANES + l] + 0.08876275643042054 * newest_4)
        newest_5 = L[k + NEWEST * STAGE + 5 * LANES + l]
        L[k + 2 * STAGE + 5 * LANES + l] = newest_5
        newest_6 = L[k + NEWEST * STAGE + 6 * LANES + l]
        L[k + 2 * STAGE + 6 * LANES + l] = newest_6


def lanes_stage_4(L, width):
    """Y_STAGE = Y + h Σ_j A[4, j] K[j], the input of stage 4 (the components its rates read), in lanes [0, width) of the block L (`numerics.lanes`)."""
    k, y, out = ROW_K * LANES, ROW_Y * LANES, ROW_Y_STAGE * LANES
    for l in range(width):
        h = L[ROW_H * LANES + l]
        newest_0 = L[k + NEWEST * STAGE + l]
        L[k + 3 * STAGE + l] = newest_0
        newest_1 = L[k + NEWEST * STAGE + 1 * LANES + l]
        L[k + 3 * STAGE + 1 * LANES + l] = newest_1
        L[out + 1 * LANES + l] = L[y + 1 * LANES + l] + h * (0.2413651341592667 * L[k + 1 * LANES + l] + -0.8845494793282861 * L[k + 2 * STAGE + 1 * LANES + l] + 0.924834003261792 * newest_1)
        newest_2 = L[k + NEWEST * STAGE + 2 * LANES + l]
        L[k + 3 * STAGE + 2 * LANES + l] = newest_2
        L[out + 2 * LANES + l] = L[y + 2 * LANES + l] + h * (0.2413651341592667 * L[k + 2 * LANES + l] + -0.8845494793282861 * L[k + 2 * STAGE + 2 * LANES + l] + 0.924834003261792 * newest_2)
        newest_3 = L[k + NEWEST * STAGE + 3 * LANES + l]
        L[k + 3 * STAGE + 3 * LANES + l] = newest_3
        L[out + 3 * LANES + l] = L[y + 3 * LANES + l] + h * (0.2413651341592667 * L[k + 3 * LANES + l] + -0.8845494793282861 * L[k + 2 * STAGE + 3 * LANES + l] + 0.924834003261792 * newest_3)
        newest_4 = L[k + NEWEST * STAGE + 4 * LANES + l]
        L[k + 3 * STAGE + 4 * LANES + l] = newest_4
        L[out + 4 * LANES + l] = L[y + 4 * LANES + l] + h * (0.2413651341592667 * L[k + 4 * LANES + l] + -0.8845494793282861 * L[k + 2 * STAGE + 4 * LANES + l] + 0.924834003261792 * newest_4)
        newest_5 = L[k + NEWEST * STAGE + 5 * LANES + l]
        L[k + 3 * STAGE + 5 * LANES + l] = newest_5
        newest_6 = L[k + NEWEST * STAGE + 6 * LANES + l]
        L[k + 3 * STAGE + 6 * LANES + l] = newest_6


def lanes_stage_5(L, width):
    """Y_STAGE = Y + h Σ_j A[5, j] K[j], the input of stage 5 (the components its rates read), in lanes [0, width) of the block L (`numerics.lanes`)."""
    k, y, out = ROW_K * LANES, ROW_Y * LANES, ROW_Y_STAGE * LANES
    for l in range(width):
        h = L[ROW_H * LANES + l]
        newest_0 = L[k + NEWEST * STAGE + l]
        L[k + 4 * STAGE + l] = newest_0
        newest_1 = L[k + NEWEST * STAGE + 1 * LANES + l]
        L[k + 4 * STAGE + 1 * LANES + l] = newest_1
        L[out + 1 * LANES + l] = L[y + 1 * LANES + l] + h * (0.037037037037037035 * L[k + 1 * LANES + l] + 0.17082860872947386 * L[k + 3 * STAGE + 1 * LANES + l] + 0.12546768756682242 * newest_1)
        newest_2 = L[k + NEWEST * STAGE + 2 * LANES + l]
        L[k + 4 * STAGE + 2 * LANES + l] = newest_2
        L[out + 2 * LANES + l] = L[y + 2 * LANES + l] + h * (0.037037037037037035 * L[k + 2 * LANES + l] + 0.17082860872947386 * L[k + 3 * STAGE + 2 * LANES + l] + 0.12546768756682242 * newest_2)
        newest_3 = L[k + NEWEST * STAGE + 3 * LANES + l]
        L[k + 4 * STAGE + 3 * LANES + l] = newest_3
        L[out + 3 * LANES + l] = L[y + 3 * LANES + l] + h * (0.037037037037037035 * L[k + 3 * LANES + l] + 0.17082860872947386 * L[k + 3 * STAGE + 3 * LANES + l] + 0.12546768756682242 * newest_3)
        newest_4 = L[k + NEWEST * STAGE + 4 * LANES + l]
        L[k + 4 * STAGE + 4 * LANES + l] = newest_4
        L[out + 4 * LANES + l] = L[y + 4 * LANES + l] + h * (0.037037037037037035 * L[k + 4 * LANES + l] + 0.17082860872947386 * L[k + 3 * STAGE + 4 * LANES + l] + 0.12546768756682242 * newest_4)
        newest_5 = L[k + NEWEST * STAGE + 5 * LANES + l]
        L[k + 4 * STAGE + 5 * LANES + l] = newest_5
        newest_6 = L[k + NEWEST * STAGE + 6 * LANES + l]
        L[k + 4 * STAGE + 6 * LANES + l] = newest_6


def lanes_stage_6(L, width):
    """Y_STAGE = Y + h Σ_j A[6, j] K[j], the input of stage 6 (the components its rates read), in lanes [0, width) of the block L (`numerics.lanes`)."""
    k, y, out = ROW_K * LANES, ROW_Y * LANES, ROW_Y_STAGE * LANES
    for l in range(width):
        h = L[ROW_H * LANES + l]
        newest_0 = L[k + NEWEST * STAGE + l]
        L[k + 5 * STAGE + l] = newest_0
        newest_1 = L[k + NEWEST * STAGE + 1 * LANES + l]
        L[k + 5 * STAGE + 1 * LANES + l] = newest_1
        L[out + 1 * LANES + l] = L[y + 1 * LANES + l] + h * (0.037109375 * L[k + 1 * LANES + l] + 0.17025221101954405 * L[k + 3 * STAGE + 1 * LANES + l] + 0.06021653898045596 * L[k + 4 * STAGE + 1 * LANES + l] + -0.017578125 * newest_1)
        newest_2 = L[k + NEWEST * STAGE + 2 * LANES + l]
        L[k + 5 * STAGE + 2 * LANES + l] = newest_2
        L[out + 2 * LANES + l] = L[y + 2 * LANES + l] + h * (0.037109375 * L[k + 2 * LANES + l] + 0.17025221101954405 * L[k + 3 * STAGE + 2 * LANES + l] + 0.06021653898045596 * L[k + 4 * STAGE + 2 * LANES + l] + -0.017578125 * newest_2)
        newest_3 = L[k + NEWEST * STAGE + 3 * LANES + l]
        L[k + 5 * STAGE + 3 * LANES + l] = newest_3
        L[out + 3 * LANES + l] = L[y + 3 * LANES + l] + h * (0.037109375 * L[k + 3 * LANES + l] + 0.17025221101954405 * L[k + 3 * STAGE + 3 * LANES + l] + 0.06021653898045596 * L[k + 4 * STAGE + 3 * LANES + l] + -0.017578125 * newest_3)
        newest_4 = L[k + NEWEST * STAGE + 4 * LANES + l]
        L[k + 5 * STAGE + 4 * LANES + l] = newest_4
        L[out + 4 * LANES + l] = L[y + 4 * LANES + l] + h * (0.037109375 * L[k + 4 * LANES + l] + 0.17025221101954405 * L[k + 3 * STAGE + 4 * LANES + l] + 0.06021653898045596 * L[k + 4 * STAGE + 4 * LANES + l] + -0.017578125 * newest_4)
        newest_5 = L[k + NEWEST * STAGE + 5 * LANES + l]
        L[k + 5 * STAGE + 5 * LANES + l] = newest_5
        newest_6 = L[k + NEWEST * STAGE + 6 * LANES + l]
        L[k + 5 * STAGE + 6 * LANES + l] = newest_6


def lanes_stage_7(L, width):
    """Y_STAGE = Y + h Σ_j A[7, j] K[j], the input of stage 7 (the components its rates read), in lanes [0, width) of the block L (`numerics.lanes`)."""
    k, y, out = ROW_K * LANES, ROW_Y * LANES, ROW_Y_STAGE * LANES
    for l in range(width):
        h = L[ROW_H * LANES + l]
        newest_0 = L[k + NEWEST * STAGE + l]
        L[k + 6 * STAGE + l] = newest_0
        newest_1 = L[k + NEWEST * STAGE + 1 * LANES + l]
        L[k + 6 * STAGE + 1 * LANES + l] = newest_1
        L[out + 1 * LANES + l] = L[y + 1 * LANES + l] + h * (0.03709200011850479 * L[k + 1 * LANES + l] + 0.17038392571223998 * L[k + 3 * STAGE + 1 * LANES + l] + 0.10726203044637328 * L[k + 4 * STAGE + 1 * LANES + l] + -0.015319437748624402 * L[k + 5 * STAGE + 1 * LANES + l] + 0.008273789163814023 * newest_1)
        newest_2 = L[k + NEWEST * STAGE + 2 * LANES + l]
        L[k + 6 * STAGE + 2 * LANES + l] = newest_2
        L[out + 2 * LANES + l] = L[y + 2 * LANES + l] + h * (0.03709200011850479 * L[k + 2 * LANES + l] + 0.17038392571223998 * L[k + 3 * STAGE + 2 * LANES + l] + 0.10726203044637328 * L[k + 4 * STAGE + 2 * LANES + l] + -0.015319437748624402 * L[k + 5 * STAGE + 2 * LANES + l] + 0.008273789163814023 * newest_2)
        newest_3 = L[k + NEWEST * STAGE + 3 * LANES + l]
        L[k + 6 * STAGE + 3 * LANES + l] = newest_3
        L[out + 3 * LANES + l] = L[y + 3 * LANES + l] + h * (0.03709200011850479 * L[k + 3 * LANES + l] + 0.17038392571223998 * L[k + 3 * STAGE + 3 * LANES + l] + 0.10726203044637328 * L[k + 4 * STAGE + 3 * LANES + l] + -0.015319437748624402 * L[k + 5 * STAGE + 3 * LANES + l] + 0.008273789163814023 * newest_3)
        newest_4 = L[k + NEWEST * STAGE + 4 * LANES + l]
        L[k + 6 * STAGE + 4 * LANES + l] = newest_4
        L[out + 4 * LANES + l] = L[y + 4 * LANES + l] + h * (0.03709200011850479 * L[k + 4 * LANES + l] + 0.17038392571223998 * L[k + 3 * STAGE + 4 * LANES + l] + 0.10726203044637328 * L[k + 4 * STAGE + 4 * LANES + l] + -0.015319437748624402 * L[k + 5 * STAGE + 4 * LANES + l] + 0.008273789163814023 * newest_4)
        newest_5 = L[k + NEWEST * STAGE + 5 * LANES + l]
        L[k + 6 * STAGE + 5 * LANES + l] = newest_5
        newest_6 = L[k + NEWEST * STAGE + 6 * LANES + l]
        L[k + 6 * STAGE + 6 * LANES + l] = newest_6


def lanes_stage_8(L, width):
    """Y_STAGE = Y + h Σ_j A[8, j] K[j], the input of stage 8 (the components its rates read), in lanes [0, width) of the block L (`numerics.lanes`)."""
    k, y, out = ROW_K * LANES, ROW_Y * LANES, ROW_Y_STAGE * LANES
    for l in range(width):
        h = L[ROW_H * LANES + l]
        newest_0 = L[k + NEWEST * STAGE + l]
        L[k + 7 * STAGE + l] = newest_0
        newest_1 = L[k + NEWEST * STAGE + 1 * LANES + l]
        L[k + 7 * STAGE + 1 * LANES + l] = newest_1
        L[out + 1 * LANES + l] = L[y + 1 * LANES + l] + h * (0.6241109587160757 * L[k + 1 * LANES + l] + -3.3608926294469414 * L[k + 3 * STAGE + 1 * LANES + l] + -0.868219346841726 * L[k + 4 * STAGE + 1 * LANES + l] + 27.59209969944671 * L[k + 5 * STAGE + 1 * LANES + l] + 20.154067550477894 * L[k + 6 * STAGE + 1 * LANES + l] + -43.48988418106996 * newest_1)
        newest_2 = L[k + NEWEST * STAGE + 2 * LANES + l]
        L[k + 7 * STAGE + 2 * LANES + l] = newest_2
        L[out + 2 * LANES + l] = L[y + 2 * LANES + l] + h * (0.6241109587160757 * L[k + 2 * LANES + l] + -3.3608926294469414 * L[k + 3 * STAGE + 2 * LANES + l] + -0.868219346841726 * L[k + 4 * STAGE + 2 * LANES + l] + 27.59209969944671 * L[k + 5 * STAGE + 2 * LANES + l] + 20.154067550477894 * L[k + 6 * STAGE + 2 * LANES + l] + -43.48988418106996 * newest_2)
        newest_3 = L[k + NEWEST * STAGE + 3 * LANES + l]
        L[k + 7 * STAGE + 3 * LANES + l] = newest_3
        L[out + 3 * LANES + l] = L[y + 3 * LANES + l] + h * (0.6241109587160757 * L[k + 3 * LANES + l] + -3.3608926294469414 * L[k + 3 * STAGE + 3 * LANES + l] + -0.868219346841726 * L[k + 4 * STAGE + 3 * LANES + l] + 27.59209969944671 * L[k + 5 * STAGE + 3 * LANES + l] + 20.154067550477894 * L[k + 6 * STAGE + 3 * LANES + l] + -43.48988418106996 * newest_3)
        newest_4 = L[k + NEWEST * STAGE + 4 * LANES + l]
        L[k + 7 * STAGE + 4 * LANES + l] = newest_4
        L[out + 4 * LANES + l] = L[y + 4 * LANES + l] + h * (0.6241109587160757 * L[k + 4 * LANES + l] + -3.3608926294469414 * L[k + 3 * STAGE + 4 * LANES + l] + -0.868219346841726 * L[k + 4 * STAGE + 4 * LANES + l] + 27.59209969944671 * L[k + 5 * STAGE + 4 * LANES + l] + 20.154067550477894 * L[k + 6 * STAGE + 4 * LANES + l] + -43.48988418106996 * newest_4)
        newest_5 = L[k + NEWEST * STAGE + 5 * LANES + l]
        L[k + 7 * STAGE + 5 * LANES + l] = newest_5
        newest_6 = L[k + NEWEST * STAGE + 6 * LANES + l]
        L[k + 7 * STAGE + 6 * LANES + l] = newest_6


def lanes_stage_9(L, width):
    """Y_STAGE = Y + h Σ_j A[9, j] K[j], the input of stage 9 (the components its rates read), in lanes [0, width) of the block L (`numerics.lanes`)."""
    k, y, out = ROW_K * LANES, ROW_Y * LANES, ROW_Y_STAGE * LANES
    for l in range(width):
        h = L[ROW_H * LANES + l]
        newest_0 = L[k + NEWEST * STAGE + l]
        L[k + 8 * STAGE + l] = newest_0
        newest_1 = L[k + NEWEST * STAGE + 1 * LANES + l]
        L[k + 8 * STAGE + 1 * LANES + l] = newest_1
        L[out + 1 * LANES + l] = L[y + 1 * LANES + l] + h * (0.47766253643826434 * L[k + 1 * LANES + l] + -2.4881146199716677 * L[k + 3 * STAGE + 1 * LANES + l] + -0.590290826836843 * L[k + 4 * STAGE + 1 * LANES + l] + 21.230051448181193 * L[k + 5 * STAGE + 1 * LANES + l] + 15.279233632882423 * L[k + 6 * STAGE + 1 * LANES + l] + -33.28821096898486 * L[k + 7 * STAGE + 1 * LANES + l] + -0.020331201708508627 * newest_1)
        newest_2 = L[k + NEWEST * STAGE + 2 * LANES + l]
        L[k + 8 * STAGE + 2 * LANES + l] = newest_2
        L[out + 2 * LANES + l] = L[y + 2 * LANES + l] + h * (0.47766253643826434 * L[k + 2 * LANES + l] + -2.4881146199716677 * L[k + 3 * STAGE + 2 * LANES + l] + -0.590290826836843 * L[k + 4 * STAGE + 2 * LANES + l] + 21.230051448181193 * L[k + 5 * STAGE + 2 * LANES + l] + 15.279233632882423 * L[k + 6 * STAGE + 2 * LANES + l] + -33.28821096898486 * L[k + 7 * STAGE + 2 * LANES + l] + -0.020331201708508627 * newest_2)
        newest_3 = L[k + NEWEST * STAGE + 3 * LANES + l]
        L[k + 8 * STAGE + 3 * LANES + l] = newest_3
        L[out + 3 * LANES + l] = L[y + 3 * LANES + l] + h * (0.47766253643826434 * L[k + 3 * LANES + l] + -2.4881146199716677 * L[k + 3 * STAGE + 3 * LANES + l] + -0.590290826836843 * L[k + 4 * STAGE + 3 * LANES + l] + 21.230051448181193 * L[k + 5 * STAGE + 3 * LANES + l] + 15.279233632882423 * L[k + 6 * STAGE + 3 * LANES + l] + -33.28821096898486 * L[k + 7 * STAGE + 3 * LANES + l] + -0.020331201708508627 * newest_3)
        newest_4 = L[k + NEWEST * STAGE + 4 * LANES + l]
        L[k + 8 * STAGE + 4 * LANES + l] = newest_4
        L[out + 4 * LANES + l] = L[y + 4 * LANES + l] + h * (0.47766253643826434 * L[k + 4 * LANES + l] + -2.4881146199716677 * L[k + 3 * STAGE + 4 * LANES + l] + -0.590290826836843 * L[k + 4 * STAGE + 4 * LANES + l] + 21.230051448181193 * L[k + 5 * STAGE + 4 * LANES + l] + 15.279233632882423 * L[k + 6 * STAGE + 4 * LANES + l] + -33.28821096898486 * L[k + 7 * STAGE + 4 * LANES + l] + -0.020331201708508627 * newest_4)
        newest_5 = L[k + NEWEST * STAGE + 5 * LANES + l]
        L[k + 8 * STAGE + 5 * LANES + l] = newest_5
        newest_6 = L[k + NEWEST * STAGE + 6 * LANES + l]
        L[k + 8 * STAGE + 6 * LANES + l] = newest_6


def lanes_stage_10(L, width):
    """Y_STAGE = Y + h Σ_j A[10, j] K[j], the input of stage 10 (the components its rates read), in lanes [0, width) of the block L (`numerics.lanes`)."""
    k, y, out = ROW_K * LANES, ROW_Y * LANES, ROW_Y_STAGE * LANES
    for l in range(width):
        h = L[ROW_H * LANES + l]
        newest_0 = L[k + NEWEST * STAGE + l]
        L[k + 9 * STAGE + l] = newest_0
        newest_1 = L[k + NEWEST * STAGE + 1 * LANES + l]
        L[k + 9 * STAGE + 1 * LANES + l] = newest_1
        L[out + 1 * LANES + l] = L[y + 1 * LANES + l] + h * (-0.9371424300859873 * L[k + 1 * LANES + l] + 5.186372428844064 * L[k + 3 * STAGE + 1 * LANES + l] + 1.0914373489967295 * L[k + 4 * STAGE + 1 * LANES + l] + -8.149787010746927 * L[k + 5 * STAGE + 1 * LANES + l] + -18.52006565999696 * L[k + 6 * STAGE + 1 * LANES + l] + 22.739487099350505 * L[k + 7 * STAGE + 1 * LANES + l] + 2.4936055526796523 * L[k + 8 * STAGE + 1 * LANES + l] + -3.0467644718982196 * newest_1)
        newest_2 = L[k + NEWEST * STAGE + 2 * LANES + l]
        L[k + 9 * STAGE + 2 * LANES + l] = newest_2
        L[out + 2 * LANES + l] = L[y + 2 * LANES + l] + h * (-0.9371424300859873 * L[k + 2 * LANES + l] + 5.186372428844064 * L[k + 3 * STAGE + 2 * LANES + l] + 1.0914373489967295 * L[k + 4 * STAGE + 2 * LANES + l] + -8.149787010746927 * L[k + 5 * STAGE + 2 * LANES + l] + -18.52006565999696 * L[k + 6 * STAGE + 2 * LANES + l] + 22.739487099350505 * L[k + 7 * STAGE + 2 * LANES + l] + 2.4936055526796523 * L[k + 8 * STAGE + 2 * LANES + l] + -3.0467644718982196 * newest_2)
        newest_3 = L[k + NEWEST * STAGE + 3 * LANES + l]
        L[k + 9 * STAGE + 3 * LANES + l] = newest_3
        L[out + 3 * LANES + l] = L[y + 3 * LANES + l] + h * (-0.9371424300859873 * L[k + 3 * LANES + l] + 5.186372428844064 * L[k + 3 * STAGE + 3 * LANES + l] + 1.0914373489967295 * L[k + 4 * STAGE + 3 * LANES + l] + -8.149787010746927 * L[k + 5 * STAGE + 3 * LANES + l] + -18.52006565999696 * L[k + 6 * STAGE + 3 * LANES + l] + 22.739487099350505 * L[k + 7 * STAGE + 3 * LANES + l] + 2.4936055526796523 * L[k + 8 * STAGE + 3 * LANES + l] + -3.0467644718982196 * newest_3)
        newest_4 = L[k + NEWEST * STAGE + 4 * LANES + l]
        L[k + 9 * STAGE + 4 * LANES + l] = newest_4
        L[out + 4 * LANES + l] = L[y + 4 * LANES + l] + h * (-0.9371424300859873 * L[k + 4 * LANES + l] + 5.186372428844064 * L[k + 3 * STAGE + 4 * LANES + l] + 1.0914373489967295 * L[k + 4 * STAGE + 4 * LANES + l] + -8.149787010746927 * L[k + 5 * STAGE + 4 * LANES + l] + -18.52006565999696 * L[k + 6 * STAGE + 4 * LANES + l] + 22.739487099350505 * L[k + 7 * STAGE + 4 * LANES + l] + 2.4936055526796523 * L[k + 8 * STAGE + 4 * LANES + l] + -3.0467644718982196 * newest_4)
        newest_5 = L[k + NEWEST * STAGE + 5 * LANES + l]
        L[k + 9 * STAGE + 5 * LANES + l] = newest_5
        newest_6 = L[k + NEWEST * STAGE + 6 * LANES + l]
        L[k + 9 * STAGE + 6 * LANES + l] = newest_6


def lanes_stage_11(L, width):
    """Y_STAGE = Y + h Σ_j A[11, j] K[j], the input of stage 11 (the components its rates read), in lanes [0, width) of the block L (`numerics.lanes`)."""
    k, y, out = ROW_K * LANES, ROW_Y * LANES, ROW_Y_STAGE * LANES
    for l in range(width):
        h = L[ROW_H * LANES + l]
        newest_0 = L[k + NEWEST * STAGE + l]
        L[k + 10 * STAGE + l] = newest_0
        newest_1 = L[k + NEWEST * STAGE + 1 * LANES + l]
        L[k + 10 * STAGE + 1 * LANES + l] = newest_1
        L[out + 1 * LANES + l] = L[y + 1 * LANES + l] + h * (2.273310147516538 * L[k + 1 * LANES + l] + -10.53449546673725 * L[k + 3 * STAGE + 1 * LANES + l] + -2.0008720582248625 * L[k + 4 * STAGE + 1 * LANES + l] + -17.9589318631188 * L[k + 5 * STAGE + 1 * LANES + l] + 27.94888452941996 * L[k + 6 * STAGE + 1 * LANES + l] + -2.8589982771350235 * L[k + 7 * STAGE + 1 * LANES + l] + -8.87285693353063 * L[k + 8 * STAGE + 1 * LANES + l] + 12.360567175794303 * L[k + 9 * STAGE + 1 * LANES + l] + 0.6433927460157636 * newest_1)
        newest_2 = L[k + NEWEST * STAGE + 2 * LANES + l]
        L[k + 10 * STAGE + 2 * LANES + l] = newest_2
        L[out + 2 * LANES + l] = L[y + 2 * LANES + l] + h * (2.273310147516538 * L[k + 2 * LANES + l] + -10.53449546673725 * L[k + 3 * STAGE + 2 * LANES + l] + -2.0008720582248625 * L[k + 4 * STAGE + 2 * LANES + l] + -17.9589318631188 * L[k + 5 * STAGE + 2 * LANES + l] + 27.94888452941996 * L[k + 6 * STAGE + 2 * LANES + l] + -2.8589982771350235 * L[k + 7 * STAGE + 2 * LANES + l] + -8.87285693353063 * L[k + 8 * STAGE + 2 * LANES + l] + 12.360567175794303 * L[k + 9 * STAGE + 2 * LANES + l] + 0.6433927460157636 * newest_2)
        newest_3 = L[k + NEWEST * STAGE + 3 * LANES + l]
        L[k + 10 * STAGE + 3 * LANES + l] = newest_3
        L[out + 3 * LANES + l] = L[y + 3 * LANES + l] + h * (2.273310147516538 * L[k + 3 * LANES + l] + -10.53449546673725 * L[k + 3 * STAGE + 3 * LANES + l] + -2.0008720582248625 * L[k + 4 * STAGE + 3 * LANES + l] + -17.9589318631188 * L[k + 5 * STAGE + 3 * LANES + l] + 27.94888452941996 * L[k + 6 * STAGE + 3 * LANES + l] + -2.8589982771350235 * L[k + 7 * STAGE + 3 * LANES + l] + -8.87285693353063 * L[k + 8 * STAGE + 3 * LANES + l] + 12.360567175794303 * L[k + 9 * STAGE + 3 * LANES + l] + 0.6433927460157636 * newest_3)
        newest_4 = L[k + NEWEST * STAGE + 4 * LANES + l]
        L[k + 10 * STAGE + 4 * LANES + l] = newest_4
        L[out + 4 * LANES + l] = L[y + 4 * LANES + l] + h * (2.273310147516538 * L[k + 4 * LANES + l] + -10.53449546673725 * L[k + 3 * STAGE + 4 * LANES + l] + -2.0008720582248625 * L[k + 4 * STAGE + 4 * LANES + l] + -17.9589318631188 * L[k + 5 * STAGE + 4 * LANES + l] + 27.94888452941996 * L[k + 6 * STAGE + 4 * LANES + l] + -2.8589982771350235 * L[k + 7 * STAGE + 4 * LANES + l] + -8.87285693353063 * L[k + 8 * STAGE + 4 * LANES + l] + 12.360567175794303 * L[k + 9 * STAGE + 4 * LANES + l] + 0.6433927460157636 * newest_4)
        newest_5 = L[k + NEWEST * STAGE + 5 * LANES + l]
        L[k + 10 * STAGE + 5 * LANES + l] = newest_5
        newest_6 = L[k + NEWEST * STAGE + 6 * LANES + l]
        L[k + 10 * STAGE + 6 * LANES + l] = newest_6


def lanes_solution(L, width):
    """Y_NEW = Y + h Σ_j B_j K[j], the 8th-order step, in lanes [0, width) of the block L (`numerics.lanes`)."""
    k, y, out = ROW_K * LANES, ROW_Y * LANES, ROW_Y_NEW * LANES
    for l in range(width):
        h = L[ROW_H * LANES + l]
        newest_0 = L[k + NEWEST * STAGE + l]
        L[k + 11 * STAGE + l] = newest_0
        L[out + l] = L[y + l] + h * (0.054293734116568765 * L[k + l] + 4.450312892752409 * L[k + 5 * STAGE + l] + 1.8915178993145003 * L[k + 6 * STAGE + l] + -5.801203960010585 * L[k + 7 * STAGE + l] + 0.3111643669578199 * L[k + 8 * STAGE + l] + -0.1521609496625161 * L[k + 9 * STAGE + l] + 0.20136540080403034 * L[k + 10 * STAGE + l] + 0.04471061572777259 * newest_0)
        newest_1 = L[k + NEWEST * STAGE + 1 * LANES + l]
        L[k + 11 * STAGE + 1 * LANES + l] = newest_1
        L[out + 1 * LANES + l] = L[y + 1 * LANES + l] + h * (0.054293734116568765 * L[k + 1 * LANES + l] + 4.450312892752409 * L[k + 5 * STAGE + 1 * LANES + l] + 1.8915178993145003 * L[k + 6 * STAGE + 1 * LANES + l] + -5.801203960010585 * L[k + 7 * STAGE + 1 * LANES + l] + 0.3111643669578199 * L[k + 8 * STAGE + 1 * LANES + l] + -0.1521609496625161 * L[k + 9 * STAGE + 1 * LANES + l] + 0.20136540080403034 * L[k + 10 * STAGE + 1 * LANES + l] + 0.04471061572777259 * newest_1)
        newest_2 = L[k + NEWEST * STAGE + 2 * LANES + l]
        L[k + 11 * STAGE + 2 * LANES + l] = newest_2
        L[out + 2 * LANES + l] = L[y + 2 * LANES + l] + h * (0.054293734116568765 * L[k + 2 * LANES + l] + 4.450312892752409 * L[k + 5 * STAGE + 2 * LANES + l] + 1.8915178993145003 * L[k + 6 * STAGE + 2 * LANES + l] + -5.801203960010585 * L[k + 7 * STAGE + 2 * LANES + l] + 0.3111643669578199 * L[k + 8 * STAGE + 2 * LANES + l] + -0.1521609496625161 * L[k + 9 * STAGE + 2 * LANES + l] + 0.20136540080403034 * L[k + 10 * STAGE + 2 * LANES + l] + 0.04471061572777259 * newest_2)
        newest_3 = L[k + NEWEST * STAGE + 3 * LANES + l]
        L[k + 11 * STAGE + 3 * LANES + l] = newest_3
        L[out + 3 * LANES + l] = L[y + 3 * LANES + l] + h * (0.054293734116568765 * L[k + 3 * LANES + l] + 4.450312892752409 * L[k + 5 * STAGE + 3 * LANES + l] + 1.8915178993145003 * L[k + 6 * STAGE + 3 * LANES + l] + -5.801203960010585 * L[k + 7 * STAGE + 3 * LANES + l] + 0.3111643669578199 * L[k + 8 * STAGE + 3 * LANES + l] + -0.1521609496625161 * L[k + 9 * STAGE + 3 * LANES + l] + 0.20136540080403034 * L[k + 10 * STAGE + 3 * LANES + l] + 0.04471061572777259 * newest_3)
        newest_4 = L[k + NEWEST * STAGE + 4 * LANES + l]
        L[k + 11 * STAGE + 4 * LANES + l] = newest_4
        L[out + 4 * LANES + l] = L[y + 4 * LANES + l] + h * (0.054293734116568765 * L[k + 4 * LANES + l] + 4.450312892752409 * L[k + 5 * STAGE + 4 * LANES + l] + 1.8915178993145003 * L[k + 6 * STAGE + 4 * LANES + l] + -5.801203960010585 * L[k + 7 * STAGE + 4 * LANES + l] + 0.3111643669578199 * L[k + 8 * STAGE + 4 * LANES + l] + -0.1521609496625161 * L[k + 9 * STAGE + 4 * LANES + l] + 0.20136540080403034 * L[k + 10 * STAGE + 4 * LANES + l] + 0.04471061572777259 * newest_4)
        newest_5 = L[k + NEWEST * STAGE + 5 * LANES + l]
        L[k + 11 * STAGE + 5 * LANES + l] = newest_5
        L[out + 5 * LANES + l] = L[y + 5 * LANES + l] + h * (0.054293734116568765 * L[k + 5 * LANES + l] + 4.450312892752409 * L[k + 5 * STAGE + 5 * LANES + l] + 1.8915178993145003 * L[k + 6 * STAGE + 5 * LANES + l] + -5.801203960010585 * L[k + 7 * STAGE + 5 * LANES + l] + 0.3111643669578199 * L[k + 8 * STAGE + 5 * LANES + l] + -0.1521609496625161 * L[k + 9 * STAGE + 5 * LANES + l] + 0.20136540080403034 * L[k + 10 * STAGE + 5 * LANES + l] + 0.04471061572777259 * newest_5)
        newest_6 = L[k + NEWEST * STAGE + 6 * LANES + l]
        L[k + 11 * STAGE + 6 * LANES + l] = newest_6
        L[out + 6 * LANES + l] = L[y + 6 * LANES + l] + h * (0.054293734116568765 * L[k + 6 * LANES + l] + 4.450312892752409 * L[k + 5 * STAGE + 6 * LANES + l] + 1.8915178993145003 * L[k + 6 * STAGE + 6 * LANES + l] + -5.801203960010585 * L[k + 7 * STAGE + 6 * LANES + l] + 0.3111643669578199 * L[k + 8 * STAGE + 6 * LANES + l] + -0.1521609496625161 * L[k + 9 * STAGE + 6 * LANES + l] + 0.20136540080403034 * L[k + 10 * STAGE + 6 * LANES + l] + 0.04471061572777259 * newest_6)


def solution(y, K, h, out):
    """out = y + h Σ_j B_j K[j]: the 8th-order step."""
    for i in range(y.shape[0]):
        out[i] = y[i] + h * (0.054293734116568765 * K[0, i] + 4.450312892752409 * K[5, i] + 1.8915178993145003 * K[6, i] + -5.801203960010585 * K[7, i] + 0.3111643669578199 * K[8, i] + -0.1521609496625161 * K[9, i] + 0.20136540080403034 * K[10, i] + 0.04471061572777259 * K[11, i])


def error_terms(K, i, l):
    """(Σ_j E5_j K[j, i, l], Σ_j E3_j K[j, i, l]): the 5th- and 3rd-order error estimates of component i
    in lane l, over h (a single scene is lane 0 of its K reshaped to (stages, components, 1))."""
    return (0.01312004499419488 * K[0, i, l] + -1.2251564463762044 * K[5, i, l] + -0.4957589496572502 * K[6, i, l] + 1.6643771824549864 * K[7, i, l] + -0.35032884874997366 * K[8, i, l] + 0.3341791187130175 * K[9, i, l] + 0.08192320648511571 * K[10, i, l] + -0.022355307863886294 * K[11, i, l], -0.18980075407240762 * K[0, i, l] + 4.450312892752409 * K[5, i, l] + 1.8915178993145003 * K[6, i, l] + -5.801203960010585 * K[7, i, l] + -0.4226823213237919 * K[8, i, l] + -0.1521609496625161 * K[9, i, l] + 0.20136540080403034 * K[10, i, l] + 0.02265179219836082 * K[11, i, l])


def lanes_error_terms(L, i, l):
    """`error_terms` of component i in lane l of the block L (`numerics.lanes`; i a constant where it is
    inlined, so that every row is)."""
    k = (ROW_K + i) * LANES
    return (0.01312004499419488 * L[k + l] + -1.2251564463762044 * L[k + 5 * STAGE + l] + -0.4957589496572502 * L[k + 6 * STAGE + l] + 1.6643771824549864 * L[k + 7 * STAGE + l] + -0.35032884874997366 * L[k + 8 * STAGE + l] + 0.3341791187130175 * L[k + 9 * STAGE + l] + 0.08192320648511571 * L[k + 10 * STAGE + l] + -0.022355307863886294 * L[k + 11 * STAGE + l], -0.18980075407240762 * L[k + l] + 4.450312892752409 * L[k + 5 * STAGE + l] + 1.8915178993145003 * L[k + 6 * STAGE + l] + -5.801203960010585 * L[k + 7 * STAGE + l] + -0.4226823213237919 * L[k + 8 * STAGE + l] + -0.1521609496625161 * L[k + 9 * STAGE + l] + 0.20136540080403034 * L[k + 10 * STAGE + l] + 0.02265179219836082 * L[k + 11 * STAGE + l])


def dense_0(K, i):
    """Σ_j D[0, j] K[j, i]: row 3 of the interpolant, over h."""
    return -8.428938276109013 * K[0, i] + 0.5667149535193777 * K[5, i] + -3.0689499459498917 * K[6, i] + 2.38466765651207 * K[7, i] + 2.117034582445028 * K[8, i] + -0.871391583777973 * K[9, i] + 2.2404374302607883 * K[10, i] + 0.6315787787694688 * K[11, i] + -0.08899033645133331 * K[12, i] + 18.148505520854727 * K[13, i] + -9.194632392478356 * K[14, i] + -4.436036387594894 * K[15, i]


def dense_1(K, i):
    """Σ_j D[1, j] K[j, i]: row 4 of the interpolant, over h."""
    return 10.427508642579134 * K[0, i] + 242.28349177525817 * K[5, i] + 165.20045171727028 * K[6, i] + -374.5467547226902 * K[7, i] + -22.113666853125306 * K[8, i] + 7.733432668472264 * K[9, i] + -30.674084731089398 * K[10, i] + -9.332130526430229 * K[11, i] + 15.697238121770845 * K[12, i] + -31.139403219565178 * K[13, i] + -9.35292435884448 * K[14, i] + 35.81684148639408 * K[15, i]


def dense_2(K, i):
    """Σ_j D[2, j] K[j, i]: row 5 of the interpolant, over h."""
    return 19.985053242002433 * K[0, i] + -387.0373087493518 * K[5, i] + -189.17813819516758 * K[6, i] + 527.8081592054236 * K[7, i] + -11.57390253995963 * K[8, i] + 6.8812326946963 * K[9, i] + -1.0006050966910838 * K[10, i] + 0.7777137798053443 * K[11, i] + -2.778205752353508 * K[12, i] + -60.19669523126412 * K[13, i] + 84.32040550667716 * K[14, i] + 11.99229113618279 * K[15, i]


def dense_3(K, i):
    """Σ_j D[3, j] K[j, i]: row 6 of the interpolant, over h."""
    return -25.69393346270375 * K[0, i] + -154.18974869023643 * K[5, i] + -231.5293791760455 * K[6, i] + 357.6391179106141 * K[7, i] + 93.40532418362432 * K[8, i] + -37.45832313645163 * K[9, i] + 104.0996495089623 * K[10, i] + 29.8402934266605 * K[11, i] + -43.53345659001114 * K[12, i] + 96.32455395918828 * K[13, i] + -39.17726167561544 * K[14, i] + -149.72683625798564 * K[15, i]
