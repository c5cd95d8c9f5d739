"""analysis/toughness_radius.py: the sqrt(R) check on synthetic lattices with known answers."""
import math

from repo_scripts import load

tr = load("analysis/toughness_radius.py")


def lattice(k_large, exponent, noise):
    """K at R = 11.5 um per placing, and at 5.75 um K (R ratio)^exponent with a per-placing relative noise."""
    placings = [(0.0, 0.0), (0.0, 0.5), (0.5, 0.0), (0.5, 0.5)]
    out = {11.5: {}, 5.75: {}}
    for (p, k), n in zip(zip(placings, k_large), noise):
        out[11.5][p] = (k, k * k)
        small = k * 0.5 ** exponent * (1 + n)
        out[5.75][p] = (small, small * small)
    return out


def test_sqrt_r_scaling_is_recognised():
    lines, ratio, expected = tr.scaling(lattice([1.0, 1.1, 1.05, 0.95], 0.5, [0.01, -0.01, 0.02, -0.02]))
    assert math.isclose(expected, math.sqrt(0.5))
    assert ratio.low <= expected <= ratio.high
    assert "holds" in lines[2]


def test_a_toughness_independent_of_r_is_told_apart():
    lines, ratio, expected = tr.scaling(lattice([1.0, 1.1, 1.05, 0.95], 0.0, [0.01, -0.01, 0.02, -0.02]))
    assert not ratio.low <= expected <= ratio.high
    assert "differs" in lines[2]
