"""mpmath 3-vector and 3x3 helpers of the reference geometry."""

from mpmath import mp


# ---------------------------------------------------------------- vectors
def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _norm(a):
    return mp.sqrt(_dot(a, a))


def _matvec(M, v):
    return tuple(M[i][0] * v[0] + M[i][1] * v[1] + M[i][2] * v[2] for i in range(3))


def _matTvec(M, v):
    return tuple(M[0][j] * v[0] + M[1][j] * v[1] + M[2][j] * v[2] for j in range(3))


def _quaternion(R):
    """Shepperd's method; returns (q0, q1, q2, q3), scalar first, sign +."""
    tr = R[0][0] + R[1][1] + R[2][2]
    cands = (tr, R[0][0], R[1][1], R[2][2])
    i = max(range(4), key=lambda k: cands[k])
    if i == 0:
        q0 = mp.sqrt(1 + tr) / 2
        f = 4 * q0
        return (q0, (R[2][1] - R[1][2]) / f, (R[0][2] - R[2][0]) / f, (R[1][0] - R[0][1]) / f)
    if i == 1:
        q1 = mp.sqrt(1 + 2 * R[0][0] - tr) / 2
        f = 4 * q1
        return ((R[2][1] - R[1][2]) / f, q1, (R[0][1] + R[1][0]) / f, (R[0][2] + R[2][0]) / f)
    if i == 2:
        q2 = mp.sqrt(1 + 2 * R[1][1] - tr) / 2
        f = 4 * q2
        return ((R[0][2] - R[2][0]) / f, (R[0][1] + R[1][0]) / f, q2, (R[1][2] + R[2][1]) / f)
    q3 = mp.sqrt(1 + 2 * R[2][2] - tr) / 2
    f = 4 * q3
    return ((R[1][0] - R[0][1]) / f, (R[0][2] + R[2][0]) / f, (R[1][2] + R[2][1]) / f, q3)


def _vee(S):
    """Axial vector of the skew part of S."""
    return ((S[2][1] - S[1][2]) / 2, (S[0][2] - S[2][0]) / 2, (S[1][0] - S[0][1]) / 2)


# ------------------------------------------------------------- reference
