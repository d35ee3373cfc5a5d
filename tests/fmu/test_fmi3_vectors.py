"""The FMI 3.0 UniversalJoint's vectors for every FMI 3 host.

OMSimulator and Ecos read and write every variable one value at a time
(`fmi3GetFloat64` with nValues 1 per value reference); FMPy and fmusim read
whole arrays. A Float64 array answers only a whole-array read, so by default
the vectors are the FMI 2.0 scalars, which both kinds of host read; the
`--fmi3-arrays` build (the `fmi3_path` fixture) keeps them as arrays.
"""

import struct

import numpy as np
import pytest

from cardan_joint.host.instance import FmuInstance
from cardan_joint.models.universal_joint import variables as table


def _bits(value: float) -> bytes:
    return struct.pack("<d", value)


def test_by_default_every_fmi2_variable_is_an_fmi3_scalar_of_the_same_name(
    fmi3_scalar_path, model_description
):
    from fmpy import read_model_description
    from fmpy.validation import validate_fmu

    assert validate_fmu(str(fmi3_scalar_path)) == []
    fmi3 = read_model_description(str(fmi3_scalar_path))
    assert fmi3.fmiVersion == "3.0"
    assert [v.name for v in fmi3.modelVariables] == ["time"] + [
        v.name for v in model_description.modelVariables
    ]
    assert not any(v.dimensions for v in fmi3.modelVariables)
    # Same causality, unit and start value as the FMI 2.0 variable (start bit for bit).
    fmi2 = {v.name: v for v in model_description.modelVariables}
    for v in fmi3.modelVariables[1:]:
        assert (v.causality, v.variability, v.unit) == (
            fmi2[v.name].causality,
            fmi2[v.name].variability,
            fmi2[v.name].unit,
        )
        if fmi2[v.name].start is not None:
            assert _bits(float(v.start)) == _bits(float(fmi2[v.name].start)), v.name


@pytest.mark.parametrize("step_size, steps", [(1e-3, 200), (0.05, 40)])
def test_a_host_reading_one_value_at_a_time_gets_every_output_as_the_fmi2_fmu(
    fmi3_scalar_path, model_description, unzipped_fmu, step_size, steps
):
    """As OMSimulator does: one fmi3SetFloat64 / fmi3GetFloat64 call per value
    reference, nValues 1; every output equals the FMI 2.0 FMU's bit for bit."""
    fmi2 = FmuInstance(model_description, unzipped_fmu, name="scalars2")
    fmi3 = FmuInstance.open(fmi3_scalar_path, name="scalars3")
    references = {v.name: v.valueReference for v in fmi3.model_description.modelVariables}
    try:
        for k in range(steps + 1):
            t = k * step_size
            inputs = {
                "input_speed": 10.0 + 30.0 * t,
                "input_acceleration": 30.0,
                "bend_angle": 0.3 + 0.2 * t * t,
                "bend_angle_rate": 0.4 * t,
                "bend_angle_acceleration": 0.4,
                "load_torque": 5.0 * np.sin(t),
            }
            fmi2.set(**inputs)
            for name, value in inputs.items():
                fmi3.fmu.setFloat64([references[name]], [value])
            expected = fmi2.get(*table.OUTPUTS)
            for name in table.OUTPUTS:
                (value,) = fmi3.fmu.getFloat64([references[name]], nValues=1)
                assert _bits(value) == _bits(expected[name]), (k, name, value, expected[name])
            for instance in (fmi2, fmi3):
                instance.step(step_size)
    finally:
        fmi2.close()
        fmi3.close()


def test_the_array_build_answers_only_whole_arrays_so_it_is_the_option(fmi3_path):
    """What a one-value-at-a-time host meets in the `--fmi3-arrays` build."""
    from fmpy.fmi1 import FMICallException

    joint = FmuInstance.open(fmi3_path, name="arrays3")
    quaternion = {v.name: v.valueReference for v in joint.model_description.modelVariables}[
        "crosspiece_quaternion"
    ]
    try:
        assert len(joint.fmu.getFloat64([quaternion], nValues=4)) == 4
        with pytest.raises(FMICallException):
            joint.fmu.getFloat64([quaternion], nValues=1)
    finally:
        joint.close()
