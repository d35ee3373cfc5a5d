"""Step every model's slave (the code an FMU runs) and print every value as JSON.

    python tests/runtime_driver.py [--no-numpy]

With --no-numpy a meta-path finder refuses numpy in this process (as on a host
whose Python has none) before anything of the project is imported. The
slaves are driven as the FMU's binary drives them, without FMPy or any host.
"""

import json
import sys

STEPS = 50
STEP_SIZE = 1e-2
JOINT_INPUTS = {
    "input_speed": 100.0,
    "input_acceleration": 5.0,
    "bend_angle": 0.3,
    "bend_angle_rate": 0.01,
    "load_torque": 50.0,
}
PROPSHAFT_INPUTS = {"input_speed": 100.0, "input_acceleration": 5.0, "load_torque": 50.0}
INPUTS = {
    "UniversalJoint": JOINT_INPUTS,
    "Propshaft2": PROPSHAFT_INPUTS,
    "Propshaft3": PROPSHAFT_INPUTS,
    "Propshaft4": PROPSHAFT_INPUTS,
    "Motor": {"load_torque": 10.0},
    "Load": {"speed": 50.0, "acceleration": 2.0},
    "UniversalJoint3": JOINT_INPUTS,
}


class NoNumpy:
    """Refuses numpy and its submodules, as an interpreter without it would."""

    def find_spec(self, name, path=None, target=None):
        if name.split(".")[0] == "numpy":
            raise ImportError(f"No module named {name!r} (refused by {__file__})")
        return None


def slave_classes() -> dict:
    from cardan_joint.fmi.slave import ModelSlave
    from cardan_joint.fmi.slave3 import ModelSlave3

    def bound(name, folder, **settings):
        return type(name, (ModelSlave,), {"model_folder": folder, "build_settings": settings})

    return {
        "UniversalJoint": bound("UniversalJoint", "universal_joint"),
        "Propshaft2": bound("Propshaft2", "propshaft", joints=2),
        "Propshaft3": bound("Propshaft3", "propshaft", joints=3),
        "Propshaft4": bound("Propshaft4", "propshaft", joints=4),
        "Motor": bound("Motor", "motor"),
        "Load": bound("Load", "load"),
        "UniversalJoint3": type(
            "UniversalJoint3", (ModelSlave3,), {"model_folder": "universal_joint"}
        ),
    }


def run(name: str, slave_class) -> dict:
    """Every variable's value (by name) after initialisation and after each step."""
    slave = slave_class(instance_name=name)
    fmi3 = hasattr(slave, "get_float64")
    names = {v.name: vr for vr, v in slave.vars.items() if v.name != "time"}
    get = slave.get_float64 if fmi3 else slave.get_real
    put = slave.set_float64 if fmi3 else slave.set_real
    if fmi3:
        slave.enter_initialization_mode()
    else:
        slave.setup_experiment(0.0)
    slave.exit_initialization_mode()
    inputs = INPUTS[name]
    rows = [get(list(names.values()))]
    for step in range(STEPS):
        put([names[n] for n in inputs], list(inputs.values()))
        slave.do_step(step * STEP_SIZE, STEP_SIZE)
        rows.append(get(list(names.values())))
    return {"names": list(names), "rows": rows}


def main() -> None:
    if "--no-numpy" in sys.argv[1:]:
        sys.meta_path.insert(0, NoNumpy())
        try:
            import numpy  # noqa: F401
        except ImportError:
            pass
        else:
            raise SystemExit("numpy imported despite the refusal")
    results = {name: run(name, cls) for name, cls in slave_classes().items()}
    results["numpy_imported"] = "numpy" in sys.modules
    json.dump(results, sys.stdout)


if __name__ == "__main__":
    main()
