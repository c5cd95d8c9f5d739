"""kerf.stats: the statistics of kerf's study records and validation cases, in one place (issue 56).

A condition's mean is over its packings (the independent samples): its standard error is the sample standard
deviation / sqrt(n), with n - 1 degrees of freedom. A ratio of two independent means has Fieller's 95 % interval
(Fieller 1954; exact for normal means, unbounded when the denominator is not resolved from zero) with Student's t at
the Welch-Satterthwaite degrees of freedom of the delta-method variance; a linear combination of independent
estimates (a difference) has the delta-method standard error sqrt(sum c_i^2 se_i^2) with Welch-Satterthwaite degrees
of freedom. Verdicts come from a difference's interval only (verdict): 'differs' when it excludes 0, 'agrees' when it
holds 0 within +-AGREEMENT_MARGIN of the value compared against, 'not resolved' otherwise.

The one Student t quantile is the C++ one (t95: kerf::quantile95, include/kerf/interval95.hpp, GSL's exact quantile
at any real degrees of freedom), through the compiled module.

    from kerf.stats import mean_of, ratio, difference, verdict
    groove = ratio(mean_of(grooved_forces), mean_of(regular_forces))   # an Estimate: value, se, dof, low, high
"""
import math
import statistics

from kerf import _quantile95


def t95(dof):
    """Student's t, two-sided 95 % (the 0.975 quantile), at `dof` degrees of freedom, fractional ones (Welch's)
    included: GSL's exact quantile, the one the C++ intervals take (kerf::quantile95, include/kerf/interval95.hpp);
    the normal's 1.96 when `dof` is not finite or not positive (kerf::kZ95: no spread, it multiplies a standard error
    of 0)."""
    return _quantile95(float(dof))


class Estimate:
    """A value with its standard error, degrees of freedom and 95 % interval (low, high); n the samples of a mean
    (0 for a derived estimate). Without low and high the interval is value -+ t95(dof) se, or nan when it cannot
    be formed (se not finite, or fewer than one degree of freedom)."""

    def __init__(self, value, se, dof, low=None, high=None, n=0):
        self.value, self.se, self.dof, self.n = value, se, dof, n
        usable = math.isfinite(se) and dof >= 1
        half = t95(dof) * se if usable else math.nan
        self.low = low if low is not None else (value - half if usable else math.nan)
        self.high = high if high is not None else (value + half if usable else math.nan)

    def resolved(self):
        """Whether the value and both ends of the interval are finite."""
        return all(math.isfinite(x) for x in (self.value, self.low, self.high))


def mean_of(values):
    """The mean over packings of the finite `values`: sample std / sqrt(n), n - 1 degrees of freedom (one value: no
    standard error; none: nan)."""
    values = [v for v in values if math.isfinite(v)]
    n = len(values)
    if n == 0:
        return Estimate(math.nan, math.nan, 0)
    if n == 1:
        return Estimate(values[0], math.nan, 0, n=1)
    return Estimate(statistics.mean(values), statistics.stdev(values) / math.sqrt(n), n - 1, n=n)


def known_mean(values):
    """The mean of the known (finite) values; nan if none is known."""
    known = [v for v in values if math.isfinite(v)]
    return statistics.mean(known) if known else math.nan


def own_error(study, pairs, force):
    """The standard error of the mean force over the packings `pairs` of `study` ({pair: record row}) from the cuts'
    own errors: sqrt(sum sem^2) / n."""
    return math.sqrt(sum(study[p][f"{force}_force_sem_N"] ** 2 for p in pairs)) / len(pairs)


def welch_dof(terms):
    """Welch-Satterthwaite: terms are (variance contribution, its dof); inf when no term has a spread."""
    total = sum(v for v, _ in terms)
    denominator = sum(v * v / d for v, d in terms if d > 0)
    return total * total / denominator if denominator > 0 else math.inf


def ratio(a, b):
    """a / b of two independent means: Fieller's 95 % interval at the delta method's Welch dof (unbounded,
    -inf..inf, when the denominator is not resolved from zero)."""
    if not (math.isfinite(a.se) and math.isfinite(b.se)) or b.value == 0:
        return Estimate(a.value / b.value if b.value else math.nan, math.nan, 0)
    r = a.value / b.value
    va, vb = (a.se / b.value) ** 2, (r * b.se / b.value) ** 2
    dof = welch_dof([(va, a.dof), (vb, b.dof)])
    q = t95(dof) ** 2
    # (a - theta b)^2 <= q (sa^2 + theta^2 sb^2): a quadratic in theta.
    qa = b.value ** 2 - q * b.se ** 2
    qb = -2 * a.value * b.value
    qc = a.value ** 2 - q * a.se ** 2
    disc = qb * qb - 4 * qa * qc
    if qa <= 0 or disc < 0:  # the denominator is not resolved from zero: unbounded
        return Estimate(r, math.sqrt(va + vb), dof, -math.inf, math.inf)
    root = math.sqrt(disc)
    return Estimate(r, math.sqrt(va + vb), dof, (-qb - root) / (2 * qa), (-qb + root) / (2 * qa))


def combination(terms):
    """sum c_i x_i of independent estimates, terms (c_i, x_i): delta-method standard error, Welch dof (not resolved
    where any term is not: an unbounded Fieller interval is not made finite by the delta method)."""
    value = sum(c * x.value for c, x in terms)
    if not all(x.resolved() for _, x in terms):
        return Estimate(value, math.nan, 0)
    se = math.hypot(*(c * x.se for c, x in terms))
    return Estimate(value, se, welch_dof([((c * x.se) ** 2, x.dof) for c, x in terms]))


def difference(x, y):
    """x - y of two independent estimates (combination)."""
    return combination([(1.0, x), (-1.0, y)])


AGREEMENT_MARGIN = 0.5  # an 'agrees' must exclude a difference of half the value compared against


def verdict(d, against):
    """From the interval of a difference x - y only, y = `against`'s value: 'differs' when it excludes 0, 'agrees'
    when it holds 0 within +-AGREEMENT_MARGIN |y|, else 'not resolved' (too wide to tell)."""
    if not d.resolved():
        return "not resolved"
    if not d.low <= 0 <= d.high:
        return "differs"
    margin = AGREEMENT_MARGIN * abs(against.value)
    return "agrees" if -margin <= d.low and d.high <= margin else "not resolved"


def scaled(e, k):
    """e at k times its packings, the spread between them as now: se / sqrt(k), k n - 1 degrees of freedom
    (n = dof + 1); k = inf: no spread left."""
    if math.isinf(k):
        return Estimate(e.value, 0.0, math.inf)
    return Estimate(e.value, e.se / math.sqrt(k), k * (e.dof + 1) - 1)


def packings_factor(terms, against, largest=100.0):
    """How many times each condition's present packings a verdict not resolved would take to resolve, the spread
    between packings as now: the smallest k at which verdict(sum c_i x_i) is 'agrees' or 'differs', where terms are
    (c_i, x_i, more_i) and more_i says whether x_i narrows with kerf's packings (kerf's estimates; the experiments'
    not). Bisection: the interval only narrows about a fixed centre as k grows, so a verdict once resolved stays.
    Returns (k, why): k = inf when none up to `largest` resolves it, why 'experiments' when not even kerf without any
    spread would (the experiments' own interval is too wide for an 'agrees'), else 'spread'."""
    def resolved_at(k):
        d = combination([(c, scaled(x, k) if more else x) for c, x, more in terms])
        return verdict(d, against) != "not resolved"

    if not resolved_at(math.inf):
        return math.inf, "experiments"
    if not resolved_at(largest):
        return math.inf, "spread"
    low, high = 1.0, largest
    if resolved_at(low):
        return low, "spread"
    while high / low > 1.001:
        mid = math.sqrt(low * high)
        low, high = (low, mid) if resolved_at(mid) else (mid, high)
    return high, "spread"
