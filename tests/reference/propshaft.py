"""Independent high-precision reference for the propshaft (models/propshaft/README.md).

Built from the geometric contract only, never from the single joint's closed
forms: pin vectors, Rodrigues rotations and cross products in 3-D at mpmath
precision. Everything is a function of the input angle gamma_0 alone (the
geometry is constant), differentiated with a central three-point stencil at
`3 * dps` working digits and step 10**-dps (truncation ~10**-2dps, cancellation
~10**-dps), so first and second derivatives are exact far below double
precision.

Dynamics by Lagrange, not by the joint's torque path: with the kinetic energy
E = 1/2 m(gamma_0) omega_0^2, m = sum J_k (dgamma_k/dgamma_0)^2 + sum over
crosspieces of W.I W (W: body angular velocity per unit input speed, [W]x =
R^T dR/dgamma_0, R = [p_k, q_k, p_k x q_k]), the virtual work of the input
torque and the load gives T_in = T_L dgamma_N/dgamma_0 + m alpha_0 + m'/2 omega_0^2.
"""

import mpmath as mp

DPS = 30


def _vec(*xs):
    return mp.matrix([[x] for x in xs])


def _cross(a, b):
    return _vec(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _unit(a):
    return a / mp.sqrt(_dot(a, a))


def _rotate(axis, angle, v):
    """Rodrigues: v turned by `angle` right-handed about the unit `axis`."""
    c, s = mp.cos(angle), mp.sin(angle)
    return v * c + _cross(axis, v) * s + axis * (_dot(axis, v) * (1 - c))


class PropshaftReference:
    def __init__(
        self, side_angles, top_angles, phases, shaft_inertias=None, crosspiece_inertia=(0, 0, 0)
    ):
        self.n = len(side_angles) - 1
        with mp.workdps(3 * DPS):
            self.d = [
                _unit(_vec(1, mp.tan(mp.mpf(t)), mp.tan(mp.mpf(s))))
                for s, t in zip(side_angles, top_angles)
            ]
            z = _vec(0, 0, 1)
            self.e = [_unit(z - d * _dot(z, d)) for d in self.d]
        self.phases = [mp.mpf(p) for p in phases]
        self.J = [mp.mpf(j) for j in (shaft_inertias or [0] * (self.n - 1))]
        self.I = [mp.mpf(i) for i in crosspiece_inertia]

    def working_angles(self):
        return [mp.acos(_dot(self.d[k - 1], self.d[k])) for k in range(1, self.n + 1)]

    def _construct(self, gamma0, guesses):
        """(shaft angles gamma_1..N, crosspiece frames) at input angle gamma0."""
        pin = _rotate(self.d[0], gamma0, self.e[0])
        angles, frames = [], []
        for k in range(1, self.n + 1):
            d, e = self.d[k], self.e[k]
            q = _unit(_cross(d, pin))
            frames.append((pin, q, _cross(pin, q)))
            raw = mp.atan2(_dot(_cross(e, q), d), _dot(e, q)) - k * mp.pi / 2
            angles.append(raw + 2 * mp.pi * mp.nint((guesses[k - 1] - raw) / (2 * mp.pi)))
            if k < self.n:
                pin = _rotate(d, self.phases[k - 1], q)
        return angles, frames

    def start_offsets(self, gamma0):
        """gamma_k - gamma_0 (k = 1..N) at `gamma0`, gamma_k on the branch nearest
        gamma0 (the contract)."""
        with mp.workdps(3 * DPS):
            g0 = mp.mpf(gamma0)
            return [a - g0 for a in self._construct(g0, [g0] * self.n)[0]]

    def at(self, gamma0, speed, acceleration, load_torque, branch_offsets):
        """All quantities at input angle gamma0; `branch_offsets` (gamma_k - gamma_0 at
        the start, from `start_offsets`) fix each shaft's branch: the offset varies
        by less than pi over a revolution for the layouts tested."""
        with mp.workdps(3 * DPS):
            g0 = mp.mpf(gamma0)
            h = mp.mpf(10) ** -DPS
            guesses = [g0 + o for o in branch_offsets]
            samples = [
                self._construct(g0 + s * h, [x + s * h for x in guesses]) for s in (-1, 0, 1)
            ]
            (a_m, f_m), (a_0, f_0), (a_p, f_p) = samples
            d1 = [(p - m) / (2 * h) for p, m in zip(a_p, a_m)]
            d2 = [(p - 2 * c + m) / h**2 for p, c, m in zip(a_p, a_0, a_m)]
            m_value, m_slope = mp.mpf(0), mp.mpf(0)
            for k in range(self.n - 1):
                m_value += self.J[k] * d1[k] ** 2
                m_slope += 2 * self.J[k] * d1[k] * d2[k]
            for fm, f0, fp in zip(f_m, f_0, f_p):
                R = [mp.matrix(3, 3) for _ in range(3)]
                for col in range(3):
                    for row in range(3):
                        R[0][row, col] = f0[col][row]
                        R[1][row, col] = (fp[col][row] - fm[col][row]) / (2 * h)
                        R[2][row, col] = (fp[col][row] - 2 * f0[col][row] + fm[col][row]) / h**2
                W = R[0].T * R[1]  # [W]x per unit input speed
                dW = R[1].T * R[1] + R[0].T * R[2]  # its derivative in gamma_0
                w = [(W[2, 1] - W[1, 2]) / 2, (W[0, 2] - W[2, 0]) / 2, (W[1, 0] - W[0, 1]) / 2]
                dw = [
                    (dW[2, 1] - dW[1, 2]) / 2,
                    (dW[0, 2] - dW[2, 0]) / 2,
                    (dW[1, 0] - dW[0, 1]) / 2,
                ]
                m_value += sum(i * x * x for i, x in zip(self.I, w))
                m_slope += sum(2 * i * x * y for i, x, y in zip(self.I, w, dw))
            w0, a0, load = mp.mpf(speed), mp.mpf(acceleration), mp.mpf(load_torque)
            return {
                "angles": [+x for x in a_0],
                "speeds": [x * w0 for x in d1],
                "accelerations": [x * w0**2 + y * a0 for y, x in zip(d1, d2)],
                "input_torque": load * d1[-1] + m_value * a0 + m_slope * w0**2 / 2,
                "kinetic_energy": m_value * w0**2 / 2,
                "speed_ratio": d1[-1],
            }

    def speed_ratio_fluctuation(self, samples=96):
        """max - min of dgamma_N/dgamma_0 over a full revolution: sign changes of
        its derivative on a grid, each refined by mpmath's bracketing solver."""
        offsets = self.start_offsets(0)

        def ratio_and_slope(x):
            r = self.at(x, 1, 0, 0, offsets)
            return r["speed_ratio"], r["accelerations"][-1]

        grid = [2 * mp.pi * i / samples for i in range(samples + 1)]
        values = [ratio_and_slope(x) for x in grid]
        extremes = [v[0] for v in values]
        for (x0, (_, s0)), (x1, (_, s1)) in zip(zip(grid, values), zip(grid[1:], values[1:])):
            if s0 * s1 < 0:
                with mp.workdps(20):
                    root = mp.findroot(lambda x: ratio_and_slope(x)[1], (x0, x1), solver="anderson")
                extremes.append(ratio_and_slope(root)[0])
        return max(extremes) - min(extremes)
