"""Write a co-simulation system as an SSP archive (SSP 1.0, xml.etree).

`write_ssp` packs the FMUs, a SystemStructure.ssd with their connected
variables as connectors (each of the kind the FMU's causality says) and one
parameter set (.ssv) per component, bound at component level. A bound parameter
is no connector: the standard binds it through the ParameterBinding, and a
connector of kind "parameter" left unconnected is an input without a source
(pyssp-standard warns), while an FMU input bound so (the joint's `bend_angle`)
would be declared a parameter. What the hosts users have apply, read in their
sources and measured:

- OSP libcosim applies component-level bindings and ignores system-level ones;
- Ecos collects component-level bindings into sets by the .ssv's set name and
  applies only the one set the user names (`--parameterSet`,
  `init(parameter_set=)`); with none named it applies none, and each FMU runs on
  its own start values (`driveline_system.build_fmus` builds them at the
  system's values for that reason);
- FMPy's `simulate_ssp` applies no binding itself but takes one parameter set
  with hierarchical names, which `fmpy_parameter_set` builds from the bindings;
- OMSimulator sets every bound value on the FMU variable of that name, and
  needs its vendor annotation to create the root system (the system kind: a
  fixed-step weakly coupled master) and one under DefaultExperiment (else it
  warns of deprecated content).

So every component's set carries the system's name (Ecos: `--parameterSet
<system>` applies them all), and the annotations are OMSimulator's own.
`check_ssp` turns a missing or broken archive into an `SSPError` naming it.
"""

import math
import zipfile
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from xml.etree.ElementTree import Element, ParseError, SubElement, fromstring, indent, tostring

_XML_NAMESPACES = {
    "ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription",
    "ssc": "http://ssp-standard.org/SSP1/SystemStructureCommon",
    "ssv": "http://ssp-standard.org/SSP1/SystemStructureParameterValues",
    "oms": "https://raw.githubusercontent.com/OpenModelica/OMSimulator/master/schema/oms.xsd",
}
# OMSimulator's vendor annotations (src/OMSimulatorLib/ssd/Tags.cpp): a weakly
# coupled system (co-simulation FMUs) with its fixed-step master ("oms-ma"), which
# steps at the SSP's step as the other hosts do.
OMS_ANNOTATION_TYPE = "org.openmodelica"
OMS_MASTER = "oms-ma"
FMU_TYPE = "application/x-fmu-sharedlibrary"
SSV_TYPE = "application/x-ssp-parameter-set"


@dataclass
class Component:
    """One FMU in the system: its instance name, FMU file, the variables connected
    (name -> "input" or "output") and its parameter values (bare variable names)."""

    name: str
    fmu: Path
    connectors: Mapping[str, str]
    parameters: Mapping[str, float] = field(default_factory=dict)

    @property
    def source(self) -> str:
        return f"resources/{Path(self.fmu).name}"

    @property
    def parameter_source(self) -> str:
        return f"resources/{self.name}.ssv"


# start element, start connector, end element, end connector
Connection = tuple[str, str, str, str]


def _qualified(prefix: str, tag: str) -> str:
    # Literal prefixes with the xmlns declarations on the root: ElementTree's
    # register_namespace would change a process-wide registry.
    return f"{prefix}:{tag}"


def _root(tag: str, prefixes, **attributes) -> Element:
    return Element(tag, {**{f"xmlns:{p}": _XML_NAMESPACES[p] for p in prefixes}, **attributes})


def _xml(root: Element) -> bytes:
    indent(root)
    return b'<?xml version="1.0" encoding="UTF-8"?>\n' + tostring(root, encoding="utf-8") + b"\n"


def _oms_annotation(parent: Element, tag: str, **attributes) -> Element:
    """OMSimulator's `<ssd:Annotations><ssc:Annotation type="org.openmodelica">
    <oms:Annotations><oms:{tag} .../>` under `parent`; returns the oms:{tag} element."""
    annotations = SubElement(parent, _qualified("ssd", "Annotations"))
    annotation = SubElement(annotations, _qualified("ssc", "Annotation"), type=OMS_ANNOTATION_TYPE)
    oms = SubElement(annotation, _qualified("oms", "Annotations"))
    return SubElement(oms, _qualified("oms", tag), attributes)


def parameter_set_xml(name: str, values: Mapping[str, float]) -> bytes:
    ssv = lambda tag: _qualified("ssv", tag)  # noqa: E731
    root = _root(ssv("ParameterSet"), ("ssv",), version="1.0", name=name)
    parameters = SubElement(root, ssv("Parameters"))
    for parameter, value in values.items():
        node = SubElement(parameters, ssv("Parameter"), name=parameter)
        SubElement(node, ssv("Real"), value=repr(float(value)))
    return _xml(root)


def _causalities(fmu) -> dict[str, str]:
    """{variable: causality} of the FMU's model description (FMI 2.0 or 3.0)."""
    with zipfile.ZipFile(fmu) as archive:
        root = fromstring(archive.read("modelDescription.xml"))
    variables = root.find("ModelVariables")
    listed = variables if variables is not None else ()
    return {str(v.get("name")): v.get("causality", "local") for v in listed}


def _check_component(component: Component) -> None:
    """Each connector of the kind its FMU variable's causality says, each bound
    parameter an FMU parameter or an input that no connection drives."""
    causality = _causalities(component.fmu)
    for connector, kind in component.connectors.items():
        if kind not in ("input", "output") or causality.get(connector) != kind:
            raise ValueError(
                f"{component.name}: connector {connector!r} is declared an {kind}, but the "
                f"FMU {Path(component.fmu).name} has it as "
                f"{causality.get(connector, 'no variable')}"
            )
    for parameter in component.parameters:
        if parameter in component.connectors:
            raise ValueError(
                f"{component.name}: {parameter!r} is bound as a parameter but connected "
                f"as an {component.connectors[parameter]}"
            )
        if causality.get(parameter) not in ("parameter", "input"):
            raise ValueError(
                f"{component.name}: {parameter!r} is bound, but the FMU "
                f"{Path(component.fmu).name} has it as "
                f"{causality.get(parameter, 'no variable')}, not a parameter or an input"
            )


def system_structure_xml(
    name: str,
    components: list[Component],
    connections: list[Connection],
    stop_time: float,
    step_size: float,
) -> bytes:
    ssd = lambda tag: _qualified("ssd", tag)  # noqa: E731
    root = _root(ssd("SystemStructureDescription"), ("ssd", "ssc", "oms"), version="1.0", name=name)
    system = SubElement(root, ssd("System"), name=name)
    elements = SubElement(system, ssd("Elements"))
    for component in components:
        node = SubElement(
            elements, ssd("Component"), name=component.name, source=component.source, type=FMU_TYPE
        )
        connectors = SubElement(node, ssd("Connectors"))
        for connector, kind in component.connectors.items():
            SubElement(
                SubElement(connectors, ssd("Connector"), name=connector, kind=kind),
                _qualified("ssc", "Real"),
            )
        if component.parameters:
            bindings = SubElement(node, ssd("ParameterBindings"))
            SubElement(
                bindings, ssd("ParameterBinding"), type=SSV_TYPE, source=component.parameter_source
            )
    wires = SubElement(system, ssd("Connections"))
    for start_element, start_connector, end_element, end_connector in connections:
        SubElement(
            wires,
            ssd("Connection"),
            startElement=start_element,
            startConnector=start_connector,
            endElement=end_element,
            endConnector=end_connector,
        )
    information = _oms_annotation(system, "SimulationInformation")
    SubElement(
        information,
        _qualified("oms", "FixedStepMaster"),
        description=OMS_MASTER,
        stepSize=repr(float(step_size)),
    )
    experiment = SubElement(
        root, ssd("DefaultExperiment"), startTime="0.0", stopTime=repr(float(stop_time))
    )
    # OMSimulator's defaults (Model.h), written out: its reader wants the element.
    _oms_annotation(
        experiment,
        "SimulationInformation",
        resultFile=f"{name}_res.mat",
        loggingInterval="0.0",
        bufferSize="10",
    )
    return _xml(root)


def write_ssp(
    path,
    name: str,
    components: list[Component],
    connections: list[Connection],
    stop_time: float,
    step_size: float,
) -> Path:
    """Write the SSP archive `path` (`step_size`: OMSimulator's fixed master step;
    the other hosts take theirs from the caller); return its path."""
    if not (math.isfinite(step_size) and 0.0 < step_size <= stop_time):
        raise ValueError(f"step_size {step_size!r} must be in (0, stop_time = {stop_time!r}]")
    by_name = {c.name: c for c in components}
    for component in components:
        _check_component(component)
    for start_element, start_connector, end_element, end_connector in connections:
        for element, connector, kind in (
            (start_element, start_connector, "output"),
            (end_element, end_connector, "input"),
        ):
            if by_name.get(element) is None or by_name[element].connectors.get(connector) != kind:
                raise ValueError(
                    f"connection {start_element}.{start_connector} -> "
                    f"{end_element}.{end_connector}: {element} has no {kind} "
                    f"connector {connector!r}"
                )
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as archive:
        archive.writestr(
            "SystemStructure.ssd",
            system_structure_xml(name, components, connections, stop_time, step_size),
        )
        for component in components:
            archive.write(component.fmu, component.source)
            if component.parameters:
                # Named after the system: the one set Ecos applies holds every component's.
                archive.writestr(
                    component.parameter_source, parameter_set_xml(name, component.parameters)
                )
    return path


class SSPError(ValueError):
    """A missing or broken SSP archive; the message names the file and the fault."""


def check_ssp(path) -> None:
    """Raise SSPError unless `path` is an SSP archive whose SystemStructure.ssd
    parses and whose components' FMUs are in it."""
    path = Path(path)
    if not path.is_file():
        raise SSPError(f"{path}: no such SSP file")
    try:
        with zipfile.ZipFile(path) as archive:
            names = set(archive.namelist())
            ssd = archive.read("SystemStructure.ssd")
    except zipfile.BadZipFile:
        raise SSPError(f"{path}: not an SSP archive (not a zip file)") from None
    except KeyError:
        raise SSPError(f"{path}: the archive has no SystemStructure.ssd") from None
    try:
        root = fromstring(ssd)
    except ParseError as error:
        raise SSPError(f"{path}: SystemStructure.ssd is not well-formed XML ({error})") from None
    sources = [e.get("source") for e in root.iter(f"{{{_XML_NAMESPACES['ssd']}}}Component")]
    if not sources:
        raise SSPError(f"{path}: SystemStructure.ssd names no component")
    missing = [str(source) for source in sources if source not in names]
    if missing:
        raise SSPError(f"{path}: the archive lacks {', '.join(missing)}, named in its ssd")


def fmpy_parameter_set(ssp_path):
    """The component-level bindings of `ssp_path` as one FMPy ParameterSet with
    hierarchical names ("<component>.<parameter>"), the form `simulate_ssp` applies."""
    from fmpy.ssp.ssd import Parameter, ParameterSet, find_components, read_ssd

    check_ssp(ssp_path)
    ssd = read_ssd(str(ssp_path))
    merged = ParameterSet(name=ssd.name)
    for component in find_components(ssd.system):
        for binding in component.parameterBindings:
            for parameter_set in binding.parameterValues:
                for parameter in parameter_set.parameters:
                    merged.parameters.append(
                        Parameter(
                            name=f"{component.name}.{binding.prefix or ''}{parameter.name}",
                            type=parameter.type,
                            value=parameter.value,
                            unit=parameter.unit,
                        )
                    )
    return merged
