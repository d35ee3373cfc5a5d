"""The compliant models' docs: reference files current and reproduced by the FMUs
(simulate_fmu), variable tables generated from the tables."""

import numpy as np
import pytest
from conftest import ROOT
from fmpy import simulate_fmu
from fmpy.util import read_csv, read_ref_opt_file

from cardan_joint.build import cross_check

FIXTURES = {"CompliantJoint": "compliant_joint_fmu_path", "InertiaLoad": "inertia_load_fmu_path"}


@pytest.mark.parametrize("model", sorted(FIXTURES))
def test_reference_files_are_current_and_the_fmu_reproduces_them(model, request, tmp_path):
    docs = ROOT / "docs" / model
    for path in cross_check.write_reference_files(tmp_path, model):
        assert (docs / path.name).read_bytes() == path.read_bytes(), (
            f"docs/{model}/{path.name} is stale: run python -m cardan_joint.build.cross_check "
            f"--model {model}"
        )
    options = read_ref_opt_file(str(docs / f"{model}_ref.opt"))
    reference = read_csv(docs / f"{model}_ref.csv")
    names = list(reference.dtype.names[1:])
    result = simulate_fmu(
        str(request.getfixturevalue(FIXTURES[model])),
        start_time=options["StartTime"],
        stop_time=options["StopTime"],
        output_interval=options["StepSize"],
        input=read_csv(docs / f"{model}_in.csv"),
        output=names,
    )
    np.testing.assert_array_equal(result["time"], reference["time"])
    for name in names:
        scale = np.max(np.abs(reference[name]))
        error = np.max(np.abs(result[name] - reference[name]))
        assert error <= 1e-12 * scale, (name, error, scale)


@pytest.mark.parametrize("model", ["CompliantJoint", "InertiaLoad", "CompliantPropshaft"])
def test_docs_variable_table_is_generated_from_the_models_table(model):
    from cardan_joint.models.compliant_joint.variables import COMPLIANT_JOINT
    from cardan_joint.models.compliant_propshaft.variables import compliant_propshaft_table
    from cardan_joint.models.inertia_load.variables import INERTIA_LOAD

    table = {
        "CompliantJoint": COMPLIANT_JOINT,
        "InertiaLoad": INERTIA_LOAD,
        "CompliantPropshaft": compliant_propshaft_table(2),
    }[model]
    text = (ROOT / "docs" / model / "README.md").read_text()
    begin, end = "<!-- variables:begin -->\n", "<!-- variables:end -->"
    assert text.split(begin)[1].split(end)[0] == table.markdown_table()
