"""Confidence intervals over seeds, for the figures a bench reports (one definition for the
report, the matrix view and ``pipflow compare``).

Why two kinds: a success rate is a share of runs (each run succeeds or not), and its 95% interval
is the **Wilson score interval**, which stays inside [0, 1] and is not empty when every run
succeeded (3 of 3 successes: 44% to 100%, not "100% +- 0"). A measured quantity (travel,
makespan, GCR, time) is a mean over seeds, and its 95% interval is the **Student t-interval**
(mean +- t(0.975, n-1) * s / sqrt(n)), right for the few seeds a bench has (2 to 10), where a
bootstrap's percentiles are too narrow. With one seed there is no interval (None): the tables
then show the value alone.
"""
from __future__ import annotations

import math
from typing import Iterable

#: the intervals' confidence level
LEVEL = 0.95
#: how the tables name the two kinds
WILSON = "Wilson score interval"
STUDENT = "Student t-interval"


def _quantile(p: float, df: float | None = None) -> float:
    # deferred: scipy.stats (~0.3 s of import; the report needs it only for benches with seeds)
    from scipy import stats

    return float(stats.norm.ppf(p) if df is None else stats.t.ppf(p, df))


def wilson(successes: int, n: int, level: float = LEVEL) -> tuple[float, float] | None:
    """The Wilson score interval of a share ``successes / n``; None for n < 2 (one run says
    nothing about the spread)."""
    if n < 2:
        return None
    z = _quantile(0.5 + level / 2)
    p = successes / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return max(0.0, centre - half), min(1.0, centre + half)


def t_interval(values: Iterable[float], level: float = LEVEL) -> tuple[float, float] | None:
    """The Student t-interval of the mean of ``values``; None for fewer than two values."""
    xs = [float(v) for v in values]
    n = len(xs)
    if n < 2:
        return None
    mean = sum(xs) / n
    sd = math.sqrt(sum((x - mean) ** 2 for x in xs) / (n - 1))
    half = _quantile(0.5 + level / 2, n - 1) * sd / math.sqrt(n)
    return mean - half, mean + half
