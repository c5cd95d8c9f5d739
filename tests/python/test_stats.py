"""kerf.stats (python/kerf/stats.py): Fieller's ratio, the delta method with Welch-Satterthwaite degrees of
freedom, the verdicts and Student's t, on estimates with known answers."""
import math
import random

import kerf.stats as ks


def test_fieller_without_denominator_error_is_the_scaled_numerator_interval():
    a = ks.Estimate(6.0, 0.5, 7)
    b = ks.Estimate(2.0, 0.0, 7)
    r = ks.ratio(a, b)
    half = ks.t95(7) * 0.5 / 2.0
    assert math.isclose(r.value, 3.0)
    assert math.isclose(r.low, 3.0 - half, rel_tol=1e-12)
    assert math.isclose(r.high, 3.0 + half, rel_tol=1e-12)


def test_fieller_is_unbounded_when_the_denominator_is_not_resolved_from_zero():
    r = ks.ratio(ks.Estimate(1.0, 0.1, 7), ks.Estimate(0.2, 0.5, 7))
    assert r.low == -math.inf and r.high == math.inf
    other = ks.Estimate(1.0, 0.1, 5)
    assert ks.verdict(ks.difference(r, other), other) == "not resolved"


def test_fieller_interval_covers_the_true_ratio_95_percent_of_the_time():
    rng = random.Random(41)
    true_a, true_b, sd, n = 0.3, 0.45, 0.08, 8
    trials, covered = 3000, 0
    for _ in range(trials):
        a = ks.mean_of([rng.gauss(true_a, sd) for _ in range(n)])
        b = ks.mean_of([rng.gauss(true_b, sd) for _ in range(n)])
        r = ks.ratio(a, b)
        covered += r.low <= true_a / true_b <= r.high
    # Welch's dof rounded down makes it a little conservative; 3000 trials: binomial sd 0.4 %.
    assert 0.94 <= covered / trials <= 0.975


def test_welch_dof_of_two_equal_samples_is_their_pooled_dof():
    x = ks.mean_of([1.0, 2.0, 3.0, 4.0, 5.0])
    y = ks.mean_of([2.0, 3.0, 4.0, 5.0, 6.0])
    d = ks.difference(x, y)
    assert math.isclose(d.dof, 8.0)
    assert math.isclose(d.value, -1.0)
    assert math.isclose(d.se, math.sqrt(2) * x.se)


def student_cdf_minus_half(x, dof, steps=20000):
    """P(0 < T < x) for Student's t with real `dof`: Simpson's rule over the density
    Gamma((dof + 1) / 2) / (sqrt(dof pi) Gamma(dof / 2)) (1 + t^2 / dof)^(-(dof + 1) / 2)."""
    c = math.exp(math.lgamma((dof + 1) / 2) - math.lgamma(dof / 2)) / math.sqrt(dof * math.pi)
    f = lambda t: c * (1 + t * t / dof) ** (-(dof + 1) / 2)  # noqa: E731
    h = x / steps
    return h / 3 * (f(0) + f(x) + sum((4 if k % 2 else 2) * f(k * h) for k in range(1, steps)))


def test_t_quantile_has_the_closed_forms_of_one_two_and_four_degrees_of_freedom():
    # 1 dof (Cauchy): tan(pi (p - 1/2)); 2 dof: a sqrt(2 / (1 - a^2)), a = 2p - 1; 4 dof: 2 sqrt(q - 1),
    # q = cos(arccos(sqrt(alpha)) / 3) / sqrt(alpha), alpha = 4 p (1 - p) (Hill 1970).
    p = 0.975
    a, alpha = 2 * p - 1, 4 * p * (1 - p)
    q = math.cos(math.acos(math.sqrt(alpha)) / 3) / math.sqrt(alpha)
    assert math.isclose(ks.t95(1), math.tan(math.pi * (p - 0.5)), rel_tol=1e-12)
    assert math.isclose(ks.t95(2), a * math.sqrt(2 / (1 - a * a)), rel_tol=1e-12)
    assert math.isclose(ks.t95(4), 2 * math.sqrt(q - 1), rel_tol=1e-12)


def test_t_quantile_is_the_textbooks_and_tends_to_the_normal():
    # Standard tables to 9 decimals (e.g. NIST/SEMATECH's); beyond, 1.96 + (1.96^3 + 1.96) / (4 dof) to first order.
    for dof, want in ((3, 3.182446305), (10, 2.228138852), (30, 2.042272456), (60, 2.000297821),
                      (120, 1.979930405)):
        assert math.isclose(ks.t95(dof), want, abs_tol=2e-9)
    z = 1.959963984540054
    assert math.isclose(ks.t95(1e6), z + (z ** 3 + z) / 4e6, abs_tol=1e-9)
    # No spread to scale: the C++ side's normal 1.96 (kerf::kZ95).
    assert ks.t95(math.inf) == 1.96 and ks.t95(0) == 1.96


def test_t_quantile_at_fractional_dof_is_where_the_distribution_holds_95_percent():
    # Welch's dof are fractional: the quantile is exact there too, P(|T| < t) = 0.95 by the density itself, and falls
    # without a jump from 12.706 at 1 dof to 4.303 at 2 (at 1.97, where two packings' Welch dof often lie, about 4.37).
    for dof in (0.5, 1.5, 1.97, 3.3, 7.25, 41.7):
        assert math.isclose(student_cdf_minus_half(ks.t95(dof), dof), 0.475, abs_tol=1e-9), dof
    assert ks.t95(0.5) > ks.t95(1.0) > ks.t95(1.5) > ks.t95(1.97) > ks.t95(2.0)
    assert 4.36 < ks.t95(1.97) < 4.38


def test_a_combination_of_estimates_adds_their_variances():
    a, b = ks.Estimate(1.0, 0.1, 4), ks.Estimate(2.0, 0.2, 9)
    c = ks.combination([(2.0, a), (-1.0, b)])
    assert math.isclose(c.value, 0.0, abs_tol=1e-12) and math.isclose(c.se, math.sqrt(0.04 + 0.04))
    assert 4 <= c.dof <= 13
    assert not ks.combination([(1.0, ks.Estimate(1.0, math.nan, 0)), (1.0, a)]).resolved()


def test_packings_factor_is_where_the_projected_interval_first_resolves():
    # kerf 0.30 +- 0.07 (7 dof) against the experiments' 0.15 +- 0.01: at 8 packings the difference's interval holds 0
    # and is wider than +-50 %; with more packings it narrows about 0.15 and comes to exclude 0.
    kerf, exp = ks.Estimate(0.30, 0.07, 7), ks.Estimate(0.15, 0.01, 2)
    terms = [(1.0, kerf, True), (-1.0, exp, False)]
    assert ks.verdict(ks.difference(kerf, exp), exp) == "not resolved"
    k, why = ks.packings_factor(terms, exp)
    assert why == "spread" and 1 < k < 100
    at = lambda f: ks.verdict(ks.difference(ks.scaled(kerf, f), exp), exp)
    assert at(k) == "differs" and at(k / 1.01) == "not resolved"
    # Already resolved: no more packings.
    assert ks.packings_factor([(1.0, ks.Estimate(0.9, 0.01, 7), True), (-1.0, exp, False)], exp) == (1.0, "spread")


def test_a_verdict_the_experiments_own_interval_leaves_open_is_never_resolved_by_packings():
    # The experiments' ratio 1.7 +- 0.25 (2 dof: half-width about 1.1): kerf's 1.2 lies within it however narrow
    # kerf's own interval becomes, and the interval is far wider than +-50 % of 1.7.
    kerf, exp = ks.Estimate(1.2, 0.08, 11), ks.Estimate(1.7, 0.25, 2)
    assert ks.packings_factor([(1.0, kerf, True), (-1.0, exp, False)], exp) == (math.inf, "experiments")
    # Two of kerf's estimates (one domain against the other) have no fixed part: packings always resolve them,
    # unless the two values are equal and the margin is zero.
    a, b = ks.Estimate(1.2, 0.3, 7), ks.Estimate(1.0, 0.3, 7)
    k, why = ks.packings_factor([(1.0, a, True), (-1.0, b, True)], b)
    assert why == "spread" and math.isfinite(k) and k > 1
