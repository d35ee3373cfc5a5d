"""What the reference checks share: the recorder, small helpers and the cases."""

import math


class Checks:
    """Called as check(name, err, tol): err (a non-negative number) must be <= tol.
    Keeps the failures and the worst error per check name."""

    def __init__(self):
        self.failures = []
        self.worst = {}

    def __call__(self, name, err, tol):
        err = float(err)
        self.worst[name] = max(self.worst.get(name, 0.0), err)
        if not (err <= tol):
            self.failures.append("%s: %.3e > %.1e" % (name, err, tol))


def poly(c0, c1=0.0, c2=0.0):
    """c0 + c1 t + c2/2 t^2 and its derivative."""
    f = lambda t: c0 + c1 * t + c2 / 2 * t**2  # noqa: E731
    df = lambda t: c1 + c2 * t  # noqa: E731
    return f, df


def rot_from_quat(q):
    q0, q1, q2, q3 = q
    return [
        [1 - 2 * (q2 * q2 + q3 * q3), 2 * (q1 * q2 - q0 * q3), 2 * (q1 * q3 + q0 * q2)],
        [2 * (q1 * q2 + q0 * q3), 1 - 2 * (q1 * q1 + q3 * q3), 2 * (q2 * q3 - q0 * q1)],
        [2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1), 1 - 2 * (q1 * q1 + q2 * q2)],
    ]


# (t, input poly (g0, w0, a1), bend poly (b0, bd, bdd), phase, inertia, T_L)
CASES = [
    (0.37, (0.3, 10.0, 2.0), (0.5, 0.2, -0.2), 0.2, (0.01, 0.02, 0.015), 3.0),
    (0.0, (0.0, 0.5, 0.0), (math.pi / 6, 0, 0), 0.0, (0.026,) * 3, 0.0),
    (1.3, (1000.3, 7.0, -0.5), (0.09, 0.0, 0.0), math.pi / 2, (0.0, 0.0, 0.0), 12.0),
    (0.05, (-2.0, -30.0, 100.0), (1.3, -1.0, 4.0), -0.7, (0.3, 0.1, 0.25), -5.0),
    (2.0, (0.8, 3.0, 0.0), (0.7, 0.0, 0.0), 0.0, (0.013, 0.052, 0.013), 1.0),
    (0.5, (0.1, 10.0, 0.0), (math.radians(80), 0.0, 0.0), 0.4, (1.0, 2.0, 3.0), 2.0),
]
