"""Exact reference values for the 'data offset by 1e9 with spread 1e-3' tests
(tests/analysis/ttest_test.cpp, descriptives_test.cpp, anova_test.cpp).

The doubles are built exactly as in the C++ tests (1e9 + 0.001 * k in IEEE double arithmetic,
which Python floats share), then every statistic is computed in exact rational arithmetic
(fractions.Fraction of the doubles' exact binary values) and only the final square root in
50-digit decimal arithmetic. Run: python3 tests/analysis/reference/offset_reference.py
"""
from decimal import Decimal, getcontext
from fractions import Fraction as Q

getcontext().prec = 50

def values(ks):
    return [1e9 + 0.001 * k for k in ks]

def mean(xs):
    return sum(Q(x) for x in xs) / len(xs)

def var(xs):
    m = mean(xs)
    return sum((Q(x) - m) ** 2 for x in xs) / (len(xs) - 1)

def sqrt(q):
    return (Decimal(q.numerator) / Decimal(q.denominator)).sqrt()

def dec(q):
    return Decimal(q.numerator) / Decimal(q.denominator)

x = values([1, 2, 4, 7, 11])
y = values([3, 5, 6, 9, 10, 12])
print("x =", [repr(v) for v in x])
print("y =", [repr(v) for v in y])
print("mean x - 1e9 =", dec(mean(x) - Q(10**9)))
print("var x =", dec(var(x)))
vx, vy = var(x) / len(x), var(y) / len(y)
t = dec(mean(x) - mean(y)) / sqrt(vx + vy)
df = (vx + vy) ** 2 / (vx ** 2 / (len(x) - 1) + vy ** 2 / (len(y) - 1))
print("welch t =", t)
print("welch df =", dec(df))
# One-way ANOVA of the two groups (F = Student t^2)
n = len(x) + len(y)
gm = (sum(Q(v) for v in x) + sum(Q(v) for v in y)) / n
ssb = len(x) * (mean(x) - gm) ** 2 + len(y) * (mean(y) - gm) ** 2
ssw = var(x) * (len(x) - 1) + var(y) * (len(y) - 1)
F = (ssb / 1) / (ssw / (n - 2))
print("one-way F =", dec(F))
print("SS between =", dec(ssb), " SS within =", dec(ssw))
