"""The mpmath reference motion (`numerics.reference_motion`, its slide `numerics.sliding`): a state for every
time asked, wherever it falls."""

from pathlib import Path

import mpmath
import pytest

from numerics import reference_motion
from numerics.scene import load

SAMPLE = Path(__file__).parents[2] / "numerics" / "scenes" / "sample.json"


def test_every_time_asked_gets_its_state():
    """The start and a time asked twice (in the slide and in the rolling): each was left out before, and with it
    every later time of the slide (the slide's event for a time already reached never fires; an audit found it)."""
    scene = load(SAMPLE)
    first = reference_motion.reference(scene, digits=15)
    in_slide, in_roll = mpmath.mpf("0.1"), (first.t_slide_end + first.t_roll_end) / 2
    ref = reference_motion.reference(scene, digits=15, times=[0, in_slide, in_slide, in_roll, in_roll])
    assert set(ref.states) == {mpmath.mpf(0), in_slide, in_roll}
    s = scene.state
    assert ref.states[mpmath.mpf(0)] == (s.xi, s.eta, s.p, s.q)
    alone = reference_motion.reference(scene, digits=15, times=[in_slide, in_roll])
    assert ref.states[in_slide] == alone.states[in_slide] and ref.states[in_roll] == alone.states[in_roll]


@pytest.mark.parametrize("method", ["taylor", pytest.param("gbs", marks=pytest.mark.slow)])  # GBS: ~10 s
def test_a_time_in_the_slides_last_stretch_gets_its_state(method):
    """The slide is integrated to V₀·tol/100 and finished to first order (`sliding.first_order_end`); a time in
    that stretch (~1e-20 s here) is taken to first order too, not left out."""
    scene = load(SAMPLE)
    first = reference_motion.reference(scene, digits=15, method=method)
    with mpmath.workdps(15 + 10):  # the reference's precision (the stretch is below the default precision)
        times = [first.t_slide_end - mpmath.mpf(10) ** -22, first.t_slide_end - mpmath.mpf(10) ** -24]
    ref = reference_motion.reference(scene, digits=15, times=times, method=method)
    assert set(ref.states) == set(times)
    end = ref.slide_end
    for t in times:
        for got, want in zip(ref.states[t], (end.xi, end.eta, end.p, end.q)):
            assert abs(got - want) <= 1e-15 * (1 + abs(want))
