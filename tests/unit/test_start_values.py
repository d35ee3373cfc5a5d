"""Every start value a model description declares reads back as the FMU's own
value bit for bit, for every model and both FMI versions.

A host that applies XML start values (as SSP tools and libcosim do) must get the
numbers the FMU itself starts from. The descriptions are made by the slaves'
own `to_xml`, the call the builders embed in the FMU, so no FMU is built here.
"""

import struct

import pytest
from pythonfmu import Fmi2Slave
from pythonfmu3 import Fmi3Slave

from cardan_joint.fmi.model_description import start_text
from cardan_joint.fmi.slave import ModelSlave
from cardan_joint.fmi.slave3 import ModelSlave3
from cardan_joint.models import discover

MODELS = discover()


def _bits(value: float) -> bytes:
    return struct.pack("<d", value)


def _slave(folder: str, fmi_version: int):
    if fmi_version == 2:
        cls = type("Fmu", (ModelSlave, Fmi2Slave), {"model_folder": folder})
    else:
        cls = type("Fmu", (ModelSlave3, Fmi3Slave), {"model_folder": folder})
    return cls(instance_name="startValues", resources=".")


def _declared_starts(slave, fmi_version: int) -> dict:
    """{value reference: [start values]} as the description's text reads back."""
    root = slave.to_xml()  # the element tree the builder serialises into the FMU
    starts = {}
    for node in root.find("ModelVariables"):
        holder = node.find("Real") if fmi_version == 2 else node
        if holder is not None and holder.get("start") is not None:
            reference = int(node.get("valueReference"))
            starts[reference] = [float(text) for text in holder.get("start").split()]
    return starts


@pytest.mark.parametrize("fmi_version", [2, 3])
@pytest.mark.parametrize("key", sorted(MODELS))
def test_start_values_read_back_as_the_fmus_own(key, fmi_version):
    spec = MODELS[key]
    if fmi_version not in spec.fmi_versions:
        pytest.skip(f"{key} is not built for FMI {fmi_version}")
    slave = _slave(spec.folder, fmi_version)
    declared = _declared_starts(slave, fmi_version)
    assert declared, f"{key}: no start value declared"
    for reference, values in declared.items():
        own = slave.get_real([reference]) if fmi_version == 2 else slave.get_float64([reference])
        assert [_bits(v) for v in values] == [_bits(v) for v in own], (key, reference, values, own)


def test_a_start_that_sixteen_digits_round_wrongly_is_written_exactly():
    # 80 degrees: %.16g gives 1.396263401595464, another double.
    value = 1.3962634015954636
    assert float(f"{value:.16g}") != value
    assert float(start_text("max_bend_angle", {"max_bend_angle": value})) == value


def test_an_array_start_lists_its_elements_and_a_missing_one_is_named():
    starts = {"q_0": 0.1, "q_1": 1 / 3}
    assert start_text("q", starts, ("q_0", "q_1")) == "0.1 0.3333333333333333"
    with pytest.raises(ValueError, match="no start value of q_2 \\(q\\)"):
        start_text("q", starts, ("q_0", "q_1", "q_2"))
