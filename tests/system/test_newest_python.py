"""Issue 33 item 1, shown by running: in Debian sid roots whose only CPython is
3.14, or 3.15, a plain C host compiled there by its gcc runs 10^4 steps of the FMI
2.0 and the FMI 3.0 FMU, equal to FMPy's run here to 1e-12: the runtime finds that
Python and starts it through PEP 741's API. A minor missing from the runtime's
table of minors (config_layout.h) fails here. FMPy on sid's python3 (3.14) runs
both FMUs there, equal to FMPy's run here: the runtime joins that interpreter.

The roots are laid out once and cached (tests/system/sid_roots.py)."""

import shutil
import tempfile
from pathlib import Path

import numpy as np
import pytest
from debian_root import RootUnavailable, in_root
from sid_roots import MINORS, prepare
from test_c_host import DT, HOST_RUN, SETTINGS, STEPS, fmpy_reference
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


FMPY_THERE = """
import sys
import numpy as np
from fmpy import simulate_fmu
settings, stop, dt = {settings!r}, {stop!r}, {dt!r}
result = simulate_fmu(sys.argv[1], stop_time=stop, output_interval=dt, start_values=settings)
np.save(sys.argv[2], result)
"""


@pytest.mark.parametrize("fmi", [2, 3])
def test_fmpy_on_sids_python_3_14_runs_the_fmu(request, tmp_path, fmi):
    try:
        root = prepare(14, fmpy=True)
    except RootUnavailable as reason:
        pytest.fail(f"cannot lay out the sid root with FMPy: {reason}")
    here = Path(tempfile.mkdtemp(prefix="cardan-joint-", dir=root / "tmp"))
    try:
        fmu = request.getfixturevalue(FMUS[fmi][1])
        shutil.copy(fmu, here / fmu.name)
        script = FMPY_THERE.format(stop=STEPS * DT, dt=DT, settings=SETTINGS)
        (here / "run.py").write_text(script)
        there = Path("/tmp") / here.name
        command = f"python3 {there / 'run.py'} {there / fmu.name} {there / 'result.npy'}"
        run = in_root(root, command, timeout=900)
        assert run.returncode == 0, run.stderr[-2000:]
        ours, theirs = np.load(here / "result.npy"), fmpy_reference(fmu)
        assert ours.dtype == theirs.dtype and len(ours) == STEPS + 1
        for name in theirs.dtype.names:
            np.testing.assert_allclose(ours[name], theirs[name], rtol=1e-12, atol=0, err_msg=name)
    finally:
        shutil.rmtree(here, ignore_errors=True)
