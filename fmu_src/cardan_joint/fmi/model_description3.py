"""Complete pythonfmu3's FMI 3.0 model description from the variable table.

pythonfmu3 0.3.4 writes no display units, no min/max, no output dependencies,
start values to 16 digits only (not enough to read back the same double), and
the co-simulation capabilities from a leftover loop variable. This sets them
all from the model's table, with the same unit definitions as the FMI 2.0 FMU.
"""

from xml.etree.ElementTree import Element, SubElement

from .model_description import _number, _unit_definitions, child, numbered_variables, start_text

CAPABILITIES = {
    "canHandleVariableCommunicationStepSize": "true",
    "canGetAndSetFMUState": "true",
    "canSerializeFMUState": "true",
}


def _attribute(node: Element, name: str) -> str:
    value = node.get(name)
    if value is None:
        raise ValueError(f"model description: a <{node.tag}> has no {name} attribute")
    return value


def complete(root: Element, groups, starts, table) -> Element:
    """`groups`: the table's `fmi3_variables()`, the order the slave registered them in
    (after the independent variable `time`); `starts`: name -> start value (the
    build's, which may differ from the table's) of every input and parameter; an
    array's start lists its elements' values."""
    cosimulation = child(root, "CoSimulation")
    for name, value in CAPABILITIES.items():
        cosimulation.set(name, value)
    if root.find("UnitDefinitions") is None:
        root.insert(list(root).index(cosimulation) + 1, _unit_definitions(table))

    by_name = {group.name: group for group in groups}
    reference: dict[str, str] = {}
    for position, node in numbered_variables(root):
        reference[_attribute(node, "name")] = str(position)
        group = by_name.get(node.get("name"))
        if group is None:  # the independent variable
            continue
        rows = tuple(row.name for row in group.rows)
        start = start_text(group.name, starts, rows) if rows[0] in starts else None
        attributes = {
            "unit": group.unit,
            "displayUnit": group.display_unit,
            "start": start,
            **{
                a: None if getattr(group, a) is None else _number(getattr(group, a))
                for a in ("min", "max")
            },
        }
        node.attrib.update({k: v for k, v in attributes.items() if v})

    structure = child(root, "ModelStructure")
    for node in list(structure):
        structure.remove(node)
    outputs = [group for group in groups if group.causality == "output"]
    for group in outputs:
        dependencies = " ".join(reference[name] for name in group.depends_on)
        SubElement(
            structure, "Output", valueReference=reference[group.name], dependencies=dependencies
        )
    for group in outputs:
        # At initialization an output depends on the inputs and on the parameters
        # (yoke phase, start angle, inertias), so no narrower list is declared.
        SubElement(structure, "InitialUnknown", valueReference=reference[group.name])
    return root
