"""Issue 33 item 1, shown by running: in Debian sid roots whose only CPython is
3.14, or 3.15, a plain C host compiled there by its gcc runs 10^4 steps of the FMI
2.0 and the FMI 3.0 FMU, equal to FMPy's run here to 1e-12: the runtime finds that
Python and starts it through PEP 741's API. A minor missing from the runtime's
table of minors (config_layout.h) fails here.

The roots are laid out once and cached (tests/system/sid_roots.py)."""

import shutil
import tempfile
from pathlib import Path

import pytest
from debian_root import RootUnavailable, in_root
from sid_roots import MINORS, prepare
from test_c_host import HOST_RUN
from test_older_linux import FMUS, assert_equals_fmpy, host_in_root

pytestmark = pytest.mark.slow


@pytest.fixture(scope="session", params=MINORS, ids=[f"python3.{m}" for m in MINORS])
def sid(request):
    """(root, scratch here, scratch there): a sid root with one CPython, and a folder in it."""
    try:
        root = prepare(request.param)
    except RootUnavailable as reason:
        pytest.fail(f"cannot lay out the sid root: {reason}")
    here = Path(tempfile.mkdtemp(prefix="cardan-joint-", dir=root / "tmp"))
    yield root, here, Path("/tmp") / here.name
    shutil.rmtree(here, ignore_errors=True)


@pytest.mark.parametrize("fmi", [2, 3])
def test_a_c_host_in_sid_runs_the_fmu_with_the_roots_only_cpython(request, sid, fmi):
    root, here, there = sid
    host = host_in_root(root, here, there, fmi)
    shutil.copytree(request.getfixturevalue(FMUS[fmi][0]), here / f"fmu{fmi}")
    command = ["env -i PATH=/usr/bin:/bin", host, HOST_RUN[0], there / f"fmu{fmi}", *HOST_RUN[1:]]
    run = in_root(root, " ".join(map(str, command)), timeout=900)
    assert run.returncode == 0 and "Fatal" not in run.stderr, run.stderr[-2000:]
    assert_equals_fmpy(run.stdout, request.getfixturevalue(FMUS[fmi][1]))
