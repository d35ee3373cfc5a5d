"""Issue 14: 8 instances in 8 threads of one process (FMPy's low-level API, each
thread its own instance, odd ones fed bad inputs) give the results and the
messages of a serial run, each bad input's message in its own instance's log."""

import math
import threading

from cardan_joint.framework import Refusal
from cardan_joint.host.instance import FmuInstance
from cardan_joint.models.universal_joint.refusals import JointReason

THREADS = 8
STEPS = 1000
H = 1e-3


def bad_bend(k):
    """A bend angle beyond the guard that only instance `k` is ever fed."""
    return 1.40 + 0.001 * k


def scenario(model_description, unzipped, k, together=None):
    """Run instance `k`'s inputs; return its trace (status, outputs) and its log.
    `together`: a barrier every thread meets before its first step and half way,
    so the runs overlap however the threads are scheduled (a step in C is short
    enough for a thread to finish before another starts)."""
    messages = []
    joint = FmuInstance(
        model_description,
        unzipped,
        name=f"joint{k}",
        messages=messages,
        start_values=dict(yoke_phase=0.1 * k, crosspiece_inertia_2=0.01 + 0.001 * k),
    )
    trace = []
    try:
        for n in range(STEPS):
            if together is not None and n in (0, STEPS // 2):
                together.wait()
            joint.set(
                input_speed=10.0 + k + 0.01 * n,
                bend_angle=0.02 * k + 1e-4 * n,
                load_torque=5.0 * k - 0.1 * n,
            )
            if k % 2 and n % 50 == 25:  # odd instances: a refused step now and then
                joint.set(bend_angle=bad_bend(k))
                trace.append((joint.try_step(H), None))
                joint.set(input_speed=math.nan if n % 100 == 25 else 1.0)
                trace.append((None, tuple(joint.get_outputs().values())))  # held outputs
                continue
            trace.append((joint.try_step(H), tuple(joint.get_outputs().values())))
    finally:
        joint.close()
    return trace, messages


def test_eight_threads_give_the_serial_results_and_messages(model_description, unzipped_fmu):
    serial = [scenario(model_description, unzipped_fmu, k) for k in range(THREADS)]
    threaded = [None] * THREADS
    errors = []
    together = threading.Barrier(THREADS, timeout=120)

    def worker(k):
        try:
            threaded[k] = scenario(model_description, unzipped_fmu, k, together)
        except BaseException as error:  # reported below, not lost in the thread
            errors.append((k, error))

    threads = [threading.Thread(target=worker, args=(k,)) for k in range(THREADS)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join(timeout=120)
    assert not errors and not any(thread.is_alive() for thread in threads), errors
    for k in range(THREADS):
        (trace, messages), (serial_trace, serial_messages) = threaded[k], serial[k]
        assert trace == serial_trace, k  # bit for bit, every step
        assert messages == serial_messages, k
        refusals = [Refusal.from_message(text) for status, _, text in messages if status == 3]
        if k % 2:
            assert len(refusals) == STEPS // 50
            # Each refusal names this instance's own bad value: no message crossed over.
            assert {(r.code, r.value) for r in refusals} == {(JointReason.BEND_ANGLE, bad_bend(k))}
            # Held-output warnings too: this instance's bend angle, or its NaN speed.
            for _, _, text in messages:
                refusal = Refusal.from_message(text)
                assert repr((refusal.variable, refusal.value)) in (
                    repr(("bend_angle", bad_bend(k))),
                    repr(("input_speed", math.nan)),
                ), text
        else:
            assert messages == [] and all(status == 0 for status, _ in trace)
