"""Write a co-simulation system as an SSP archive (SSP 1.0, xml.etree).

`write_ssp` packs the FMUs, a SystemStructure.ssd with their connectors and
connections, and one parameter set (.ssv) per component, bound at component
level. Component-level bindings with bare variable names are what both hosts
of this project apply: OSP libcosim ignores system-level bindings, and FMPy's
`simulate_ssp` applies no binding at all but takes a parameter set with
hierarchical names, which `fmpy_parameter_set` builds from the bindings.
The same values are also bound once at system level, as one parameter set
named after the system with hierarchical names ("<component>.<parameter>"): a host
that applies one named parameter set at a time still gets every component's.
`check_ssp` turns a missing or broken archive into an `SSPError` naming it.
"""

import zipfile
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from xml.etree.ElementTree import Element, ParseError, SubElement, fromstring, indent, tostring

_XML_NAMESPACES = {
    "ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription",
    "ssc": "http://ssp-standard.org/SSP1/SystemStructureCommon",
    "ssv": "http://ssp-standard.org/SSP1/SystemStructureParameterValues",
}
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


def parameter_set_xml(name: str, values: Mapping[str, float]) -> bytes:
    ssv = lambda tag: _qualified("ssv", tag)  # noqa: E731
    root = _root(ssv("ParameterSet"), ("ssv",), version="1.0", name=name)
    parameters = SubElement(root, ssv("Parameters"))
    for parameter, value in values.items():
        node = SubElement(parameters, ssv("Parameter"), name=parameter)
        SubElement(node, ssv("Real"), value=repr(float(value)))
    return _xml(root)


def system_structure_xml(
    name: str, components: list[Component], connections: list[Connection], stop_time: float
) -> bytes:
    ssd = lambda tag: _qualified("ssd", tag)  # noqa: E731
    root = _root(ssd("SystemStructureDescription"), ("ssd", "ssc"), version="1.0", name=name)
    system = SubElement(root, ssd("System"), name=name)
    if any(component.parameters for component in components):
        bindings = SubElement(system, ssd("ParameterBindings"))
        SubElement(bindings, ssd("ParameterBinding"), type=SSV_TYPE, source=_system_source(name))
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
    SubElement(root, ssd("DefaultExperiment"), startTime="0.0", stopTime=repr(float(stop_time)))
    return _xml(root)


def write_ssp(
    path, name: str, components: list[Component], connections: list[Connection], stop_time: float
) -> Path:
    """Write the SSP archive `path`; return its path."""
    by_name = {c.name: c for c in components}
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
            "SystemStructure.ssd", system_structure_xml(name, components, connections, stop_time)
        )
        everything = {}
        for component in components:
            archive.write(component.fmu, component.source)
            if component.parameters:
                archive.writestr(
                    component.parameter_source,
                    parameter_set_xml(component.name, component.parameters),
                )
            everything.update({f"{component.name}.{n}": v for n, v in component.parameters.items()})
        if everything:
            archive.writestr(_system_source(name), parameter_set_xml(name, everything))
    return path


def _system_source(name: str) -> str:
    return f"resources/{name}.ssv"


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
