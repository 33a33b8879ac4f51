# Exact oracles in Python rationals (fractions.Fraction holds every float exactly).
from fractions import Fraction


def F(x):
    return Fraction(float(x))


def orient2d(a, b, c):
    ax, ay, bx, by, cx, cy = map(F, (*a, *b, *c))
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


def incircle(a, b, c, d):
    """> 0 when d is strictly inside the circle through a, b, c (counter-clockwise)."""
    rows = []
    for p in (a, b, c):
        x, y = F(p[0]) - F(d[0]), F(p[1]) - F(d[1])
        rows.append((x, y, x * x + y * y))
    (a0, a1, a2), (b0, b1, b2), (c0, c1, c2) = rows
    return a0 * (b1 * c2 - b2 * c1) - a1 * (b0 * c2 - b2 * c0) + a2 * (b0 * c1 - b1 * c0)


def det3(m):
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))


def orient3d(a, b, c, d):
    """Sign convention of locus (core/predicates.hpp): positive when d lies below the plane of
    a, b, c seen counter-clockwise from above, i.e. det[a-d, b-d, c-d]."""
    return det3([[F(p[i]) - F(d[i]) for i in range(3)] for p in (a, b, c)])


def insphere(a, b, c, d, e):
    """det of the lifted 4x4 matrix of a-e, b-e, c-e, d-e: its sign times orient3d(a,b,c,d)
    is positive when e is strictly inside the sphere through a, b, c, d."""
    rows = []
    for p in (a, b, c, d):
        v = [F(p[i]) - F(e[i]) for i in range(3)]
        rows.append(v + [v[0] * v[0] + v[1] * v[1] + v[2] * v[2]])
    det = Fraction(0)
    for j in range(4):
        minor = [[rows[i][k] for k in range(4) if k != j] for i in range(1, 4)]
        det += (-1) ** j * rows[0][j] * det3(minor)
    return det
