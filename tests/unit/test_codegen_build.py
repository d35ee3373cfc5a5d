"""What the build makes of a model's step (build/step_source.py, fmi/native's
generated.c): the joint's step in C, with life and without; a step the generator cannot
translate, or one off the runtime's convention, stays in Python and the build
says why; the runtime uses a compiled step only when its sizes are the slave's."""

import subprocess
from dataclasses import replace
from pathlib import Path

import codegen_samples as samples
import pytest

from cardan_joint.build import step_source
from cardan_joint.build.step_source import generated_step, install_runtime
from cardan_joint.fmi import native
from cardan_joint.fmi.native import C_FLAGS, GENERATED_STEP, NativeBuildError, compiler
from cardan_joint.models import discover

JOINT = discover()["UniversalJoint"]
NATIVE = Path(native.__file__).parent


def test_the_joints_step_is_generated_with_life_and_without(capsys):
    step = generated_step(JOINT, {"life": False}, "UniversalJointNoLife")
    assert step is not None and step.name == GENERATED_STEP
    assert step.arguments[:3] == ("time", "h", "turns")
    with_life = generated_step(JOINT, {"life": True}, "UniversalJoint")
    assert with_life is not None
    assert with_life.arguments[9:11] == ("life_consumed", "life_consumed_error")
    assert with_life.arguments[-1] == "life_min_angle"
    assert capsys.readouterr().err == ""


def test_an_untranslatable_step_stays_in_python_and_the_build_says_why(capsys):
    copied = replace(JOINT, step=lambda settings: samples.with_list)
    assert generated_step(copied, {"life": False}, "CopiedJoint") is None
    said = capsys.readouterr().err
    assert "CopiedJoint's step runs in Python" in said
    assert "`[x, x]` at " in said and "codegen_samples.py:" in said


@pytest.mark.parametrize("step", [samples.loops, samples.misordered], ids=lambda f: f.__name__)
def test_a_step_off_the_runtimes_convention_stays_in_python(capsys, step):
    copied = replace(JOINT, step=lambda settings: step)
    assert generated_step(copied, {"life": False}, "CopiedJoint") is None
    said = capsys.readouterr().err
    assert "CopiedJoint's step runs in Python" in said
    assert "are not (time, h, the 7 values of step_state(), then ('input_speed'," in said


def test_a_generated_step_that_does_not_compile_stays_in_python(monkeypatch, capsys):
    installed = []

    def install(fmu, model_name, fmi_version, step=None):
        installed.append(step)
        if step is not None:
            raise NativeBuildError("compiling the loader failed: generated_step.c:1: error")

    monkeypatch.setattr(step_source, "install_loader", install)
    step = generated_step(JOINT, {"life": False}, "UniversalJointNoLife")
    install_runtime("joint.fmu", "UniversalJointNoLife", 2, step)
    assert installed == [step, None]
    said = capsys.readouterr().err
    assert "UniversalJointNoLife's step runs in Python: its C did not compile" in said
    assert "generated_step.c:1: error" in said


def test_a_runtime_that_does_not_compile_fails_the_build(monkeypatch):
    def install(fmu, model_name, fmi_version, step=None):
        raise NativeBuildError("no C compiler")

    monkeypatch.setattr(step_source, "install_loader", install)
    with pytest.raises(NativeBuildError, match="no C compiler"):
        install_runtime("joint.fmu", "UniversalJointNoLife", 2, None)


HARNESS = """
#include "fast_path.h"
#include <stdio.h>
int generated_step(const double *arguments, double *results) { return 0; }
const long generated_step_sizes[2] = {ARGUMENTS, RESULTS};
int main(void)
{
    struct fast_path fast = {.inputs = 6, .known_size = 12, .outputs = 20, .state_size = 7};
    printf("%d", generated_attach(&fast));
    return 0;
}
"""


@pytest.mark.parametrize(
    "arguments, results, used",
    [(21, 33, 1), (15, 33, 1), (22, 33, 0), (14, 33, 0), (21, 34, 0), (21, 32, 0)],
)
def test_the_runtime_uses_a_step_only_when_its_sizes_are_the_slaves(
    tmp_path, arguments, results, used
):
    """(t, h, 7 state values, 6 inputs and up to 6 parameters) -> (7 + 6 + 20)."""
    harness = tmp_path / "harness.c"
    harness.write_text(
        HARNESS.replace("ARGUMENTS", str(arguments)).replace("RESULTS", str(results))
    )
    flags = [f for f in C_FLAGS if f not in ("-shared", "-fPIC")]
    program = tmp_path / "harness"
    sources = [str(harness), str(NATIVE / "generated.c")]
    defines = ['-DMODEL_IDENTIFIER="harness"', "-DGENERATED_STEP"]
    command = [*compiler(), *flags, f"-I{NATIVE}", *defines, *sources, "-o", str(program)]
    subprocess.run(command, check=True, capture_output=True)
    assert subprocess.run([program], capture_output=True, text=True).stdout == str(used)
