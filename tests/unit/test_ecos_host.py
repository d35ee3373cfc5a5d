"""The Ecos runner's own checks, without running Ecos."""

import ctypes

import pytest

from cardan_joint.extras import MissingExtra
from cardan_joint.host import ecos


def test_a_missing_tbb_library_is_named_with_the_extra_to_install(monkeypatch, tmp_path):
    def no_library(name, *args, **kwargs):
        raise OSError(f"{name}: cannot open shared object file")

    monkeypatch.setattr(ctypes, "CDLL", no_library)
    monkeypatch.setattr(ecos.sys, "prefix", str(tmp_path))
    monkeypatch.setattr(ecos.sys, "base_prefix", str(tmp_path))
    with pytest.raises(MissingExtra, match=r"libtbb\.so\.12.*install the ecos extra"):
        ecos.require_ecos()


@pytest.mark.parametrize("stop_time, step", [(0.1, 0.03), (0.1, 0.0), (0.0, 0.01), (0.1, -0.01)])
def test_a_stop_time_that_is_no_whole_number_of_steps_is_refused(stop_time, step):
    with pytest.raises(ValueError, match="is not a positive whole number of steps"):
        ecos.run_ecos_ssp("missing.ssp", stop_time, step, ["Motor.speed"], "Driveline")
