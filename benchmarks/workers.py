"""What `python -m benchmarks --worker REQUEST` runs (timing.in_fresh_process,
and section 6's FMPy loop under callgrind): the request and the answer in JSON."""

import json

from .accuracy import worker_accuracy
from .growth import worker_tracemalloc
from .instructions import worker_instructions
from .step_cost import worker_loop, worker_simulate
from .vectorized import worker_scalar, worker_trigonometry, worker_vector

WORKERS = {
    "loop": worker_loop,
    "simulate": worker_simulate,
    "tracemalloc": worker_tracemalloc,
    "accuracy": worker_accuracy,
    "vector": worker_vector,
    "scalar": worker_scalar,
    "trigonometry": worker_trigonometry,
    "instructions": worker_instructions,
}


def run_worker(request: str) -> None:
    arguments = json.loads(request)
    kind = arguments.pop("kind")
    print(json.dumps(WORKERS[kind](**arguments)))
