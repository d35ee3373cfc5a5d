"""Complete pythonfmu's model description from the variable table.

pythonfmu 0.7.0 writes neither units nor min/max, nor InitialUnknowns, nor
output dependencies; FMPy's validator rejects the result. This adds them. It
also writes start values to 16 significant digits, which does not always read
back as the same double (1.3962634015954636 becomes 1.396263401595464): every
start is rewritten here as the shortest text that does (`repr`).
"""

from xml.etree.ElementTree import Element, SubElement

from .references import FIRST_VALUE_REFERENCE


def _number(value: float) -> str:
    # The shortest text that reads back as the same double.
    return repr(float(value))


def start_text(name: str, starts, rows=None) -> str:
    """`name`'s start attribute: the FMU's own start value(s) `starts[row]` of each of
    `rows` (an FMI 3 array's elements; default: the one row `name`)."""
    missing = [row for row in rows or (name,) if row not in starts]
    if missing:
        raise ValueError(f"model description: no start value of {', '.join(missing)} ({name})")
    return " ".join(_number(starts[row]) for row in rows or (name,))


def child(node: Element, tag: str) -> Element:
    """`node`'s `tag` element; a model description without it cannot be completed."""
    found = node.find(tag)
    if found is None:
        raise ValueError(f"model description: <{node.tag}> has no <{tag}> element")
    return found


def numbered_variables(root: Element):
    """(1-based position, node) of each variable under <ModelVariables>, each checked
    to have its position as value reference (`references`: so every host reads the
    dependencies alike)."""
    for position, node in enumerate(child(root, "ModelVariables"), start=FIRST_VALUE_REFERENCE):
        if node.get("valueReference") is None:
            raise ValueError(f"model description: a <{node.tag}> has no valueReference attribute")
        if node.get("valueReference") != str(position):
            raise ValueError(
                f"model description: {node.get('name')} has value reference "
                f"{node.get('valueReference')}, not its position {position}"
            )
        yield position, node


def _unit_definitions(table) -> Element:
    node = Element("UnitDefinitions")
    for unit in table.UNITS.values():
        unit_node = SubElement(node, "Unit", name=unit.name)
        base = {name: str(exponent) for name, exponent in unit.exponents}
        if unit.factor != 1.0:
            base["factor"] = _number(unit.factor)
        SubElement(unit_node, "BaseUnit", base)
        for display, factor in unit.display:
            SubElement(unit_node, "DisplayUnit", name=display, factor=_number(factor))
    return node


def complete(root: Element, table, starts) -> Element:
    """`root` with units, ranges and ModelStructure from the model's `table`, and
    every start value from `starts` (name -> the FMU's own start value)."""
    children = list(root)
    position = next(i for i, node in enumerate(children) if node.tag == "CoSimulation") + 1
    root.insert(position, _unit_definitions(table))

    index = {}
    for i, scalar in numbered_variables(root):
        variable = table.BY_NAME[scalar.get("name")]
        index[variable.name] = i
        if variable.initial and scalar.get("initial") is None:
            scalar.set("initial", variable.initial)
        real = child(scalar, "Real")
        if real.get("start") is not None:
            real.set("start", start_text(variable.name, starts))
        real.set("unit", variable.unit)
        if variable.display_unit:
            real.set("displayUnit", variable.display_unit)
        for attribute in ("min", "max"):
            value = getattr(variable, attribute)
            if value is not None:
                real.set(attribute, _number(value))

    structure = child(root, "ModelStructure")
    for node in list(structure):
        structure.remove(node)
    outputs = SubElement(structure, "Outputs")
    initial_unknowns = SubElement(structure, "InitialUnknowns")
    for name in table.OUTPUTS:
        variable = table.BY_NAME[name]
        dependencies = " ".join(str(index[d]) for d in variable.depends_on)
        SubElement(outputs, "Unknown", index=str(index[name]), dependencies=dependencies)
        # At initialization an output depends on the inputs and on the parameters
        # (geometry, start angle, inertias), so no narrower list is declared.
        SubElement(initial_unknowns, "Unknown", index=str(index[name]))
    return root
