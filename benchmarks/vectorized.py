"""3. Throughput of `joint_response` on numpy arrays against a scalar loop.

Each rate in a fresh process: how earlier work left malloc's heap changes the
time of a numpy call on large arrays by up to 1.5x.
"""

import math
import time

from .timing import best_time, in_fresh_process, met

# Blocks of this many samples stay in the L2 cache through joint_response's
# temporaries; one call on 10^6 samples streams every temporary through memory.
CHUNK = 8192
VECTOR_SPEEDUP_GOAL = 50.0


def joint_samples(count, seed=6):
    """Arguments of joint_response, every one an array of `count` samples."""
    import numpy as np

    rng = np.random.default_rng(seed)
    return (
        rng.uniform(0.0, 2 * math.pi, count),  # psi
        rng.uniform(-1.2, 1.2, count),  # bend angle
        rng.uniform(-300.0, 300.0, count),  # input speed
        rng.uniform(-50.0, 50.0, count),  # input acceleration
        rng.uniform(-1.0, 1.0, count),  # bend rate
        rng.uniform(-5.0, 5.0, count),  # bend acceleration
        tuple(rng.uniform(0.0, 0.05, count) for _ in range(3)),  # inertias
        rng.uniform(-500.0, 500.0, count),
    )  # load torque


def in_chunks(samples, size):
    count = len(samples[0])
    for start in range(0, count, size):
        part = slice(start, start + size)
        yield tuple(tuple(i[part] for i in x) if isinstance(x, tuple) else x[part] for x in samples)


def time_scalar_loop(samples):
    from cardan_joint.physics import joint_response

    psi, beta, w1, a1, rb, ab, inertias, load = (
        [i.tolist() for i in x] if isinstance(x, tuple) else x.tolist() for x in samples
    )
    rows = list(zip(psi, beta, w1, a1, rb, ab, zip(*inertias), load))
    start = time.perf_counter()
    for p, b, w, a, r, c, inertia, torque in rows:
        joint_response(p, b, w, a, r, c, inertia, torque)
    return time.perf_counter() - start


def worker_vector(samples, chunk):
    """Samples per second of joint_response on arrays: one call on all samples, or
    consecutive calls on blocks of `chunk` samples."""
    from cardan_joint.physics import joint_response

    arrays = joint_samples(samples)
    if chunk >= samples:
        seconds = best_time(lambda: joint_response(*arrays))
    else:
        seconds = best_time(lambda: [joint_response(*part) for part in in_chunks(arrays, chunk)])
    return {"rate": samples / seconds}


def worker_trigonometry(samples, chunk):
    """Samples per second of joint_response's trigonometric calls alone (sin, cos of
    the half pin angle and of the bend, one atan), in blocks of `chunk`: a ceiling
    for the array path, since numpy has no SIMD float64 sin/cos/atan without AVX-512."""
    import numpy as np

    psi, beta = joint_samples(samples)[:2]

    def trigonometry():
        for start in range(0, samples, chunk):
            half, bend = 0.5 * psi[start : start + chunk], beta[start : start + chunk]
            np.sin(half), np.cos(half), np.sin(bend), np.cos(bend), np.atan(bend)

    return {"rate": samples / best_time(trigonometry)}


def worker_scalar(samples):
    return {"rate": samples / time_scalar_loop(joint_samples(samples))}


def vectorized(sizes):
    return {
        "scalar_rate": in_fresh_process("scalar", samples=sizes.scalar_samples)["rate"],
        "whole_rate": in_fresh_process(
            "vector", samples=sizes.vector_samples, chunk=sizes.vector_samples
        )["rate"],
        "chunked_rate": in_fresh_process("vector", samples=sizes.vector_samples, chunk=CHUNK)[
            "rate"
        ],
        "trigonometry_rate": in_fresh_process(
            "trigonometry", samples=sizes.vector_samples, chunk=CHUNK
        )["rate"],
    }


def vector_rows(vector, sizes):
    whole = vector["whole_rate"] / vector["scalar_rate"]
    chunked = vector["chunked_rate"] / vector["scalar_rate"]
    ceiling = vector["trigonometry_rate"] / vector["scalar_rate"]
    samples = (
        f"{sizes.vector_samples:,} samples vs a scalar loop on "
        f"{sizes.scalar_samples:,} samples (rate scaled)"
    )
    return [
        f"| 3. `joint_response` on numpy arrays, one call on {samples} | "
        f"{vector['whole_rate']:.3g} vs {vector['scalar_rate']:.3g} samples/s: **×{whole:.0f}** | "
        f"≥ ×{VECTOR_SPEEDUP_GOAL:.0f} | {met(whole >= VECTOR_SPEEDUP_GOAL)} |",
        f"| 3. the same in blocks of {CHUNK} samples | {vector['chunked_rate']:.3g} samples/s: "
        f"×{chunked:.0f} | (context) | |",
        f"| 3. ceiling: the array path's 5 trigonometric calls alone (numpy float64 sin, cos, "
        f"atan; blocks of {CHUNK}) | {vector['trigonometry_rate']:.3g} samples/s: "
        f"×{ceiling:.0f} | (context) | |",
    ]
