"""Files a whole test session shares across pytest-xdist's workers: the folder
they share and `shared`, a value made once for all of them."""

import shutil
from pathlib import Path


def session_folder(config, tmp_path_factory, name: str) -> Path:
    """A folder every process of the test session shares: pytest-xdist's workers
    (their config has `workerinput`; a child pytest that inherited a worker's
    environment does not) each have their own base temp below one common parent."""
    base = tmp_path_factory.getbasetemp()
    folder = (base.parent if hasattr(config, "workerinput") else base) / name
    folder.mkdir(exist_ok=True)
    return folder


def shared(config, tmp_path_factory, name: str, make):
    """make(folder) -> a picklable value (a run, a path in `folder`), made at most
    once per test session however many xdist workers ask, as `built` builds: for a
    module's costly fixture, whose tests the workers share out."""
    import fcntl
    import pickle

    folder = session_folder(config, tmp_path_factory, "shared") / name
    with open(f"{folder}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        done = Path(f"{folder}.pickle")
        if not done.exists():
            shutil.rmtree(folder, ignore_errors=True)  # a make that failed half way
            folder.mkdir()
            done.write_bytes(pickle.dumps(make(folder)))
        return pickle.loads(done.read_bytes())
