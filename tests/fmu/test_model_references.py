"""Every reference run a model's spec declares: its files in the model's folder
are current (the one generator rewrites them byte for byte) and the model's
FMU reproduces them (simulate_fmu), for every model discovery finds."""

import numpy as np
import pytest
from fmpy import simulate_fmu
from fmpy.util import read_csv, read_ref_opt_file

from cardan_joint.build import cross_check
from cardan_joint.models import discover


@pytest.mark.parametrize("model", sorted(cross_check.with_reference()))
def test_reference_files_are_current_and_the_fmu_reproduces_them(model, model_fmu, tmp_path):
    committed = cross_check.reference_files(model)
    for path, fresh in zip(committed, cross_check.write_reference_files(tmp_path, model)):
        assert path.read_bytes() == fresh.read_bytes(), (
            f"{path} is stale: run python -m cardan_joint.build.cross_check --model {model}"
        )
    inputs, options_file, outputs = committed
    options = read_ref_opt_file(str(options_file))
    reference = read_csv(outputs)
    names = list(reference.dtype.names[1:])
    assert 0 < len(names) <= 9  # the cross-check rules' 10 columns with the time
    result = simulate_fmu(
        str(model_fmu(model)),
        start_time=options["StartTime"],
        stop_time=options["StopTime"],
        output_interval=options["StepSize"],
        input=read_csv(inputs),
        output=names,
    )
    np.testing.assert_array_equal(result["time"], reference["time"])
    for name in names:
        scale = np.max(np.abs(reference[name]))
        error = np.max(np.abs(result[name] - reference[name]))
        assert error <= 1e-12 * scale, (name, error, scale)


def test_no_model_folder_holds_reference_files_its_spec_does_not_declare():
    for key, spec in discover().items():
        found = {p.name for p in spec.path.iterdir() if p.suffix in (".csv", ".opt")}
        declared = {p.name for p in cross_check.reference_files(key)} if spec.reference else set()
        assert found == declared, key


def test_a_model_without_a_reference_run_is_refused_by_name():
    without = [key for key, spec in discover().items() if spec.reference is None]
    if not without:
        pytest.skip("every model declares a reference run")
    with pytest.raises(ValueError, match=f"{without[0]} declares no reference run"):
        cross_check.reference(without[0])
