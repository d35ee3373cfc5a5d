"""What every SSP the project writes must be, checked by tools other than ours:
pyssp-standard's schema validation and connection checks (every one of them, the
unconnected inputs included: 0 errors and 0 warnings), each connector of the kind
its FMU variable's causality says (read by pyssp-standard), each bound parameter
an FMU parameter or input and no connector, one parameter set name (the one Ecos
applies), and OMSimulator's vendor annotations as its importer reads them (by
literal prefixed names, src/OMSimulatorLib/Model.cpp and System.cpp)."""

import tempfile
import warnings
import zipfile
from pathlib import Path
from xml.etree.ElementTree import parse

SSD = "{http://ssp-standard.org/SSP1/SystemStructureDescription}"
SSC = "{http://ssp-standard.org/SSP1/SystemStructureCommon}"
SSV = "{http://ssp-standard.org/SSP1/SystemStructureParameterValues}"
OMS = "{https://raw.githubusercontent.com/OpenModelica/OMSimulator/master/schema/oms.xsd}"


def _oms_information(parent):
    """The oms:SimulationInformation of `parent`'s OMSimulator annotation, or None."""
    for annotation in parent.findall(f"{SSD}Annotations/{SSC}Annotation"):
        if annotation.get("type") == "org.openmodelica":
            return annotation.find(f"{OMS}Annotations/{OMS}SimulationInformation")
    return None


def _causalities(folder: Path, source: str) -> dict:
    """{variable: causality} of the FMU `source` in the extracted SSP, as pyssp-standard
    reads its model description."""
    from pyssp_standard.fmu import ModelDescription

    description = folder / f"{source}.modelDescription.xml"
    description.write_bytes(zipfile.ZipFile(folder / source).read("modelDescription.xml"))
    return {v.name: v.causality for v in ModelDescription(description).get()}


def check_ssp_for_every_host(path) -> dict:
    """Raise AssertionError unless the SSP `path` passes; return {component: {bound
    parameter: value}} for the caller's own checks."""
    from pyssp_standard.ssd import SSD as PysspSSD
    from pyssp_standard.ssv import SSV as PysspSSV

    with tempfile.TemporaryDirectory(prefix="ssp_check_") as folder, warnings.catch_warnings():
        warnings.simplefilter("error")  # pyssp-standard's own warnings too
        folder = Path(folder)
        zipfile.ZipFile(path).extractall(folder)
        ssd_path = folder / "SystemStructure.ssd"
        ssd = PysspSSD(ssd_path)
        ssd.__check_compliance__()  # raises on any schema violation
        problems = ssd.check_connections(unconnected_inputs=True, connector_not_in_system=True)
        assert problems == [], problems

        root = parse(ssd_path).getroot()
        system = root.find(f"{SSD}System")
        bound = {}
        for component in system.iter(f"{SSD}Component"):
            name = component.get("name")
            causality = _causalities(folder, component.get("source"))
            kinds = {c.get("name"): c.get("kind") for c in component.iter(f"{SSD}Connector")}
            for connector, kind in kinds.items():
                assert causality.get(connector) == kind, (
                    f"{name}.{connector}: connector kind {kind}, FMU causality "
                    f"{causality.get(connector)}"
                )
            bound[name] = {}
            for binding in component.iter(f"{SSD}ParameterBinding"):
                ssv_path = folder / binding.get("source")
                PysspSSV(ssv_path).__check_compliance__()
                parameter_set = parse(ssv_path).getroot()
                assert parameter_set.get("name") == system.get("name"), (
                    f"{name}: parameter set {parameter_set.get('name')!r} is not the one "
                    f"named after the system, which Ecos applies"
                )
                for parameter in parameter_set.iter(f"{SSV}Parameter"):
                    variable = parameter.get("name")
                    assert variable not in kinds, f"{name}.{variable} is bound and a connector"
                    assert causality.get(variable) in ("parameter", "input"), (
                        f"{name}.{variable} is bound but the FMU has it as "
                        f"{causality.get(variable)}"
                    )
                    bound[name][variable] = float(parameter.find(f"{SSV}Real").get("value"))
        assert system.find(f"{SSD}ParameterBindings") is None, "a system-level binding"

        master = _oms_information(system)
        assert master is not None, "no OMSimulator annotation on the system"
        fixed_step = master.find(f"{OMS}FixedStepMaster")
        assert fixed_step is not None and fixed_step.get("description") == "oms-ma"
        assert float(fixed_step.get("stepSize")) > 0
        experiment = root.find(f"{SSD}DefaultExperiment")
        information = _oms_information(experiment)
        assert information is not None, "no OMSimulator annotation under DefaultExperiment"
        assert information.get("resultFile")
    return bound
