"""Every model whose spec names a step (docs/codegen.md), at every build
setting: its generated C gives the Python step's bits for every output, state
value and moved input, and the same decision to take or refuse each step, over
random steps drawn from the model's variable table (`step_cases`); and a
generator whose products are sums, or whose strict comparisons are loose, is
caught for each; and the model's own `run` gives the bits of the step its spec
names. A model that opts in is covered here without a line of its own.
The Motor, Load and InertiaLoad also take, through their written step, exactly
the steps and refusals of the checks' own path."""

import ast

import pytest
from generated_c import CStep, bits
from step_cases import cases

from cardan_joint.codegen import expressions, generate
from cardan_joint.framework.refusal import Refusal
from cardan_joint.framework.stepped import SteppedModel
from cardan_joint.models import discover

CASES = 2_000


def case_count(settings) -> int:
    """A chain of joints steps in Python at a few milliseconds with life (its
    own test, test_codegen_propshaft, draws its layouts further): a quarter."""
    return CASES // 4 if "joints" in settings else CASES


def written_steps():
    for key, spec in discover().items():
        for variant in spec.variants():
            settings = {**spec.default_settings, **variant}
            if spec.step and spec.step(settings) is not None:
                name = "-".join(f"{k}={v}" for k, v in variant.items())
                yield pytest.param((key, settings), id=f"{key}-{name}" if name else key)


STEPS = list(written_steps())


@pytest.fixture(scope="module", params=STEPS)
def written(request, tmp_path_factory):
    """(the model's spec, its build settings, its Python step, that step in C)."""
    key, settings = request.param
    spec = discover()[key]
    step = spec.step(settings)
    c = CStep(generate(step, step.__name__), tmp_path_factory.mktemp(step.__name__))
    return spec, settings, step, c


def compared(spec, settings, step, c_step, count: int) -> tuple[int, int, int]:
    """(cases whose bits or decision differ, steps taken, steps refused): each
    case from where the Python step left the model."""
    differ = taken = 0
    for case in cases(spec, settings, seed=32, count=count):
        python = step(*case.arguments)
        differ += bits(python) != bits(c_step(*case.arguments))
        taken += python is not None
        case.follow(python)
    return differ, taken, count - taken


def test_every_written_step_in_c_gives_the_python_steps_bits(written):
    spec, settings, step, c_step = written
    count = case_count(settings)
    differ, taken, refused = compared(spec, settings, step, c_step, count)
    assert differ == 0
    # Both decisions are exercised: the cases are not all refused, nor all taken
    # (a 3-joint propshaft's guards refuse four in five of the table's draws).
    assert taken > count // 10 and refused > count // 50, (taken, refused)


def test_each_models_run_takes_the_step_its_spec_names(written):
    """The model's own `run` gives the bits of the step the build translates:
    one definition for Python and C."""
    spec, settings, step, _ = written
    checked = 0
    for case in cases(spec, settings, seed=9, count=case_count(settings) // 4):
        python = step(*case.arguments)
        if python is not None:
            model, state, inputs = case.model, case.state_size, case.input_count
            outputs, moved = model.run(*case.arguments[:2], model.inputs())
            assert bits(model.step_state()) == bits(python[:state])
            assert bits(moved) == bits(python[state : state + inputs])
            assert bits(outputs) == bits(python[state + inputs :])
            checked += 1
        case.follow(python)
    assert checked > case_count(settings) // 20


MUTANTS = {
    "* as +": ("BINARY", {**expressions.BINARY, ast.Mult: "+"}),
    "strict comparisons loose": (
        "COMPARE",
        {**expressions.COMPARE, ast.Lt: "<=", ast.Gt: ">="},
    ),
}


@pytest.mark.parametrize("mutant", MUTANTS)
def test_a_mutated_generator_fails_every_models_bit_test(written, mutant, monkeypatch, tmp_path):
    spec, settings, step, _ = written
    name, replacement = MUTANTS[mutant]
    monkeypatch.setattr(expressions, name, replacement)
    mutated = CStep(generate(step, step.__name__), tmp_path, strict=False)
    # The same cases as the bit test, up to the first one the mutant gets wrong.
    for case in cases(spec, settings, seed=32, count=CASES):
        python = step(*case.arguments)
        if bits(python) != bits(mutated(*case.arguments)):
            return
        case.follow(python)
    pytest.fail(f"the generator with {mutant} gives {spec.key}'s bits in {CASES} cases")


@pytest.mark.parametrize("key", ["Motor", "Load", "InertiaLoad"])
def test_the_written_step_takes_what_the_checks_take_and_refuses_the_rest(key):
    """The written step takes a step exactly when the checks and `_advance`
    alone take it, to the same bits; `run` through it gives the checks'
    refusals (reason, variable, value, limit, time)."""
    spec = discover()[key]
    step = spec.step({})
    taken = 0
    count = 10 * CASES  # cheap steps: enough that a value past its range is met in a short step
    for case in cases(spec, {}, seed=5, count=count):
        model = case.model
        state, time, h = model.state(), *case.arguments[:2]
        inputs = model.inputs()
        written = step(*case.arguments)
        checked = SteppedModel.run(model, time, h, inputs)
        assert (written is None) == isinstance(checked, Refusal), (case.arguments, checked)
        model.restore(state)
        run = model.run(time, h, inputs)
        if written is None:
            assert run == checked  # a Refusal: the checks' own
        else:
            taken += 1
            assert bits(written) == bits((*model.step_state(), *run[1], *run[0]))
            assert bits(run[0] + run[1]) == bits(checked[0] + checked[1])
        case.follow(written)
    assert taken > count // 2
