"""Student's t distribution without scipy (the analysis depends on numpy, pandas and matplotlib only).

cdf(x, df) from the regularized incomplete beta function, I_{df/(df+x^2)}(df/2, 1/2) (Abramowitz and
Stegun 26.7.1), evaluated by its continued fraction (modified Lentz); quantile(p, df) inverts it by
Newton's method from the Cornish-Fisher expansion, inside a bracket that always holds the root. df = inf (or above 1e7) is the normal distribution.
welch_df(variances, dfs) is the Welch-Satterthwaite degrees of freedom of a sum of independent variance
estimates (a component with df = inf is known exactly and adds nothing to the denominator).
"""
import functools
import math

EPS = 1e-14
MAX_ITER = 300


def _betacf(a, b, x):
    """The continued fraction of the incomplete beta function (modified Lentz)."""
    tiny = 1e-300
    c, d = 1.0, 1.0 - (a + b) * x / (a + 1.0)
    d = 1.0 / (d if abs(d) > tiny else tiny)
    h = d
    for m in range(1, MAX_ITER + 1):
        m2 = 2 * m
        for num in (m * (b - m) * x / ((a + m2 - 1) * (a + m2)), -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1))):
            d = 1.0 + num * d
            d = 1.0 / (d if abs(d) > tiny else tiny)
            c = 1.0 + num / c
            c = c if abs(c) > tiny else tiny
            h *= d * c
        if abs(d * c - 1.0) < EPS:
            break
    return h


def betainc(a, b, x):
    """The regularized incomplete beta function I_x(a, b), 0 <= x <= 1."""
    if x <= 0:
        return 0.0
    if x >= 1:
        return 1.0
    lead = math.exp(math.lgamma(a + b) - math.lgamma(a) - math.lgamma(b) + a * math.log(x) + b * math.log1p(-x))
    if x < (a + 1) / (a + b + 2):
        return lead * _betacf(a, b, x) / a
    return 1.0 - lead * _betacf(b, a, 1.0 - x) / b


def normal_cdf(x):
    return 0.5 * math.erfc(-x / math.sqrt(2.0))


def cdf(x, df):
    """P(T <= x) for Student's t with df degrees of freedom (df > 0; inf: the normal)."""
    if not math.isfinite(df) or df > 1e7:
        return normal_cdf(x)
    tail = 0.5 * betainc(df / 2.0, 0.5, df / (df + x * x))
    return 1.0 - tail if x >= 0 else tail


def pdf(x, df):
    """The density of Student's t with df degrees of freedom."""
    if not math.isfinite(df) or df > 1e7:
        return math.exp(-0.5 * x * x) / math.sqrt(2 * math.pi)
    return math.exp(math.lgamma((df + 1) / 2) - math.lgamma(df / 2) - 0.5 * math.log(df * math.pi)
                    - (df + 1) / 2 * math.log1p(x * x / df))


@functools.lru_cache(maxsize=4096)
def quantile(p, df):
    """x with cdf(x, df) = p, 0 < p < 1: Newton's method from the Cornish-Fisher expansion of the t quantile
    about the normal one (Abramowitz and Stegun 26.7.5), kept inside a bracket that always holds the root (a
    step leaving it bisects instead); stops at a step below 1e-12 relative."""
    if not 0 < p < 1:
        raise ValueError(f"quantile: p = {p} is not in (0, 1)")
    if p < 0.5:
        return -quantile(1 - p, df)
    z = _normal_quantile(p)
    if not math.isfinite(df) or df > 1e7:
        return z
    x = z + (z ** 3 + z) / (4 * df) + (5 * z ** 5 + 16 * z ** 3 + 3 * z) / (96 * df ** 2)
    lo, hi = 0.0, math.inf
    for _ in range(200):
        f = cdf(x, df) - p
        if f < 0:
            lo = x
        else:
            hi = x
        nxt = x - f / max(pdf(x, df), 1e-300)
        if not lo < nxt < hi:
            nxt = 0.5 * (lo + hi) if math.isfinite(hi) else 2 * x
        if abs(nxt - x) <= 1e-12 * max(1.0, abs(x)):
            return nxt
        x = nxt
    return x


@functools.lru_cache(maxsize=64)
def _normal_quantile(p):
    """The normal quantile by bisection on erfc (exact to double precision)."""
    lo, hi = -40.0, 40.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if normal_cdf(mid) < p:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def welch_df(variances, dfs):
    """Welch-Satterthwaite: (sum v)^2 / sum (v^2 / df) over the components with a finite df; inf when none
    has one (or every finite-df variance is 0)."""
    total = sum(variances)
    denom = sum(v * v / d for v, d in zip(variances, dfs) if math.isfinite(d) and d > 0)
    if denom <= 0 or total <= 0:
        return math.inf
    return total * total / denom
