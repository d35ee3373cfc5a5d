"""The propshaft's constant geometry (models/propshaft/README.md, "Geometry").

Frame: x along the nominal driveline, z up, y = z x x. Shaft k points along
d_k = unit(1, tan(top_k), tan(side_k)); e_k is the unit vector normal to d_k
nearest +z. Joint k (between shafts k-1 and k) is a single Cardan joint in its
own frame: input axis d_{k-1}, hinge axis Y_k = unit(d_{k-1} x d_k), bend-plane
directions X_k = Y_k x d_{k-1} (input side) and X2_k = Y_k x d_k (output side),
working angle beta_k = angle(d_{k-1}, d_k). The single joint's closed forms
(`physics.response`) then hold with the pin angle psi_k measured from X_k.

Every shaft angle is measured from its e_k, so the chain needs per joint the
angle b_k from e_{k-1} to X_k about d_{k-1} and the twist c_k = a_k - b_k,
a_k the angle from e_k to X2_k about d_k. Pure math, floats only: evaluated
once per start.
"""

import math
from typing import NamedTuple

from ...physics.revolutions import split_angle

HALF_PI = 0.5 * math.pi
TWO_PI = 2.0 * math.pi


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _unit(a):
    norm = math.sqrt(_dot(a, a))
    return (a[0] / norm, a[1] / norm, a[2] / norm)


def shaft_direction(side_angle: float, top_angle: float):
    """d = unit(1, tan top, tan side): side-view angle rising along x, top-view toward +y."""
    return _unit((1.0, math.tan(top_angle), math.tan(side_angle)))


def reference_vector(direction):
    """e: the unit vector normal to `direction` nearest +z (defined for |side angle| < 90 deg)."""
    return _unit(
        (
            -direction[2] * direction[0],
            -direction[2] * direction[1],
            1.0 - direction[2] * direction[2],
        )
    )


def signed_angle(u, v, axis) -> float:
    """Angle from u to v (both normal to the unit `axis`), right-handed about it."""
    return math.atan2(_dot(_cross(u, v), axis), _dot(u, v))


def wrapped(angle: float) -> float:
    """`angle` reduced to (-pi, pi], exactly however large (whole turns split off)."""
    turns = split_angle(angle)
    reduced = turns.fraction + turns.fraction_error
    return reduced - TWO_PI if reduced > math.pi else reduced


class JointGeometry(NamedTuple):
    working_angle: float  # beta_k, in [0, pi)
    pin_offset: float  # b_k: from e_{k-1} to X_k about d_{k-1}
    twist: float  # c_k = a_k - b_k, reduced to (-pi, pi]
    plane_normal: tuple  # Y_k, the joint's hinge axis


class Layout(NamedTuple):
    """A propshaft's geometry: N + 1 shafts, N joints, N - 1 yoke phasings."""

    directions: tuple[tuple, ...]
    references: tuple[tuple, ...]
    joints: tuple[JointGeometry, ...]
    phases: tuple[float, ...]  # phi_1 .. phi_{N-1}, reduced to (-pi, pi]

    @property
    def working_angles(self):
        return tuple(j.working_angle for j in self.joints)

    def with_phases(self, phases) -> "Layout":
        return self._replace(phases=tuple(wrapped(float(p)) for p in phases))


def _joint(d_in, e_in, d_out, e_out) -> JointGeometry:
    normal = _cross(d_in, d_out)
    sine = math.sqrt(_dot(normal, normal))
    # atan2 keeps full relative precision for small working angles (acos does not).
    beta = math.atan2(sine, _dot(d_in, d_out))
    if sine == 0.0:
        # Straight joint: the hinge axis is arbitrary; any choice gives the same
        # motion (beta = 0) and twist 0, as the shafts share d and e.
        normal = _cross(d_in, e_in)
    else:
        normal = (normal[0] / sine, normal[1] / sine, normal[2] / sine)
    x_in, x_out = _cross(normal, d_in), _cross(normal, d_out)
    b = signed_angle(e_in, x_in, d_in)
    a = signed_angle(e_out, x_out, d_out)
    return JointGeometry(beta, b, wrapped(a - b), normal)


def layout(side_angles, top_angles, phases=()) -> Layout:
    """The geometry of shafts 0..N with the given angles (rad) and N - 1 yoke phasings."""
    if len(side_angles) != len(top_angles) or len(side_angles) < 2:
        raise ValueError("give side and top angles for the same number (>= 2) of shafts")
    if len(phases) != len(side_angles) - 2:
        raise ValueError(
            f"{len(side_angles) - 2} yoke phasing(s) expected for "
            f"{len(side_angles)} shafts, got {len(phases)}"
        )
    directions = tuple(shaft_direction(s, t) for s, t in zip(side_angles, top_angles))
    references = tuple(reference_vector(d) for d in directions)
    joints = tuple(
        _joint(directions[k - 1], references[k - 1], directions[k], references[k])
        for k in range(1, len(directions))
    )
    return Layout(directions, references, joints, tuple(wrapped(float(p)) for p in phases))


def plane_angle(geometry: Layout, shaft: int) -> float:
    """Signed angle from joint `shaft`'s plane to joint `shaft + 1`'s, right-handed
    about intermediate shaft `shaft` (1 <= shaft <= N - 1), in (-pi, pi]."""
    first, second = geometry.joints[shaft - 1], geometry.joints[shaft]
    return signed_angle(first.plane_normal, second.plane_normal, geometry.directions[shaft])
